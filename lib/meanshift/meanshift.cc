#include "meanshift/meanshift.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "dsp/dsp.h"
#include "pixels/mask.h"

namespace ctrack {

namespace {

// sqrt(i / 65536) in Q16 = sqrt(x) with x = i * 65536, rounded to the
// nearest integer: the largest r with (r - 1/2)^2 <= x, that is r (r - 1) < x.
// The roots of increasing arguments never decrease, so each entry starts
// from the previous one: the whole table costs a few hundred thousand steps
// at compile time.
constexpr std::array<uint16_t, 65536> make_sqrt_table()
{
    std::array<uint16_t, 65536> t{};
    uint64_t r = 0;
    for (uint64_t i = 0; i < 65536; i++) {
        const uint64_t x = i * 65536;
        while ((r + 1) * r < x)
            r++;
        t[i] = (uint16_t)(r < 65535 ? r : 65535);
    }
    return t;
}

constexpr std::array<uint16_t, 65536> kSqrt = make_sqrt_table();


// Windows larger than this (half-sides, pixels) are cut to it: no frame is
// near so large (16384 at most), and the arithmetic below stays in range.
constexpr double kMaxHalfSide = 1 << 20;

inline int sample_step(double area, double target)
{
    return std::max(1, (int)std::floor(std::sqrt(area / target)));
}

// 2^48 / total, so that a count's probability in Q16 is a multiplication
// (probability_q16 below) instead of a division.
inline uint64_t reciprocal(uint64_t total)
{
    return ((uint64_t)1 << 48) / total;
}

// count / total in Q16, rounded, at most 65535 (the table's last entry).
inline uint32_t probability_q16(uint64_t count, uint64_t inv)
{
    return (uint32_t)std::min<uint64_t>(65535, (count * inv + ((uint64_t)1 << 31)) >> 32);
}

} // namespace

uint32_t sqrt_q16(uint32_t i)
{
    return kSqrt[std::min<uint32_t>(i, 65535)];
}

// The bins the samples reached, in ascending order: a pass over the
// histogram afterwards, eight bins at a time (most groups are empty), costs
// less than keeping the list sample by sample.
void MeanShift::list_touched()
{
    int n = 0;
    for (int g = 0; g < kHistBins; g += 8) {
        uint32_t any = 0;
        for (int j = 0; j < 8; j++)
            any |= hist_[g + j];
        if (any == 0)
            continue;
        for (int j = 0; j < 8; j++) {
            touched_[n] = (uint16_t)(g + j);
            n += hist_[g + j] != 0;
        }
    }
    n_touched_ = n;
}

void MeanShift::chroma_columns(const Planes &img, int x0, int step, int ncols)
{
    chroma_.resize(ncols);
    for (int i = 0; i < ncols; i++)
        chroma_[i] = ((x0 + i * step) >> 1) * (int32_t)img.c_step;
}

void MeanShift::clear_hist()
{
    for (int i = 0; i < n_touched_; i++)
        hist_[touched_[i]] = 0;
    n_touched_ = 0;
}

namespace {

// One row's run of the window (n samples s pixels apart from column x,
// with their column terms and, in colour, chroma offsets) into the
// histogram: each sample's kernel weight to its bin, its bin to *out;
// returns the row's weight.
CT_ALWAYS_INLINE uint32_t bin_run(const Planes &img, int y, int x, int s, const int32_t *cols,
                                  const int32_t *chroma, int n, uint32_t rk, uint32_t *hist,
                                  uint16_t **out)
{
    uint32_t row_total = 0;
    uint16_t *o = *out;
    const uint8_t *py = img.y + (size_t)y * img.y_stride + x;
    if (img.color) {
        const uint8_t *urow = img.u + (size_t)(y >> 1) * img.u_stride;
        const uint8_t *vrow = img.v + (size_t)(y >> 1) * img.v_stride;
        for (int i = 0; i < n; i++, py += s) {
            const int32_t c = chroma[i];
            const int bin = colour_bin(*py, urow[c], vrow[c]);
            const uint32_t k = rk - (uint32_t)cols[i];
            hist[bin] += k;
            row_total += k;
            *o++ = (uint16_t)bin;
        }
    } else {
        for (int i = 0; i < n; i++, py += s) {
            const int bin = grey_bin(*py);
            const uint32_t k = rk - (uint32_t)cols[i];
            hist[bin] += k;
            row_total += k;
            *o++ = (uint16_t)bin;
        }
    }
    *out = o;
    return row_total;
}

} // namespace

uint64_t MeanShift::sample(const Planes &img, double cx, double cy, double hw, double hh)
{
    clear_hist();
    n_runs_ = 0;
    if (!(hw >= 1 && hh >= 1))
        return 0;
    hw = std::min(hw, kMaxHalfSide);
    hh = std::min(hh, kMaxHalfSide);
    const int s = sample_step(M_PI * hw * hh, kTargetSamples); // the ellipse's area
    const int x0 = std::max(0, pixel_int(std::ceil(cx - hw))), x1 = std::min(img.width - 1, pixel_int(std::floor(cx + hw)));
    const int y0 = std::max(0, pixel_int(std::ceil(cy - hh))), y1 = std::min(img.height - 1, pixel_int(std::floor(cy + hh)));
    if (x1 < x0 || y1 < y0)
        return 0; // also when cx or cy is NaN
    // r^2 = dx^2 / hw^2 + dy^2 / hh^2 in Q12, as a column term (a table) plus
    // a row term; positions in Q8 so that sub-pixel centres count.
    const int64_t cx8 = std::llround(cx * 256), cy8 = std::llround(cy * 256);
    const int64_t hw8 = std::max<int64_t>(1, std::llround(hw * 256));
    const int64_t hh8 = std::max<int64_t>(1, std::llround(hh * 256));
    const KernelTerm col_term(hw8 * hw8), row_term(hh8 * hh8);
    const int ncols = (x1 - x0) / s + 1;
    columns_.resize(ncols);
    for (int i = 0; i < ncols; i++) {
        int64_t dx = ((int64_t)(x0 + i * s) << 8) - cx8;
        columns_[i] = col_term(dx);
    }
    // Each column's offset in the chroma rows.
    if (img.color)
        chroma_columns(img, x0, s, ncols);
    // The loop works on locals, which the compiler keeps in registers: the
    // members would be reloaded after every store.
    const int nrows = (y1 - y0) / s + 1;
    if (bins_.size() < (size_t)nrows * ncols)
        bins_.resize((size_t)nrows * ncols); // grows once, then keeps its size
    if (runs_.size() < (size_t)nrows)
        runs_.resize((size_t)nrows);
    uint16_t *out = bins_.data();
    Run *runs = runs_.data();
    size_t n_runs = 0;
    step_ = s;
    uint32_t *hist = hist_;
    const int32_t *cols = columns_.data();
    const int32_t *chroma = chroma_.data();
    uint64_t total = 0;
    // The columns inside the ellipse on a row are one run: the column term
    // falls to the centre and rises after it.
    int centre = 0;
    for (int i = 1; i < ncols; i++)
        if (cols[i] < cols[centre])
            centre = i;
    // Each row's run starts from the last row's (-1: none), which it
    // differs from by a few columns at each end.
    int i0 = -1, i1 = -1;
    for (int y = y0; y <= y1; y += s) {
        int64_t dy = ((int64_t)y << 8) - cy8;
        const int32_t row = row_term(dy);
        if (row >= kKernelOne || row + cols[centre] >= kKernelOne) {
            i0 = -1;
            continue;
        }
        if (i0 < 0) {
            i0 = centre;
            i1 = centre + 1;
        }
        while (i0 > 0 && row + cols[i0 - 1] < kKernelOne)
            i0--;
        while (i1 < ncols && row + cols[i1] < kKernelOne)
            i1++;
        while (row + cols[i0] >= kKernelOne) // stops at the centre at the latest
            i0++;
        while (row + cols[i1 - 1] >= kKernelOne)
            i1--;
        runs[n_runs++] = Run{x0 + i0 * s, y, i1 - i0};
        const uint32_t rk = (uint32_t)(kKernelOne - row); // Epanechnikov: rk - column term
        total += bin_run(img, y, x0 + i0 * s, s, cols + i0, img.color ? chroma + i0 : nullptr,
                         i1 - i0, rk, hist, &out);
    }
    n_runs_ = n_runs;
    list_touched();
    return total;
}

void MeanShift::normalise(uint64_t total, uint16_t *out) const
{
    std::memset(out, 0, kHistBins * sizeof *out);
    if (total == 0)
        return;
    const uint64_t inv = reciprocal(total);
    for (int i = 0; i < n_touched_; i++) {
        int b = touched_[i];
        out[b] = (uint16_t)probability_q16(hist_[b], inv);
    }
}

int MeanShift::rho(uint64_t total, const uint16_t *model) const
{
    if (total == 0)
        return 0;
    uint64_t sum = 0;
    const uint64_t inv = reciprocal(total);
    for (int i = 0; i < n_touched_; i++) {
        int b = touched_[i];
        sum += (uint64_t)kSqrt[probability_q16(hist_[b], inv)] * kSqrt[model[b]];
    }
    return (int)std::min<uint64_t>(kQ16, sum >> 16);
}

// The ring between the box and the box grown `grow` times in area.
void MeanShift::background(const Planes &img, double cx, double cy, double w, double h,
                           double grow, uint16_t *out)
{
    const double g = std::sqrt(grow);
    w = std::min(w, kMaxHalfSide);
    h = std::min(h, kMaxHalfSide);
    const double ow = w * g / 2, oh = h * g / 2, iw = w / 2, ih = h / 2;
    const int s = sample_step(w * h * (grow - 1), kTargetRingSamples);
    const int x0 = std::max(0, pixel_int(std::ceil(cx - ow))), x1 = std::min(img.width - 1, pixel_int(std::floor(cx + ow)));
    const int y0 = std::max(0, pixel_int(std::ceil(cy - oh))), y1 = std::min(img.height - 1, pixel_int(std::floor(cy + oh)));
    clear_hist();
    if (x1 < x0 || y1 < y0) {
        normalise(0, out);
        return; // also when cx or cy is NaN
    }
    // The ring's columns, with their chroma offsets; those inside the box
    // (|x - cx| < iw) are one run [ja, jb), left out on the box's rows.
    const int ncols = (x1 - x0) / s + 1;
    chroma_columns(img, x0, s, ncols);
    int ja = 0;
    while (ja < ncols && !(std::fabs(x0 + ja * s - cx) < iw))
        ja++;
    int jb = ja;
    while (jb < ncols && std::fabs(x0 + jb * s - cx) < iw)
        jb++;
    const int32_t *chroma = chroma_.data();
    uint32_t *hist = hist_;
    uint64_t total = 0;
    for (int y = y0; y <= y1; y += s) {
        const uint8_t *yrow = img.y + (size_t)y * img.y_stride;
        const uint8_t *urow = img.color ? img.u + (size_t)(y >> 1) * img.u_stride : nullptr;
        const uint8_t *vrow = img.color ? img.v + (size_t)(y >> 1) * img.v_stride : nullptr;
        auto count = [&](int j0, int j1) {
            const uint8_t *py = yrow + x0 + (size_t)j0 * s;
            if (img.color)
                for (int j = j0; j < j1; j++, py += s)
                    hist[colour_bin(*py, urow[chroma[j]], vrow[chroma[j]])]++;
            else
                for (int j = j0; j < j1; j++, py += s)
                    hist[grey_bin(*py)]++;
            total += (uint64_t)(j1 - j0);
        };
        if (std::fabs(y - cy) < ih) {
            count(0, ja);
            count(jb, ncols);
        } else {
            count(0, ncols);
        }
    }
    list_touched();
    normalise(total, out);
    clear_hist();
}

// CBWH: v_u = min(o* / o_u, 1) with o* the smallest non-zero background
// probability, and qw = v q renormalised. Colours common around the target
// weigh less in the target model.
void MeanShift::weight_against_background(const Planes &img, double cx, double cy, double w,
                                          double h, ColorModel *m)
{
    uint16_t o[kHistBins];
    background(img, cx, cy, w, h, 3.0, o);
    uint32_t o_min = kQ16;
    for (int b = 0; b < kHistBins; b++)
        if (o[b] > 0)
            o_min = std::min<uint32_t>(o_min, o[b]);
    // Only the bins the target has matter (a few dozen of 512, found eight
    // at a time): the others stay 0.
    uint16_t bins[kHistBins];
    uint32_t weighted[kHistBins];
    int n = 0;
    uint64_t sum = 0;
    for (int g = 0; g < kHistBins; g += 8) {
        uint64_t any[2];
        std::memcpy(any, &m->q[g], sizeof any);
        if ((any[0] | any[1]) == 0)
            continue;
        for (int b = g; b < g + 8; b++) {
            if (m->q[b] == 0)
                continue;
            const uint32_t v = o[b] > o_min ? (o_min << 16) / o[b] : kQ16; // Q16, <= 1
            weighted[n] = (uint32_t)(((uint64_t)m->q[b] * v) >> 16);
            bins[n++] = (uint16_t)b;
            sum += weighted[n - 1];
        }
    }
    const uint64_t inv = sum ? ((uint64_t)1 << 32) / sum : 0; // 1 / sum in Q32
    std::memset(m->qw, 0, sizeof m->qw);
    for (int i = 0; i < n; i++)
        m->qw[bins[i]] = (uint16_t)std::min<uint64_t>(65535, ((uint64_t)weighted[i] * inv) >> 16);
}

void MeanShift::build(const Planes &img, double cx, double cy, double w, double h,
                      ColorModel *m)
{
    uint64_t total = sample(img, cx, cy, w / 2, h / 2);
    m->valid = total > 0;
    m->color = img.color;
    normalise(total, m->q);
    if (m->valid)
        weight_against_background(img, cx, cy, w, h, m);
    clear_hist();
}

bool MeanShift::learn(const Planes &img, double cx, double cy, double w, double h, int mu_q8,
                      int min_rho, ColorModel *m)
{
    uint64_t total = sample(img, cx, cy, w / 2, h / 2);
    if (total == 0 || m->color != img.color || rho(total, m->qw) < min_rho) {
        clear_hist();
        return false;
    }
    uint16_t obs[kHistBins];
    normalise(total, obs);
    for (int b = 0; b < kHistBins; b++)
        m->q[b] = (uint16_t)((mu_q8 * obs[b] + (256 - mu_q8) * m->q[b] + 128) >> 8);
    weight_against_background(img, cx, cy, w, h, m);
    clear_hist();
    return true;
}

int MeanShift::similarity(const Planes &img, double cx, double cy, double w, double h,
                          const ColorModel &m)
{
    uint64_t total = sample(img, cx, cy, w / 2, h / 2);
    int r = rho(total, m.qw);
    clear_hist();
    return r;
}

int MeanShift::contrast(const Planes &img, double cx, double cy, double hw, double hh,
                        const ColorModel &m)
{
    uint64_t total = sample(img, cx, cy, hw, hh);
    int inside = rho(total, m.qw);
    uint16_t o[kHistBins];
    background(img, cx, cy, 2 * hw, 2 * hh, 2.0, o);
    uint64_t sum = 0;
    for (int b = 0; b < kHistBins; b++)
        sum += (uint64_t)kSqrt[o[b]] * kSqrt[m.qw[b]];
    return inside - (int)std::min<uint64_t>(kQ16, sum >> 16);
}

bool MeanShift::step(const Planes &img, double cx, double cy, double hw, double hh,
                     const ColorModel &m, double *nx, double *ny, uint32_t *weights)
{
    uint64_t total = sample(img, cx, cy, hw, hh);
    return total > 0 && centroid(total, m, nx, ny, weights);
}

// Eq. (12): w_u = sqrt(q_u / p_u) for the bins in the window, Q16; eq. (13)
// with the Epanechnikov kernel, whose profile derivative is constant: the new
// centre is the weighted mean of the samples.
bool MeanShift::centroid(uint64_t total, const ColorModel &m, double *nx, double *ny,
                         uint32_t *weights_out)
{
    uint32_t local[kHistBins];
    uint32_t *weight = weights_out ? weights_out : local;
    const uint64_t inv = reciprocal(total);
    for (int i = 0; i < n_touched_; i++) {
        int b = touched_[i];
        uint32_t sp = std::max<uint32_t>(1, kSqrt[probability_q16(hist_[b], inv)]);
        weight[b] = (uint32_t)std::min<uint64_t>(UINT32_MAX, ((uint64_t)kSqrt[m.qw[b]] << 16) / sp);
    }
    // Sums of weights and of weighted positions, row by row: on a row the
    // samples are at x, x + step, ..., so the sum of w x is x times the
    // sum of w plus step times the sum of w i; all exact in integers.
    int64_t sw = 0, sx = 0, sy = 0;
    const uint16_t *bins = bins_.data();
    for (size_t r = 0; r < n_runs_; r++) {
        const Run &run = runs_[r];
        int64_t rw = 0, ri = 0;
        for (int i = 0; i < run.count; i++) {
            const uint32_t wt = weight[bins[i]];
            rw += wt;
            ri += (int64_t)wt * i;
        }
        bins += run.count;
        sw += rw;
        sx += rw * run.x + ri * step_;
        sy += rw * run.y;
    }
    if (sw == 0)
        return false;
    *nx = (double)sx / sw;
    *ny = (double)sy / sw;
    return true;
}

MeanShiftResult MeanShift::track(const Planes &img, double cx, double cy, double w, double h,
                                 const ColorModel &m, const MeanShiftParams &p)
{
    if (!m.valid || m.color != img.color)
        return MeanShiftResult(cx, cy, w, h);
    // Coarse to fine: where the prediction missed by more than the window
    // reaches (fast motion), a first search with a window p.coarse_scale
    // times larger, and so sampled more sparsely, finds the person; the
    // window at its own size then refines it.
    int coarse_iterations = 0;
    if (p.coarse_below > 0 && p.coarse_scale > 1 &&
        similarity(img, cx, cy, w, h, m) < p.coarse_below) {
        MeanShiftResult r =
            converge(img, cx, cy, w * p.coarse_scale, h * p.coarse_scale, m, p);
        cx = r.cx;
        cy = r.cy;
        coarse_iterations = r.iterations;
    }
    MeanShiftResult r = converge(img, cx, cy, w, h, m, p);
    r.iterations += coarse_iterations;
    return r;
}

MeanShiftResult MeanShift::converge(const Planes &img, double cx, double cy, double w, double h,
                                    const ColorModel &m, const MeanShiftParams &p)
{
    MeanShiftResult res(cx, cy, w, h);
    const double hw = w / 2, hh = h / 2;
    uint64_t total = sample(img, cx, cy, hw, hh);
    int rho0 = rho(total, m.qw);
    for (int it = 0; it < p.max_iterations && total > 0; it++) {
        res.iterations = it + 1;
        double nx, ny;
        if (!centroid(total, m, &nx, &ny, nullptr))
            break;
        total = sample(img, nx, ny, hw, hh);
        int rho1 = rho(total, m.qw);
        // Step 7: while the move lost similarity, halve it.
        for (int k = 0; k < p.max_halvings && rho1 < rho0; k++) {
            nx = (cx + nx) / 2;
            ny = (cy + ny) / 2;
            total = sample(img, nx, ny, hw, hh);
            rho1 = rho(total, m.qw);
        }
        double moved = std::hypot(nx - cx, ny - cy);
        cx = nx;
        cy = ny;
        rho0 = rho1;
        // Step 8: converged.
        if (moved < p.epsilon)
            break;
    }
    res.cx = cx;
    res.cy = cy;
    res.rho = rho0;
    clear_hist();
    return res;
}

void MeanShift::scale(const Planes &img, const ColorModel &m, const MeanShiftParams &p,
                      MeanShiftResult *r)
{
    if (p.scale_step <= 0 || !m.valid || m.color != img.color)
        return;
    const double w = r->width, h = r->height;
    int best = contrast(img, r->cx, r->cy, w / 2, h / 2, m) + p.scale_margin;
    for (double s : {1 - p.scale_step, 1 + p.scale_step}) {
        int c = contrast(img, r->cx, r->cy, w * s / 2, h * s / 2, m);
        if (c > best) {
            best = c;
            r->width = w * s;
            r->height = h * s;
            r->rho = rho(sample(img, r->cx, r->cy, w * s / 2, h * s / 2), m.qw);
        }
    }
    clear_hist();
}

} // namespace ctrack
