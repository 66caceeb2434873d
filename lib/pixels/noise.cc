#include "pixels/noise.h"

#include <cmath>
#include <cstdlib>

namespace ctrack {

void NoiseSamples::begin()
{
    hist_.assign(9 * 256, 0);
    n = m_n = 0;
}

void NoiseSamples::levels(const uint8_t *my, int w)
{
    uint32_t *h = m();
    for (int x = 0; x < w; x += 4)
        h[my[x]]++;
    m_n += (uint32_t)((w + 3) / 4);
}

void NoiseSamples::sample(const uint8_t *dy, const uint8_t *dc, const uint8_t *frozen, int w)
{
    uint32_t count = 0; // a local: the histograms' stores would reload a member
    uint32_t *hy[4] = {y(0), y(1), y(2), y(3)}, *hc[4] = {c(0), c(1), c(2), c(3)};
    if (dc) {
        for (int x = 0, k = 0; x < w; x += 4, k = (k + 1) & 3) {
            if (frozen[x])
                continue;
            hy[k][dy[x]]++;
            hc[k][dc[x]]++;
            count++;
        }
    } else {
        for (int x = 0, k = 0; x < w; x += 4, k = (k + 1) & 3) {
            if (frozen[x])
                continue;
            hy[k][dy[x]]++;
            count++;
        }
    }
    n += count;
}

void sum_of_four(const uint32_t *a, const uint32_t *b, const uint32_t *c, const uint32_t *d,
                 uint32_t *out)
{
    for (int v = 0; v < 256; v++)
        out[v] = a[v] + b[v] + c[v] + d[v];
}

double quantile_of(const uint32_t *hist, uint32_t n, double q)
{
    uint32_t below = 0;
    for (int v = 0; v < 256; v++) {
        below += hist[v];
        if (below >= q * n)
            return v;
    }
    return 255;
}

double median_of(const uint32_t *hist, uint32_t n)
{
    return quantile_of(hist, n, 0.5);
}

namespace {

// How fast the estimates follow the frames, in seconds.
constexpr double kNoiseTime = 1.0;
// The median absolute deviation of Gaussian noise, in standard deviations.
constexpr double kMadPerSd = 0.6745;
// The dark level is the model's first percentile of luma.
constexpr double kDarkPercentile = 0.01;

} // namespace

void NoiseLevel::end_fine(double sd, double dt)
{
    const double rate = fine_known_ && dt > 0 ? 1.0 - std::exp(-dt / kNoiseTime) : 1.0;
    fine += rate * (sd - fine);
    fine_known_ = true;
}

void NoiseLevel::end(const NoiseSamples &s, double dt)
{
    if (s.n == 0)
        return;
    uint32_t hy[256], hc[256];
    sum_of_four(s.y(0), s.y(1), s.y(2), s.y(3), hy);
    sum_of_four(s.c(0), s.c(1), s.c(2), s.c(3), hc);
    const double y = median_of(hy, s.n) / kMadPerSd;
    const double c = median_of(hc, s.n) / kMadPerSd;
    const double rate = known_ && dt > 0 ? 1.0 - std::exp(-dt / kNoiseTime) : 1.0;
    luma += rate * (y - luma);
    chroma += rate * (c - chroma);
    if (s.m_n > 0) {
        const uint32_t *m = s.m();
        const int median = (int)median_of(m, s.m_n);
        uint32_t deviation[256] = {};
        for (int v = 0; v < 256; v++)
            deviation[std::abs(v - median)] += m[v];
        contrast += rate * (median_of(deviation, s.m_n) - contrast);
        dark += rate * (quantile_of(m, s.m_n, kDarkPercentile) - dark);
    }
    known_ = true;
}

} // namespace ctrack
