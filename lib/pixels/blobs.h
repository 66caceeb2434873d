// From the foreground mask to person-sized candidates: a closing, the outer
// regions (regions.h), fragments merged, groups split, with the
// classifier's consent where a merge or a split is in doubt.
#ifndef CTRACK_BLOBS_H
#define CTRACK_BLOBS_H

#include <cstdint>
#include <memory>
#include <vector>

#include "base/memory.h"

#include "template/classifier.h"
#include "pixels/mask.h"
#include "track/person_size.h"

namespace ctrack {

class BlobFinder {
public:
    BlobFinder();
    ~BlobFinder();
    BlobFinder(const BlobFinder &) = delete;
    BlobFinder &operator=(const BlobFinder &) = delete;

    // Cleans the w x h mask (a closing) and returns the boxes of
    // its blobs: those at least min_area pixels, fragments of one person
    // (stacked one above the other) merged, and blobs wider than a person
    // split, at the predicted boxes' centres when tracks are there, else
    // into equal parts at the valleys of the column profile; beside a whole
    // blob, a box for someone it hides in part behind (behind()). What counts as
    // a speck, a person's height and a person's width come from `size`
    // (frame pixels; a working pixel of the mask is `scale` frame pixels
    // across); `cls` votes where a merge or a split is in doubt.
    void find(const uint8_t *mask, int w, int h, int scale, const Rect *predicted,
              int n_predicted, const PersonSize &size, Classifier &cls, Vec<Rect> &out);
    // The last find()'s cuts: blobs past the cap (the smallest), and whether
    // the mask was so full of foreground that it gave none.
    int dropped() const { return dropped_; }
    // Whether the last find()'s blob i is a whole blob, not a part of one
    // that was split (a group, or a blob two tracks shared).
    bool whole(size_t i) const { return whole_[i] == kWhole; }
    // Whether it is a part of a split blob holding one head of the blob's
    // top edge: its neighbours' arms and legs fill its outline's hollows, so
    // its fill says nothing of its shape.
    bool headed_part(size_t i) const { return whole_[i] == kHeadedPart; }
    // Whether it is someone behind the person a whole blob is (behind()):
    // a box the people's size draws under a head on the blob's top edge,
    // not a part of the blob.
    bool behind_part(size_t i) const { return whole_[i] == kBehind; }
    // How many heads blob r shows on its top edge, as the split finds them
    // (heads()).
    int head_count(const Rect &r);
    bool flooded() const { return flooded_; }
    // Only the cleaning: the closing of the w x h mask.
    void clean(const uint8_t *mask, int w, int h);
    // The cleaned mask of the last find() or clean(), and its size.
    const uint8_t *cleaned() const;
    int width() const;
    int height() const;
    size_t memory_bytes() const;

private:
    // The outer regions of the cleaned mask into Impl::blobs (at most
    // kMaxBlobs, the largest); false when the mask is flooded.
    bool outer_blobs();
    // Fragments of one person, one above the other, merged in Impl::blobs.
    void merge_fragments(int scale, const PersonSize &size, Classifier &cls);
    // Whether blob r is too small to be a person where its feet are.
    bool speck(const Rect &r, int scale, const PersonSize &size) const;
    // Blob r into `out`: whole, or split into the people it holds.
    void split(const Rect &r, int scale, const Rect *predicted, int n_predicted,
               const PersonSize &size, Classifier &cls, Vec<Rect> &out);
    // The column of [lo, hi] with the least foreground in r's rows, the
    // nearest to `want` of equals.
    int emptiest(const Rect &r, int lo, int hi, int want) const;
    // The classifier's score of the cleaned mask inside r.
    float vote(Classifier &cls, const Rect &r) const;
    // The part of r between columns x0 and x1, with its own rows.
    Rect rows_of(const Rect &r, int x0, int x1) const;
    // Where to cut r between two people side by side, from two heads on its
    // top edge, when the contour template takes both parts for pedestrians
    // and scores them above the whole: the column, or -1.
    // `top` is r's top edge (top_edge()) and h1 its highest column.
    int between_heads(const Rect &r, const Vec<int> &top, int h1, Classifier &cls);
    // The column of the highest point of `top` at least `gap` columns from
    // column h1 (its highest), with the edge between them dipping `dip`
    // rows below both; -1 if none.
    static int second_head(const Vec<int> &top, int h1, int gap, double dip);
    // Someone behind the person whole blob r is, whom it hides in part:
    // under one of its two highest heads (second_head(), half as far
    // apart as between_heads() asks; the line must put a person under
    // both), the person the people's size puts there, when their feet are
    // well above the blob's bottom. Their box, from that head to those
    // feet and as wide as a person there, goes into `out` beside r.
    // `top` and h1 as for between_heads().
    void behind(const Rect &r, const Vec<int> &top, int h1, int scale, const PersonSize &size,
                Vec<Rect> &out);
    // r's top edge: each column's first foreground row (r.y1 if none), in
    // Impl::tops.
    Vec<int> &top_edge(const Rect &r);
    // The middle of the deepest run of the top edge between columns a and b
    // (the edge is often flat there: shoulders).
    static int dip_middle(const Vec<int> &top, int a, int b);
    // The columns of r (from r.x0) of the heads on its top edge, left to
    // right (top_edge() is left in Impl::tops).
    void heads(const Rect &r, Vec<int> &out);
    // Cuts (absolute columns) between heads `hs` appended to `cuts` when the
    // contour template takes every part for a pedestrian, its fill aside,
    // surely (kHeadsVote) and above the whole; false, `cuts` as it was,
    // otherwise.
    bool cut_between_heads(const Rect &r, const Vec<int> &hs, Classifier &cls, Vec<int> &cuts);
    // Whether each part between the cuts [r.x0, ..., r.x1] holds one head.
    static bool one_head_each(const Rect &r, const Vec<int> &hs, const Vec<int> &cuts);
    enum : char { kPart, kWhole, kHeadedPart, kBehind };
    struct Impl;
    Owned<Impl> impl_;
    Vec<char> whole_;
    int dropped_ = 0;
    bool flooded_ = false;
};

// Person shape in working pixels: height over width of an upright person is
// at least this...
constexpr double kPersonAspect = 2.0;

} // namespace ctrack

#endif
