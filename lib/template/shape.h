// A blob's shape in the contour template's canonical box: its outer profile
// row by row, how much of its convex hull it fills, and its outline as a
// distance map, the representation the classifier compares with the
// template's silhouettes.
#ifndef CTRACK_SHAPE_H
#define CTRACK_SHAPE_H

#include <cstdint>
#include <vector>

#include "base/memory.h"
#include "pixels/regions.h"

namespace ctrack {

// A shape is its outer profile in its bounding box: for each of kRows rows,
// the leftmost and rightmost foreground points, from the box's centre in box
// heights (so a shape keeps its proportions). An empty row is marked by
// Profile::kEmpty.
constexpr int kRows = 64;

struct Profile {
    static constexpr float kEmpty = -100;
    float edge[kRows][2];
    // How much of its convex hull the blob fills, from 0 to 1 (0 for an
    // empty box), over the profile's rows: the area inside its outer
    // contour, holes included (a ring fills its hull as a disc does).
    float fill;
    bool empty(int row) const { return edge[row][0] == kEmpty; }
    // The row's extent, leftmost to rightmost foreground point (0 when the
    // row is empty), in box heights.
    float extent(int row) const { return empty(row) ? 0 : edge[row][1] - edge[row][0]; }
};

// A blob's outline as a distance map on a kGrid x kGrid canvas of the
// canonical box (x from -0.5 to 0.5 box heights around its centre, y from 0
// to 1 box height): each cell holds its distance to the nearest outline
// pixel (3-4 chamfer units, a cell is 3).
constexpr int kGrid = 32;
struct Outline {
    uint16_t dist[kGrid][kGrid];
};

// The blob: its profile says which regions can vote (abstention); its
// outline gives eq. (1)'s distances.
struct Shape {
    Profile profile;
    Outline outline;
    // shape_of()'s working memory, kept so that a Shape used again makes
    // no allocation: the box's runs, the background's joined to tell the
    // background around the blob from its holes.
    BoxRuns runs;
    Vec<int> columns; // each column's cell of the outline's canvas
};

// The shape of the foreground (non-zero) pixels of mask inside the box
// [x0, x1) x [y0, y1): for each of the profile's rows, the leftmost and
// rightmost foreground points, from the box's centre in box heights (so a
// shape keeps its proportions), and the outline's distance map.
void shape_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Shape *s);

// How much of their convex hull the profile's row strips fill: the strips'
// ends (n points a side, (y, x) in box heights, top row first; n at most
// 2 * kRows) and their area, holes included (shape_of()'s fill).
float hull_fill(const float (*left)[2], const float (*right)[2], int n, double area);

} // namespace ctrack

#endif
