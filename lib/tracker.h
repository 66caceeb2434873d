// The tracking engine: prediction, association and track lifecycles.
#ifndef CTRACK_TRACKER_H
#define CTRACK_TRACKER_H

#include <cstdint>
#include <vector>

#include "ctrack/ctrack.h"
#include "assign.h"
#include "meanshift.h"
#include "motion.h"
#include "planes.h"

namespace ctrack {

struct Box {
    double left, top, width, height;
};

double iou(const Box &a, const Box &b);

struct Track {
    uint64_t id = 0;              // 0 until confirmed
    int state = CT_TRACK_TENTATIVE;
    Axis cx, cy, w, h;
    int age = 0, hits = 0;
    int64_t last_update_us = 0;
    int det_index = -1;
    int class_id = 0;
    float score = 0;
    // The box association compares with detections this step: the
    // prediction, or where mean shift moved it.
    Box cue{0, 0, 0, 0};
    // This step's mean shift result, when it ran (rho in Q16).
    bool followed = false;
    MeanShiftResult ms;
    ColorModel model;

    Box box() const;
};

// One image size: 0 x 0 when unknown.
struct ImageSize {
    int width = 0, height = 0;
    bool known() const { return width > 0 && height > 0; }
};

class Engine {
public:
    explicit Engine(const ct_config &cfg);

    // One step; timestamps are checked by the caller. `img` is empty when
    // the frame has no pixels. If it throws, the engine is as it was before
    // the call.
    void step(int64_t t_us, const Planes &img, ImageSize image, const ct_detection *dets,
              size_t n);
    void reset();

    const std::vector<ct_track> &reported() const { return reported_; }
    size_t live_tracks() const { return tracks_.size(); }
    uint64_t mean_shift_runs() const { return ms_runs_; }
    size_t memory_bytes() const;
    // Nanoseconds spent in each ct_stage, summed over the steps.
    const uint64_t *stage_ns() const { return stage_ns_; }
    bool has_time() const { return has_time_; }
    int64_t last_time() const { return last_us_; }

private:
    void step_unguarded(int64_t t_us, const Planes &img, ImageSize image,
                        const ct_detection *dets, size_t n);
    void predict(double dt);
    void refine(const Planes &img);
    void follow_or_lose(const Planes &img, int64_t t_us);
    void learn_models(const Planes &img);
    bool occluded(size_t i) const;
    void match(std::vector<int> &track_idx, std::vector<int> &det_idx,
               const ct_detection *dets, double min_iou);
    void update(Track &t, const ct_detection &d, int index, int64_t t_us);
    void start_track(const ct_detection &d, int index, int64_t t_us, bool confirm);
    void report(int64_t t_us, ImageSize image);

    uint64_t stage_ns_[CT_STATS_MAX_STAGES] = {};
    uint64_t ms_runs_ = 0;
    ct_config cfg_;
    std::vector<Track> tracks_;
    std::vector<ct_track> reported_;
    uint64_t next_id_ = 1;
    int64_t last_us_ = 0;
    bool has_time_ = false;

    // The state before the step in progress, restored if it throws (the
    // restoring copy fits in capacity the vectors already have, so it cannot
    // throw). Kept as members so that steady state does not allocate.
    std::vector<Track> saved_tracks_;
    std::vector<ct_track> saved_reported_;

    // Scratch reused from step to step.
    Assigner assigner_;
    MeanShift ms_;
    MeanShiftParams ms_params_;
    std::vector<double> cost_;
    std::vector<int> row_to_col_, pool_tracks_, pool_dets_, low_dets_;
    std::vector<char> det_used_;
};

} // namespace ctrack

#endif
