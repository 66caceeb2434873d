#include "track/gate.h"

#include <algorithm>
#include <cmath>

namespace ctrack {

namespace {

// Whether d's centre lies within reach of (cx, cy) at a height within
// (0.67, 1.5) times h: a person near where a track expects them. *dist is
// the distance.
bool within_reach(const ct_detection &d, double cx, double cy, double reach, double h,
                  double *dist)
{
    *dist = std::hypot(d.left + d.width / 2 - cx, d.top + d.height / 2 - cy);
    const double ratio = d.height / h;
    return *dist <= reach && ratio > 0.67 && ratio < 1.5;
}

} // namespace

void Gate::index(const ct_detection *dets, const Vec<int> &cols)
{
    dets_ = dets;
    cols_ = &cols;
    order_.resize(cols.size());
    for (size_t k = 0; k < cols.size(); k++)
        order_[k] = (int)k;
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
        const float la = dets[cols[(size_t)a]].left, lb = dets[cols[(size_t)b]].left;
        return la != lb ? la < lb : a < b;
    });
    left_.resize(order_.size());
    max_width_ = 0;
    for (size_t i = 0; i < order_.size(); i++) {
        const ct_detection &d = dets[cols[(size_t)order_[i]]];
        left_[i] = d.left;
        max_width_ = std::max(max_width_, (double)d.width);
    }
}

void Gate::range(double lo, double hi, size_t *first, size_t *last) const
{
    *first = (size_t)(std::lower_bound(left_.begin(), left_.end(), lo) - left_.begin());
    *last = (size_t)(std::lower_bound(left_.begin(), left_.end(), hi) - left_.begin());
}

void Gate::keep_best(Vec<Pair> &out)
{
    if (row_.size() > (size_t)kMaxPairsPerTrack) {
        std::nth_element(row_.begin(), row_.begin() + kMaxPairsPerTrack, row_.end(),
                         [](const Pair &a, const Pair &b) {
                             return a.cost != b.cost ? a.cost < b.cost : a.col < b.col;
                         });
        row_.resize(kMaxPairsPerTrack);
    }
    std::sort(row_.begin(), row_.end(), [](const Pair &a, const Pair &b) { return a.col < b.col; });
    out.insert(out.end(), row_.begin(), row_.end());
}

void Gate::overlapping(int row, const Box &box, double min_iou, Vec<Pair> &out, double reach,
                       double buffer)
{
    row_.clear();
    // A detection overlaps the box only if its left edge lies in
    // (box.left - widest detection, box right edge), both widened by the
    // buffer; one near it, if its centre is within reach of the box's.
    const double cx = box.left + box.width / 2, cy = box.top + box.height / 2;
    const bool reaching = reach > 0;
    const double lo = box.left - buffer * box.width - (1 + buffer) * max_width_;
    const double hi = box.left + box.width + buffer * (box.width + max_width_);
    size_t first, last;
    range(reaching ? std::min(lo, cx - reach - 1 - max_width_) : lo,
          reaching ? std::max(hi, cx + reach + 1) : hi, &first, &last);
    for (size_t i = first; i < last; i++) {
        const int k = order_[i];
        const ct_detection &d = dets_[(*cols_)[(size_t)k]];
        const double o = buffered_iou(box, det_box(d), buffer);
        if (o + 1e-12 >= min_iou) {
            row_.push_back(Pair{row, k, 1.0 - o});
            continue;
        }
        if (!reaching)
            continue;
        double dist;
        if (within_reach(d, cx, cy, reach, box.height, &dist))
            row_.push_back(Pair{row, k, (1.0 - min_iou) * (0.5 + 0.5 * dist / reach)});
    }
    keep_best(out);
}

void Gate::near(int row, double cx, double cy, double reach, double h, Vec<Pair> &out)
{
    row_.clear();
    size_t first, last;
    range(cx - reach - max_width_ / 2 - 1, cx + reach + 1, &first, &last);
    for (size_t i = first; i < last; i++) {
        const int k = order_[i];
        double dist;
        if (within_reach(dets_[(*cols_)[(size_t)k]], cx, cy, reach, h, &dist))
            row_.push_back(Pair{row, k, dist});
    }
    keep_best(out);
}

size_t Gate::memory_bytes() const
{
    return order_.capacity() * sizeof(int) + left_.capacity() * sizeof(double) +
           row_.capacity() * sizeof(Pair);
}

} // namespace ctrack
