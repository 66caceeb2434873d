#include "template/classifier.h"

#include <algorithm>
#include <cmath>

#include "base/tunable.h"
#ifdef CT_TUNING
#include <cstdio>
#endif

namespace ctrack {

namespace {

#include "silhouettes.inc"
#include "classifier_params.inc"

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

// Silhouettes whose region cells repeat an earlier one's, in the same
// order: they would get the same distances, and classify() keeps the first
// of equals, so it skips them (lib/template/silhouettes.inc repeats many, see
// docs/notes/pixels.md).
struct Repeats {
    bool of_earlier[kSilhouettes];
    int distinct;
};

constexpr bool same_cells(int s, int t)
{
    for (int g = 0; g <= kRegions; g++)
        if (kRegionCells.start[s][g] != kRegionCells.start[t][g])
            return false;
    for (int k = 0; k < kRegionCells.start[s][kRegions]; k++)
        if (kRegionCells.cell[s][k] != kRegionCells.cell[t][k])
            return false;
    return true;
}

constexpr Repeats make_repeats()
{
    Repeats r{};
    for (int s = 0; s < kSilhouettes; s++) {
        r.of_earlier[s] = false;
        for (int t = 0; t < s && !r.of_earlier[s]; t++)
            r.of_earlier[s] = same_cells(s, t);
        r.distinct += s < kPeople && !r.of_earlier[s];
    }
    return r;
}

constexpr Repeats kRepeats = make_repeats();

// The head's rows (the median of eight rows is the fifth smallest: an
// upper median).
constexpr int kHeadRows = kZones[kHead].row1 - kZones[kHead].row0;

// Whether a candidate with no upper body to compare is no pedestrian (a
// tuning build turns it off with CTRACK_UPPER_BODY=0; docs/tuning.md, "No
// upper body").
CT_TUNABLE(kUpperBodyVeto, "CTRACK_UPPER_BODY", 1);

const char *const kNames[kRegions] = {"head", "neck", "shoulders", "chest", "back",
                                      "abdomen", "buttocks", "upper limbs", "lower limbs"};

} // namespace

int library_silhouettes()
{
    return kPeople;
}

int distinct_silhouettes()
{
    return kRepeats.distinct;
}

int not_person_shapes()
{
    return kSilhouettes - kPeople;
}

const char *region_name(int r)
{
    return r >= 0 && r < kRegions ? kNames[r] : nullptr;
}

const ClassifierParams &default_params()
{
#ifdef CT_TUNING
    // A tuning build reads each threshold from CTRACK_REGION_<g> and the
    // vetoes from CTRACK_MAX_FILL and CTRACK_MAX_TOP (docs/tuning.md).
    static const ClassifierParams tuned = [] {
        ClassifierParams p = kDefaultParams;
        char name[32];
        for (int g = 0; g < kRegions; g++) {
            std::snprintf(name, sizeof name, "CTRACK_REGION_%d", g);
            p.region[g] = (float)tunable(name, p.region[g]);
        }
        p.veto.max_fill = (float)tunable("CTRACK_MAX_FILL", p.veto.max_fill);
        p.veto.max_top_width = (float)tunable("CTRACK_MAX_TOP", p.veto.max_top_width);
        return p;
    }();
    return tuned;
#else
    return kDefaultParams;
#endif
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

Vote classify(const Shape &shape, const ClassifierParams &params)
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
    const uint16_t *dist = &shape.outline.dist[0][0];
    // Eq. (1) against library shape s: each voting region's distance, the
    // votes, and the mean distance over the voters (returned).
    auto compare = [&](int s, Vote *v) {
        float total = 0;
        const uint16_t *cell = kRegionCells.cell[s];
        const uint16_t *start = kRegionCells.start[s];
        for (int g = 0; g < kRegions; g++) {
            const int n = start[g + 1] - start[g];
            if (!votes[g] || n == 0) {
                v->distance[g] = -1;
                continue;
            }
            // A sum of chamfer units, exact in integers.
            uint32_t acc = 0;
            for (int k = start[g]; k < start[g + 1]; k++)
                acc += dist[cell[k]];
            v->distance[g] = (float)acc / n * (1.0f / (3 * kGrid)); // box heights
            v->voters++;
            v->yes += v->distance[g] <= params.region[g];
            total += v->distance[g];
        }
        return v->voters ? total / v->voters : INFINITY;
    };
    Vote best;
    float best_total = INFINITY;
    for (int s = 0; s < kPeople; s++) {
        if (kRepeats.of_earlier[s])
            continue;
        Vote v;
        const float mean = compare(s, &v);
        v.score = v.voters >= kMinVoters ? (float)v.yes / v.voters : 0;
        v.silhouette = s;
        // The closest silhouette (mean distance over the voting regions)
        // speaks for the library, whatever the thresholds: the distances a
        // blob reports do not depend on them.
        if (mean < best_total) {
            best = v;
            best_total = mean;
        }
    }
    // The vetoes overrule the regions: a blob that fills its convex hull,
    // or has no head on top (a T, an H, a Π, an X, a Y, a U; a person under
    // an open umbrella has a T's outline too), is no pedestrian; nor is a
    // blob that a shape a person is not fits better than every silhouette
    // (a group that a wide silhouette, three-quarters with legs in stride,
    // would take for one person). Those shapes, the library's last, are
    // compared only when they could overrule a yes.
    best.fill = p.fill;
    best.top = top_width(p);
    if (best.fill > params.veto.max_fill || best.top > params.veto.max_top_width) {
        best.score = std::min(best.score, 0.5f);
    } else if (best.score > 0.5f) {
        for (int s = kPeople; s < kSilhouettes; s++) {
            Vote v;
            if (!kRepeats.of_earlier[s] && compare(s, &v) < best_total) {
                best.regions_alone = best.score;
                best.score = 0.5f;
                break;
            }
        }
    }
    return best;
}

Vote Classifier::vote(const uint8_t *mask, int w, const Rect &r)
{
    for (const Memo &m : memo_)
        if (m.mask == mask && m.w == w && m.r.x0 == r.x0 && m.r.y0 == r.y0 && m.r.x1 == r.x1 &&
            m.r.y1 == r.y1)
            return m.vote;
    shape_of(mask, w, r.x0, r.y0, r.x1, r.y1, &shape_);
    const Vote v = classify(shape_, default_params());
    // A few dozen boxes a frame at most are asked for; past that (a flood
    // of blobs) the rest are not remembered.
    if (memo_.size() < kMemoBoxes)
        memo_.push_back(Memo{mask, w, r, v});
    return v;
}

Vote Classifier::vote_part(const uint8_t *mask, int w, const Rect &r)
{
    ClassifierParams p = default_params();
    p.veto.max_fill = 1;
    shape_of(mask, w, r.x0, r.y0, r.x1, r.y1, &shape_);
    return classify(shape_, p);
}

ct_candidate Classifier::candidate(const uint8_t *mask, int w, int h, Rect r, float left,
                                   float top, float width, float height, bool part,
                                   float *regions_alone)
{
    if (regions_alone)
        *regions_alone = -1;
    r.x0 = std::max(r.x0, 0);
    r.y0 = std::max(r.y0, 0);
    r.x1 = std::min(r.x1, w);
    r.y1 = std::min(r.y1, h);
    ct_candidate c = {};
    c.left = left;
    c.top = top;
    c.width = width;
    c.height = height;
    if (r.x1 <= r.x0 || r.y1 <= r.y0) {
        for (float &d : c.region_distance)
            d = -1;
        return c; // outside the image: no voters
    }
    const Vote v = part ? vote_part(mask, w, r) : vote(mask, w, r);
    if (regions_alone)
        *regions_alone = v.regions_alone;
    c.score = v.score;
    // A candidate whose box's top quarter is mostly empty rows (a speck
    // above a gap: the head, the neck and the shoulders all abstain) shows
    // no upper body, and is no pedestrian however well its lower regions
    // fit. Only the candidate is turned down: the blob merging and the
    // splits between people, which vote on boxes of their own, go as the
    // regions say, and one head on its top edge does not lift it back
    // (PixelCandidates::score_blob()).
    if (kUpperBodyVeto && v.distance[kHead] < 0 && v.distance[kNeck] < 0 &&
        v.distance[kShoulders] < 0) {
        c.score = std::min(c.score, 0.5f);
        if (regions_alone)
            *regions_alone = -1;
    }
    c.votes_yes = v.yes;
    c.voters = v.voters;
    for (int g = 0; g < kRegions; g++)
        c.region_distance[g] = v.distance[g];
    c.fill = v.fill;
    c.top_width = v.top;
    return c;
}

} // namespace ctrack
