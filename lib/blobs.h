// From the foreground mask to person-sized candidates: morphology, contours
// (OpenCV), fragments merged, groups split. OpenCV's headers stay in
// blobs.cc.
#ifndef CTRACK_BLOBS_H
#define CTRACK_BLOBS_H

#include <cstdint>
#include <memory>
#include <vector>

#include "background.h"
#include "contour_template.h"

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
    // into equal parts at the valleys of the column profile.
    void find(const uint8_t *mask, int w, int h, const Rect *predicted, int n_predicted,
              std::vector<Rect> &out);
    // Only the cleaning: the closing of the w x h mask.
    void clean(const uint8_t *mask, int w, int h);
    // The cleaned mask of the last find() or clean().
    const uint8_t *cleaned() const;
    // The contour template's vote on the cleaned mask inside r (within the
    // mask).
    Vote classify(const Rect &r);
    size_t memory_bytes() const;

private:
    float vote(const Rect &r) { return classify(r).score; }
    // The part of r between columns x0 and x1, with its own rows.
    Rect rows_of(const Rect &r, int x0, int x1) const;
    // Where to cut r between two people side by side, from two heads on its
    // top edge, when the contour template takes both parts for pedestrians
    // and scores them above the whole: the column, or -1.
    int between_heads(const Rect &r);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Person shape in working pixels: height over width of an upright person is
// at least this...
constexpr double kPersonAspect = 2.0;

} // namespace ctrack

#endif
