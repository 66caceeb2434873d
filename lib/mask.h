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

} // namespace ctrack

#endif
