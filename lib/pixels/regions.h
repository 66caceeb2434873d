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

#include "base/memory.h"

#include "dsp/dsp.h"

#include "pixels/mask.h"
#include "base/unionfind.h"

namespace ctrack {

// The first non-zero byte of row[x, end), or end; eight bytes at a time.
int first_nonzero(const uint8_t *row, int x, int end);

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
    Closing();
    void run(const uint8_t *in, uint8_t *out, int w, int h, const Rect &area);
    size_t memory_bytes() const { return a_.capacity() + b_.capacity(); }

private:
    Dsp dsp_;            // the row kernels for this CPU
    Vec<uint8_t> a_, b_; // the area's rows, between the passes
};

// The runs of a box of the mask (stretches of zero or non-zero pixels in
// a row), joined into regions: foreground through the 8 neighbours,
// background through the 4, the box surrounded by background. Background
// run 0 stands for what surrounds the box; a background run joined to it is
// outside every region, one that is not lies in a hole.
class BoxRuns {
public:
    // A run [x0, x1) of row y; for a foreground run, `left` is the
    // background run just before it, -1 at the box's edge. Runs are
    // numbered in raster order, and a region's root (unionfind.h) is its
    // first run.
    struct Run {
        int x0, x1, y, left;
    };
    // With join_foreground false, the foreground runs are not joined into
    // regions (each is its own root).
    void label(const uint8_t *mask, int stride, const Rect &box, bool join_foreground = true);
    int fg_root(int i) { return find_root(fg_up_, i); }
    // Whether background run i is outside (joined to what surrounds the box).
    bool outside(int i) { return find_root(bg_up_, i) == 0; }
    const Vec<Run> &fg() const { return fg_; }
    const Vec<Run> &bg() const { return bg_; }
    // The background runs of the box's row r (0 for its first): [first, end).
    int bg_first(int r) const { return bg_row_[(size_t)r]; }
    int bg_end(int r) const { return bg_row_[(size_t)r + 1]; }
    size_t memory_bytes() const
    {
        return (fg_.capacity() + bg_.capacity()) * sizeof(Run) +
               (fg_up_.capacity() + bg_up_.capacity() + fg_row_.capacity() +
                bg_row_.capacity()) * sizeof(int);
    }

private:
    // Joins a's and b's sets under the first of their roots.
    static void join(Vec<int> &up, int a, int b);
    Vec<Run> fg_, bg_;
    Vec<int> fg_up_, bg_up_; // the runs' union-find parents
    Vec<int> fg_row_, bg_row_; // each row's first run, then the end
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
        return runs_.memory_bytes() + box_of_.capacity() * sizeof(int) +
               boxes_.capacity() * sizeof(Rect);
    }

private:
    BoxRuns runs_;
    Vec<int> box_of_; // per root foreground run: its box
    Vec<Rect> boxes_;
};

} // namespace ctrack

#endif
