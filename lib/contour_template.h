// The paper's multiregion contour template (section 2.1-2.2, eq. 1) and its
// region voting: is a blob shaped like a pedestrian?
#ifndef CTRACK_CONTOUR_TEMPLATE_H
#define CTRACK_CONTOUR_TEMPLATE_H

#include <cstdint>
#include <vector>

namespace ctrack {

// A shape is its outer profile in its bounding box: for each of kRows rows,
// the leftmost and rightmost foreground points, from the box's centre in box
// heights (so a shape keeps its proportions). An empty row is marked by
// Profile::kEmpty.
constexpr int kRows = 64;
constexpr int kRegions = 9;

enum Region {
    kHead, kNeck, kShoulders, kChest, kBack, kAbdomen, kButtocks, kUpperLimbs, kLowerLimbs
};

const char *region_name(int r);

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
    // no allocation: the box's pixels (foreground, background reached from
    // the box's border, or hole) and the flood fill's queue.
    std::vector<uint8_t> cells;
    std::vector<int> todo;
};

// The shape of the foreground (non-zero) pixels of mask inside the box
// [x0, x1) x [y0, y1): for each of the profile's rows, the leftmost and
// rightmost foreground points, from the box's centre in box heights (so a
// shape keeps its proportions), and the outline's distance map.
void shape_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Shape *s);

struct Vote {
    // Eq. (1) per region: the mean distance from the best silhouette's
    // outline points in the region to the blob's outline (nearest-point
    // correspondence), in box heights; negative where the region abstained
    // (too few of its rows hold foreground): all of them when no region
    // votes.
    float distance[kRegions] = {-1, -1, -1, -1, -1, -1, -1, -1, -1};
    int yes = 0, voters = 0;
    // yes / voters, 0 with fewer than kMinVoters voters, at most 0.5 (no
    // pedestrian) when the blob fills more than RegionThresholds::max_fill
    // of its convex hull or its top is wider than kMaxTopWidth of its body.
    float score = 0;
    int silhouette = -1;
    float fill = 0;  // Profile::fill
    float top = 0;   // top_width()
};

// How wide the blob's top is against its body: the median extent of the
// head's rows (an empty row counts 0) over the widest row from the
// shoulders to the feet; 0 when fewer than half the rows from the shoulders
// to the hips hold foreground. A person's head is narrower than their
// shoulders, arms or legs in stride: about 0.15 for the library's
// silhouettes. A T, an H, a Π, an X, a Y, a V or a U reach 1.
float top_width(const Profile &p);

// The widest top a pedestrian's blob has (top_width()): above it the vote's
// score is cut to 0.5, as for a blob that fills its hull.
constexpr float kMaxTopWidth = 0.9f;

// The thresholds of eq. (1)'s regions: a region votes yes when its distance
// is at most its threshold.
struct RegionThresholds {
    float t[kRegions];
    // The largest part of its convex hull a pedestrian's blob fills (a
    // walking person's outline is concave).
    float max_fill;
};
const RegionThresholds &default_thresholds();

// Votes with the closest silhouette of the library (the smallest mean
// distance over the regions that vote), so that the distances reported do
// not depend on the thresholds. A tie of votes (yes = no) is a no: score
// 0.5 is not above the majority.
Vote classify(const Shape &s, const RegionThresholds &th);

// At least this many regions must vote for a score.
constexpr int kMinVoters = 5;

} // namespace ctrack

#endif
