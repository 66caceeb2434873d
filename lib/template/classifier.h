// The pedestrian decision (the paper's sections 2.1-2.2, eq. 1): a blob's
// shape against the contour template's silhouette library, region by
// region; the 9 regions' vote; and the vetoes that overrule it. Every
// constant of the decision is here or in classifier_params.inc.
#ifndef CTRACK_CLASSIFIER_H
#define CTRACK_CLASSIFIER_H

#include <cstdint>

#include "base/memory.h"
#include "ctrack/ctrack.h"
#include "pixels/mask.h"
#include "template/shape.h"

namespace ctrack {

constexpr int kRegions = 9;
static_assert(kRegions == CT_REGIONS, "the API's region count");

enum Region {
    kHead, kNeck, kShoulders, kChest, kBack, kAbdomen, kButtocks, kUpperLimbs, kLowerLimbs
};

const char *region_name(int r);
// How many pedestrian silhouettes the library has, and how many of them
// classify() compares (the others repeat one of them, cell for cell); and
// how many shapes a person is not follow them (two people side by side: a
// blob closer to one of them than to every silhouette is no pedestrian).
int library_silhouettes();
int distinct_silhouettes();
int not_person_shapes();

// At least this many regions must vote for a score.
constexpr int kMinVoters = 5;

// What overrules the regions' vote: a blob past either bound scores at most
// 0.5, not a pedestrian.
struct Vetoes {
    // The largest part of its convex hull a pedestrian's blob fills: a
    // walking person's outline is concave at the neck, under the arms and
    // between the legs.
    float max_fill;
    // The widest top, against the body (top_width()), a pedestrian's blob
    // has: a person's head is narrower than their shoulders, arms or legs
    // in stride. A T, an H, a Y have no head on top.
    float max_top_width;
};

struct ClassifierParams {
    // Eq. (1)'s threshold per region, in box heights: a region votes yes
    // when its distance is at most this.
    float region[kRegions];
    Vetoes veto;
};

// The shipped parameters (classifier_params.inc, which names the command
// that chose them).
const ClassifierParams &default_params();

struct Vote {
    // Eq. (1) per region: the mean distance from the best silhouette's
    // outline points in the region to the blob's outline (nearest-point
    // correspondence), in box heights; negative where the region abstained
    // (too few of its rows hold foreground): all of them when no region
    // votes.
    float distance[kRegions] = {-1, -1, -1, -1, -1, -1, -1, -1, -1};
    int yes = 0, voters = 0;
    // yes / voters, 0 with fewer than kMinVoters voters, at most 0.5 (no
    // pedestrian) when a veto applies or a shape a person is not fits the
    // blob better than every silhouette.
    float score = 0;
    int silhouette = -1;
    float fill = 0; // Profile::fill
    float top = 0;  // top_width()
    // When a shape a person is not (two walkers side by side) overruled a
    // majority of the regions, the score they gave (score is then 0.5);
    // else -1.
    float regions_alone = -1;
};

// How wide the blob's top is against its body: the median extent of the
// head's rows (an empty row counts 0) over the widest row from the
// shoulders to the feet; 0 when fewer than half the rows from the shoulders
// to the hips hold foreground. About 0.15 for the library's silhouettes; a
// T, an H, a Π, an X, a Y, a V or a U reach 1.
float top_width(const Profile &p);

// Votes with the closest silhouette of the library (the smallest mean
// distance over the regions that vote), so that the distances reported do
// not depend on the thresholds. A tie of votes (yes = no) is a no: score
// 0.5 is not above the majority.
Vote classify(const Shape &s, const ClassifierParams &params);

// The vote on a mask's foreground inside a box, with the scratch memory a
// shape needs kept from one call to the next.
// The boxes a Classifier remembers the votes of, per mask (the buffer grows
// to what the scene needs, at most this).
constexpr size_t kMemoBoxes = 64;

class Classifier {
public:
    // A new mask (or new contents in the same buffer): the votes remembered
    // for the last one are forgotten. Within a frame a box is voted on once
    // (the blob merging asks for the boxes the candidates then report).
    // BlobFinder::find() calls it for the mask it cleans.
    void new_mask() { memo_.clear(); }
    // The vote on the foreground of the w x h mask inside r (within it).
    Vote vote(const uint8_t *mask, int w, const Rect &r);
    // The vote on a part of a group cut between two people's heads, whose
    // fill the vetoes do not read (the neighbours' arms and legs fill its
    // outline's hollows); not remembered.
    Vote vote_part(const uint8_t *mask, int w, const Rect &r);
    // The vote inside r (clipped to the mask) as the candidate the API
    // reports, with the box (left, top, width, height) in frame pixels; a
    // `part` as vote_part() has it. `regions_alone`, when given, receives
    // Vote::regions_alone.
    ct_candidate candidate(const uint8_t *mask, int w, int h, Rect r, float left, float top,
                           float width, float height, bool part = false,
                           float *regions_alone = nullptr);
    size_t memory_bytes() const
    {
        return shape_.runs.memory_bytes() + shape_.columns.capacity() * sizeof(int) +
               memo_.capacity() * sizeof(Memo);
    }

private:
    struct Memo {
        const uint8_t *mask;
        int w;
        Rect r;
        Vote vote;
    };
    Shape shape_;
    Vec<Memo> memo_;
};

// Whether the vote rejects a candidate: enough regions voted and no
// majority said pedestrian, or a veto applied.
inline bool rejects(const ct_candidate &c)
{
    return c.voters >= kMinVoters && c.score <= 0.5f;
}

} // namespace ctrack

#endif
