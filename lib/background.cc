#include "background.h"

#include <algorithm>
#include <cstdlib>

namespace ctrack {

namespace {

// Sigma-Delta's amplification: V follows N |I - M|.
constexpr int kN = 4;
// Bounds of V: below kVMin, sensor noise would show; above kVMax, nothing.
constexpr int kVMin = 25, kVMax = 80;
// While the model starts (its first kWarmup frames), M moves up to
// kWarmupStep levels a frame, so that people present in the first frame
// leave no lasting ghost when they walk away.
constexpr int kWarmup = 12, kWarmupStep = 8;
// A pixel darker than the background by a ratio in [kShadowLow, kShadowHigh]
// (of 256) with chroma within kShadowChroma levels is a shadow.
constexpr int kShadowLow = 128, kShadowHigh = 240, kShadowChroma = 8;
// A pixel whose chroma differs from the background's by more than this is
// foreground whatever its brightness (a red shirt on grey stone).
constexpr int kChromaForeground = 24;

inline int step_toward(int m, int target, int step)
{
    int d = target - m;
    return m + (d > step ? step : d < -step ? -step : d);
}

} // namespace

size_t Background::memory_bytes() const
{
    return my_.capacity() + vy_.capacity() + mu_.capacity() + mv_.capacity() +
           mask_.capacity() + frozen_.capacity();
}

void Background::start(const Planes &img)
{
    fw_ = img.width;
    fh_ = img.height;
    color_ = img.color;
    w_ = (img.width + kScale - 1) / kScale;
    h_ = (img.height + kScale - 1) / kScale;
    const size_t n = (size_t)w_ * h_;
    my_.assign(n, 0);
    vy_.assign(n, kVMax);
    mu_.assign(n, 128);
    mv_.assign(n, 128);
    mask_.assign(n, 0);
    frozen_.assign(n, 0);
    for (int y = 0; y < h_; y++)
        for (int x = 0; x < w_; x++) {
            size_t i = (size_t)y * w_ + x;
            my_[i] = img.y[(size_t)(y * kScale) * img.y_stride + x * kScale];
            if (color_) {
                const int c = kScale / 2;
                mu_[i] = img.u[(size_t)(y * c) * img.u_stride + (size_t)(x * c) * img.c_step];
                mv_[i] = img.v[(size_t)(y * c) * img.v_stride + (size_t)(x * c) * img.c_step];
            }
        }
    frames_ = 0;
}

void Background::apply(const Planes &img, const Rect *frozen, int n_frozen)
{
    if (frames_ == 0 || img.width != fw_ || img.height != fh_ || img.color != color_)
        start(img);
    std::fill(frozen_.begin(), frozen_.end(), 0);
    for (int k = 0; k < n_frozen; k++) {
        const Rect &r = frozen[k];
        for (int y = std::max(0, r.y0); y < std::min(h_, r.y1); y++)
            std::fill(frozen_.begin() + (size_t)y * w_ + std::max(0, r.x0),
                      frozen_.begin() + (size_t)y * w_ + std::max(std::max(0, r.x0), std::min(w_, r.x1)),
                      1);
    }
    const int step = frames_ < kWarmup ? kWarmupStep : 1;
    const int cs = kScale / 2;            // working pixel to chroma sample
    const int cstep = cs * img.c_step;
    for (int y = 0; y < h_; y++) {
        const uint8_t *iy = img.y + (size_t)(y * kScale) * img.y_stride;
        const uint8_t *iu = color_ ? img.u + (size_t)(y * cs) * img.u_stride : nullptr;
        const uint8_t *iv = color_ ? img.v + (size_t)(y * cs) * img.v_stride : nullptr;
        const size_t row = (size_t)y * w_;
        uint8_t *my = &my_[row], *vy = &vy_[row], *mask = &mask_[row];
        const uint8_t *frozen = &frozen_[row];
        for (int x = 0; x < w_; x++) {
            const int I = iy[x * kScale];
            int M = my[x], V = vy[x];
            const bool learn = !frozen[x];
            if (learn) {
                M = step_toward(M, I, step);
                const int D = std::abs(I - M);
                if (D != 0)
                    V = std::min(kVMax, std::max(kVMin, V + (kN * D > V ? 1 : -1)));
            }
            const int D = std::abs(I - M);
            bool fg = D > V;
            if (color_) {
                const size_t i = row + x;
                const int U = iu[(size_t)x * cstep], W = iv[(size_t)x * cstep];
                int mu = mu_[i], mv = mv_[i];
                const int dc = std::max(std::abs(U - mu), std::abs(W - mv));
                if (fg && I < M && I * 256 >= kShadowLow * M && I * 256 <= kShadowHigh * M &&
                    dc <= kShadowChroma)
                    fg = false; // a shadow: darker, same colour
                else if (!fg && dc > kChromaForeground)
                    fg = true;  // same brightness, another colour
                if (learn) {
                    mu_[i] = (uint8_t)step_toward(mu, U, step);
                    mv_[i] = (uint8_t)step_toward(mv, W, step);
                }
            }
            my[x] = (uint8_t)M;
            vy[x] = (uint8_t)V;
            mask[x] = fg ? 255 : 0;
        }
    }
    frames_++;
}

} // namespace ctrack
