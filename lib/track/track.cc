#include "track/track.h"

#include <algorithm>
#include <cmath>

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
// detection's, its size this many times less again.
constexpr double kFollowNoiseRatio = 2.0;
constexpr double kFollowSizeNoiseRatio = 4.0;
// The part of a track's box another must cover for it to be occluded.
constexpr double kOccludedFraction = 0.2;

// A quantity in box heights (a noise, a speed) at detection d's height.
double at_height(double per_height, const ct_detection &d)
{
    return per_height * std::max<double>(d.height, kMinSide);
}

double intersection(const Box &a, const Box &b)
{
    double x0 = std::max(a.left, b.left), y0 = std::max(a.top, b.top);
    double x1 = std::min(a.left + a.width, b.left + b.width);
    double y1 = std::min(a.top + a.height, b.top + b.height);
    return x1 <= x0 || y1 <= y0 ? 0 : (x1 - x0) * (y1 - y0);
}

} // namespace

double iou(const Box &a, const Box &b)
{
    const double inter = intersection(a, b);
    if (!(inter > 0))
        return 0;
    double uni = a.width * a.height + b.width * b.height - inter;
    return uni > 0 ? inter / uni : 0;
}

double overlap_share(const Box &a, const Box &b)
{
    const double inter = intersection(a, b);
    const double smaller = std::min(a.width * a.height, b.width * b.height);
    return inter > 0 && smaller > 0 ? inter / smaller : 0;
}

double buffered_iou(const Box &a, const Box &b, double buffer)
{
    if (buffer <= 0)
        return iou(a, b);
    const double g = 1 + 2 * buffer;
    return iou(Box{a.left - buffer * a.width, a.top - buffer * a.height, a.width * g,
                   a.height * g},
               Box{b.left - buffer * b.width, b.top - buffer * b.height, b.width * g,
                   b.height * g});
}

void separate_buffers(const Vec<Box> &boxes, Vec<double> &buffers, Vec<int> &order)
{
    const size_t n = boxes.size();
    order.resize(n);
    double max_w = 0;
    for (size_t k = 0; k < n; k++) {
        order[k] = (int)k;
        max_w = std::max(max_w, boxes[k].width);
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return boxes[(size_t)a].left != boxes[(size_t)b].left
                   ? boxes[(size_t)a].left < boxes[(size_t)b].left
                   : a < b;
    });
    // Widened by b, boxes p and q meet once their gap on both axes is under
    // b times their summed sizes on that axis. Only a box whose left edge
    // lies within b (p.width + max_w) of p's extent (past the widest box on
    // the left) can lower p's buffer.
    for (size_t a = 0; a < n; a++) {
        const size_t i = (size_t)order[a];
        const Box &p = boxes[i];
        double &b = buffers[i];
        auto meet = [&](const Box &q) {
            const double gx =
                std::max(q.left - (p.left + p.width), p.left - (q.left + q.width));
            const double gy = std::max(q.top - (p.top + p.height), p.top - (q.top + q.height));
            b = std::min(b, std::max(0.0, std::max(gx / (p.width + q.width),
                                                   gy / (p.height + q.height))));
        };
        for (size_t c = a; c-- > 0 && b > 0;) {
            const Box &q = boxes[(size_t)order[c]];
            if (q.left + max_w + b * (p.width + max_w) < p.left)
                break;
            meet(q);
        }
        for (size_t c = a + 1; c < n && b > 0; c++) {
            const Box &q = boxes[(size_t)order[c]];
            if (q.left > p.left + p.width + b * (p.width + max_w))
                break;
            meet(q);
        }
    }
}

double inside_fraction(const Box &b, int w, int h)
{
    double iw = std::min<double>(w, b.left + b.width) - std::max(0.0, b.left);
    double ih = std::min<double>(h, b.top + b.height) - std::max(0.0, b.top);
    return iw > 0 && ih > 0 ? iw * ih / (b.width * b.height) : 0;
}

Box BoxMotion::box() const
{
    double bw = std::max(w.x, kMinSide), bh = std::max(h.x, kMinSide);
    return Box{cx.x - bw / 2, cy.x - bh / 2, bw, bh};
}

void BoxMotion::init(const ct_detection &d, double sd, double vsd)
{
    cx.init(d.left + d.width / 2.0, sd, vsd);
    cy.init(d.top + d.height / 2.0, sd, vsd);
    w.init(d.width, sd, vsd * kSizeNoiseRatio);
    h.init(d.height, sd, vsd * kSizeNoiseRatio);
}

void BoxMotion::predict(double dt, double motion_noise)
{
    double accel = motion_noise * std::max(h.x, kMinSide);
    cx.predict(dt, accel);
    cy.predict(dt, accel);
    w.predict(dt, accel * kSizeNoiseRatio);
    h.predict(dt, accel * kSizeNoiseRatio);
}

void BoxMotion::update(const ct_detection &d, double sd)
{
    cx.update(d.left + d.width / 2.0, sd);
    cy.update(d.top + d.height / 2.0, sd);
    w.update(d.width, sd);
    h.update(d.height, sd);
}

void BoxMotion::normalized_innovation(const ct_detection &d, double detection_noise,
                                      double *nx, double *ny) const
{
    const double sd = at_height(detection_noise, d);
    *nx = (d.left + d.width / 2.0 - cx.x) / std::sqrt(cx.innovation_var(sd));
    *ny = (d.top + d.height / 2.0 - cy.x) / std::sqrt(cy.innovation_var(sd));
}

void Track::start(const ct_detection &d, double detection_noise, int index, int64_t t_us)
{
    double sd = at_height(detection_noise, d);
    double vsd = at_height(kInitialSpeedSd, d);
    init(d, sd, vsd);
    shown = static_cast<const BoxMotion &>(*this);
    shown_age = -1;
    age = 1;
    hits = 1;
    last_update_us = t_us;
    seen_h = d.height;
    seen = det_box(d);
    start_x = d.left + d.width / 2.0;
    start_y = d.top + d.height / 2.0;
    start_bottom = (double)d.top + d.height;
    start_us = t_us;
    live_us = t_us;
    det_index = index;
    class_id = d.class_id;
    score = d.score;
    best_score = d.score;
}

double Track::from_start(const Box &b) const
{
    return std::hypot(b.left + b.width / 2 - start_x, b.top + b.height / 2 - start_y);
}

void Track::predict(double dt, double motion_noise, double shown_noise)
{
    const bool corrected = det_index >= 0;
    BoxMotion::predict(dt, motion_noise);
    if (corrected)
        sd_after_hit = std::sqrt(std::max(cx.p00, cy.p00));
    shown.predict(dt, shown_noise);
    age++;
    det_index = -1;
    followed = false;
    ms = MeanShiftResult();
    cue = box();
}

double Track::centre_nis(const ct_detection &d, double detection_noise) const
{
    const double sd = at_height(detection_noise, d);
    return 0.5 * (cx.nis(d.left + d.width / 2.0, sd) + cy.nis(d.top + d.height / 2.0, sd));
}

double Track::centre_innovation2(const ct_detection &d) const
{
    const double h = std::max(this->h.x, kMinSide);
    const double ex = (d.left + d.width / 2.0 - cx.x) / h;
    const double ey = (d.top + d.height / 2.0 - cy.x) / h;
    return 0.5 * (ex * ex + ey * ey);
}

double Track::centre_innovation_sd(double detection_noise) const
{
    const double sd = detection_noise * std::max(h.x, kMinSide);
    return std::sqrt(std::max(cx.innovation_var(sd), cy.innovation_var(sd)));
}

void Track::correct(const ct_detection &d, double detection_noise, double shown_noise,
                    int index, int64_t t_us)
{
    update(d, at_height(detection_noise, d));
    shown.update(d, at_height(shown_noise, d));
    hits++;
    last_update_us = t_us;
    seen_h = d.height;
    seen = det_box(d);
    if (from_start(seen) > 0.5 * d.height)
        moved = true;
    det_index = index;
    class_id = d.class_id;
    score = d.score;
    best_score = std::max(best_score, d.score);
}

void Track::follow(double detection_noise)
{
    double sd = kFollowNoiseRatio * detection_noise * std::max(h.x, kMinSide);
    cx.update(ms.cx, sd);
    cy.update(ms.cy, sd);
    // The scale mean shift found moves the size only slowly (Comaniciu's
    // blend of the new and old size): small windows drift to a part of the
    // person, and their similarity stays high.
    w.update(ms.width, sd * kFollowSizeNoiseRatio);
    h.update(ms.height, sd * kFollowSizeNoiseRatio);
    // Without detections nothing measures how the size changes: hold it,
    // rather than let a trend shrink the box to a part of the person.
    w.v = 0;
    h.v = 0;
    followed = true;
    shown = static_cast<const BoxMotion &>(*this);
}

bool occluded(const Vec<Track> &tracks, size_t i)
{
    const Box a = tracks[i].box();
    const double area = a.width * a.height;
    for (size_t j = 0; j < tracks.size(); j++) {
        if (j == i || tracks[j].state == CT_TRACK_TENTATIVE)
            continue;
        const Box b = tracks[j].box();
        double iw = std::min(a.left + a.width, b.left + b.width) - std::max(a.left, b.left);
        double ih = std::min(a.top + a.height, b.top + b.height) - std::max(a.top, b.top);
        if (iw > 0 && ih > 0 && iw * ih > kOccludedFraction * area)
            return true;
    }
    return false;
}

} // namespace ctrack
