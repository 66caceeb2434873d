// The blob finder's two mask operations, of its own: a closing by a small
// rectangle, and the boxes of the mask's outer regions. They give what
// OpenCV's morphologyEx(MORPH_CLOSE) and findContours(RETR_EXTERNAL) with
// boundingRect() gave, to the bit and in the same order
// (tests/check_regions.cc compares them on random and real masks), over the
// foreground's rows and columns only, and they keep their buffers: no heap
// allocation once a frame's needs have been met (OpenCV's allocate on every
// call).
#ifndef CTRACK_REGIONS_H
#define CTRACK_REGIONS_H

#include <cstdint>
#include <vector>

#include "memory.h"

#include "mask.h"

namespace ctrack {

// The closing (dilation, then erosion) of the w x h mask `in` by a
// rectangle kCloseWidth wide and kCloseHeight tall centred on each pixel,
// written into `out` (w x h) inside `area`; pixels outside the image count
// as neither (OpenCV's default border). `in` must be 0 outside `area` but
// for a margin of kCloseWidth - 1 columns and kCloseHeight - 1 rows inside
// its edges that are not the image's (the closing of the whole mask is then
// 0 outside `area`, and this is the whole mask's closing there). `out` is
// left as it is outside `area`.
class Closing {
public:
    static constexpr int kCloseWidth = 3, kCloseHeight = 5;
    void run(const uint8_t *in, uint8_t *out, int w, int h, const Rect &area);
    size_t memory_bytes() const { return a_.capacity() + b_.capacity(); }

private:
    Vec<uint8_t> a_, b_; // the area's rows, between the passes
};

// The bounding boxes of the outer regions of the mask inside `area`:
// regions of non-zero pixels joined through their 8 neighbours, background
// joined through its 4, the area surrounded by background, and a region
// inside a hole of another left out. OpenCV's findContours(RETR_EXTERNAL)
// traces the same regions' outer borders. The boxes are in its order, the
// reverse of the order in which a raster scan meets each region's first
// pixel, in the mask's coordinates.
class OuterRegions {
public:
    void find(const uint8_t *mask, int stride, const Rect &area, Vec<Rect> &out);
    size_t memory_bytes() const
    {
        return (fg_.capacity() + bg_.capacity()) * sizeof(Run) +
               (fg_row_.capacity() + bg_row_.capacity() + box_of_.capacity()) * sizeof(int) +
               boxes_.capacity() * sizeof(Rect);
    }

private:
    // A run of equal pixels in one row, [x0, x1); `up` is its union-find
    // parent (runs are numbered in raster order and a set's root is its
    // first run); for a foreground run, `left` is the background run just
    // before it, -1 at the area's edge.
    struct Run {
        int x0, x1, y, up, left;
    };
    int root(Vec<Run> &runs, int i);
    void join(Vec<Run> &runs, int a, int b);
    Vec<Run> fg_, bg_;
    Vec<int> fg_row_, bg_row_; // each row's first run, then the end
    Vec<int> box_of_;          // per root foreground run: its box
    Vec<Rect> boxes_;
};

} // namespace ctrack

#endif
