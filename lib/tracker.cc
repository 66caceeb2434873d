#include "tracker.h"

#include <algorithm>
#include <cmath>

#include "clock.h"

namespace ctrack {

namespace {

// A walking person covers about one body height per second: the prior
// uncertainty of a new track's velocity, in box heights per second.
constexpr double kInitialSpeedSd = 1.0;
// Box sizes change more slowly than positions: their acceleration noise is
// this fraction of the centre's.
constexpr double kSizeNoiseRatio = 0.5;
constexpr double kMinSide = 1.0;
// A position from mean shift is trusted this many times less than a
// detection's.
constexpr double kFollowNoiseRatio = 2.0;
constexpr double kFollowSizeNoiseRatio = 4.0;
// A track is occluded when another covers this much of its box: it is then
// not followed by mean shift, and its colour model and appearance template
// are left as they are.
constexpr double kOccludedFraction = 0.2;
// Mean shift follows a track only while this much of its box is in the image.
constexpr double kMinInside = 0.9;
// A track's appearance template is remade from its detection at most this
// often (seconds), when nothing occludes it.
constexpr double kTemplateRefresh = 0.5;

} // namespace

double iou(const Box &a, const Box &b)
{
    double x0 = std::max(a.left, b.left), y0 = std::max(a.top, b.top);
    double x1 = std::min(a.left + a.width, b.left + b.width);
    double y1 = std::min(a.top + a.height, b.top + b.height);
    if (x1 <= x0 || y1 <= y0)
        return 0;
    double inter = (x1 - x0) * (y1 - y0);
    double uni = a.width * a.height + b.width * b.height - inter;
    return uni > 0 ? inter / uni : 0;
}

// The part of a box that lies in the image.
static double inside_fraction(const Box &b, const Planes &img)
{
    double iw = std::min<double>(img.width, b.left + b.width) - std::max(0.0, b.left);
    double ih = std::min<double>(img.height, b.top + b.height) - std::max(0.0, b.top);
    return iw > 0 && ih > 0 ? iw * ih / (b.width * b.height) : 0;
}

static Box det_box(const ct_detection &d)
{
    return Box{d.left, d.top, d.width, d.height};
}

Box Track::box() const
{
    double bw = std::max(w.x, kMinSide), bh = std::max(h.x, kMinSide);
    return Box{cx.x - bw / 2, cy.x - bh / 2, bw, bh};
}


Engine::Engine(const ct_config &cfg) : cfg_(cfg)
{
    ms_params_.coarse_below = (int)(cfg.mean_shift_coarse_below * kQ16);
    min_rho_ = (int)(cfg.mean_shift_min_similarity * kQ16);
}

void Engine::reset()
{
    background_.reset();
    candidates_.clear();
    tracks_.clear();
    reported_.clear();
    has_time_ = false;
    last_us_ = 0;
}

void Engine::predict(double dt)
{
    for (Track &t : tracks_) {
        double hgt = std::max(t.h.x, kMinSide);
        double accel = cfg_.motion_noise * hgt;
        t.cx.predict(dt, accel);
        t.cy.predict(dt, accel);
        t.w.predict(dt, accel * kSizeNoiseRatio);
        t.h.predict(dt, accel * kSizeNoiseRatio);
        t.age++;
        t.det_index = -1;
        t.followed = false;
        t.ms = MeanShiftResult();
        t.cue = t.box();
    }
}

// Mean shift from each confirmed track's prediction: where the pixels say
// the person is, before the detections are compared.
void Engine::refine(const Planes &img)
{
    for (size_t i = 0; i < tracks_.size(); i++) {
        Track &t = tracks_[i];
        if (t.state != CT_TRACK_CONFIRMED || !t.model.valid)
            continue;
        Box b = t.box();
        t.ms = ms_.track(img, t.cx.x, t.cy.x, b.width, b.height, t.model, ms_params_);
        ms_runs_++;
        if (t.ms.rho >= min_rho_)
            t.cue = Box{t.ms.cx - b.width / 2, t.ms.cy - b.height / 2, b.width, b.height};
    }
}

// A confirmed track that no detection claimed is carried by mean shift while
// the pixels hold it; otherwise it will be lost.
void Engine::follow_or_lose(const Planes &img, int64_t t_us)
{
    for (size_t i = 0; i < tracks_.size(); i++) {
        Track &t = tracks_[i];
        if (t.state != CT_TRACK_CONFIRMED || t.last_update_us == t_us || !t.model.valid ||
            t.ms.iterations == 0 || t.ms.rho < min_rho_)
            continue;
        if (elapsed_s(t_us, t.last_update_us) > cfg_.mean_shift_max_time)
            continue;
        // Behind another person the window sees the occluder: coast instead.
        if (occluded(i))
            continue;
        // Leaving the image: the detector stops seeing a person cut by the
        // border, and the part left in the window does not hold them.
        if (inside_fraction(t.box(), img) < kMinInside)
            continue;
        ms_.scale(img, t.model, ms_params_, &t.ms);
        if (t.ms.rho < min_rho_)
            continue;
        double sd = kFollowNoiseRatio * cfg_.detection_noise * std::max(t.h.x, kMinSide);
        t.cx.update(t.ms.cx, sd);
        t.cy.update(t.ms.cy, sd);
        // The scale mean shift found moves the size only slowly (Comaniciu's
        // blend of the new and old size): small windows drift to a part of
        // the person, and their similarity stays high.
        t.w.update(t.ms.width, sd * kFollowSizeNoiseRatio);
        t.h.update(t.ms.height, sd * kFollowSizeNoiseRatio);
        // Without detections nothing measures how the size changes: hold
        // it, rather than let a trend shrink the box to a part of the person.
        t.w.v = 0;
        t.h.v = 0;
        t.followed = true;
    }
}

bool Engine::occluded(size_t i) const
{
    const Box a = tracks_[i].box();
    const double area = a.width * a.height;
    for (size_t j = 0; j < tracks_.size(); j++) {
        if (j == i || tracks_[j].state == CT_TRACK_TENTATIVE)
            continue;
        const Box b = tracks_[j].box();
        double iw = std::min(a.left + a.width, b.left + b.width) - std::max(a.left, b.left);
        double ih = std::min(a.top + a.height, b.top + b.height) - std::max(a.top, b.top);
        if (iw > 0 && ih > 0 && iw * ih > kOccludedFraction * area)
            return true;
    }
    return false;
}

// Colour models: made when a track is confirmed, then learnt (eq. 9) from
// the boxes that detections confirm, unless another track overlaps the box
// or the box no longer looks like the model.
void Engine::learn_models(const Planes &img)
{
    const int mu = (int)std::lround(cfg_.model_learning_rate * 256);
    for (size_t i = 0; i < tracks_.size(); i++) {
        Track &t = tracks_[i];
        if (t.state != CT_TRACK_CONFIRMED || t.det_index < 0)
            continue;
        Box b = t.box();
        if (!t.model.valid || t.model.color != img.color) {
            ms_.build(img, t.cx.x, t.cy.x, b.width, b.height, &t.model);
            continue;
        }
        if (mu == 0 || occluded(i))
            continue;
        ms_.learn(img, t.cx.x, t.cy.x, b.width, b.height, mu, min_rho_, &t.model);
    }
}

void Engine::update(Track &t, const ct_detection &d, int index, int64_t t_us)
{
    double sd = cfg_.detection_noise * std::max<double>(d.height, kMinSide);
    t.cx.update(d.left + d.width / 2.0, sd);
    t.cy.update(d.top + d.height / 2.0, sd);
    t.w.update(d.width, sd);
    t.h.update(d.height, sd);
    t.hits++;
    t.last_update_us = t_us;
    t.seen_h = d.height;
    if (std::hypot(d.left + d.width / 2.0 - t.start_x, d.top + d.height / 2.0 - t.start_y) >
        0.5 * d.height)
        t.moved = true;
    t.det_index = index;
    t.class_id = d.class_id;
    t.score = d.score;
    if (t.state == CT_TRACK_LOST)
        t.state = CT_TRACK_CONFIRMED;
    else if (t.state == CT_TRACK_TENTATIVE && t.hits >= cfg_.min_hits) {
        t.state = CT_TRACK_CONFIRMED;
        t.id = next_id_++;
    }
}

void Engine::start_track(const ct_detection &d, int index, int64_t t_us, bool confirm)
{
    Track t;
    double sd = cfg_.detection_noise * std::max<double>(d.height, kMinSide);
    double vsd = kInitialSpeedSd * std::max<double>(d.height, kMinSide);
    t.cx.init(d.left + d.width / 2.0, sd, vsd);
    t.cy.init(d.top + d.height / 2.0, sd, vsd);
    t.w.init(d.width, sd, vsd * kSizeNoiseRatio);
    t.h.init(d.height, sd, vsd * kSizeNoiseRatio);
    t.age = 1;
    t.hits = 1;
    t.last_update_us = t_us;
    t.seen_h = d.height;
    t.start_x = d.left + d.width / 2.0;
    t.start_y = d.top + d.height / 2.0;
    t.det_index = index;
    t.class_id = d.class_id;
    t.score = d.score;
    if (confirm || t.hits >= cfg_.min_hits) {
        t.state = CT_TRACK_CONFIRMED;
        t.id = next_id_++;
    }
    tracks_.push_back(t);
}

// Matches tracks_[track_idx] to dets[det_idx] by IoU with the gate min_iou,
// updates the matched tracks, and leaves only the unmatched in both lists.
void Engine::match(std::vector<int> &track_idx, std::vector<int> &det_idx,
                   const ct_detection *dets, double min_iou)
{
    const int n = (int)track_idx.size(), m = (int)det_idx.size();
    if (n == 0 || m == 0)
        return;
    // Cost: 1 - IoU, plus appearance_weight (1 - DDIS) with appearance. A
    // pair is allowed only when its IoU reaches min_iou (the tiny slack lets
    // an IoU exactly at the gate through), whatever it looks like.
    const double w = appearance_ ? cfg_.appearance_weight : 0.0;
    const double limit = 1.0 - min_iou + w + 1e-12;
    cost_.resize((size_t)n * m);
    for (int i = 0; i < n; i++) {
        const Track &t = tracks_[track_idx[i]];
        for (int j = 0; j < m; j++) {
            double o = iou(t.cue, det_box(dets[det_idx[j]]));
            double c = 1.0 - o;
            if (o + 1e-12 < min_iou)
                c = limit; // not allowed
            else if (w > 0)
                c += w * (1.0 - similarity(t, det_idx[j]));
            cost_[(size_t)i * m + j] = c;
        }
    }
    assigner_.solve(cost_.data(), n, m, limit, row_to_col_);
    for (int i = 0; i < n; i++) {
        int j = row_to_col_[i];
        if (j < 0)
            continue;
        det_used_[det_idx[j]] = 1;
        update(tracks_[track_idx[i]], dets[det_idx[j]], det_idx[j], last_us_);
        track_idx[i] = -1;
    }
    track_idx.erase(std::remove(track_idx.begin(), track_idx.end(), -1), track_idx.end());
    det_idx.erase(std::remove_if(det_idx.begin(), det_idx.end(),
                                 [this](int d) { return det_used_[d] != 0; }),
                  det_idx.end());
}

// Each detection's descriptors (what DDIS compares), once a step.
void Engine::describe_detections(const Planes &img, const ct_detection *dets, size_t n)
{
    const size_t per = (size_t)kPoints * kDescDim;
    det_desc_.resize(n * per);
    for (size_t j = 0; j < n; j++)
        if (dets[j].score >= cfg_.low_score)
            describe(img, dets[j].left, dets[j].top, dets[j].width, dets[j].height,
                     &det_desc_[j * per]);
}

// DDIS of detection det against the track's template; a track without one
// looks like anything (1).
double Engine::similarity(const Track &t, int det)
{
    if (t.tmpl < 0)
        return 1.0;
    ddis_runs_++;
    return ddis_.ddis(templates_[t.tmpl], &det_desc_[(size_t)det * kPoints * kDescDim]);
}

// Lost tracks take back high-score detections that nobody claimed and that
// look like them (DDIS), near where they were heading: a person who
// reappears after an occlusion keeps their id.
void Engine::reidentify(const ct_detection *dets)
{
    pool_tracks_.clear();
    for (size_t i = 0; i < tracks_.size(); i++)
        if (tracks_[i].state == CT_TRACK_LOST && tracks_[i].tmpl >= 0 &&
            tracks_[i].last_update_us != last_us_)
            pool_tracks_.push_back((int)i);
    const int n = (int)pool_tracks_.size(), m = (int)pool_dets_.size();
    if (n == 0 || m == 0)
        return;
    const double limit = 1.0 - cfg_.reid_min_similarity + 1e-12;
    cost_.resize((size_t)n * m);
    for (int i = 0; i < n; i++) {
        const Track &t = tracks_[pool_tracks_[i]];
        const double lost_s = elapsed_s(last_us_, t.last_update_us);
        // The size the person had when last seen: the coasted one drifts.
        const double h = std::max<double>(t.seen_h, kMinSide);
        const double reach = h * std::max(1.0, cfg_.reid_max_speed * lost_s);
        for (int j = 0; j < m; j++) {
            const ct_detection &d = dets[pool_dets_[j]];
            double dx = d.left + d.width / 2 - t.cx.x, dy = d.top + d.height / 2 - t.cy.x;
            double ratio = d.height / h;
            bool plausible = std::hypot(dx, dy) <= reach && ratio > 0.67 && ratio < 1.5;
            cost_[(size_t)i * m + j] = plausible ? 1.0 - similarity(t, pool_dets_[j]) : limit;
        }
    }
    assigner_.solve(cost_.data(), n, m, limit, row_to_col_);
    for (int i = 0; i < n; i++) {
        int j = row_to_col_[i];
        if (j < 0)
            continue;
        update(tracks_[pool_tracks_[i]], dets[pool_dets_[j]], pool_dets_[j], last_us_);
        det_used_[pool_dets_[j]] = 1;
    }
    pool_dets_.erase(std::remove_if(pool_dets_.begin(), pool_dets_.end(),
                                    [this](int d) { return det_used_[d] != 0; }),
                     pool_dets_.end());
}

// Templates: made when a track is confirmed, remade from its detection at
// most every kTemplateRefresh seconds while nothing occludes it. Slots of
// removed tracks are reused. A template is built in a slot that no track
// points to, before or in this step, and only then does the track take it:
// if the step fails on the way, the tracks restored point to their old
// templates, untouched.
void Engine::learn_templates(int64_t t_us)
{
    slot_used_.assign(templates_.size(), 0);
    for (const std::vector<Track> *v : {&tracks_, &saved_tracks_})
        for (const Track &t : *v)
            if (t.tmpl >= 0)
                slot_used_[t.tmpl] = 1;
    size_t slot = 0;
    for (size_t i = 0; i < tracks_.size(); i++) {
        Track &t = tracks_[i];
        if (t.state != CT_TRACK_CONFIRMED || t.det_index < 0 || t.last_update_us != t_us)
            continue;
        if (t.tmpl >= 0 && (elapsed_s(t_us, t.tmpl_us) < kTemplateRefresh || occluded(i)))
            continue;
        while (slot < slot_used_.size() && slot_used_[slot])
            slot++;
        if (slot == templates_.size()) {
            templates_.emplace_back();
            slot_used_.push_back(0);
        }
        templates_[slot].build(&det_desc_[(size_t)t.det_index * kPoints * kDescDim]);
        slot_used_[slot] = 1;
        t.tmpl = (int)slot;
        t.tmpl_us = t_us;
        template_builds_++;
    }
}

// Model edges over frame edges above which a blob is a ghost. On the
// labelled blobs (docs/recognition.md) people's blobs are under 1 but for
// 0.5%; blobs on no one are above 1.5 for 10% (PETS09-S2L1) to 43%
// (TUD-Campus). Pixels only, 2 against none: MOTA 51.9 -> 52.4 on
// PETS09-S2L1, 17.5 -> 24.2 on TUD-Campus (1.0 absorbed people: 10.0).
constexpr double kGhostEdges = 2.0;

static Rect to_working(const Box &b)
{
    const int s = Background::kScale;
    return Rect{(int)std::floor(b.left / s), (int)std::floor(b.top / s),
                (int)std::ceil((b.left + b.width) / s), (int)std::ceil((b.top + b.height) / s)};
}

void Engine::update_background(const Planes &img)
{
    frozen_.clear();
    predicted_.clear();
    for (const Track &t : tracks_) {
        if (t.state == CT_TRACK_TENTATIVE)
            continue;
        predicted_.push_back(to_working(t.box()));
        // Where a confirmed track stands, the background learns nothing: a
        // person who stops stays foreground. Only tracks that have moved:
        // a track that never did may stand on a ghost of the model, which
        // freezing would keep forever (MOTA 47 -> 39 on PETS09-S2L1).
        if (t.state == CT_TRACK_CONFIRMED && t.moved)
            frozen_.push_back(predicted_.back());
    }
    background_.apply(last_us_, img, frozen_.data(), (int)frozen_.size());
}

ct_candidate Engine::vote_on(Rect r, float left, float top, float width, float height)
{
    r.x0 = std::max(r.x0, 0);
    r.y0 = std::max(r.y0, 0);
    r.x1 = std::min(r.x1, background_.width());
    r.y1 = std::min(r.y1, background_.height());
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
    const Vote v = blobs_.classify(r);
    c.score = v.score;
    c.votes_yes = v.yes;
    c.voters = v.voters;
    for (int g = 0; g < kRegions; g++)
        c.region_distance[g] = v.distance[g];
    c.fill = v.fill;
    c.top_width = v.top;
    return c;
}

void Engine::find_candidates(const Planes &img)
{
    Stopwatch sw;
    update_background(img);
    stage_ns_[CT_STAGE_BACKGROUND] += sw.lap();
    blobs_.find(background_.mask(), background_.width(), background_.height(), predicted_.data(),
                (int)predicted_.size(), blob_rects_);
    have_mask_ = true;
    stage_ns_[CT_STAGE_BLOBS] += sw.lap();
    cand_dets_.clear();
    candidates_.clear();
    const int s = Background::kScale;
    for (const Rect &r : blob_rects_) {
        // A ghost (what has left, still in the model: people of the first
        // frames, a car that drove off): the model's edges along the blob's
        // outline are more than kGhostEdges times the frame's. It is learnt
        // at once and is no candidate.
        long frame_edges, model_edges;
        background_.outline_edges(img, blobs_.cleaned(), r, &frame_edges, &model_edges);
        if (model_edges > kGhostEdges * frame_edges) {
            background_.absorb(img, blobs_.cleaned(), r);
            continue;
        }
        const ct_candidate c = vote_on(r, (float)(r.x0 * s), (float)(r.y0 * s),
                                       (float)((r.x1 - r.x0) * s), (float)((r.y1 - r.y0) * s));
        candidates_.push_back(c);
        cand_dets_.push_back(ct_detection{c.left, c.top, c.width, c.height, c.score, 0});
    }
    stage_ns_[CT_STAGE_CLASSIFY] += sw.lap();
}

void Engine::verify_detections(const Planes &img, const ct_detection *dets, size_t n)
{
    Stopwatch sw;
    update_background(img);
    stage_ns_[CT_STAGE_BACKGROUND] += sw.lap();
    blobs_.clean(background_.mask(), background_.width(), background_.height());
    have_mask_ = true;
    stage_ns_[CT_STAGE_BLOBS] += sw.lap();
    cand_dets_.clear();
    candidates_.clear();
    for (size_t j = 0; j < n; j++) {
        const ct_detection &d = dets[j];
        const ct_candidate c = vote_on(to_working(Box{d.left, d.top, d.width, d.height}), d.left,
                                       d.top, d.width, d.height);
        candidates_.push_back(c);
        ct_detection v = d;
        // Rejected: enough regions voted, and no majority said pedestrian,
        // or the foreground fills its convex hull or has no head on top
        // (score at most 0.5).
        if (c.voters >= kMinVoters && c.score <= 0.5f)
            v.score *= c.score;
        cand_dets_.push_back(v);
    }
    stage_ns_[CT_STAGE_CLASSIFY] += sw.lap();
}

void Engine::barycenter(const Box &b, float *x, float *y) const
{
    *x = (float)(b.left + b.width / 2);
    *y = (float)(b.top + b.height / 2);
    if (!have_mask_)
        return;
    const int s = Background::kScale, w = background_.width(), h = background_.height();
    const Rect r = to_working(b);
    const uint8_t *m = blobs_.cleaned();
    long sx = 0, sy = 0, n = 0;
    for (int yy = std::max(0, r.y0); yy < std::min(h, r.y1); yy++)
        for (int xx = std::max(0, r.x0); xx < std::min(w, r.x1); xx++)
            if (m[(size_t)yy * w + xx]) {
                sx += xx;
                sy += yy;
                n++;
            }
    if (n > 0) {
        *x = (float)((sx / (double)n + 0.5) * s);
        *y = (float)((sy / (double)n + 0.5) * s);
    }
}

void Engine::step(int64_t t_us, const Planes &img, ImageSize image, const ct_detection *dets,
                  size_t n)
{
    saved_tracks_ = tracks_;
    saved_reported_ = reported_;
    saved_candidates_ = candidates_;
    const uint64_t next_id = next_id_;
    const int64_t last_us = last_us_;
    const bool has_time = has_time_;
    const uint64_t runs[3] = {ms_runs_, ddis_runs_, template_builds_};
    uint64_t stage_ns[CT_STATS_MAX_STAGES];
    std::copy(stage_ns_, stage_ns_ + CT_STATS_MAX_STAGES, stage_ns);
    background_.commit(); // the last step's update stands
    try {
        step_unguarded(t_us, img, image, dets, n);
    } catch (...) {
        // Appearance templates need nothing here: learn_templates() builds
        // in slots that the restored tracks do not point to.
        tracks_ = saved_tracks_;
        reported_ = saved_reported_;
        candidates_ = saved_candidates_;
        background_.rollback();
        next_id_ = next_id;
        last_us_ = last_us;
        has_time_ = has_time;
        ms_runs_ = runs[0];
        ddis_runs_ = runs[1];
        template_builds_ = runs[2];
        std::copy(stage_ns, stage_ns + CT_STATS_MAX_STAGES, stage_ns_);
        throw;
    }
}

void Engine::step_unguarded(int64_t t_us, const Planes &img, ImageSize image,
                            const ct_detection *dets, size_t n)
{
    const bool pixels = cfg_.mean_shift && !img.empty();
    appearance_ = cfg_.appearance && !img.empty();
    const bool first = !has_time_;
    const double dt = first ? 0.0 : elapsed_s(t_us, last_us_);
    last_us_ = t_us;
    has_time_ = true;

    Stopwatch sw;
    predict(dt);
    stage_ns_[CT_STAGE_PREDICT] += sw.lap();
    have_mask_ = false;
    candidates_.clear();
    if (cfg_.source == CT_SOURCE_PIXELS) {
        cand_dets_.clear();
        if (!img.empty())
            find_candidates(img);
        dets = cand_dets_.data();
        n = cand_dets_.size();
        sw.lap();
    } else if (cfg_.verify_detections && !img.empty()) {
        verify_detections(img, dets, n);
        dets = cand_dets_.data();
        sw.lap();
    }
    if (pixels) {
        refine(img);
        stage_ns_[CT_STAGE_MEAN_SHIFT] += sw.lap();
    }
    if (appearance_) {
        describe_detections(img, dets, n);
        stage_ns_[CT_STAGE_APPEARANCE] += sw.lap();
    }

    det_used_.assign(n, 0);
    pool_dets_.clear();
    low_dets_.clear();
    const float high =
        cfg_.source == CT_SOURCE_PIXELS ? cfg_.candidate_min_score : cfg_.high_score;
    for (size_t j = 0; j < n; j++) {
        if (dets[j].score >= high)
            pool_dets_.push_back((int)j);
        else if (dets[j].score >= cfg_.low_score)
            low_dets_.push_back((int)j);
    }

    // 1. High-score detections against confirmed and lost tracks.
    pool_tracks_.clear();
    for (size_t i = 0; i < tracks_.size(); i++)
        if (tracks_[i].state != CT_TRACK_TENTATIVE)
            pool_tracks_.push_back((int)i);
    match(pool_tracks_, pool_dets_, dets, cfg_.match_iou);

    // 2. Low-score detections continue tracks that were confirmed and not
    //    yet lost: a weak detection near where a person is expected.
    {
        size_t k = 0;
        for (int i : pool_tracks_)
            if (tracks_[i].state == CT_TRACK_CONFIRMED)
                pool_tracks_[k++] = i;
        pool_tracks_.resize(k);
    }
    match(pool_tracks_, low_dets_, dets, cfg_.low_match_iou);

    // 3. Tentative tracks against the high-score detections left.
    pool_tracks_.clear();
    for (size_t i = 0; i < tracks_.size(); i++)
        if (tracks_[i].state == CT_TRACK_TENTATIVE)
            pool_tracks_.push_back((int)i);
    match(pool_tracks_, pool_dets_, dets, cfg_.tentative_match_iou);

    // 4. Lost tracks against the high-score detections still left, by
    //    appearance.
    if (appearance_)
        reidentify(dets);
    stage_ns_[CT_STAGE_ASSOCIATE] += sw.lap();
    if (pixels) {
        follow_or_lose(img, t_us);
        stage_ns_[CT_STAGE_MEAN_SHIFT] += sw.lap();
    }

    // Lifecycle of the tracks no detection updated.
    size_t k = 0;
    for (size_t i = 0; i < tracks_.size(); i++) {
        Track &t = tracks_[i];
        bool keep = true;
        if (t.last_update_us != t_us && !t.followed) {
            if (t.state == CT_TRACK_TENTATIVE) {
                keep = false;
            } else {
                t.state = CT_TRACK_LOST;
                double since = elapsed_s(t_us, t.last_update_us);
                Box b = t.box();
                bool outside = image.known() &&
                    (b.left >= image.width || b.top >= image.height ||
                     b.left + b.width <= 0 || b.top + b.height <= 0);
                keep = since <= cfg_.lost_lifetime && !outside;
            }
        }
        if (keep) {
            if (k != i) // a track is some 2 KiB (its colour model): move only the ones that move
                tracks_[k] = t;
            k++;
        }
    }
    tracks_.resize(k);

    // New tracks from the high-score detections nobody claimed. The first
    // step confirms them at once: there is no earlier frame to wait for.
    for (int j : pool_dets_) {
        if ((int)tracks_.size() >= cfg_.max_tracks)
            break;
        start_track(dets[j], j, t_us, first);
    }
    stage_ns_[CT_STAGE_LIFECYCLE] += sw.lap();
    if (pixels) {
        learn_models(img);
        stage_ns_[CT_STAGE_MEAN_SHIFT] += sw.lap();
    }
    if (appearance_) {
        learn_templates(t_us);
        stage_ns_[CT_STAGE_APPEARANCE] += sw.lap();
    }

    report(t_us, image);
    stage_ns_[CT_STAGE_REPORT] += sw.lap();
}

size_t Engine::templates_memory() const
{
    size_t b = templates_.capacity() * sizeof(Template);
    for (const Template &tp : templates_)
        b += tp.desc.capacity() * sizeof(float) + tp.index.memory_bytes();
    return b;
}

size_t Engine::memory_bytes() const
{
    return sizeof(*this) + tracks_.capacity() * sizeof(Track) +
           saved_tracks_.capacity() * sizeof(Track) +
           (reported_.capacity() + saved_reported_.capacity()) * sizeof(ct_track) +
           cost_.capacity() * sizeof(double) +
           (row_to_col_.capacity() + pool_tracks_.capacity() + pool_dets_.capacity() +
            low_dets_.capacity()) * sizeof(int) +
           det_used_.capacity() + assigner_.memory_bytes() + ms_.memory_bytes() +
           det_desc_.capacity() * sizeof(float) + slot_used_.capacity() + templates_memory() +
           background_.memory_bytes() + blobs_.memory_bytes() +
           (frozen_.capacity() + predicted_.capacity() + blob_rects_.capacity()) * sizeof(Rect) +
           cand_dets_.capacity() * sizeof(ct_detection) +
           (candidates_.capacity() + saved_candidates_.capacity()) * sizeof(ct_candidate);
}

void Engine::report(int64_t t_us, ImageSize image)
{
    reported_.clear();
    for (const Track &t : tracks_) {
        if (t.state == CT_TRACK_TENTATIVE)
            continue;
        double since = elapsed_s(t_us, t.last_update_us);
        if (t.state == CT_TRACK_LOST && since > cfg_.report_lost_time)
            continue;
        Box b = t.box();
        if (cfg_.clip_boxes && image.known()) {
            double x0 = std::max(0.0, b.left), y0 = std::max(0.0, b.top);
            double x1 = std::min<double>(image.width, b.left + b.width);
            double y1 = std::min<double>(image.height, b.top + b.height);
            if (x1 <= x0 || y1 <= y0)
                continue;
            b = Box{x0, y0, x1 - x0, y1 - y0};
        }
        ct_track o = {};
        o.id = t.id;
        o.left = (float)b.left;
        o.top = (float)b.top;
        o.width = (float)b.width;
        o.height = (float)b.height;
        barycenter(b, &o.barycenter_x, &o.barycenter_y);
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
        reported_.push_back(o);
    }
    std::sort(reported_.begin(), reported_.end(),
              [](const ct_track &a, const ct_track &b) { return a.id < b.id; });
}

} // namespace ctrack
