// The contour template's shape (lib/template/shape.cc) as first written, for
// tests/check_regions.cc to hold the faster one to it, to the bit: the
// per-pixel flood fill of the background the box's border reaches, the
// outline pixel by pixel, the chamfer distance cell by cell (the convex
// hull is the library's, unchanged).
#ifndef CTRACK_TESTS_SHAPE_REFERENCE_H
#define CTRACK_TESTS_SHAPE_REFERENCE_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "pixels/mask.h"
#include "template/shape.h"


namespace reference {
using namespace ctrack;
// lib/template/shape.cc as it was before its runs and chamfer passes (0.9.0):
// the per-pixel flood fill and the cell-by-cell chamfer distance.
struct RefShape {
    Profile profile;
    Outline outline;
    std::vector<uint8_t> cells;
    std::vector<int> todo;
};

namespace {

enum Cell : uint8_t { kHole = 0, kForeground = 1, kOutside = 2 };

// Marks each pixel of the box [x0, x1) x [y0, y1): foreground, background
// that the box's border reaches through background (4-connected), or hole.
void mark_cells(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, RefShape *s)
{
    const int w = x1 - x0, h = y1 - y0;
    s->cells.resize((size_t)w * h);
    uint8_t *c = s->cells.data();
    for (int y = 0; y < h; y++) {
        const uint8_t *row = mask + (size_t)(y0 + y) * stride + x0;
        for (int x = 0; x < w; x++)
            c[(size_t)y * w + x] = row[x] ? kForeground : kHole;
    }
    std::vector<int> &todo = s->todo;
    todo.clear();
    auto reach = [&](int x, int y) {
        const size_t i = (size_t)y * w + x;
        if (c[i] == kHole) {
            c[i] = kOutside;
            todo.push_back((int)i);
        }
    };
    for (int x = 0; x < w; x++) {
        reach(x, 0);
        reach(x, h - 1);
    }
    for (int y = 0; y < h; y++) {
        reach(0, y);
        reach(w - 1, y);
    }
    while (!todo.empty()) {
        const int i = todo.back();
        todo.pop_back();
        const int x = i % w, y = i / w;
        if (x > 0) reach(x - 1, y);
        if (x + 1 < w) reach(x + 1, y);
        if (y > 0) reach(x, y - 1);
        if (y + 1 < h) reach(x, y + 1);
    }
}

// The profile of the foreground inside the box, whose cells mark_cells()
// marked in s->cells.
void profile_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, RefShape *s)
{
    Profile *p = &s->profile;
    const int w = x1 - x0, h = y1 - y0;
    const double centre = (x0 + x1) / 2.0;
    // Each row's foreground as a strip one profile row high: its ends feed
    // the convex hull, its pixels the area (both in box heights).
    float left[2 * kRows][2], right[2 * kRows][2];
    int n = 0;
    double area = 0;
    p->fill = 0;
    for (int r = 0; r < kRows; r++) {
        p->edge[r][0] = p->edge[r][1] = Profile::kEmpty;
        if (w <= 0 || h <= 0)
            continue;
        const int y = y0 + (int)((r + 0.5) * h / kRows);
        const uint8_t *row = mask + (size_t)y * stride;
        int l = x0;
        while (l < x1 && !row[l])
            l++;
        if (l == x1)
            continue;
        int rr = x1 - 1;
        while (!row[rr])
            rr--;
        // The area inside the outer contour: foreground and holes.
        const uint8_t *cells = s->cells.data() + (size_t)(y - y0) * w;
        int count = 0;
        for (int x = l; x <= rr; x++)
            count += cells[x - x0] != kOutside;
        // Pixel centres, from the box's centre in box heights.
        p->edge[r][0] = (float)((l + 0.5 - centre) / h);
        p->edge[r][1] = (float)((rr + 0.5 - centre) / h);
        const float xl = (float)((l - centre) / h), xr = (float)((rr + 1 - centre) / h);
        for (int k = 0; k < 2; k++) {
            const float yy = (float)(r + k) / kRows;
            left[n + k][0] = right[n + k][0] = yy;
            left[n + k][1] = xl;
            right[n + k][1] = xr;
        }
        n += 2;
        area += (double)count / h / kRows;
    }
    if (n > 0)
        p->fill = hull_fill(left, right, n, area);
}

// The outline's distance map of the foreground inside the box.
void outline_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Outline *o)
{
    const int kFar = 60000;
    for (int r = 0; r < kGrid; r++)
        for (int c = 0; c < kGrid; c++)
            o->dist[r][c] = kFar;
    const int w = x1 - x0, h = y1 - y0;
    if (w <= 0 || h <= 0)
        return;
    const double centre = (x0 + x1) / 2.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            if (!on_outline(mask, (size_t)stride, x0, y0, x1, y1, x, y))
                continue;
            int c = (int)(((x + 0.5 - centre) / h + 0.5) * kGrid);
            int r = (int)((y + 0.5 - y0) / h * kGrid);
            if (c >= 0 && c < kGrid && r >= 0 && r < kGrid)
                o->dist[r][c] = 0;
        }
    // Two passes of the 3-4 chamfer distance.
    for (int r = 0; r < kGrid; r++)
        for (int c = 0; c < kGrid; c++) {
            int d = o->dist[r][c];
            if (c > 0) d = std::min(d, o->dist[r][c - 1] + 3);
            if (r > 0) {
                d = std::min(d, o->dist[r - 1][c] + 3);
                if (c > 0) d = std::min(d, o->dist[r - 1][c - 1] + 4);
                if (c + 1 < kGrid) d = std::min(d, o->dist[r - 1][c + 1] + 4);
            }
            o->dist[r][c] = (uint16_t)d;
        }
    for (int r = kGrid - 1; r >= 0; r--)
        for (int c = kGrid - 1; c >= 0; c--) {
            int d = o->dist[r][c];
            if (c + 1 < kGrid) d = std::min(d, o->dist[r][c + 1] + 3);
            if (r + 1 < kGrid) {
                d = std::min(d, o->dist[r + 1][c] + 3);
                if (c + 1 < kGrid) d = std::min(d, o->dist[r + 1][c + 1] + 4);
                if (c > 0) d = std::min(d, o->dist[r + 1][c - 1] + 4);
            }
            o->dist[r][c] = (uint16_t)d;
        }
}

} // namespace

inline void ref_shape_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, RefShape *s)
{
    if (x1 > x0 && y1 > y0)
        mark_cells(mask, stride, x0, y0, x1, y1, s);
    profile_of(mask, stride, x0, y0, x1, y1, s);
    outline_of(mask, stride, x0, y0, x1, y1, &s->outline);
}

} // namespace reference

#endif
