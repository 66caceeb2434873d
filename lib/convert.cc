#include "convert.h"

#include "cpu.h"

namespace ctrack {

namespace {

#if defined(__GNUC__)
#define CT_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define CT_ALWAYS_INLINE inline
#endif

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

// The mean of each 2x2 block of two rows' chroma (an odd last column
// counts twice).
void block_means(const int16_t *__restrict a, const int16_t *__restrict b, int w,
                 uint8_t *__restrict out)
{
    const int pairs = w / 2;
    for (int c = 0; c < pairs; c++)
        out[c] = (uint8_t)((a[2 * c] + a[2 * c + 1] + b[2 * c] + b[2 * c + 1] + 2) >> 2);
    if (w % 2)
        out[pairs] = (uint8_t)((2 * a[w - 1] + 2 * b[w - 1] + 2) >> 2);
}

} // namespace

Planes packed_to_i420(const ct_frame &f, const Dsp &dsp, Vec<int16_t> *buf)
{
    const int w = f.width, h = f.height, cw = (w + 1) / 2, ch = (h + 1) / 2;
    // The planes' bytes, then two rows of each pixel's chroma (U and V for
    // the block's top row, then for its bottom row).
    const size_t planes = ((size_t)w * h + 2 * (size_t)cw * ch + 1) / 2;
    buf->resize(planes + 4 * (size_t)w);
    uint8_t *const Y = reinterpret_cast<uint8_t *>(buf->data());
    uint8_t *const U = Y + (size_t)w * h;
    uint8_t *const V = U + (size_t)cw * ch;
    int16_t *const rows = buf->data() + planes;
    int16_t *const u0 = rows, *const v0 = rows + w, *const u1 = rows + 2 * w,
                   *const v1 = rows + 3 * w;
    const bool rgb = f.format == CT_FORMAT_RGB24;
    auto row = [&](int y, int16_t *u, int16_t *v) {
        const uint8_t *src = f.planes[0] + (size_t)y * f.strides[0];
        (rgb ? dsp.rgb_row : dsp.bgr_row)(src, w, Y + (size_t)y * w, u, v);
    };
    for (int cy = 0; cy < ch; cy++) {
        row(2 * cy, u0, v0);
        // An odd last row counts twice (the image's edge repeated).
        const bool pair = 2 * cy + 1 < h;
        if (pair)
            row(2 * cy + 1, u1, v1);
        block_means(u0, pair ? u1 : u0, w, U + (size_t)cy * cw);
        block_means(v0, pair ? v1 : v0, w, V + (size_t)cy * cw);
    }
    Planes p;
    p.width = w;
    p.height = h;
    p.y = Y;
    p.u = U;
    p.v = V;
    p.y_stride = w;
    p.u_stride = p.v_stride = cw;
    p.color = true;
    return p;
}

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
