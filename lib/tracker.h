// The tracking engine: prediction, association and track lifecycles.
#ifndef CTRACK_TRACKER_H
#define CTRACK_TRACKER_H

#include <cstdint>
#include <vector>

#include "ctrack/ctrack.h"
#include "appearance.h"
#include "assign.h"
#include "background.h"
#include "blobs.h"
#include "contour_template.h"
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
    float seen_h = 0; // the height of the last detection
    // Where it started, and whether it has since moved half its height: a
    // track that never moved may be a ghost of the background model.
    double start_x = 0, start_y = 0;
    bool moved = false;
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
    // Appearance template: a slot of Engine::templates_ (-1: none), and when
    // it was made.
    int tmpl = -1;
    int64_t tmpl_us = 0;

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
    const std::vector<ct_candidate> &candidates() const { return candidates_; }
    size_t live_tracks() const { return tracks_.size(); }
    uint64_t mean_shift_runs() const { return ms_runs_; }
    uint64_t ddis_runs() const { return ddis_runs_; }
    uint64_t template_builds() const { return template_builds_; }
    size_t memory_bytes() const;
    size_t templates_memory() const;
    // Nanoseconds spent in each ct_stage, summed over the steps.
    const uint64_t *stage_ns() const { return stage_ns_; }
    bool has_time() const { return has_time_; }
    // This step's cleaned foreground mask at the background model's scale
    // (Background::kScale), or null when the step had no pixels.
    const uint8_t *foreground(int *w, int *h) const
    {
        *w = background_.width();
        *h = background_.height();
        return have_mask_ ? blobs_.cleaned() : nullptr;
    }
    int64_t last_time() const { return last_us_; }

private:
    void step_unguarded(int64_t t_us, const Planes &img, ImageSize image,
                        const ct_detection *dets, size_t n);
    void predict(double dt);
    void refine(const Planes &img);
    void follow_or_lose(const Planes &img, int64_t t_us);
    void learn_models(const Planes &img);
    void describe_detections(const Planes &img, const ct_detection *dets, size_t n);
    double similarity(const Track &t, int det);
    void reidentify(const ct_detection *dets);
    void learn_templates(int64_t t_us);
    // Source pixels: candidates from the background model and the contour
    // template, into cand_dets_ (as detections) and candidates_.
    void find_candidates(const Planes &img);
    // verify_detections: the background model's foreground, the contour
    // template's vote on each detection into candidates_, and the
    // detections with their scores lowered where the vote rejects them
    // into cand_dets_.
    void verify_detections(const Planes &img, const ct_detection *dets, size_t n);
    // The background model over this frame (tracks that moved are frozen).
    void update_background(const Planes &img);
    // The contour template's vote on the cleaned mask inside r (clipped),
    // as a candidate with the box `box`.
    ct_candidate vote_on(Rect r, float left, float top, float width, float height);
    // The centroid of the foreground inside b, or its centre.
    void barycenter(const Box &b, float *x, float *y) const;
    bool occluded(size_t i) const;
    void match(std::vector<int> &track_idx, std::vector<int> &det_idx,
               const ct_detection *dets, double min_iou);
    void update(Track &t, const ct_detection &d, int index, int64_t t_us);
    void start_track(const ct_detection &d, int index, int64_t t_us, bool confirm);
    void report(int64_t t_us, ImageSize image);

    uint64_t stage_ns_[CT_STATS_MAX_STAGES] = {};
    uint64_t ms_runs_ = 0, ddis_runs_ = 0, template_builds_ = 0;
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
    std::vector<ct_candidate> saved_candidates_;

    // Scratch reused from step to step.
    Assigner assigner_;
    MeanShift ms_;
    MeanShiftParams ms_params_;
    int min_rho_ = 0; // mean_shift_min_similarity in Q16

    // Appearance: templates in slots that tracks point to (a slot no track
    // points to is free), and this step's descriptors of the detections.
    bool appearance_ = false; // this step
    std::vector<Template> templates_;
    std::vector<char> slot_used_;
    std::vector<float> det_desc_;
    Ddis ddis_;

    // Source pixels.
    Background background_;
    BlobFinder blobs_;
    bool have_mask_ = false; // this step
    std::vector<Rect> frozen_, predicted_, blob_rects_;
    std::vector<ct_detection> cand_dets_;
    std::vector<ct_candidate> candidates_;
    std::vector<double> cost_;
    std::vector<int> row_to_col_, pool_tracks_, pool_dets_, low_dets_;
    std::vector<char> det_used_;
};

} // namespace ctrack

#endif
