// Foreground masks: one byte a pixel, non-zero in the foreground.
#ifndef CTRACK_MASK_H
#define CTRACK_MASK_H

#include <cstddef>
#include <cstdint>

namespace ctrack {

// A box of mask pixels: [x0, x1) x [y0, y1).
struct Rect {
    int x0, y0, x1, y1;
};

// A pixel position as an int, clamped to +-2^29 first (NaN to the lower
// end): a box far outside any frame (a track predicted far away, absurd
// input) converts without overflow, holds no pixel, and the sum or the
// difference of two such positions is still an int.
inline int pixel_int(double v)
{
    return (int)(v > -536870912.0 ? (v < 536870912.0 ? v : 536870912.0) : -536870912.0);
}

// Non-zero bytes among p[0..n-1].
inline int count_nonzero(const uint8_t *p, int n)
{
    int c = 0;
    for (int i = 0; i < n; i++)
        c += p[i] != 0;
    return c;
}

// Non-zero bytes of the mask (rows of `stride` bytes) in the box
// [x0, x1) x [y0, y1), which lies within it.
inline long count_nonzero(const uint8_t *mask, size_t stride, int x0, int y0, int x1, int y1)
{
    long c = 0;
    for (int y = y0; y < y1; y++)
        c += count_nonzero(mask + (size_t)y * stride + x0, x1 - x0);
    return c;
}

// Whether pixel (x, y) of the mask (rows of `stride` bytes) is on the
// outline of the foreground inside the box [x0, x1) x [y0, y1), which lies
// within the mask: foreground, with a 4-neighbour that is background or
// outside the box.
inline bool on_outline(const uint8_t *mask, size_t stride, int x0, int y0, int x1, int y1, int x,
                       int y)
{
    auto fg = [&](int u, int v) {
        return u >= x0 && u < x1 && v >= y0 && v < y1 && mask[(size_t)v * stride + u] != 0;
    };
    return fg(x, y) && !(fg(x - 1, y) && fg(x + 1, y) && fg(x, y - 1) && fg(x, y + 1));
}

// Calls f(x, y) for each pixel of the outline inside the box, row by row:
// what on_outline() says pixel by pixel, with each row's neighbours read in
// place (tests/check_regions.cc compares the two).
template <typename F>
inline void for_each_outline(const uint8_t *mask, size_t stride, int x0, int y0, int x1, int y1,
                             F &&f)
{
    for (int y = y0; y < y1; y++) {
        const uint8_t *row = mask + (size_t)y * stride;
        const uint8_t *up = y > y0 ? row - stride : nullptr;
        const uint8_t *down = y + 1 < y1 ? row + stride : nullptr;
        for (int x = x0; x < x1; x++)
            if (row[x] && !(x > x0 && row[x - 1] && x + 1 < x1 && row[x + 1] && up && up[x] &&
                            down && down[x]))
                f(x, y);
    }
}

} // namespace ctrack

#endif
