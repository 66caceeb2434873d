#include "background.h"

#include <algorithm>
#include <cstdlib>

namespace ctrack {

namespace {

// Sigma-Delta's amplification: V follows N |I - M|.
constexpr int kN = 4;
// Bounds of V: below kVMin, sensor noise would show; above kVMax, nothing.
constexpr int kVMin = 25, kVMax = 80;
// While the model starts (its first kWarmup frames), M and V move up to
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
           mask_.capacity() + frozen_.capacity() + line_y_.capacity() + line_u_.capacity() +
           line_v_.capacity();
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
    // While warming up, V moves as fast as M, and also where M has reached
    // the image: else V stays near kVMax, where it starts, for some 50
    // frames, and hides people with the background's contrast (TUD-Campus,
    // pixels only: recall 15% -> 39%, MOTA -3 -> 20).
    const bool warm = frames_ < kWarmup;
    const int vstep = warm ? kWarmupStep : 1;
    const int cs = kScale / 2; // working pixel to chroma sample
    // Locals and restrict pointers: stores through uint8_t pointers may
    // alias anything, and would make the compiler reload every member after
    // each one (the loop ran at about 100 instructions a pixel).
    const bool color = color_;
    const int w = w_, h = h_;
    const size_t cstep = (size_t)cs * img.c_step;
    // Each row's samples are gathered first into contiguous buffers, so that
    // the loop below reads unit-stride arrays and the compiler vectorises it.
    line_y_.resize(w);
    line_u_.resize(w);
    line_v_.resize(w);
    for (int y = 0; y < h; y++) {
        const uint8_t *src = img.y + (size_t)(y * kScale) * img.y_stride;
        uint8_t *__restrict iy = line_y_.data();
        for (int x = 0; x < w; x++)
            iy[x] = src[x * kScale];
        const size_t row = (size_t)y * w;
        uint8_t *__restrict my = my_.data() + row;
        uint8_t *__restrict vy = vy_.data() + row;
        uint8_t *__restrict mask = mask_.data() + row;
        const uint8_t *__restrict frozen = frozen_.data() + row;
        if (!color) {
            for (int x = 0; x < w; x++) {
                const int I = iy[x];
                int M = my[x], V = vy[x];
                if (!frozen[x]) {
                    M = step_toward(M, I, step);
                    const int D = std::abs(I - M);
                    if (D != 0 || warm)
                        V = std::min(kVMax, std::max(kVMin, V + (kN * D > V ? vstep : -vstep)));
                }
                my[x] = (uint8_t)M;
                vy[x] = (uint8_t)V;
                mask[x] = std::abs(I - M) > V ? 255 : 0;
            }
            continue;
        }
        const uint8_t *su = img.u + (size_t)(y * cs) * img.u_stride;
        const uint8_t *sv = img.v + (size_t)(y * cs) * img.v_stride;
        uint8_t *__restrict iu = line_u_.data(), *__restrict iv = line_v_.data();
        for (int x = 0; x < w; x++) {
            iu[x] = su[x * cstep];
            iv[x] = sv[x * cstep];
        }
        uint8_t *__restrict mu = mu_.data() + row;
        uint8_t *__restrict mv = mv_.data() + row;
        for (int x = 0; x < w; x++) {
            const int I = iy[x];
            int M = my[x], V = vy[x];
            const int U = iu[x], W = iv[x];
            const int bu = mu[x], bv = mv[x];
            if (!frozen[x]) {
                M = step_toward(M, I, step);
                const int D = std::abs(I - M);
                if (D != 0 || warm)
                    V = std::min(kVMax, std::max(kVMin, V + (kN * D > V ? vstep : -vstep)));
                mu[x] = (uint8_t)step_toward(bu, U, step);
                mv[x] = (uint8_t)step_toward(bv, W, step);
            }
            const int D = std::abs(I - M);
            const int dc = std::max(std::abs(U - bu), std::abs(W - bv));
            bool fg = D > V;
            if (fg && I < M && I * 256 >= kShadowLow * M && I * 256 <= kShadowHigh * M &&
                dc <= kShadowChroma)
                fg = false; // a shadow: darker, same colour
            else if (!fg && dc > kChromaForeground)
                fg = true;  // same brightness, another colour
            my[x] = (uint8_t)M;
            vy[x] = (uint8_t)V;
            mask[x] = fg ? 255 : 0;
        }
    }
    frames_++;
}

} // namespace ctrack
