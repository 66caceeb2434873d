// The tracking engine's step: prediction, the candidates of the step,
// association in passes, mean shift and appearance, track lifecycles and
// the tracks reported.
#ifndef CTRACK_ENGINE_H
#define CTRACK_ENGINE_H

#include <cstdint>
#include <vector>

#include "base/memory.h"

#include "ctrack/ctrack.h"
#include "track/assign.h"
#include "pixels/candidates.h"
#include "track/gate.h"
#include "meanshift/meanshift.h"
#include "base/planes.h"
#include "track/person_size.h"
#include "track/scene.h"
#include "track/score_scale.h"
#include "track/size_gate.h"
#include "appearance/templates.h"
#include "track/track.h"

namespace ctrack {

// The most DDIS an association or re-identification runs in one step
// (about 30 ms); a flood past it is matched by overlap alone.
constexpr size_t kMaxDdisPairs = 1024;

class Engine {
public:
    explicit Engine(const ct_config &cfg);

    // One step; timestamps are checked by the caller. `img` is empty when
    // the frame has no pixels. If it throws, the engine is as it was before
    // the call.
    void step(int64_t t_us, const Planes &img, ImageSize image, const ct_detection *dets,
              size_t n);
    void reset();
    // Forgets the tracks and the last timestamp, as reset(), but keeps what
    // was learnt of the scene: the background model with its noise,
    // contrast and exposure, the people's size, the scene's motion, the
    // size gate and the detector's scale of scores. The next step may go
    // back in time (a recording played again): the background's own clock
    // goes on from where it was.
    void rewind();
    // The id the next confirmed track takes; set_next_id() puts back one
    // taken before (a priming's steps confirm no track a host saw).
    uint64_t next_id() const { return next_id_; }
    void set_next_id(uint64_t id) { next_id_ = id; }

    const Vec<ct_track> &reported() const { return reported_; }
    const Vec<ct_candidate> &candidates() const { return pixels_.candidates(); }
    size_t live_tracks() const { return tracks_.size(); }
    uint64_t mean_shift_runs() const { return ms_runs_; }
    uint64_t ddis_runs() const { return bank_.ddis_runs; }
    uint64_t template_builds() const { return bank_.builds; }
    uint64_t blobs_dropped() const { return pixels_.blobs_dropped; }
    uint64_t masks_flooded() const { return pixels_.masks_flooded; }
    const PersonSize &person_size() const { return size_; }
    size_t memory_bytes() const;
    // Nanoseconds spent in each ct_stage, summed over the steps.
    const uint64_t *stage_ns() const { return stage_ns_; }
    bool has_time() const { return has_time_; }
    // This step's cleaned foreground mask at the background model's scale
    // (working_scale() frame pixels a working pixel), or null when the
    // step had no pixels.
    const uint8_t *foreground(int *w, int *h) const { return pixels_.foreground(w, h); }
    // The pixels' working scale (1, 2 or 4), 0 until the background model
    // has learnt a frame (since the last reset).
    int working_scale() const { return pixels_.started() ? pixels_.scale() : 0; }
    int64_t last_time() const { return last_us_; }

private:
    void step_unguarded(int64_t t_us, const Planes &img, ImageSize image,
                        const ct_detection *dets, size_t n);
    // Mean shift from each confirmed track's prediction: where the pixels
    // say the person is, before the detections are compared.
    void refine(const Planes &img);
    // A confirmed track that no detection claimed is carried by mean shift
    // while the pixels hold it; otherwise it will be lost.
    void follow_or_lose(const Planes &img, int64_t t_us);
    // Colour models: made when a track is confirmed, then learnt (eq. 9)
    // from the boxes that detections confirm, unless another track
    // overlaps the box or the box no longer looks like the model.
    void learn_models(const Planes &img);
    // Lost tracks take back high-score detections that nobody claimed and
    // that look like them (DDIS), near where they were heading: a person
    // who reappears after an occlusion keeps their id.
    void reidentify(const ct_detection *dets);
    // Matches tracks_[track_idx] to dets[det_idx] by IoU with the gate
    // min_iou (and appearance, when on), updates the matched tracks, and
    // leaves only the unmatched in both lists.
    void match(Vec<int> &track_idx, Vec<int> &det_idx,
               const ct_detection *dets, double min_iou);
    void update(Track &t, const ct_detection &d, int index, int64_t t_us);
    void start_track(const ct_detection &d, int index, int64_t t_us, bool confirm);
    // Whether a detector's boxes go through the size gate (size_gate).
    bool size_gate_on() const
    {
        return cfg_.source == CT_SOURCE_DETECTIONS && cfg_.size_gate > 0;
    }
    // Tracks no detection updated: lost, or removed when tentative, past
    // their lifetime or outside the image.
    void age_unmatched(int64_t t_us, ImageSize image);
    // The people's size learnt from this step's confident single-person
    // boxes: the detections (or candidates) that updated confirmed tracks.
    void learn_sizes(const ct_detection *dets, int64_t t_us, ImageSize image);
    // Matches the tracks left in pool_tracks_ to the detections left in
    // pool_dets_ by their last detection's box instead of the prediction.
    void recover(const ct_detection *dets);
    // Whether a lost track is likely where predicted and not seen for a
    // reason: another track covers it, and its centre is known to within
    // report_lost_sd of its size.
    bool hidden_in_view(const Track &t, size_t i) const;
    void report(int64_t t_us, ImageSize image);

    uint64_t stage_ns_[CT_STATS_MAX_STAGES] = {};
    uint64_t ms_runs_ = 0;
    ct_config cfg_;
    Vec<Track> tracks_;
    Vec<ct_track> reported_;
    uint64_t next_id_ = 1;
    int64_t last_us_ = 0;
    bool has_time_ = false;
    // The scene's clock (the background model's): the host's timestamps
    // plus scene_shift_us_, which rewind() sets so that the clock goes on
    // one frame interval after the last step before it.
    int64_t scene_shift_us_ = 0;
    int64_t scene_last_us_ = 0;
    int64_t scene_interval_us_ = 0;
    bool rewound_ = false;

    // The state before the step in progress, restored if it throws (the
    // restoring copy fits in capacity the vectors already have, so it cannot
    // throw). Kept as members so that steady state does not allocate.
    Vec<Track> saved_tracks_;
    Vec<ct_track> saved_reported_;
    Vec<ct_candidate> saved_candidates_;
    PersonSize saved_size_;

    MeanShift ms_;
    MeanShiftParams ms_params_;
    int min_rho_ = 0;         // mean_shift_min_similarity in Q16
    SceneMotion scene_;
    PersonSize size_;
    SizeGate size_gate_; // a detector's people's height (size_gate)
    ScoreScale scores_;  // a detector's scale of scores (confirm_score)
    // The score one of a tentative track's detections must reach before it
    // is confirmed, this step: with a detector's boxes confirm_score, or
    // less where the detector's scores are lower (score_scale.h); 0 (none)
    // with the pixels' candidates, for which it is never learnt.
    float confirm_ = 0;
    bool appearance_ = false; // this step
    TemplateBank bank_;
    PixelCandidates pixels_;

    // Association's scratch, reused from step to step.
    Gate gate_;
    Vec<Pair> pairs_;
    Vec<int> row_pairs_, col_pairs_; // pairs per row and column in match()
    Assigner assigner_;
    Vec<int> row_to_col_, pool_tracks_, pool_dets_, low_dets_;
    Vec<char> det_used_;
};

} // namespace ctrack

#endif
