// Candidates from the pixels: the background model's foreground, its blobs,
// and the classifier's vote on each (source CT_SOURCE_PIXELS), or on each
// of the host's detections (verify_detections).
#ifndef CTRACK_CANDIDATES_H
#define CTRACK_CANDIDATES_H

#include <cstdint>
#include <vector>

#include "base/counters.h"
#include "base/memory.h"

#include "pixels/background.h"
#include "pixels/blobs.h"
#include "pixels/box_fit.h"
#include "template/classifier.h"
#include "track/person_size.h"
#include "base/planes.h"
#include "track/track.h"

namespace ctrack {

class PixelCandidates {
public:
    // Forgets this step's mask (at the start of every step).
    void clear() { have_mask_ = false; }
    // Blobs of the frame's foreground as candidates (into `out`) and as
    // detections scored by their vote (dets()). `tracks` are the engine's,
    // predicted to this frame: confirmed tracks that have moved freeze the
    // background under them, and tracks inside a blob split it. The time
    // of each stage, and the blobs dropped and masks flooded, are counted.
    // `test` is a ct_pedestrian_test: what scores each candidate. While the
    // model holds the people of its first frames (Background::motion()),
    // the blobs of what changed since the frame before are candidates too,
    // where no blob of the model's that could start a track (scoring
    // `start_score`) covers them.
    void find(int64_t t_us, const Planes &img, const Vec<Track> &tracks, int test,
              float start_score, const PersonSize &size, Counters &counters,
              Vec<ct_candidate> &out);
    // The vote on the foreground inside each of the n detections: one
    // candidate each, in order (into `out`), and dets() the detections
    // with the score of those the vote rejects multiplied by the vote's.
    void verify(int64_t t_us, const Planes &img, const Vec<Track> &tracks,
                const ct_detection *dets, size_t n, const PersonSize &size,
                Counters &counters, Vec<ct_candidate> &out);

    // Only the frame's foreground: the background model's update and the
    // mask's cleaning (for fit(), with a detector's boxes).
    void mask_only(int64_t t_us, const Planes &img, const Vec<Track> &tracks,
                   const PersonSize &size, Counters &counters);
    // Whether this step's mask shows silhouettes clearly enough to fit
    // boxes to (box_fit.h): the model has learnt for a while, and the frame
    // is not mostly foreground (a moving camera, a light switched).
    bool silhouettes_clear(int64_t t_us) const;
    // Box b fitted to this step's silhouette (fit_box()), or false.
    bool fit(const Box &b, const PersonSize &size, bool detector, Box *out,
             Stature *stature = nullptr) const;
    // Box b, whose top a box with its bottom at `cover_bottom` covers,
    // fitted to this step's silhouette below that (fit_in_front()), or false.
    bool fit_in_front(const Box &b, double cover_bottom, const PersonSize &size, Box *out) const;
    // A detector's box b too faint to fit, fitted from its person's head and
    // stature (fit_faint()), or false.
    bool fit_faint(const Box &b, const PersonSize &size, double stature, Box *out) const;
    // A detector's box b whose person is behind a box from row cover_top
    // to cover_bottom, placed from their head above it and their stature
    // (fit_behind()), or false.
    bool fit_behind(const Box &b, double cover_top, double cover_bottom, const PersonSize &size,
                    double stature, Box *out) const;

    const Vec<ct_detection> &dets() const { return dets_; }
    // Whether this step's candidate i (of find()) is a whole blob: a part
    // of a split one tells nothing of a person's width.
    bool whole(size_t i) const { return kind_[i] == kWhole; }
    // Whether candidate i is someone behind the person a blob is
    // (BlobFinder::behind_part()).
    bool behind(size_t i) const { return i < kind_.size() && kind_[i] == kBehind; }
    // Whether this step's candidate i (of find()) moved inside since the
    // frame before (Background::live(); computed when asked).
    bool live(size_t i) const;
    // Whether the frame changed within box b (frame pixels) since the
    // frame before, as live() asks of a blob, over all of b's pixels.
    bool stirs(const Box &b) const;
    // The share of box b (frame pixels) that this step's foreground fills,
    // or -1 when the step has no mask.
    double foreground_share(const Box &b) const;
    // The centroid of this step's foreground inside b, or its centre.
    void barycenter(const Box &b, float *x, float *y) const;
    // This step's cleaned foreground mask at the background model's scale
    // (scale()), or null when the step had no pixels.
    const uint8_t *foreground(int *w, int *h) const;
    // Frame pixels across a working pixel of the mask: 1, 2 or 4, chosen
    // from the people's size.
    int scale() const { return background_.scale(); }
    // Whether the background model has learnt a frame (since a reset).
    bool started() const { return background_.started(); }

    // The background model starts again with the next frame.
    void reset();
    // The background model's update of a step stands (commit) or is undone
    // (rollback, after a failed step).
    void commit() { background_.commit(); }
    void rollback() { background_.rollback(); }
    // Over many steps (a priming): keep_background() keeps a copy of the
    // background model as it is (it may throw, and then keeps none);
    // restore_kept_background() puts it back, drop_kept_background()
    // forgets it. Neither of these throws.
    void keep_background();
    void restore_kept_background() noexcept;
    void drop_kept_background() noexcept { kept_.reset(); }
    size_t memory_bytes() const;

private:
    // The background model over this frame (tracks that moved are frozen).
    // The working scale from the people's size, no finer than `finest`.
    void update_background(int64_t t_us, const Planes &img, const Vec<Track> &tracks,
                           const PersonSize &size, int finest);
    // Whether blob r (working pixels) is an object put down: a track the
    // engine took for one (Track::object) stands on it.
    bool put_down(const Vec<Track> &tracks, const Rect &r) const;
    // Blob i of `blobs` (box r, working pixels) as the candidate `test`
    // scores.
    ct_candidate score_blob(BlobFinder &blobs, size_t i, const Rect &r, int test,
                            const PersonSize &size);
    // The candidates of Background::motion() (find()) appended to `out`.
    void add_moving(int test, float start_score, const PersonSize &size,
                    Vec<ct_candidate> &out);
    // What a candidate of find() is: a part of a split blob, a whole blob,
    // a box for someone behind a blob's person, or a blob of what moved.
    enum : char { kPart, kWhole, kBehind, kMoving };
    // Appends candidate c of blob r, of that kind, to this step's lists.
    void keep(const ct_candidate &c, const Rect &r, char kind, Vec<ct_candidate> &out);

    Background background_;
    Owned<Background> kept_; // keep_background()'s copy
    BlobFinder blobs_;
    Owned<BlobFinder> moving_blobs_; // add_moving()'s, while there is motion()
    Vec<Rect> moving_rects_;
    Classifier classifier_;
    bool have_mask_ = false; // this step
    Vec<Rect> frozen_, predicted_, blob_rects_;
    Vec<ct_detection> dets_;
    Vec<char> kind_; // this step's candidates' kinds (keep())
    Vec<Rect> rects_; // this step's candidates' blobs, working pixels
};

} // namespace ctrack

#endif
