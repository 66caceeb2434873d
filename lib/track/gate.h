// The association's gates: which (track, detection) pairs may be compared,
// found from the detections sorted by their left edge rather than by
// comparing every track with every detection, and at most
// kMaxPairsPerTrack for any one track, so that a flood of overlapping
// detections (a detector without non-maximum suppression) costs a bounded
// number of appearance comparisons and a sparse assignment.
#ifndef CTRACK_GATE_H
#define CTRACK_GATE_H

#include <vector>

#include "base/memory.h"

#include "ctrack/ctrack.h"
#include "track/assign.h"
#include "track/track.h"

namespace ctrack {

// The pairs one track keeps at most: its best by overlap (or nearness).
// A real scene gives a track one to three.
constexpr int kMaxPairsPerTrack = 16;

class Gate {
public:
    // Indexes the detections dets[cols[k]] for the queries that follow;
    // pairs name them by their position k in cols. cols must outlive the
    // queries.
    void index(const ct_detection *dets, const Vec<int> &cols);
    // Appends (row, k, 1 - IoU) for the indexed detections whose IoU with
    // `box` reaches min_iou (an IoU within 1e-12 of it counts), the
    // kMaxPairsPerTrack best when more do (ties: the lower k). With reach >
    // 0, also the detections that miss min_iou but whose centre lies within
    // `reach` of the box's, at a height within (0.67, 1.5) times the box's,
    // at a cost from (1 - min_iou) / 2 to 1 - min_iou as they lie farther:
    // a new track's person may have walked out of their last box. With
    // buffer > 0 the IoU is that of the two boxes each widened by `buffer`
    // of its own width and height on every side (buffered_iou()).
    void overlapping(int row, const Box &box, double min_iou, Vec<Pair> &out,
                     double reach = 0, double buffer = 0);
    // Appends (row, k, distance) for the indexed detections whose centre
    // lies within `reach` of (cx, cy) and whose height is within (0.67, 1.5)
    // times h, the kMaxPairsPerTrack nearest when more do (ties: the lower
    // k).
    void near(int row, double cx, double cy, double reach, double h, Vec<Pair> &out);
    size_t memory_bytes() const;

private:
    // The positions k whose detection's left edge may lie in [lo, hi).
    void range(double lo, double hi, size_t *first, size_t *last) const;
    // Keeps the row's kMaxPairsPerTrack best (lowest cost) of row_ and
    // appends them to out in increasing k.
    void keep_best(Vec<Pair> &out);

    const ct_detection *dets_ = nullptr;
    const Vec<int> *cols_ = nullptr;
    Vec<int> order_;   // positions k by increasing left edge
    Vec<double> left_; // the left edges in that order
    double max_width_ = 0;
    Vec<Pair> row_;
};

} // namespace ctrack

#endif
