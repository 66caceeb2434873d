#include "template/shape.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "pixels/mask.h"

namespace ctrack {

namespace {

// Twice the signed area of the triangle o, a, b: positive when o, a, b turn
// counter-clockwise in axes (first coordinate, second coordinate).
float cross(const float *o, const float *a, const float *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// One side of the convex hull of the points (y, x), in order of y (the
// monotone chain): with sign 1 the side of the smallest x (the hull's left
// edge at each y), with sign -1 the side of the largest. Returns the number
// of points kept in out.
int hull_side(const float (*pts)[2], int n, float sign, float (*out)[2])
{
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && sign * cross(out[k - 2], out[k - 1], pts[i]) <= 0)
            k--;
        out[k][0] = pts[i][0];
        out[k][1] = pts[i][1];
        k++;
    }
    return k;
}

// The area of the polygon that runs down one chain and back up the other
// (both from the top row to the bottom one), by the shoelace formula; the
// order of the two coordinates does not matter.
float area_between(const float (*l)[2], int nl, const float (*r)[2], int nr)
{
    double a = 0;
    auto edge = [&](const float *p, const float *q) {
        a += (double)p[0] * q[1] - (double)q[0] * p[1];
    };
    for (int i = 0; i + 1 < nl; i++)
        edge(l[i], l[i + 1]);
    edge(l[nl - 1], r[nr - 1]);
    for (int i = nr - 1; i > 0; i--)
        edge(r[i], r[i - 1]);
    edge(r[0], l[0]);
    return (float)(std::fabs(a) / 2);
}

// The profile of the foreground inside the box, whose runs s->runs
// labelled.
void profile_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Shape *s)
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
        // The area inside the outer contour: foreground and holes, all of
        // [l, rr] but the background outside the blob (reached from the
        // box's border).
        int count = rr - l + 1;
        const Vec<BoxRuns::Run> &bg = s->runs.bg();
        for (int i = s->runs.bg_first(y - y0); i < s->runs.bg_end(y - y0); i++)
            if (bg[i].x0 > l && bg[i].x1 <= rr && s->runs.outside(i))
                count -= bg[i].x1 - bg[i].x0;
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

// One pass of the 3-4 chamfer distance over the rows in the order of
// `step` (1 down, -1 up): each cell takes the least of itself, its three
// neighbours in the row before (+3 straight, +4 diagonal) and its
// neighbour before it in its own row (+3). The row before is final when a
// row starts, so its terms go first, for every cell at once; the row's own
// term is the only one carried along it. The same minimum as visiting each
// cell with its four neighbours (a minimum in any order), in integers.
void chamfer_pass(Outline *o, int step)
{
    const int first = step > 0 ? 0 : kGrid - 1;
    for (int r = first; r >= 0 && r < kGrid; r += step) {
        uint16_t *d = o->dist[r];
        if (r != first) {
            // The row before, final: 60000 + 4 fits in 16 bits.
            const uint16_t *p = o->dist[r - step];
            d[0] = std::min<uint16_t>(d[0], std::min<uint16_t>(p[0] + 3, p[1] + 4));
            for (int c = 1; c < kGrid - 1; c++)
                d[c] = std::min<uint16_t>(
                    d[c],
                    std::min<uint16_t>(p[c] + 3, std::min<uint16_t>(p[c - 1], p[c + 1]) + 4));
            d[kGrid - 1] = std::min<uint16_t>(
                d[kGrid - 1], std::min<uint16_t>(p[kGrid - 1] + 3, p[kGrid - 2] + 4));
        }
        // Then along the row, in the pass's direction.
        if (step > 0)
            for (int c = 1; c < kGrid; c++)
                d[c] = std::min<uint16_t>(d[c], d[c - 1] + 3);
        else
            for (int c = kGrid - 2; c >= 0; c--)
                d[c] = std::min<uint16_t>(d[c], d[c + 1] + 3);
    }
}

// The outline's distance map of the foreground inside the box.
void outline_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Shape *s)
{
    Outline *o = &s->outline;
    const int kFar = 60000;
    for (int r = 0; r < kGrid; r++)
        for (int c = 0; c < kGrid; c++)
            o->dist[r][c] = kFar;
    const int w = x1 - x0, h = y1 - y0;
    if (w <= 0 || h <= 0)
        return;
    const double centre = (x0 + x1) / 2.0;
    // Each column's cell, -1 off the canvas.
    Vec<int> &col = s->columns;
    col.resize((size_t)w);
    for (int x = x0; x < x1; x++) {
        const int c = (int)(((x + 0.5 - centre) / h + 0.5) * kGrid);
        col[(size_t)(x - x0)] = c >= 0 && c < kGrid ? c : -1;
    }
    // The outline (mask.h), each pixel in its cell of the canvas; the row's
    // cell computed once a row (the pixels come row by row).
    int last_y = -1, r = 0;
    for_each_outline(mask, (size_t)stride, x0, y0, x1, y1, [&](int x, int y) {
        if (y != last_y) {
            r = (int)((y + 0.5 - y0) / h * kGrid);
            last_y = y;
        }
        const int c = col[(size_t)(x - x0)];
        if (r >= 0 && r < kGrid && c >= 0)
            o->dist[r][c] = 0;
    });
    chamfer_pass(o, 1);
    chamfer_pass(o, -1);
}

} // namespace

float hull_fill(const float (*left)[2], const float (*right)[2], int n, double area)
{
    // The hull's left side is a convex function of y, its right side a
    // concave one.
    float lh[2 * kRows][2], rh[2 * kRows][2];
    const int nl = hull_side(left, n, 1, lh), nr = hull_side(right, n, -1, rh);
    const float hull = area_between(lh, nl, rh, nr);
    return hull > 0 ? std::min(1.0f, (float)(area / hull)) : 0;
}

void shape_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Shape *s)
{
    if (x1 > x0 && y1 > y0)
        s->runs.label(mask, stride, Rect{x0, y0, x1, y1}, false);
    profile_of(mask, stride, x0, y0, x1, y1, s);
    outline_of(mask, stride, x0, y0, x1, y1, s);
}

} // namespace ctrack
