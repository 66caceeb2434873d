#include "api/convert.h"

namespace ctrack {

namespace {

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

} // namespace ctrack
