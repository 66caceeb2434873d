// The conversion's row kernels (Dsp::bgr_row, rgb_row): one row of packed
// BGR24 or RGB24 pixels to its luma and each pixel's chroma, for
// packed_to_i420() (api/convert.cc).
#include "dsp/cpu.h"
#include "dsp/dsp.h"

namespace ctrack {

namespace {

// One row of packed pixels (R at byte ri, B at byte bi): its luma, and each
// pixel's chroma before the 2x2 means. BT.601, limited range, in integers:
// OpenCV's COLOR_BGR2YUV_I420 up to rounding, and exactly the Python
// binding's bgr_to_i420(). Adding 128 << 8 before the shift keeps the chroma
// sums positive, so that the shift is a floor in C as in numpy. Unit-stride
// outputs and no branches, so that the loop vectorises wherever the target
// can read every third byte (below).
template <int ri, int bi>
CT_ALWAYS_INLINE void
convert_row(const uint8_t *__restrict src, int w, uint8_t *__restrict y, int16_t *__restrict u,
            int16_t *__restrict v)
{
    for (int x = 0; x < w; x++) {
        const int r = src[3 * x + ri], g = src[3 * x + 1], b = src[3 * x + bi];
        y[x] = (uint8_t)(((66 * r + 129 * g + 25 * b + 128) >> 8) + 16);
        u[x] = (int16_t)((-38 * r - 74 * g + 112 * b + 128 + (128 << 8)) >> 8);
        v[x] = (int16_t)((112 * r - 94 * g - 18 * b + 128 + (128 << 8)) >> 8);
    }
}

// Reading every third byte vectorises only with byte shuffles, which x86-64's
// baseline (SSE2) lacks: there the same loop is also built for SSSE3 and
// AVX2, and the dispatch table picks the best the CPU has (docs/bench.md
// measures them). Other targets (NEON) have the loads the loop needs in
// their baseline.
void bgr_row_c(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v)
{
    convert_row<2, 0>(src, w, y, u, v);
}

void rgb_row_c(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v)
{
    convert_row<0, 2>(src, w, y, u, v);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define CT_X86_BUILDS 1
__attribute__((target("ssse3"))) void bgr_row_ssse3(const uint8_t *src, int w, uint8_t *y,
                                                    int16_t *u, int16_t *v)
{
    convert_row<2, 0>(src, w, y, u, v);
}

__attribute__((target("ssse3"))) void rgb_row_ssse3(const uint8_t *src, int w, uint8_t *y,
                                                    int16_t *u, int16_t *v)
{
    convert_row<0, 2>(src, w, y, u, v);
}

__attribute__((target("avx2"))) void bgr_row_avx2(const uint8_t *src, int w, uint8_t *y,
                                                  int16_t *u, int16_t *v)
{
    convert_row<2, 0>(src, w, y, u, v);
}

__attribute__((target("avx2"))) void rgb_row_avx2(const uint8_t *src, int w, uint8_t *y,
                                                  int16_t *u, int16_t *v)
{
    convert_row<0, 2>(src, w, y, u, v);
}
#endif

} // namespace

void convert_dsp_init(Dsp *dsp, unsigned flags)
{
    dsp->bgr_row = bgr_row_c;
    dsp->rgb_row = rgb_row_c;
#ifdef CT_X86_BUILDS
    if (flags & kCpuSSSE3) {
        dsp->bgr_row = bgr_row_ssse3;
        dsp->rgb_row = rgb_row_ssse3;
    }
    if (flags & kCpuAVX2) {
        dsp->bgr_row = bgr_row_avx2;
        dsp->rgb_row = rgb_row_avx2;
    }
#else
    (void)flags;
#endif
}

} // namespace ctrack
