// The scene's sensor noise, contrast and black level, as the background
// model reads them from its own differences and levels (background.h).
#ifndef CTRACK_NOISE_H
#define CTRACK_NOISE_H

#include <cstdint>

#include "base/memory.h"

namespace ctrack {

// One frame's samples of the noise: histograms of the image's differences
// from the model, four of each taken in turn (a sample never waits on the
// one before it to count the same level, as neighbours mostly do). Scratch,
// not the model's state.
struct NoiseSamples {
    // y(k) and c(k): luma's and chroma's histogram k of 4, 256 counts each
    // (on the heap, and only once the pixels are used).
    uint32_t *y(int k) { return &hist_[(size_t)k * 256]; }
    uint32_t *c(int k) { return &hist_[(size_t)(4 + k) * 256]; }
    const uint32_t *y(int k) const { return &hist_[(size_t)k * 256]; }
    const uint32_t *c(int k) const { return &hist_[(size_t)(4 + k) * 256]; }
    // The model's luma levels on the same grid (m_n counts).
    uint32_t *m() { return &hist_[(size_t)8 * 256]; }
    const uint32_t *m() const { return &hist_[(size_t)8 * 256]; }
    uint32_t n = 0, m_n = 0;
    void begin();
    // One row's samples (every 4th pixel): |I - M| (dy) and the larger of
    // the chroma's differences (dc, null for grey frames); frozen marks
    // where tracks stand.
    void sample(const uint8_t *dy, const uint8_t *dc, const uint8_t *frozen, int w);
    // One row of the model's luma after the frame (every 4th pixel, tracks
    // or not: the scene's levels).
    void levels(const uint8_t *my, int w);
    size_t memory_bytes() const { return hist_.capacity() * sizeof(uint32_t); }

private:
    Vec<uint32_t> hist_;
};

// The scene's sensor noise, contrast and black level, learnt from the
// frames and smoothed over about a second. Each frame, over a grid of
// pixels no track stands on (most of them are background, whatever moves),
// the median absolute difference between the image and the background
// model is read as the noise's standard deviation; over the whole grid, the
// model's luma gives the contrast (its median absolute deviation) and the
// dark level (its first percentile). A lower contrast or a raised black, as
// in haze, a dim scene or a camera's low-contrast setting, shrinks the
// differences a person makes, and moves a dark coat's ratio to the ground
// toward a shadow's (docs/notes/pixels.md, "Contrast and black level").
struct NoiseLevel {
    double luma = 0, chroma = 0; // standard deviations, grey levels
    double contrast = 0, dark = 0; // grey levels
    // The noise within the frame itself (Background's fine_noise(): the
    // differences between neighbouring pixels), a standard deviation. It
    // does not depend on the model, so the model's own choices (its 2 x 2
    // means) do not move it.
    double fine = 0;
    // The frame's samples into the estimates, dt seconds after the last.
    void end(const NoiseSamples &s, double dt);
    // A frame's fine noise into its estimate, dt seconds after the last.
    void end_fine(double sd, double dt);
    // Whether a frame has been sampled (else all are 0).
    bool known() const { return known_; }

private:
    bool known_ = false; // the first frame's samples are taken as they are
    bool fine_known_ = false;
};

// Histograms of 256 levels: the sum of four taken in turn, the q-quantile
// of one of n counts (the first level at which the counts up to it reach q
// n; 255 if none does) and its median.
void sum_of_four(const uint32_t *a, const uint32_t *b, const uint32_t *c, const uint32_t *d,
                 uint32_t *out);
double quantile_of(const uint32_t *hist, uint32_t n, double q);
double median_of(const uint32_t *hist, uint32_t n);

} // namespace ctrack

#endif
