// The pixel kernels built for several CPU feature levels, as a table of
// function pointers filled for the CPU at hand (dav1d's way): each tracker
// fills its own when it is created, from cpu_flags(). The portable build
// of each kernel is the reference; tests/check_dsp.cc checks every other
// against it, bit for bit.
#ifndef CTRACK_DSP_H
#define CTRACK_DSP_H

#include <cstdint>

namespace ctrack {

struct Dsp {
    // One row of packed pixels to its luma, and each pixel's chroma before
    // the 2x2 means (convert.cc): BGR24 and RGB24.
    void (*bgr_row)(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v);
    void (*rgb_row)(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v);
};

// Fills every entry with the fastest build the flags (CpuFlag bits) allow.
void dsp_init(Dsp *dsp, unsigned flags);

} // namespace ctrack

#endif
