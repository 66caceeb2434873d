#include "contour_template.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mask.h"

namespace ctrack {

namespace {

#include "silhouettes.inc"
#include "region_thresholds.inc"

// The regions as zones of the canonical box: row bands of the 64-row
// profile and which edges count (0 left, 1 right, 2 both). Front and back
// mean nothing in a frontal view, so the halves are left and right. Zones
// overlap: the upper limbs share rows with chest, back, abdomen and
// buttocks, and a point counts in every region whose zone holds it.
struct Zone {
    int row0, row1, side;
};
constexpr Zone kZones[kRegions] = {
    {0, 8, 2},    // head
    {8, 11, 2},   // neck
    {11, 16, 2},  // shoulders
    {16, 29, 0},  // chest
    {16, 29, 1},  // back
    {29, 36, 0},  // abdomen
    {29, 36, 1},  // buttocks
    {16, 36, 2},  // upper limbs
    {36, 64, 2},  // lower limbs
};

// Each outline point's cell on the canvas and the regions holding it, made
// at compile time from the silhouettes.
struct PointInfo {
    uint16_t cell;    // row * kGrid + col
    uint16_t regions; // bit g: region g holds the point
};

constexpr int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

struct PointTable {
    PointInfo p[kSilhouettes][kOutlinePoints];
};

constexpr PointTable make_points()
{
    PointTable t{};
    for (int s = 0; s < kSilhouettes; s++)
        for (int k = 0; k < kOutlinePoints; k++) {
            const float x = kOutline[s][k][0], y = kOutline[s][k][1];
            const int col = clampi((int)((x + 0.5f) * kGrid), 0, kGrid - 1);
            const int row = clampi((int)(y * kGrid), 0, kGrid - 1);
            const int side = x < 0 ? 0 : 1;
            uint16_t regions = 0;
            for (int g = 0; g < kRegions; g++) {
                const Zone &z = kZones[g];
                if (row >= z.row0 * kGrid / kRows && row < z.row1 * kGrid / kRows &&
                    (z.side == 2 || z.side == side))
                    regions |= (uint16_t)(1u << g);
            }
            t.p[s][k] = PointInfo{(uint16_t)(row * kGrid + col), regions};
        }
    return t;
}

constexpr PointTable kPoints = make_points();

// The same points grouped by region, for classify(): each silhouette's
// cells of region g are cell[s][start[s][g]] up to cell[s][start[s][g + 1]]
// (a point in two regions is listed in both).
constexpr int kMaxEntries = 2 * kOutlinePoints;
struct RegionCells {
    uint16_t cell[kSilhouettes][kMaxEntries];
    uint16_t start[kSilhouettes][kRegions + 1];
};

constexpr RegionCells make_region_cells()
{
    RegionCells t{};
    for (int s = 0; s < kSilhouettes; s++) {
        int k = 0;
        for (int g = 0; g < kRegions; g++) {
            t.start[s][g] = (uint16_t)k;
            for (int i = 0; i < kOutlinePoints; i++)
                if (kPoints.p[s][i].regions & (1u << g)) {
                    if (k == kMaxEntries)
                        throw "a point is in more than two regions"; // not a constant
                    t.cell[s][k++] = kPoints.p[s][i].cell;
                }
        }
        t.start[s][kRegions] = (uint16_t)k;
    }
    return t;
}

constexpr RegionCells kRegionCells = make_region_cells();

// The head's rows (the median of eight rows is the fifth smallest: an
// upper median).
constexpr int kHeadRows = kZones[kHead].row1 - kZones[kHead].row0;

const char *const kNames[kRegions] = {"head", "neck", "shoulders", "chest", "back",
                                      "abdomen", "buttocks", "upper limbs", "lower limbs"};

} // namespace

const char *region_name(int r)
{
    return r >= 0 && r < kRegions ? kNames[r] : nullptr;
}

const RegionThresholds &default_thresholds()
{
    return kDefaultThresholds;
}

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

enum Cell : uint8_t { kHole = 0, kForeground = 1, kOutside = 2 };

// Marks each pixel of the box [x0, x1) x [y0, y1): foreground, background
// that the box's border reaches through background (4-connected), or hole.
void mark_cells(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Shape *s)
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
    if (n == 0)
        return;
    // The hull's left side is a convex function of y, its right side a
    // concave one.
    float lh[2 * kRows][2], rh[2 * kRows][2];
    const int nl = hull_side(left, n, 1, lh), nr = hull_side(right, n, -1, rh);
    const float hull = area_between(lh, nl, rh, nr);
    p->fill = hull > 0 ? std::min(1.0f, (float)(area / hull)) : 0;
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

void shape_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Shape *s)
{
    if (x1 > x0 && y1 > y0)
        mark_cells(mask, stride, x0, y0, x1, y1, s);
    profile_of(mask, stride, x0, y0, x1, y1, s);
    outline_of(mask, stride, x0, y0, x1, y1, &s->outline);
}

float top_width(const Profile &p)
{
    float head[kHeadRows];
    for (int r = 0; r < kHeadRows; r++)
        head[r] = p.extent(r);
    std::nth_element(head, head + kHeadRows / 2, head + kHeadRows);
    const float top = head[kHeadRows / 2];
    // The body from the shoulders down: a person seen from the side has a
    // head as wide as their torso at the working scale, but legs in stride
    // wider than both.
    float body = 0;
    for (int r = kZones[kShoulders].row0; r < kRows; r++)
        body = std::max(body, p.extent(r));
    // Like a region, the torso abstains when fewer than half its rows hold
    // foreground (hidden, or in pieces that the fragments' merging did not
    // join): then no comparison.
    int present = 0;
    const int r0 = kZones[kShoulders].row0, r1 = kZones[kButtocks].row1;
    for (int r = r0; r < r1; r++)
        present += !p.empty(r);
    return 2 * present >= r1 - r0 && body > 0 ? top / body : 0;
}

Vote classify(const Shape &shape, const RegionThresholds &th)
{
    const Profile &p = shape.profile;
    // Which regions vote depends on the blob alone.
    bool votes[kRegions];
    for (int g = 0; g < kRegions; g++) {
        const Zone &z = kZones[g];
        int present = 0;
        for (int r = z.row0; r < z.row1; r++)
            present += !p.empty(r);
        votes[g] = 2 * present >= z.row1 - z.row0;
    }
    Vote best;
    float best_total = INFINITY;
    const uint16_t *dist = &shape.outline.dist[0][0];
    for (int s = 0; s < kSilhouettes; s++) {
        // Sums of chamfer units, exact in integers.
        uint32_t sum[kRegions] = {0};
        int n[kRegions] = {0};
        const uint16_t *cell = kRegionCells.cell[s];
        const uint16_t *start = kRegionCells.start[s];
        for (int g = 0; g < kRegions; g++) {
            if (!votes[g])
                continue;
            uint32_t acc = 0;
            for (int k = start[g]; k < start[g + 1]; k++)
                acc += dist[cell[k]];
            sum[g] = acc;
            n[g] = start[g + 1] - start[g];
        }
        Vote v;
        float total = 0;
        for (int g = 0; g < kRegions; g++) {
            if (!votes[g] || n[g] == 0) {
                v.distance[g] = -1;
                continue;
            }
            v.distance[g] = (float)sum[g] / n[g] * (1.0f / (3 * kGrid)); // box heights
            v.voters++;
            v.yes += v.distance[g] <= th.t[g];
            total += v.distance[g];
        }
        v.score = v.voters >= kMinVoters ? (float)v.yes / v.voters : 0;
        v.silhouette = s;
        // The closest silhouette (mean distance over the voting regions)
        // speaks for the library, whatever the thresholds: the distances a
        // blob reports do not depend on them.
        const float mean = v.voters ? total / v.voters : INFINITY;
        if (mean < best_total) {
            best = v;
            best_total = mean;
        }
    }
    // A walking person's outline is concave: at the neck, under the arms,
    // between the legs. A blob that fills its convex hull is no pedestrian,
    // whatever its regions say.
    best.fill = p.fill;
    if (best.fill > th.max_fill)
        best.score = std::min(best.score, 0.5f);
    // A person's head is narrower than their body. A blob whose top rows
    // are as wide as its body has no head on top: a T, an H, a Π, an X, a
    // Y, a U. (A person under an open umbrella has a T's outline too.)
    best.top = top_width(p);
    if (best.top > kMaxTopWidth)
        best.score = std::min(best.score, 0.5f);
    return best;
}

} // namespace ctrack
