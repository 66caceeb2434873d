#include "pixels/candidates.h"

#include <algorithm>
#include <cmath>

#include "base/clock.h"
#include "base/tunable.h"
#include "pixels/box_fit.h"

namespace ctrack {

namespace {

// Model edges over frame edges above which a blob is a ghost: what has left
// but is still in the model (people of the first frames, a car that drove
// off) has its edges in the model, a real object in the frame. The choice
// is measured in docs/notes/pixels.md.
constexpr double kGhostEdges = 2.0;
// The narrowest blob at the image's left or right edge that is voted on, in
// working pixels (docs/tuning.md, "A sliver at the edge").
constexpr int kEdgeMinWidth = 3;
// A blob of what moved (Background::motion()) is no candidate where more
// than this share of it, or of the model's blob, is the other's
// (docs/tuning.md, "The first second").
CT_TUNABLE(kMovingOverlap, "CTRACK_MOVING_OVERLAP", 0.5);

// The working scale from the people's size (docs/notes/pixels.md, "The
// working scale"): the coarsest of 1, 2 and 4 at which a typical person
// keeps kPersonRows working rows. Going coarser needs kScaleMargin times
// that, going finer less than it over kScaleMargin, so that a size near a
// bound does not swing the model between two scales. Finer is taken as
// soon as the size is known (people are being missed); coarser, which
// only saves time, once kCoarserSamples boxes are behind the size (each
// change perturbs the tracks for a moment).
CT_TUNABLE(kPersonRows, "CTRACK_PERSON_ROWS", 33);
CT_TUNABLE(kScaleMargin, "CTRACK_SCALE_MARGIN", 1.2);
CT_TUNABLE(kCoarserSamples, "CTRACK_COARSER_SAMPLES", 200);

int working_scale(const PersonSize &size, int current, int finest)
{
    if (!size.known())
        return std::max(Background::kStartScale, finest);
    const double h = size.typical_height();
    int s = current;
    if ((double)size.samples() >= kCoarserSamples)
        while (s < Background::kMaxScale && h / (2 * s) >= kPersonRows * kScaleMargin)
            s *= 2;
    while (s > finest && h / s < kPersonRows / kScaleMargin)
        s /= 2;
    return s;
}

Rect to_working(const Box &b, int s)
{
    return Rect{pixel_int(std::floor(b.left / s)), pixel_int(std::floor(b.top / s)),
                pixel_int(std::ceil((b.left + b.width) / s)),
                pixel_int(std::ceil((b.top + b.height) / s))};
}

} // namespace

void PixelCandidates::reset()
{
    background_.reset();
}

void PixelCandidates::keep_background()
{
    kept_ = make_owned<Background>(background_);
}

void PixelCandidates::restore_kept_background() noexcept
{
    if (kept_) {
        background_ = std::move(*kept_);
        kept_.reset();
    }
}

size_t PixelCandidates::memory_bytes() const
{
    return background_.memory_bytes() + (kept_ ? kept_->memory_bytes() : 0) +
           blobs_.memory_bytes() + classifier_.memory_bytes() +
           (frozen_.capacity() + predicted_.capacity() + blob_rects_.capacity()) * sizeof(Rect) +
           dets_.capacity() * sizeof(ct_detection) + kind_.capacity() +
           (rects_.capacity() + moving_rects_.capacity()) * sizeof(Rect) +
           (moving_blobs_ ? moving_blobs_->memory_bytes() : 0);
}

void PixelCandidates::update_background(int64_t t_us, const Planes &img,
                                        const Vec<Track> &tracks, const PersonSize &size,
                                        int finest)
{
    const int s =
        working_scale(size, background_.scale(), std::max(finest, background_.finest_scale()));
    frozen_.clear();
    predicted_.clear();
    for (const Track &t : tracks) {
        if (t.state == CT_TRACK_TENTATIVE)
            continue;
        predicted_.push_back(to_working(t.box(), s));
        // Where a confirmed track stands, the background learns nothing: a
        // person who stops stays foreground. Only tracks that have moved:
        // a track that never did may stand on a ghost of the model, which
        // freezing would keep forever.
        if (t.state == CT_TRACK_CONFIRMED && t.moved)
            frozen_.push_back(predicted_.back());
    }
    background_.apply(t_us, img, s, frozen_.data(), (int)frozen_.size());
}

// CT_PEDESTRIAN_SIZE: the box's aspect and height against the people's
// size, the filter eval/recognition.py compares with the template.
static bool person_sized(const ct_candidate &c, const PersonSize &size)
{
    constexpr double kMinAspect = 1.0, kMaxAspect = 4.25, kLow = 0.5, kHigh = 1.5;
    const double aspect = c.height / c.width;
    if (!(aspect >= kMinAspect && aspect <= kMaxAspect))
        return false;
    if (!size.known())
        return c.height >= PersonSize::kPriorMinHeight;
    const double tall = size.height_at(c.top + c.height);
    return c.height >= kLow * tall && c.height <= kHigh * tall;
}

void PixelCandidates::find(int64_t t_us, const Planes &img, const Vec<Track> &tracks,
                           int test, float start_score, const PersonSize &size,
                           Counters &counters, Vec<ct_candidate> &out)
{
    dets_.clear();
    if (img.empty())
        return;
    Stopwatch sw;
    background_.keep_luma(true); // for live() and motion()
    // The finer scales are for the contour template, which needs a
    // person's rows; size and aspect alone need none, and would only meet
    // more fragments (docs/notes/pixels.md, "The working scale").
    update_background(t_us, img, tracks, size,
                      test == CT_PEDESTRIAN_SIZE ? Background::kStartScale
                                                 : Background::kMinScale);
    counters.stage_ns[CT_STAGE_BACKGROUND] += sw.lap();
    const int s = background_.scale();
    blobs_.find(background_.mask(), background_.width(), background_.height(), s,
                predicted_.data(), (int)predicted_.size(), size, classifier_, blob_rects_);
    have_mask_ = true;
    counters.blobs_dropped += (uint64_t)blobs_.dropped();
    counters.masks_flooded += blobs_.flooded();
    counters.stage_ns[CT_STAGE_BLOBS] += sw.lap();
    out.clear();
    kind_.clear();
    rects_.clear();
    bool dropped = false; // the last blob, a ghost or an object put down
    for (size_t i = 0; i < blob_rects_.size(); i++) {
        const Rect &r = blob_rects_[i];
        // A ghost is learnt at once and is no candidate. A box drawn for
        // someone behind a blob's person is no blob: it goes with the blob
        // it was drawn in, which comes before it.
        if (blobs_.behind_part(i)) {
            if (dropped)
                continue;
        } else {
            long frame_edges, model_edges;
            background_.outline_edges(img, blobs_.cleaned(), r, &frame_edges, &model_edges);
            dropped = model_edges > kGhostEdges * frame_edges || put_down(tracks, r);
            if (dropped) {
                background_.absorb(img, blobs_.cleaned(), r);
                continue;
            }
        }
        keep(score_blob(blobs_, i, r, test, size), r,
             blobs_.behind_part(i) ? kBehind : blobs_.whole(i) ? kWhole : kPart, out);
    }
    if (background_.motion())
        add_moving(test, start_score, size, out);
    else
        moving_blobs_.reset();
    counters.stage_ns[CT_STAGE_CLASSIFY] += sw.lap();
}

ct_candidate PixelCandidates::score_blob(BlobFinder &blobs, size_t i, const Rect &r, int test,
                                         const PersonSize &size)
{
    const int s = background_.scale(), w = background_.width();
    float regions;
    ct_candidate c = classifier_.candidate(
        blobs.cleaned(), w, background_.height(), r, (float)(r.x0 * s), (float)(r.y0 * s),
        (float)((r.x1 - r.x0) * s), (float)((r.y1 - r.y0) * s), blobs.headed_part(i), &regions);
    // A blob that a shape of two walkers fits better than every
    // silhouette, but that shows one head on its top edge, is one
    // person far more often than two: a pedestrian, the regions' margin
    // over an even vote halved for the doubt. At most 0.75, under
    // candidate_min_score's default: it continues a track and starts
    // none, as when the pair shapes turned it down (docs/tuning.md,
    // "Shapes a person is not", has the blobs it lifts).
    if (regions > 0.5f && blobs.head_count(r) == 1)
        c.score = 0.5f + 0.5f * (regions - 0.5f);
    if (test == CT_PEDESTRIAN_SIZE)
        c.score = person_sized(c, size) ? 1.0f : 0.0f;
    // A sliver at the image's left or right edge, fewer than
    // kEdgeMinWidth working pixels wide, has no outline to vote on (its
    // side is the image's border): no score, so it neither starts nor
    // continues a track. A background column that stays foreground
    // there started one (docs/tuning.md, "A sliver at the edge").
    if ((r.x0 <= 0 || r.x1 >= w) && r.x1 - r.x0 < kEdgeMinWidth)
        c.score = 0;
    return c;
}

void PixelCandidates::keep(const ct_candidate &c, const Rect &r, char kind,
                           Vec<ct_candidate> &out)
{
    out.push_back(c);
    dets_.push_back(ct_detection{c.left, c.top, c.width, c.height, c.score, 0});
    kind_.push_back(kind);
    rects_.push_back(r);
}

void PixelCandidates::add_moving(int test, float start_score, const PersonSize &size,
                                 Vec<ct_candidate> &out)
{
    // While the model learns its first frames, a person who was in them
    // is in pieces in its mask, or in none (docs/notes/pixels.md,
    // "Start"); what changed since the frame before holds them whole
    // enough, where they walk. Their blobs come from a finder of their
    // own: the model's mask stays the one fit() and live() read.
    if (!moving_blobs_)
        moving_blobs_ = make_owned<BlobFinder>();
    BlobFinder &blobs = *moving_blobs_;
    const int s = background_.scale();
    blobs.find(background_.motion(), background_.width(), background_.height(), s,
               predicted_.data(), (int)predicted_.size(), size, classifier_, moving_rects_);
    const size_t from_model = out.size();
    for (size_t i = 0; i < moving_rects_.size(); i++) {
        const Rect &r = moving_rects_[i];
        if (blobs.behind_part(i))
            continue;
        // Where the model's blob could start a track, it stands for the
        // person; both would start two.
        const Box b{(double)r.x0 * s, (double)r.y0 * s, (double)(r.x1 - r.x0) * s,
                    (double)(r.y1 - r.y0) * s};
        bool covered = false;
        for (size_t j = 0; j < from_model && !covered; j++)
            covered = out[j].score >= start_score &&
                      overlap_share(b, Box{out[j].left, out[j].top, out[j].width,
                                           out[j].height}) > kMovingOverlap;
        if (!covered)
            keep(score_blob(blobs, i, r, test, size), r, kMoving, out);
    }
}

bool PixelCandidates::live(size_t i) const
{
    // A blob of what moved changed by its making.
    if (i < kind_.size() && kind_[i] == kMoving)
        return true;
    return i < rects_.size() && background_.live(blobs_.cleaned(), rects_[i]);
}

bool PixelCandidates::put_down(const Vec<Track> &tracks, const Rect &r) const
{
    const int s = background_.scale();
    for (const Track &t : tracks) {
        if (!t.object)
            continue;
        // The blob holds the track's centre, and the track's box most of
        // the blob.
        const Rect b = to_working(t.box(), s);
        const int cx = (b.x0 + b.x1) / 2, cy = (b.y0 + b.y1) / 2;
        if (cx < r.x0 || cx >= r.x1 || cy < r.y0 || cy >= r.y1)
            continue;
        const long inter = (long)std::max(0, std::min(b.x1, r.x1) - std::max(b.x0, r.x0)) *
                           std::max(0, std::min(b.y1, r.y1) - std::max(b.y0, r.y0));
        if (2 * inter >= (long)(r.x1 - r.x0) * (r.y1 - r.y0))
            return true;
    }
    return false;
}

void PixelCandidates::verify(int64_t t_us, const Planes &img, const Vec<Track> &tracks,
                             const ct_detection *dets, size_t n, const PersonSize &size,
                             Counters &counters, Vec<ct_candidate> &out)
{
    Stopwatch sw;
    background_.keep_luma(false);
    update_background(t_us, img, tracks, size, Background::kMinScale);
    counters.stage_ns[CT_STAGE_BACKGROUND] += sw.lap();
    classifier_.new_mask();
    blobs_.clean(background_.mask(), background_.width(), background_.height());
    have_mask_ = true;
    counters.stage_ns[CT_STAGE_BLOBS] += sw.lap();
    dets_.clear();
    out.clear();
    for (size_t j = 0; j < n; j++) {
        const ct_detection &d = dets[j];
        const ct_candidate c = classifier_.candidate(
            blobs_.cleaned(), background_.width(), background_.height(),
            to_working(Box{d.left, d.top, d.width, d.height}, background_.scale()), d.left, d.top,
            d.width, d.height);
        out.push_back(c);
        ct_detection v = d;
        if (rejects(c))
            v.score *= c.score;
        dets_.push_back(v);
    }
    counters.stage_ns[CT_STAGE_CLASSIFY] += sw.lap();
}

void PixelCandidates::mask_only(int64_t t_us, const Planes &img, const Vec<Track> &tracks,
                                const PersonSize &size, Counters &counters)
{
    Stopwatch sw;
    background_.keep_luma(false);
    update_background(t_us, img, tracks, size, Background::kMinScale);
    counters.stage_ns[CT_STAGE_BACKGROUND] += sw.lap();
    blobs_.clean(background_.mask(), background_.width(), background_.height());
    have_mask_ = true;
    counters.stage_ns[CT_STAGE_BLOBS] += sw.lap();
}

bool PixelCandidates::silhouettes_clear(int64_t t_us) const
{
    // Twice the model's fast start (background.cc): the people of the
    // first frames are out of it. A camera that moved in that time has its
    // background in the wrong place (and a panning camera's frames do not
    // all show it: a frame can match the last one unshifted), and a mask
    // over a quarter foreground is no picture of a few people.
    constexpr double kLearntFor = 1.0, kMaxForegroundShare = 0.25;
    if (!have_mask_ || background_.age_s(t_us) < kLearntFor ||
        background_.since_camera_moved_s(t_us) < kLearntFor)
        return false;
    const int w = background_.width(), h = background_.height();
    const long fg = count_nonzero(blobs_.cleaned(), (size_t)w, 0, 0, w, h);
    return fg <= kMaxForegroundShare * w * h;
}

bool PixelCandidates::fit(const Box &b, const PersonSize &size, bool detector, Box *out,
                          Stature *stature) const
{
    return have_mask_ && fit_box(blobs_.cleaned(), background_.width(), background_.height(),
                                 background_.scale(), b, kFitFollow, &size, detector, out,
                                 stature);
}

bool PixelCandidates::fit_in_front(const Box &b, double cover_bottom, const PersonSize &size,
                                   Box *out) const
{
    return have_mask_ && ctrack::fit_in_front(blobs_.cleaned(), background_.width(),
                                              background_.height(), background_.scale(), b,
                                              cover_bottom, kFitFollow, &size, out);
}

bool PixelCandidates::fit_faint(const Box &b, const PersonSize &size, double stature,
                                Box *out) const
{
    return have_mask_ && ctrack::fit_faint(blobs_.cleaned(), background_.width(),
                                           background_.height(), background_.scale(), b,
                                           kFitFollow, size, stature, out);
}

bool PixelCandidates::fit_behind(const Box &b, double cover_top, double cover_bottom,
                                 const PersonSize &size, double stature, Box *out) const
{
    return have_mask_ && ctrack::fit_behind(blobs_.cleaned(), background_.width(),
                                            background_.height(), background_.scale(), b,
                                            cover_top, cover_bottom, kFitFollow, size, stature,
                                            out);
}

const uint8_t *PixelCandidates::foreground(int *w, int *h) const
{
    *w = background_.width();
    *h = background_.height();
    return have_mask_ ? blobs_.cleaned() : nullptr;
}

double PixelCandidates::foreground_share(const Box &b) const
{
    if (!have_mask_)
        return -1;
    const int s = background_.scale(), w = background_.width(), h = background_.height();
    const Rect r = to_working(b, s);
    const int x0 = std::max(0, r.x0), x1 = std::min(w, r.x1);
    const int y0 = std::max(0, r.y0), y1 = std::min(h, r.y1);
    if (x1 <= x0 || y1 <= y0)
        return -1;
    return (double)count_nonzero(blobs_.cleaned(), (size_t)w, x0, y0, x1, y1) /
           ((double)(x1 - x0) * (y1 - y0));
}

bool PixelCandidates::stirs(const Box &b) const
{
    return have_mask_ && background_.live(nullptr, to_working(b, background_.scale()));
}

void PixelCandidates::barycenter(const Box &b, float *x, float *y) const
{
    *x = (float)(b.left + b.width / 2);
    *y = (float)(b.top + b.height / 2);
    if (!have_mask_)
        return;
    const int s = background_.scale(), w = background_.width(), h = background_.height();
    const Rect r = to_working(b, s);
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

} // namespace ctrack
