// One person's track: its boxes' motion model, its state and what it keeps
// of the person (colour model, appearance template).
#ifndef CTRACK_TRACK_H
#define CTRACK_TRACK_H

#include <cstdint>
#include <vector>

#include "base/memory.h"

#include "ctrack/ctrack.h"
#include "meanshift/meanshift.h"
#include "track/motion.h"

namespace ctrack {

struct Box {
    double left, top, width, height;
};

double iou(const Box &a, const Box &b);
// The share of the smaller of a and b that the other covers.
double overlap_share(const Box &a, const Box &b);
// The IoU of a and b each widened by `buffer` of its own width and height
// on every side (Yang et al.'s buffered IoU, WACV 2023): an offset between
// the centres counts 1 + 2 buffer times less against the boxes' sizes, a
// ratio of sizes as much as in iou().
double buffered_iou(const Box &a, const Box &b, double buffer);
// Lowers each buffers[k] so that boxes[k], widened by it as in
// buffered_iou(), reaches no other box widened by the same share; for two
// boxes that already overlap, to 0. order is scratch.
void separate_buffers(const Vec<Box> &boxes, Vec<double> &buffers, Vec<int> &order);

inline Box det_box(const ct_detection &d)
{
    return Box{d.left, d.top, d.width, d.height};
}

// The part of a box that lies in a w x h image.
double inside_fraction(const Box &b, int w, int h);

// One image size: 0 x 0 when unknown.
struct ImageSize {
    int width = 0, height = 0;
    bool known() const { return width > 0 && height > 0; }
};

// A box's constant-velocity model: its centre, width and height.
struct BoxMotion {
    Axis cx, cy, w, h;

    Box box() const;
    // Its first box, d, known to within sd on each coordinate, its velocity
    // to within vsd (the size's to within a fraction of it).
    void init(const ct_detection &d, double sd, double vsd);
    // dt seconds ahead, under an acceleration noise of motion_noise box
    // heights per second squared on the centre (the size's a fraction).
    void predict(double dt, double motion_noise);
    // Corrected by box d, measured to within sd on each coordinate.
    void update(const ct_detection &d, double sd);
    // Box d's centre innovation on each axis, over its standard deviation
    // (d measured to within detection_noise of its height).
    void normalized_innovation(const ct_detection &d, double detection_noise, double *nx,
                               double *ny) const;
};

struct Track : BoxMotion {
    uint64_t id = 0;              // 0 until confirmed
    int state = CT_TRACK_TENTATIVE;
    // The motion model that association reads is the one above; the boxes
    // reported come from this one, the same model under the noises
    // SceneMotion learns for them (Engine::update()): it follows a
    // detector's boxes as closely as their innovations say they can be
    // followed, where association needs a steady prediction.
    BoxMotion shown;
    // shown's last centre innovation (normalized) and the step it came at.
    double shown_nx = 0, shown_ny = 0;
    int shown_age = -1;
    int age = 0, hits = 0;
    int64_t last_update_us = 0;
    float seen_h = 0; // the height of the last detection
    Box seen{0, 0, 0, 0}; // the last detection's box
    // Where it started, and whether it has since moved half its height: a
    // track that never moved may be a ghost of the background model.
    double start_x = 0, start_y = 0;
    bool moved = false;
    // Its first box's bottom, and when it was seen: where counting takes
    // its starting side of a line from.
    double start_bottom = 0;
    int64_t start_us = 0;
    // From the pixels alone: when its candidate last moved inside
    // (PixelCandidates::live(); read only while it has not moved), and
    // whether it is taken for an object put
    // down (a sign, a bag): it never moved and nothing moved in it for a
    // while. An object's blob is learnt by the background and is no
    // candidate.
    int64_t live_us = 0;
    bool object = false;
    // With a detector's boxes and frames, the person's own stature: their
    // silhouette's head-to-feet extent over the people's size at its feet,
    // a running mean over the fits that saw the whole extent
    // (Engine::fit_reported()), and how many it is over.
    double stature = 0;
    int stature_n = 0;
    // The last step a still track's box stirred (Engine::follow_or_lose()).
    int64_t stir_us = -1;
    int det_index = -1;
    int class_id = 0;
    float score = 0;
    float best_score = 0; // the highest score of its detections
    // The box association compares with detections this step: the
    // prediction, or where mean shift moved it.
    Box cue{0, 0, 0, 0};
    // The centre's standard deviation (the less certain axis) one step
    // after the track's last correction: how far its person may stray from
    // the prediction while the track keeps up with them. Not grown while
    // the track coasts (Engine::buffer()).
    double sd_after_hit = 0;
    // This step's mean shift result, when it ran (rho in Q16).
    bool followed = false;
    MeanShiftResult ms;
    ColorModel model;
    // Appearance template: a slot of the TemplateBank (-1: none), and when
    // it was made.
    int tmpl = -1;
    int64_t tmpl_us = 0;

    // How far box b's centre lies from where the track started.
    double from_start(const Box &b) const;
    // The motion models started at detection d (position noise
    // detection_noise box heights) and the bookkeeping of a first hit.
    void start(const ct_detection &d, double detection_noise, int index, int64_t t_us);
    // Predicts dt seconds ahead (acceleration noise motion_noise box heights
    // per second squared; shown_noise for the reported box's model) and
    // forgets the last step's match and mean shift; after a correction,
    // sets sd_after_hit.
    void predict(double dt, double motion_noise, double shown_noise);
    // The centre's normalized innovation squared for detection d (the mean
    // of both axes), before correct().
    double centre_nis(const ct_detection &d, double detection_noise) const;
    // Detection d's centre's squared innovation in the track's heights
    // squared (the mean of both axes), before correct().
    double centre_innovation2(const ct_detection &d) const;
    // The standard deviation of a detection's centre about the prediction
    // on the less certain axis (a detection's noise at the track's height).
    double centre_innovation_sd(double detection_noise) const;
    // Corrects the motion models by detection d (shown's with its own
    // noise, shown_noise box heights), and records the hit.
    void correct(const ct_detection &d, double detection_noise, double shown_noise, int index,
                 int64_t t_us);
    // Corrects the motion model by where mean shift followed the person
    // (this->ms), trusted less than a detection; the reported box is then
    // that estimate.
    void follow(double detection_noise);
};

// Whether another non-tentative track covers more than a fifth of track i's
// box: it is then not followed by mean shift, and its colour model and
// appearance template are left as they are.
bool occluded(const Vec<Track> &tracks, size_t i);

} // namespace ctrack

#endif
