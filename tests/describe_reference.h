// The appearance descriptor as first written, block by block, each mean
// from its own loop over its pixels: the reference that Describer
// (lib/appearance/appearance.cc), which sums each band of rows once, must equal to the
// bit (check_appearance). Deliberately a copy of the old code.
#ifndef CT_TESTS_DESCRIBE_REFERENCE_H
#define CT_TESTS_DESCRIBE_REFERENCE_H

#include <algorithm>
#include <cmath>

#include "appearance/appearance.h"

namespace describe_reference {

using ctrack::kDescDim;
using ctrack::kGridX;
using ctrack::kGridY;
using ctrack::Planes;

constexpr float kChromaWeight = 2.0f;

inline int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

// The mean of plane p (stride, subsampling shift) over the rectangle
// [x0, x1) x [y0, y1) of luma coordinates, clamped to the image; at least
// one sample.
inline float mean_of(const uint8_t *p, int stride, int step, int shift, const Planes &img,
                     double x0, double y0, double x1, double y1)
{
    const int w = (img.width + (1 << shift) - 1) >> shift, h = (img.height + (1 << shift) - 1) >> shift;
    int a = clampi((int)std::floor(x0) >> shift, 0, w - 1);
    int b = clampi(((int)std::ceil(x1) - 1) >> shift, a, w - 1);
    int c = clampi((int)std::floor(y0) >> shift, 0, h - 1);
    int d = clampi(((int)std::ceil(y1) - 1) >> shift, c, h - 1);
    unsigned sum = 0;
    const unsigned n = (unsigned)(d - c + 1) * (unsigned)(b - a + 1);
    if (step == 1) {
        // Unit stride (luma, I420's chroma): a loop the compiler vectorises.
        for (int y = c; y <= d; y++) {
            const uint8_t *__restrict row = p + (size_t)y * stride + a;
            unsigned s = 0;
            for (int x = 0; x <= b - a; x++)
                s += row[x];
            sum += s;
        }
    } else {
        for (int y = c; y <= d; y++)
            for (int x = a; x <= b; x++)
                sum += p[(size_t)y * stride + (size_t)x * step];
    }
    return (float)sum / (float)n;
}

inline void describe(const Planes &img, double left, double top, double width,
                     double height, float *out)
{
    const double cw = width / kGridX, ch = height / kGridY;
    for (int gy = 0; gy < kGridY; gy++)
        for (int gx = 0; gx < kGridX; gx++) {
            float *d = out + (size_t)(gy * kGridX + gx) * kDescDim;
            const double x0 = left + gx * cw, y0 = top + gy * ch;
            int k = 0;
            // Luma: the means of the cell's 3 x 3 sub-blocks (means, not
            // single pixels, so that a shift of a pixel or two changes
            // little).
            for (int sy = 0; sy < 3; sy++)
                for (int sx = 0; sx < 3; sx++)
                    d[k++] = mean_of(img.y, img.y_stride, 1, 0, img, x0 + sx * cw / 3,
                                     y0 + sy * ch / 3, x0 + (sx + 1) * cw / 3,
                                     y0 + (sy + 1) * ch / 3);
            if (img.color) {
                d[k++] = kChromaWeight * mean_of(img.u, img.u_stride, img.c_step, 1, img, x0, y0,
                                                 x0 + cw, y0 + ch);
                d[k++] = kChromaWeight * mean_of(img.v, img.v_stride, img.c_step, 1, img, x0, y0,
                                                 x0 + cw, y0 + ch);
            } else {
                d[k++] = 0;
                d[k++] = 0;
            }
        }
}

} // namespace describe_reference

#endif
