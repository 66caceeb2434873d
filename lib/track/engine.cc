#include "track/engine.h"

#include <algorithm>
#include <cmath>

#include "base/clock.h"
#include "base/tunable.h"

namespace ctrack {

namespace {

// Mean shift follows a track only while this much of its box is in the
// image: the detector stops seeing a person cut by the border, and the part
// left in the window does not hold them.
constexpr double kMinInside = 0.9;
// Nor when the background model, where it shows silhouettes clearly, finds
// less than this share of the window foreground: the person has gone (out
// of the image, or where no blob is), and what the window holds is the
// background, which the window's colours can match as well as they matched
// the person (0.8 to 0.9 on TUD-Campus's pavement). A person who stops
// stays foreground: the model is frozen under a confirmed track that moved
// (docs/tuning.md, "Mean shift on the background").
CT_TUNABLE(kFollowForeground, "CTRACK_FOLLOW_FOREGROUND", 0.1);
// A person standing from the first frame is in the model from the start:
// their blob is the outline their sway stirs, under the share above, and
// no candidate comes for seconds on end. From the pixels alone, where the
// model shows silhouettes clearly (learnt for a second, the camera still:
// a moving picture stirs every box), a confirmed track that never moved
// (half its height), stands within kStillReach of its height from where
// it started and moves under kStillSpeed of its height a second is carried
// by mean shift whatever the foreground, and a stir of its box
// (Background::live() over the box) keeps it as a candidate would for
// mean_shift_max_time. A walker's track left on the background has moved
// or moves, and is not held (docs/tuning.md, "A person standing from the
// first frame").
CT_TUNABLE(kStillHold, "CTRACK_STILL_HOLD", 1);
CT_TUNABLE(kStillReach, "CTRACK_STILL_REACH", 0.1);
CT_TUNABLE(kStillSpeed, "CTRACK_STILL_SPEED", 0.1);
// Such a person's low-score candidates are often the part of their outline
// that stirs (the legs alone, at 25 frames/s); one shorter than
// kStillFragment of the track's height moves its box sideways only, and
// keeps its top and height: else one such blob took the box a fifth of
// its height down, under IoU 0.5 of the person for a second.
CT_TUNABLE(kStillFragment, "CTRACK_STILL_FRAGMENT", 0.9);
constexpr double kMinSide = 1.0;
// A tentative track meets a detection that misses its IoU gate when the
// detection's centre lies within this many standard deviations of where
// the track predicts it (its motion model's, with a detection's noise): at
// a few frames a second a person walks out of their last box before their
// track knows their velocity. At 25 frames/s the reach is inside the IoU
// gate (docs/tuning.md, "A new track's reach").
CT_TUNABLE(kNewTrackReach, "CTRACK_NEW_TRACK_REACH", 2.0);
// From the pixels alone, a confirmed track that never moved half its
// height, stands within kObjectReach of its height from where it started,
// and whose blob stayed still inside for kObjectAfterS is an object put
// down, not a person (docs/tuning.md, "An object put down"): a person who
// came in slowly toward the camera and stands is not.
CT_TUNABLE(kObjectAfterS, "CTRACK_OBJECT_AFTER", 1.0);
CT_TUNABLE(kObjectReach, "CTRACK_OBJECT_REACH", 0.15);
// Without the pixels, a confirmed or lost track meets the detections
// through boxes widened by kBufferSd standard deviations of the centre it
// predicts one step after a correction (Track::sd_after_hit), at most
// kBufferMax of their sizes on each side, and never so far that it reaches
// another track's box (separate_buffers()). Where the prediction is
// uncertain (a few frames a second, a moving camera) a person moves further
// than a plain IoU gate allows; a track coasting keeps its width, and in a
// group each box stays clear of its neighbours' (docs/tuning.md, "The
// association's buffer").
CT_TUNABLE(kBufferSd, "CTRACK_BUFFER_SD", 4.0);
CT_TUNABLE(kBufferMax, "CTRACK_BUFFER_MAX", 0.5);
// From the pixels alone, a box drawn for someone behind the person a blob
// is (BlobFinder::behind()) meets only tracks within this ratio of its
// height either way: the blob's own person's track, of another height,
// would shrink to it and lose its person (docs/tuning.md, "Someone
// behind").
CT_TUNABLE(kBehindRatio, "CTRACK_BEHIND_RATIO", 0.8);
// A person's own stature (box_fit.h) stands in for the people's size once
// this many fits have read it, and is a running mean over the last
// kStatureSamples (docs/tuning.md, "A person's own stature").
CT_TUNABLE(kStatureMin, "CTRACK_STATURE_MIN", 5);
CT_TUNABLE(kStatureSamples, "CTRACK_STATURE_SAMPLES", 20);
// Whether a detector's boxes are trusted by their scores as the tracker
// learns them (score_noise.h); 0 only in a tuning build's sweeps.
CT_TUNABLE(kScoreNoise, "CTRACK_SCORE_NOISE", 1.0);
// high_score and start_score are read on the scale of a detector whose best
// 40% of boxes (from low_score up) score kScaleRef or more, as the public
// MOTChallenge detections do (0.96 to 0.99). A detector whose best boxes
// score less has both scaled down with them, once kScaleMinBoxes of its
// boxes are known: its scores are on a scale of their own (an SVM's margin
// through a logistic, a confidence spread lower), and on the defaults'
// scale a track would start only from its rare best boxes (docs/tuning.md,
// "The detector's scale for starting tracks").
CT_TUNABLE(kScaleRef, "CTRACK_SCALE_REF", 0.9);
constexpr uint32_t kScaleMinBoxes = 50;

} // namespace

Engine::Engine(const ct_config &cfg)
    : cfg_(cfg), state_(cfg), before_prime_(cfg), saved_(cfg)
{
    ms_params_.coarse_below = (int)(cfg.mean_shift_coarse_below * kQ16);
    min_rho_ = (int)(cfg.mean_shift_min_similarity * kQ16);
}

void Engine::rewind()
{
    EngineState &s = state_;
    s.tracks.clear();
    s.reported.clear();
    s.candidates.clear();
    s.clock.rewound = s.clock.rewound || s.has_time;
    s.has_time = false;
    s.last_us = 0;
    pixels_.clear();
}

void Engine::reset()
{
    rewind();
    state_.clock = SceneClock();
    state_.learnt = SceneModels(cfg_);
    pixels_.reset();
    count_.forget_tracks();
}

void Engine::begin_prime()
{
    pixels_.keep_background();
    try {
        before_prime_ = state_;
    } catch (...) {
        pixels_.drop_kept_background();
        throw;
    }
    priming_ = true;
    rewind();
}

void Engine::end_prime() noexcept
{
    state_.learnt = before_prime_.learnt;
    state_.next_id = before_prime_.next_id;
    rewind();
    count_.forget_tracks();
    before_prime_ = EngineState(cfg_);
    pixels_.drop_kept_background();
    priming_ = false;
}

void Engine::abort_prime() noexcept
{
    std::swap(state_, before_prime_);
    before_prime_ = EngineState(cfg_);
    pixels_.restore_kept_background();
    priming_ = false;
}

void Engine::refine(const Planes &img)
{
    for (Track &t : state_.tracks) {
        if (t.state != CT_TRACK_CONFIRMED || !t.model.valid)
            continue;
        Box b = t.box();
        t.ms = ms_.track(img, t.cx.x, t.cy.x, b.width, b.height, t.model, ms_params_);
        state_.counters.mean_shift_runs++;
        if (t.ms.rho >= min_rho_)
            t.cue = Box{t.ms.cx - b.width / 2, t.ms.cy - b.height / 2, b.width, b.height};
    }
}

void Engine::follow_or_lose(const Planes &img, int64_t t_us)
{
    for (size_t i = 0; i < state_.tracks.size(); i++) {
        Track &t = state_.tracks[i];
        if (t.state != CT_TRACK_CONFIRMED || t.last_update_us == t_us || !t.model.valid ||
            t.ms.iterations == 0 || t.ms.rho < min_rho_)
            continue;
        const bool still = standing(t);
        if (still && pixels_.stirs(t.box()))
            t.stir_us = t_us;
        const double quiet_s = elapsed_s(t_us, still && t.stir_us > t.last_update_us
                                                   ? t.stir_us
                                                   : t.last_update_us);
        if (quiet_s > cfg_.mean_shift_max_time)
            continue;
        // Behind another person the window sees the occluder: coast instead.
        if (occluded(state_.tracks, i))
            continue;
        if (inside_fraction(t.box(), img.width, img.height) < kMinInside)
            continue;
        ms_.scale(img, t.model, ms_params_, &t.ms);
        if (t.ms.rho < min_rho_)
            continue;
        if (silhouettes_ && kFollowForeground > 0) {
            const Box w{t.ms.cx - t.ms.width / 2, t.ms.cy - t.ms.height / 2, t.ms.width,
                        t.ms.height};
            const double share = pixels_.foreground_share(w);
            if (share >= 0 && share < kFollowForeground &&
                !(still && t.from_start(w) <= kStillReach * w.height))
                continue;
        }
        t.follow(cfg_.detection_noise);
    }
}

void Engine::learn_models(const Planes &img)
{
    const int mu = (int)std::lround(cfg_.model_learning_rate * 256);
    for (size_t i = 0; i < state_.tracks.size(); i++) {
        Track &t = state_.tracks[i];
        if (t.state != CT_TRACK_CONFIRMED || t.det_index < 0)
            continue;
        Box b = t.box();
        if (!t.model.valid || t.model.color != img.color) {
            ms_.build(img, t.cx.x, t.cy.x, b.width, b.height, &t.model);
            continue;
        }
        if (mu == 0 || occluded(state_.tracks, i))
            continue;
        ms_.learn(img, t.cx.x, t.cy.x, b.width, b.height, mu, min_rho_, &t.model);
    }
}

bool Engine::standing(const Track &t) const
{
    return kStillHold > 0 && cfg_.source == CT_SOURCE_PIXELS && silhouettes_ && !t.moved &&
           !t.object && t.from_start(t.box()) <= kStillReach * t.box().height &&
           std::hypot(t.cx.v, t.cy.v) <= kStillSpeed * t.h.x;
}

void Engine::update(Track &t, const ct_detection &d, int index, int64_t t_us)
{
    // The scene's motion is learnt from a detector's boxes (the pixels'
    // blobs need a still camera, and jitter on their own), on the tracks
    // that were confirmed before this step: a tentative track's first
    // steps tell little. The reported boxes' filter learns its own, and
    // how its successive innovations correlate.
    const double shown_noise = cfg_.detection_noise * state_.learnt.shown.noise();
    if (t.state == CT_TRACK_CONFIRMED && cfg_.source == CT_SOURCE_DETECTIONS) {
        state_.learnt.motion.observe(t.centre_nis(d, cfg_.detection_noise));
        double nx, ny;
        t.shown.normalized_innovation(d, shown_noise, &nx, &ny);
        state_.learnt.shown.observe(0.5 * (nx * nx + ny * ny));
        if (t.shown_age == t.age - 1)
            state_.learnt.shown.observe_pair(nx, ny, t.shown_nx, t.shown_ny);
        t.shown_nx = nx;
        t.shown_ny = ny;
        t.shown_age = t.age;
        if (by_score_)
            state_.learnt.score_noise.observe(d.score, t.centre_innovation2(d));
    }
    // A detector's box is trusted as much as its score's boxes earned.
    const double f = by_score_ ? state_.learnt.score_noise.factor(d.score) : 1.0;
    ct_detection kept = d;
    if (kStillFragment > 0 && t.state == CT_TRACK_CONFIRMED && d.score < high_ &&
        d.height < kStillFragment * t.h.x && standing(t)) {
        const Box b = t.box();
        kept.top = (float)b.top;
        kept.height = (float)b.height;
    }
    t.correct(kept, cfg_.detection_noise * f, shown_noise * f, index, t_us);
    if (t.state == CT_TRACK_LOST)
        t.state = CT_TRACK_CONFIRMED;
    else if (t.state == CT_TRACK_TENTATIVE && t.hits >= cfg_.min_hits &&
             t.best_score >= confirm_) {
        t.state = CT_TRACK_CONFIRMED;
        t.id = state_.next_id++;
    }
}

void Engine::start_track(const ct_detection &d, int index, int64_t t_us, bool confirm)
{
    Track t;
    t.start(d, cfg_.detection_noise, index, t_us);
    if (confirm || (t.hits >= cfg_.min_hits && d.score >= confirm_)) {
        t.state = CT_TRACK_CONFIRMED;
        t.id = state_.next_id++;
    }
    state_.tracks.push_back(t);
}

double Engine::buffer(const Track &t) const
{
    return std::min(kBufferMax, kBufferSd * t.sd_after_hit / std::max(t.h.x, kMinSide));
}

void Engine::match(Vec<int> &track_idx, Vec<int> &det_idx,
                   const ct_detection *dets, double min_iou, bool buffered)
{
    const int n = (int)track_idx.size(), m = (int)det_idx.size();
    if (n == 0 || m == 0)
        return;
    if (buffered) {
        cues_.resize((size_t)n);
        buffers_.resize((size_t)n);
        for (int i = 0; i < n; i++) {
            const Track &t = state_.tracks[(size_t)track_idx[(size_t)i]];
            cues_[(size_t)i] = t.cue;
            buffers_[(size_t)i] = buffer(t);
        }
        separate_buffers(cues_, buffers_, buffer_order_);
    }
    // Cost: 1 - IoU, plus appearance_weight (1 - DDIS) with appearance. A
    // pair is allowed only when its IoU reaches min_iou, whatever it looks
    // like, or for a tentative track when the detection is within its reach
    // (Gate::overlapping()).
    const double w = appearance_ ? cfg_.appearance_weight : 0.0;
    const double limit = 1.0 - min_iou + w + 1e-12;
    gate_.index(dets, det_idx);
    pairs_.clear();
    for (int i = 0; i < n; i++) {
        const Track &t = state_.tracks[(size_t)track_idx[(size_t)i]];
        const double reach = t.state == CT_TRACK_TENTATIVE
                                 ? kNewTrackReach * t.centre_innovation_sd(cfg_.detection_noise)
                                 : 0;
        gate_.overlapping(i, t.cue, min_iou, pairs_, reach,
                          buffered ? buffers_[(size_t)i] : 0.0);
    }
    if (cfg_.source == CT_SOURCE_PIXELS)
        drop_other_heights(track_idx, det_idx, dets);
    if (w > 0)
        add_appearance(track_idx, det_idx, n, m, w);
    assigner_.solve(n, m, pairs_, limit, row_to_col_);
    for (int i = 0; i < n; i++) {
        const int j = row_to_col_[(size_t)i];
        if (j < 0)
            continue;
        const int d = det_idx[(size_t)j];
        det_used_[(size_t)d] = 1;
        update(state_.tracks[(size_t)track_idx[(size_t)i]], dets[d], d, state_.last_us);
        track_idx[(size_t)i] = -1;
    }
    track_idx.erase(std::remove(track_idx.begin(), track_idx.end(), -1), track_idx.end());
    det_idx.erase(std::remove_if(det_idx.begin(), det_idx.end(),
                                 [this](int d) { return det_used_[(size_t)d] != 0; }),
                  det_idx.end());
}

void Engine::drop_other_heights(const Vec<int> &track_idx, const Vec<int> &det_idx,
                                const ct_detection *dets)
{
    pairs_.erase(std::remove_if(pairs_.begin(), pairs_.end(),
                                [&](const Pair &p) {
                                    const int d = det_idx[(size_t)p.col];
                                    if (!pixels_.behind((size_t)d))
                                        return false;
                                    const Track &t =
                                        state_.tracks[(size_t)track_idx[(size_t)p.row]];
                                    const double r = dets[d].height / t.box().height;
                                    return !(r >= kBehindRatio && r <= 1 / kBehindRatio);
                                }),
                 pairs_.end());
}

void Engine::add_appearance(const Vec<int> &track_idx, const Vec<int> &det_idx, int n, int m,
                            double w)
{
    // A pair alone in its row and its column is matched whatever it looks
    // like: its cost stays under the limit (the IoU gate holds and DDIS >
    // 0), and nothing competes for it. DDIS runs only where pairs compete.
    row_pairs_.assign((size_t)n, 0);
    col_pairs_.assign((size_t)m, 0);
    for (const Pair &p : pairs_) {
        row_pairs_[(size_t)p.row]++;
        col_pairs_[(size_t)p.col]++;
    }
    size_t competing = 0;
    for (const Pair &p : pairs_)
        competing += row_pairs_[(size_t)p.row] > 1 || col_pairs_[(size_t)p.col] > 1;
    // A flood (a detector without non-maximum suppression) makes thousands
    // of competing pairs, each a DDIS of some 30 us: past kMaxDdisPairs the
    // step is associated by overlap alone, as without appearance, so that
    // its work stays bounded.
    if (competing > kMaxDdisPairs)
        return;
    for (Pair &p : pairs_)
        if (row_pairs_[(size_t)p.row] > 1 || col_pairs_[(size_t)p.col] > 1)
            p.cost += w * (1.0 - bank_.similarity(state_.tracks[(size_t)track_idx[(size_t)p.row]],
                                                  det_idx[(size_t)p.col]));
}

void Engine::reidentify(const ct_detection *dets)
{
    pool_tracks_.clear();
    for (size_t i = 0; i < state_.tracks.size(); i++)
        if (state_.tracks[i].state == CT_TRACK_LOST && state_.tracks[i].tmpl >= 0 &&
            state_.tracks[i].last_update_us != state_.last_us)
            pool_tracks_.push_back((int)i);
    const int n = (int)pool_tracks_.size(), m = (int)pool_dets_.size();
    if (n == 0 || m == 0)
        return;
    const double limit = 1.0 - cfg_.reid_min_similarity + 1e-12;
    gate_.index(dets, pool_dets_);
    pairs_.clear();
    for (int i = 0; i < n; i++) {
        const Track &t = state_.tracks[(size_t)pool_tracks_[(size_t)i]];
        const double lost_s = elapsed_s(state_.last_us, t.last_update_us);
        // The size the person had when last seen: the coasted one drifts.
        const double h = std::max<double>(t.seen_h, kMinSide);
        const double reach = h * std::max(1.0, cfg_.reid_max_speed * lost_s);
        gate_.near(i, t.cx.x, t.cy.x, reach, h, pairs_);
    }
    // Bounded like association: a flood that would take more than
    // kMaxDdisPairs DDIS re-identifies nobody this step.
    if (pairs_.size() > kMaxDdisPairs)
        return;
    // Nearness only gates: the cost is how unlike the track each looks, and
    // a pair as unlike as the limit is no pair.
    size_t kept = 0;
    for (size_t k = 0; k < pairs_.size(); k++) {
        Pair p = pairs_[k];
        const Track &t = state_.tracks[(size_t)pool_tracks_[(size_t)p.row]];
        p.cost = 1.0 - bank_.similarity(t, pool_dets_[(size_t)p.col]);
        if (p.cost < limit)
            pairs_[kept++] = p;
    }
    pairs_.resize(kept);
    assigner_.solve(n, m, pairs_, limit, row_to_col_);
    for (int i = 0; i < n; i++) {
        const int j = row_to_col_[(size_t)i];
        if (j < 0)
            continue;
        const int d = pool_dets_[(size_t)j];
        update(state_.tracks[(size_t)pool_tracks_[(size_t)i]], dets[d], d, state_.last_us);
        det_used_[(size_t)d] = 1;
    }
    pool_dets_.erase(std::remove_if(pool_dets_.begin(), pool_dets_.end(),
                                    [this](int d) { return det_used_[(size_t)d] != 0; }),
                     pool_dets_.end());
}

void Engine::learn_sizes(const ct_detection *dets, int64_t t_us, ImageSize image)
{
    // From the confirmed tracks a box updated this step, but boxes touching
    // a known image's edge (they may hold part of a person): the size
    // gate's line (a detector's boxes, whatever their score) and, when the
    // image is known, the people's size (confident boxes, whole blobs).
    const bool gate = size_gate_on();
    if (!gate && !image.known())
        return;
    PersonSize &size = state_.learnt.size;
    if (image.known() && size.image_height() != image.height)
        size.reset(image.height);
    constexpr double kEdge = 2;
    for (const Track &t : state_.tracks) {
        if (t.state != CT_TRACK_CONFIRMED || t.last_update_us != t_us || t.det_index < 0)
            continue;
        const ct_detection &d = dets[t.det_index];
        if (image.known() && (d.left < kEdge || d.top < kEdge ||
                              d.left + d.width > image.width - kEdge ||
                              d.top + d.height > image.height - kEdge))
            continue;
        if (gate)
            state_.learnt.size_gate.observe(d.top, d.height);
        if (!image.known() || d.score < high_ ||
            (cfg_.source == CT_SOURCE_PIXELS && !pixels_.whole((size_t)t.det_index)))
            continue;
        size.observe(d.top, d.height, d.width);
    }
    if (image.known())
        size.learn();
}

void Engine::note_live(int64_t t_us)
{
    for (Track &t : state_.tracks) {
        // A track that moved is never an object: its blob is not read.
        // Stillness counts only over steps where the track had a blob of
        // its own: one carried by mean shift, or lost, may be a person
        // hidden behind another.
        if (t.moved) {
            t.object = false;
            continue;
        }
        if (t.last_update_us != t_us || t.det_index < 0 || pixels_.live((size_t)t.det_index))
            t.live_us = t_us;
        const Box b = t.box();
        t.object = t.state == CT_TRACK_CONFIRMED && t.from_start(b) <= kObjectReach * b.height &&
                   elapsed_s(t_us, t.live_us) >= kObjectAfterS;
    }
}

void Engine::recover(const ct_detection *dets)
{
    for (int i : pool_tracks_)
        state_.tracks[(size_t)i].cue = state_.tracks[(size_t)i].seen;
    match(pool_tracks_, pool_dets_, dets, cfg_.match_iou);
    for (int i : pool_tracks_)
        state_.tracks[(size_t)i].cue = state_.tracks[(size_t)i].box();
}

bool Engine::hidden_in_view(const Track &t, size_t i) const
{
    const double limit = cfg_.report_lost_sd;
    return std::sqrt(t.cx.p00) <= limit * t.w.x && std::sqrt(t.cy.p00) <= limit * t.h.x &&
           occluded(state_.tracks, i);
}

void Engine::step(int64_t t_us, const Planes &img, ImageSize image, const ct_detection *dets,
                  size_t n)
{
    saved_ = state_;
    pixels_.commit(); // the last step's update stands
    try {
        step_unguarded(t_us, img, image, dets, n);
    } catch (...) {
        // Appearance templates need nothing here: TemplateBank::learn()
        // builds in slots that the restored tracks do not point to.
        state_ = saved_;
        pixels_.rollback();
        throw;
    }
}

Engine::StepTime Engine::advance_clock(int64_t t_us)
{
    StepTime time;
    time.first = !state_.has_time;
    time.dt = time.first ? 0.0 : elapsed_s(t_us, state_.last_us);
    state_.last_us = t_us;
    state_.has_time = true;
    // The scene's clock: after rewind(), one frame interval (40 ms when
    // none is known) after its last step, whatever the host's timestamp.
    SceneClock &c = state_.clock;
    if (time.first && c.rewound)
        c.shift_us = (int64_t)((uint64_t)c.last_us +
                               (uint64_t)(c.interval_us > 0 ? c.interval_us : 40000) -
                               (uint64_t)t_us);
    c.rewound = false;
    time.scene_us = (int64_t)((uint64_t)t_us + (uint64_t)c.shift_us);
    if (!time.first)
        c.interval_us = (int64_t)elapsed_us(time.scene_us, c.last_us);
    c.last_us = time.scene_us;
    return time;
}

bool Engine::find_candidates(int64_t scene_us, const Planes &img, const ct_detection **dets,
                             size_t *n)
{
    pixels_.clear();
    if (cfg_.source == CT_SOURCE_PIXELS) {
        pixels_.find(scene_us, img, state_.tracks, cfg_.pedestrian_test,
                     cfg_.candidate_min_score, state_.learnt.size, state_.counters,
                     state_.candidates);
        *dets = pixels_.dets().data();
        *n = pixels_.dets().size();
        return true;
    }
    state_.candidates.clear();
    if (cfg_.verify_detections && !img.empty()) {
        pixels_.verify(scene_us, img, state_.tracks, *dets, *n, state_.learnt.size,
                       state_.counters, state_.candidates);
        *dets = pixels_.dets().data();
        return true;
    }
    // The boxes are fitted to the silhouettes: the background is read.
    if (cfg_.refine_boxes && !img.empty()) {
        pixels_.mask_only(scene_us, img, state_.tracks, state_.learnt.size, state_.counters);
        return true;
    }
    return false;
}

void Engine::sort_detections(double dt, const ct_detection *dets, size_t n)
{
    det_used_.assign(n, 0);
    pool_dets_.clear();
    low_dets_.clear();
    // A detector's boxes far off the height its people have where they
    // stand are ignored (size_gate; the pixels' candidates have their own
    // size test).
    SceneModels &learnt = state_.learnt;
    const bool gate = size_gate_on();
    if (gate)
        learnt.size_gate.age(dt);
    // The pixels' candidates match first and start tracks from
    // candidate_min_score.
    high_ = cfg_.candidate_min_score;
    start_ = 0.0f;
    if (cfg_.source == CT_SOURCE_DETECTIONS) {
        // The detector's scale of scores, learnt from all its boxes, sets
        // the scores that match first and start tracks (kScaleRef)...
        for (size_t j = 0; j < n; j++)
            if (dets[j].score >= cfg_.low_score)
                learnt.box_scores.observe(dets[j].score);
        const double scale =
            learnt.box_scores.count() >= kScaleMinBoxes
                ? std::min(1.0, learnt.box_scores.best() / kScaleRef)
                : 1.0;
        // Never under low_score: a box under it is ignored on any scale.
        high_ = std::max(cfg_.low_score, (float)(cfg_.high_score * scale));
        start_ = std::max(cfg_.low_score, (float)(cfg_.start_score * scale));
        // ... and, learnt from the boxes that may start a track, bounds
        // the score that confirms one (score_scale.h).
        for (size_t j = 0; j < n; j++)
            if (dets[j].score >= start_)
                learnt.scores.observe(dets[j].score);
        confirm_ = learnt.scores.confirm(cfg_.confirm_score);
    }
    for (size_t j = 0; j < n; j++) {
        if (gate && !learnt.size_gate.admits(dets[j]))
            continue;
        if (dets[j].score >= high_)
            pool_dets_.push_back((int)j);
        else if (dets[j].score >= cfg_.low_score)
            low_dets_.push_back((int)j);
    }
}

void Engine::associate(const ct_detection *dets, bool pixels)
{
    const Vec<Track> &tracks = state_.tracks;
    const int64_t t_us = state_.last_us;
    // 1. High-score detections against confirmed and lost tracks (those
    //    lost for longer than lost_lifetime are gone, whatever lies where
    //    they were); without mean shift to follow them, through boxes
    //    widened by the prediction's uncertainty.
    const bool predicted_only = cfg_.source == CT_SOURCE_DETECTIONS && !pixels;
    pool_tracks_.clear();
    for (size_t i = 0; i < tracks.size(); i++)
        if (tracks[i].state != CT_TRACK_TENTATIVE &&
            elapsed_s(t_us, tracks[i].last_update_us) <= cfg_.lost_lifetime)
            pool_tracks_.push_back((int)i);
    match(pool_tracks_, pool_dets_, dets, cfg_.match_iou, predicted_only);
    // 1b. Without mean shift to follow them, the tracks left try again
    //     from where their detection last was: a person who stopped, or a
    //     camera that jerked, leaves the prediction off.
    if (predicted_only)
        recover(dets);

    // 2. Low-score detections continue tracks that were confirmed and not
    //    yet lost: a weak detection near where a person is expected.
    size_t k = 0;
    for (int i : pool_tracks_)
        if (tracks[(size_t)i].state == CT_TRACK_CONFIRMED)
            pool_tracks_[k++] = i;
    pool_tracks_.resize(k);
    match(pool_tracks_, low_dets_, dets, cfg_.low_match_iou);

    // 3. Tentative tracks against the high-score detections left.
    pool_tracks_.clear();
    for (size_t i = 0; i < tracks.size(); i++)
        if (tracks[i].state == CT_TRACK_TENTATIVE)
            pool_tracks_.push_back((int)i);
    match(pool_tracks_, pool_dets_, dets, cfg_.tentative_match_iou);

    // 4. Lost tracks against the high-score detections still left, by
    //    appearance.
    if (appearance_)
        reidentify(dets);
}

void Engine::start_tracks(const ct_detection *dets, int64_t t_us, bool first)
{
    // New tracks from the high-score detections nobody claimed that reach
    // start_score on the detector's scale (a detector's boxes only: the
    // pixels' candidates start at candidate_min_score). A tentative track
    // is confirmed after min_hits once one of its detections reached
    // confirm_score (update()).
    // With a detector's boxes the first step confirms them at once: there
    // is no earlier frame to wait for. Not the pixels' candidates: a
    // background model learns its first frame and finds none there, and
    // one primed on the recording (ct_tracker_prime()) finds fragments and
    // groups as in any frame (docs/tuning.md, "A recording's start").
    const bool confirm_now = first && cfg_.source == CT_SOURCE_DETECTIONS;
    for (int j : pool_dets_) {
        if ((int)state_.tracks.size() >= cfg_.max_tracks)
            break;
        if (dets[j].score >= start_)
            start_track(dets[j], j, t_us, confirm_now);
    }
}

void Engine::step_unguarded(int64_t t_us, const Planes &img, ImageSize image,
                            const ct_detection *dets, size_t n)
{
    const bool pixels = cfg_.mean_shift && !img.empty();
    appearance_ = cfg_.appearance && !img.empty();
    // With frames, the pixels (mean shift, DDIS) decide the crossings, and
    // a detector's boxes are trusted alike (docs/tuning.md, "A detection's
    // noise by its score").
    by_score_ = cfg_.source == CT_SOURCE_DETECTIONS && img.empty() && kScoreNoise > 0;
    const StepTime time = advance_clock(t_us);
    uint64_t *const ns = state_.counters.stage_ns;

    Stopwatch sw;
    const double motion_noise = cfg_.motion_noise * std::sqrt(state_.learnt.motion.scale());
    const double shown_motion_noise =
        cfg_.motion_noise * std::sqrt(state_.learnt.shown.scale());
    for (Track &t : state_.tracks)
        t.predict(time.dt, motion_noise, shown_motion_noise);
    ns[CT_STAGE_PREDICT] += sw.lap();
    if (find_candidates(time.scene_us, img, &dets, &n))
        sw.lap(); // its stages counted themselves
    // Read by the fit and by mean shift's follow (a pass over the mask).
    silhouettes_ = (cfg_.refine_boxes || pixels) && pixels_.silhouettes_clear(time.scene_us);
    fit_boxes_ = cfg_.refine_boxes && silhouettes_;
    if (pixels) {
        refine(img);
        ns[CT_STAGE_MEAN_SHIFT] += sw.lap();
    }
    if (appearance_)
        bank_.begin(img, dets, n, &state_.counters);

    sort_detections(time.dt, dets, n);
    associate(dets, pixels);
    ns[CT_STAGE_ASSOCIATE] += sw.lap();
    if (pixels) {
        follow_or_lose(img, t_us);
        ns[CT_STAGE_MEAN_SHIFT] += sw.lap();
    }

    state_.learnt.motion.learn(time.dt);
    state_.learnt.shown.learn(time.dt, true);
    learn_sizes(dets, t_us, image);
    if (cfg_.source == CT_SOURCE_PIXELS && !img.empty())
        note_live(t_us);
    age_unmatched(t_us, image);
    start_tracks(dets, t_us, time.first);
    ns[CT_STAGE_LIFECYCLE] += sw.lap();
    if (pixels) {
        learn_models(img);
        ns[CT_STAGE_MEAN_SHIFT] += sw.lap();
    }
    if (appearance_) {
        bank_.learn(state_.tracks, saved_.tracks, priming_ ? &before_prime_.tracks : nullptr,
                    t_us);
        ns[CT_STAGE_APPEARANCE] += sw.lap();
    }

    report(t_us, image);
    if (!priming_)
        count_.step(t_us, state_.tracks, state_.reported);
    ns[CT_STAGE_REPORT] += sw.lap();
}

void Engine::age_unmatched(int64_t t_us, ImageSize image)
{
    size_t k = 0;
    for (size_t i = 0; i < state_.tracks.size(); i++) {
        Track &t = state_.tracks[i];
        bool keep = true;
        if (t.last_update_us != t_us && !t.followed) {
            if (t.state == CT_TRACK_TENTATIVE) {
                keep = false;
            } else {
                t.state = CT_TRACK_LOST;
                double since = elapsed_s(t_us, t.last_update_us);
                // A person whose predicted box is more than half outside a
                // known image has left it: the track ends, rather than
                // coast out of sight.
                bool outside = image.known() &&
                               inside_fraction(t.box(), image.width, image.height) < 0.5;
                keep = since <= cfg_.lost_lifetime && !outside;
            }
        }
        if (keep) {
            if (k != i) // a track is some 2 KiB (its colour model): move only the ones that move
                state_.tracks[k] = t;
            k++;
        }
    }
    state_.tracks.resize(k);
}

size_t Engine::memory_bytes() const
{
    const EngineState *const both[] = {&state_, &saved_};
    size_t state = 0;
    for (const EngineState *e : both)
        state += e->tracks.capacity() * sizeof(Track) +
                 e->reported.capacity() * sizeof(ct_track) +
                 e->candidates.capacity() * sizeof(ct_candidate);
    return sizeof(*this) + state + pairs_.capacity() * sizeof(Pair) + gate_.memory_bytes() +
           (row_to_col_.capacity() + pool_tracks_.capacity() + pool_dets_.capacity() +
            low_dets_.capacity() + row_pairs_.capacity() + col_pairs_.capacity() +
            buffer_order_.capacity()) *
               sizeof(int) +
           cues_.capacity() * sizeof(Box) + buffers_.capacity() * sizeof(double) +
           det_used_.capacity() + assigner_.memory_bytes() + ms_.memory_bytes() +
           bank_.memory_bytes() + pixels_.memory_bytes() + count_.memory_bytes();
}

bool Engine::clip_box(ImageSize image, Box *b) const
{
    if (!cfg_.clip_boxes || !image.known())
        return true;
    const double x0 = std::max(0.0, b->left), y0 = std::max(0.0, b->top);
    const double x1 = std::min<double>(image.width, b->left + b->width);
    const double y1 = std::min<double>(image.height, b->top + b->height);
    if (x1 <= x0 || y1 <= y0)
        return false;
    *b = Box{x0, y0, x1 - x0, y1 - y0};
    return true;
}

bool Engine::reported_box(const Track &t, ImageSize image, Box *out) const
{
    // Where the box is fitted to the person's silhouette, the fit starts
    // from the steady estimate and places it; elsewhere the reported
    // boxes' own filter does.
    Box b = fit_boxes_ ? t.box() : t.shown.box();
    if (!clip_box(image, &b))
        return false;
    *out = b;
    return true;
}

void Engine::report(int64_t t_us, ImageSize image)
{
    state_.reported.clear();
    reported_from_.clear();
    for (const Track &t : state_.tracks) {
        if (t.state == CT_TRACK_TENTATIVE)
            continue;
        double since = elapsed_s(t_us, t.last_update_us);
        if (t.state == CT_TRACK_LOST && since > cfg_.report_lost_time)
            continue;
        if (t.state == CT_TRACK_LOST && cfg_.report_lost_sd > 0 &&
            !hidden_in_view(t, (size_t)(&t - state_.tracks.data())))
            continue;
        Box b;
        if (!reported_box(t, image, &b))
            continue;
        ct_track o = {};
        o.id = t.id;
        o.left = (float)b.left;
        o.top = (float)b.top;
        o.width = (float)b.width;
        o.height = (float)b.height;
        o.velocity_x = (float)t.cx.v;
        o.velocity_y = (float)t.cy.v;
        double conf = std::min(1.0, std::max(0.0, (double)t.score));
        if (t.followed)
            conf = (double)t.ms.rho / kQ16;
        else if (t.state == CT_TRACK_LOST && cfg_.lost_lifetime > 0)
            conf *= std::max(0.0, 1.0 - since / cfg_.lost_lifetime);
        o.confidence = (float)conf;
        o.state = t.state;
        o.age = t.age;
        o.hits = t.hits;
        o.time_since_update = since;
        o.detection_index = t.det_index;
        o.class_id = t.class_id;
        state_.reported.push_back(o);
        reported_from_.push_back((size_t)(&t - state_.tracks.data()));
    }
    if (fit_boxes_)
        fit_reported(image);
    for (ct_track &o : state_.reported)
        pixels_.barycenter(Box{o.left, o.top, o.width, o.height}, &o.barycenter_x,
                           &o.barycenter_y);
    std::sort(state_.reported.begin(), state_.reported.end(),
              [](const ct_track &a, const ct_track &b) { return a.id < b.id; });
}

void Engine::fit_reported(ImageSize image)
{
    // Where another track covers more than this of a box, its silhouette
    // is its own only below the other box, and only if it is in front.
    constexpr double kMaxCovered = 1.0 / 6;
    Vec<ct_track> &rows = state_.reported;
    // A detector's boxes are often looser or taller than a person; the
    // pixels' own are the blobs' extents already.
    const bool detector = cfg_.source == CT_SOURCE_DETECTIONS;
    auto box_of = [](const ct_track &o) { return Box{o.left, o.top, o.width, o.height}; };
    // A detector's box changed without its silhouette (to the learnt
    // mean, or cut to one person) is fitted again from there. Still too
    // faint to fit, it is placed from its person's head where their own
    // stature is known (docs/tuning.md, "A box too faint to fit"), and
    // stays as changed elsewhere.
    auto refit = [&](Box *x, Stature *stature) {
        Box again;
        if (pixels_.fit(*x, state_.learnt.size, true, &again, stature) ||
            pixels_.fit_faint(*x, state_.learnt.size, stature->known, &again))
            *x = again;
    };
    // Each box is fitted against the others as they were before the fit:
    // the fitted ones are written once all are known.
    fitted_.resize(rows.size());
    for (size_t i = 0; i < rows.size(); i++) {
        const Box b = box_of(rows[i]);
        // The person's own stature, once a few fits have read it.
        Track &track = state_.tracks[reported_from_[i]];
        Stature stature;
        if (track.stature_n >= kStatureMin)
            stature.known = track.stature;
        const ct_track *cover = nullptr;
        for (size_t j = 0; j < rows.size() && !cover; j++) {
            if (j == i)
                continue;
            const Box o = box_of(rows[j]);
            const double ix = std::min(b.left + b.width, o.left + o.width) -
                              std::max(b.left, o.left);
            const double iy = std::min(b.top + b.height, o.top + o.height) -
                              std::max(b.top, o.top);
            if (ix > 0 && iy > 0 && ix * iy > kMaxCovered * b.width * b.height)
                cover = &rows[j];
        }
        if (cover) {
            // Only the legs of a detector's person in front are theirs
            // alone to read, and the head of one behind (docs/tuning.md,
            // "The person behind"). A blob's box is its extent already,
            // and moved by them it tracks groups worse (docs/tuning.md,
            // "The person in front").
            const double cover_bottom = (double)cover->top + cover->height;
            Box x;
            if (detector &&
                (pixels_.fit_in_front(b, cover_bottom, state_.learnt.size, &x) ||
                 pixels_.fit_behind(b, cover->top, cover_bottom, state_.learnt.size,
                                    stature.known, &x)) &&
                clip_box(image, &x))
                fitted_[i] = x;
            else
                fitted_[i] = b;
            continue;
        }
        if (pixels_.fit(b, state_.learnt.size, detector, &fitted_[i], &stature)) {
            // Learnt as fitted, before any clipping at the image's edge.
            if (detector)
                state_.learnt.fit_bias.learn(b, fitted_[i]);
            if (stature.seen > 0) {
                track.stature_n++;
                track.stature += (stature.seen - track.stature) /
                                 std::min(track.stature_n, (int)kStatureSamples);
            }
        } else if (detector) {
            // No silhouette to read: a detector's box takes what the fit
            // does to its boxes on average. A box too loose for the fit
            // (its person under 30% of it) is read again at that size,
            // where the person fills it as they fill the detector's usual
            // box; not learnt from, since it starts from what was learnt.
            fitted_[i] = state_.learnt.fit_bias.apply(b);
            if (state_.learnt.fit_bias.known())
                refit(&fitted_[i], &stature);
        } else {
            fitted_[i] = b;
        }
        // A box cut to the one person whose feet are its bottom is that
        // person's: the fit before the cut read the joined extent and
        // moved it neither up nor down.
        if (detector && cut_to_one_person(state_.learnt.size, &fitted_[i]))
            refit(&fitted_[i], &stature);
        if (!clip_box(image, &fitted_[i]))
            fitted_[i] = b;
    }
    for (size_t i = 0; i < rows.size(); i++) {
        rows[i].left = (float)fitted_[i].left;
        rows[i].top = (float)fitted_[i].top;
        rows[i].width = (float)fitted_[i].width;
        rows[i].height = (float)fitted_[i].height;
    }
}

} // namespace ctrack
