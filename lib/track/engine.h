// The tracking engine's step: prediction, the candidates of the step,
// association in passes, mean shift and appearance, track lifecycles and
// the tracks reported.
#ifndef CTRACK_ENGINE_H
#define CTRACK_ENGINE_H

#include <cstdint>
#include <vector>

#include "base/counters.h"
#include "base/memory.h"
#include "count/counter.h"

#include "ctrack/ctrack.h"
#include "track/assign.h"
#include "pixels/box_fit.h"
#include "pixels/candidates.h"
#include "track/gate.h"
#include "meanshift/meanshift.h"
#include "base/planes.h"
#include "track/person_size.h"
#include "track/scene.h"
#include "track/score_noise.h"
#include "track/score_scale.h"
#include "track/size_gate.h"
#include "appearance/templates.h"
#include "track/track.h"

namespace ctrack {

// The most DDIS an association or re-identification runs in one step
// (about 30 ms); a flood past it is matched by overlap alone.
constexpr size_t kMaxDdisPairs = 1024;

// The clock the scene's models run on (the background's): the host's
// timestamps plus `shift`, which Engine::rewind() sets so that the clock goes
// on one frame interval after the last step before it.
struct SceneClock {
    int64_t shift_us = 0, last_us = 0, interval_us = 0;
    bool rewound = false; // rewind() was called since the last step
};

// What the tracker learns of the scene as it runs: rewind() keeps it,
// reset() forgets it, and priming leaves it as it was. (The background
// model is the pixels', which commit and roll back their own update.)
struct SceneModels {
    explicit SceneModels(const ct_config &cfg) { size_gate.set_gate(cfg.size_gate); }
    SceneMotion motion; // the association's motion model's
    SceneMotion shown;  // the reported boxes' (Track::shown)
    PersonSize size;
    SizeGate size_gate; // a detector's people's height (size_gate)
    ScoreScale scores;  // a detector's scale of scores (confirm_score)
    ScoreScale box_scores; // ... of all its boxes (high_score, start_score)
    ScoreNoise score_noise; // how far a detector's boxes stray by score
    FitBias fit_bias;   // what the fit does to a detector's boxes (refine_boxes)
};

// Everything a step changes but the background model, in one value: a
// failed step puts the whole of it back.
struct EngineState {
    explicit EngineState(const ct_config &cfg) : learnt(cfg) {}
    // What rewind() forgets: the tracks, this step's outputs and the time.
    Vec<Track> tracks;
    Vec<ct_track> reported;
    Vec<ct_candidate> candidates;
    int64_t last_us = 0;
    bool has_time = false;
    // What it keeps.
    uint64_t next_id = 1;
    SceneClock clock; // reset() starts it again
    SceneModels learnt;
    Counters counters;
};

class Engine {
public:
    explicit Engine(const ct_config &cfg);

    // One step; timestamps are checked by the caller. `img` is empty when
    // the frame has no pixels. If it throws, the engine is as it was before
    // the call.
    void step(int64_t t_us, const Planes &img, ImageSize image, const ct_detection *dets,
              size_t n);
    // Forgets what a rewind() forgets, and what was learnt of the scene
    // (SceneModels and the background model); ids keep increasing.
    void reset();
    // Forgets the tracks, this step's outputs and the last timestamp
    // (EngineState's first part), but keeps what was learnt of the scene:
    // SceneModels and the background model with its noise, contrast and
    // exposure. The next step may go back in time (a recording played
    // again): the scene's clock goes on from where it was.
    void rewind();
    // Priming (ct_tracker_prime()): begin_prime() keeps the state as it is
    // and the background model beside it, then rewinds (it may throw, and
    // then changes nothing); the steps that follow teach the background
    // model. end_prime() forgets what else they did: the learnt models and
    // the next id are put back as they were, so that none ages through the
    // primed stretch and no id a host never saw is taken, and it rewinds.
    // abort_prime() puts back everything as it was at begin_prime(), the
    // background model included. Neither throws.
    void begin_prime();
    void end_prime() noexcept;
    void abort_prime() noexcept;

    const Vec<ct_track> &reported() const { return state_.reported; }
    const Vec<ct_candidate> &candidates() const { return state_.candidates; }
    size_t live_tracks() const { return state_.tracks.size(); }
    const Counters &counters() const { return state_.counters; }
    const PersonSize &person_size() const { return state_.learnt.size; }
    // The lines and zones counted on, from every step but the primed ones.
    Counter &counter() { return count_; }
    const Counter &counter() const { return count_; }
    size_t memory_bytes() const;
    bool has_time() const { return state_.has_time; }
    // This step's cleaned foreground mask at the background model's scale
    // (working_scale() frame pixels a working pixel), or null when the
    // step had no pixels.
    const uint8_t *foreground(int *w, int *h) const { return pixels_.foreground(w, h); }
    // The pixels' working scale (1, 2 or 4), 0 until the background model
    // has learnt a frame (since the last reset).
    int working_scale() const { return pixels_.started() ? pixels_.scale() : 0; }
    int64_t last_time() const { return state_.last_us; }

private:
    // This step's time: seconds since the last step (0 at the first after
    // create, reset or rewind) and the scene's clock.
    struct StepTime {
        bool first;
        double dt;
        int64_t scene_us;
    };

    void step_unguarded(int64_t t_us, const Planes &img, ImageSize image,
                        const ct_detection *dets, size_t n);
    // The engine's clocks moved to this step's timestamp.
    StepTime advance_clock(int64_t t_us);
    // This step's candidates from the pixels, when the tracker reads them:
    // the blobs (source CT_SOURCE_PIXELS), or the host's detections with
    // the contour template's vote (verify_detections). *dets and *n then
    // point at them.
    bool find_candidates(int64_t scene_us, const Planes &img, const ct_detection **dets,
                         size_t *n);
    // The detections that may be matched, by pass: the high-score ones in
    // pool_dets_, the low-score ones in low_dets_ (those the size gate
    // sets aside in neither); the detector's scale of scores learnt.
    void sort_detections(double dt, const ct_detection *dets, size_t n);
    // The passes of association (high scores, recovery, low scores,
    // tentative tracks, re-identification).
    void associate(const ct_detection *dets, bool pixels);
    // New tracks from the high-score detections nobody claimed.
    void start_tracks(const ct_detection *dets, int64_t t_us, bool first);
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
    // Matches tracks[track_idx] to dets[det_idx] by IoU with the gate
    // min_iou (and appearance, when on), updates the matched tracks, and
    // leaves only the unmatched in both lists. With `buffered`, the IoU of
    // boxes widened by each track's uncertainty (buffer()).
    void match(Vec<int> &track_idx, Vec<int> &det_idx,
               const ct_detection *dets, double min_iou, bool buffered = false);
    // How much a confirmed or lost track's box and a detection's are
    // widened on each side, as a share of their sizes, when they are
    // compared without the pixels (kBufferSd): the track's sd_after_hit in
    // its heights.
    double buffer(const Track &t) const;
    // From match(): the pairs of a box drawn for someone behind a blob's
    // person with a track of another height (kBehindRatio) dropped.
    void drop_other_heights(const Vec<int> &track_idx, const Vec<int> &det_idx,
                            const ct_detection *dets);
    // The costs of match()'s pairs: 1 - IoU, plus appearance_weight (1 -
    // DDIS) where pairs compete.
    void add_appearance(const Vec<int> &track_idx, const Vec<int> &det_idx, int n, int m,
                        double weight);
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
    // From the pixels alone: the tracks whose candidate moved inside this
    // step, or that had none, are alive at t_us (Track::live_us), and those
    // that never moved and have not been alive for kObjectAfterS are
    // objects put down.
    void note_live(int64_t t_us);
    // Whether a track is a person standing from the first frame, whom the
    // background holds (follow_or_lose()).
    bool standing(const Track &t) const;
    // Matches the tracks left in pool_tracks_ to the detections left in
    // pool_dets_ by their last detection's box instead of the prediction.
    void recover(const ct_detection *dets);
    // Whether a lost track is likely where predicted and not seen for a
    // reason: another track covers it, and its centre is known to within
    // report_lost_sd of its size.
    bool hidden_in_view(const Track &t, size_t i) const;
    void report(int64_t t_us, ImageSize image);
    // The reported boxes fitted to the silhouettes (refine_boxes), each
    // that another does not cover.
    void fit_reported(ImageSize image);
    // A box clipped to the image when clip_boxes asks; false when nothing
    // of it is left.
    bool clip_box(ImageSize image, Box *b) const;
    // A track's reported box: its reported boxes' model's estimate (the
    // association's where the box is then fitted to the silhouette),
    // clipped to the image when asked; false when clipping leaves nothing.
    bool reported_box(const Track &t, ImageSize image, Box *out) const;

    const ct_config cfg_;
    EngineState state_;
    // The state at begin_prime(), while priming (else empty).
    EngineState before_prime_;
    bool priming_ = false;
    // The state before the step in progress, restored as a whole if it
    // throws (the restoring copy fits in capacity the vectors already
    // have, so it cannot throw). A member, so that steady state does not
    // allocate.
    EngineState saved_;

    MeanShift ms_;
    MeanShiftParams ms_params_;
    int min_rho_ = 0;         // mean_shift_min_similarity in Q16
    // The score one of a tentative track's detections must reach before it
    // is confirmed, this step: with a detector's boxes confirm_score, or
    // less where the detector's scores are lower (score_scale.h); 0 (none)
    // with the pixels' candidates, for which it is never learnt.
    float confirm_ = 0;
    // This step's scores that match first and start a track
    // (Engine::sort_detections()): high_score and start_score on a
    // detector's scale of scores, or the pixels' candidate_min_score and 0.
    float high_ = 0, start_ = 0;
    bool appearance_ = false; // this step
    bool fit_boxes_ = false;  // this step: the reported boxes are fitted
    bool silhouettes_ = false; // this step: the mask shows silhouettes clearly
    TemplateBank bank_;
    PixelCandidates pixels_;
    // Counting runs last in a step: it changes nothing unless the step is
    // done, and reset() and priming forget its tracks with the engine's.
    Counter count_;

    // Association's scratch, reused from step to step.
    Gate gate_;
    Vec<Pair> pairs_;
    Vec<int> row_pairs_, col_pairs_; // pairs per row and column in match()
    Vec<Box> cues_;                  // the buffered match()'s tracks' cues,
    Vec<double> buffers_;            // their buffers
    Vec<int> buffer_order_;          // and separate_buffers()' scratch
    Assigner assigner_;
    Vec<int> row_to_col_, pool_tracks_, pool_dets_, low_dets_;
    Vec<char> det_used_;
    Vec<Box> fitted_; // fit_reported()'s
    Vec<size_t> reported_from_; // report()'s: the track each reported row is
    // Whether this step's detections are trusted by their scores
    // (score_noise.h): a detector's boxes without frames.
    bool by_score_ = false;
};

} // namespace ctrack

#endif
