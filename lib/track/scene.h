// What the tracker learns of the scene's motion as it runs: how much less
// predictable the boxes move than motion_noise describes (a camera that
// pans, shakes or drives; people close to it), from the innovations of the
// tracks it updates. One scale for the whole scene: a moving camera moves
// every box.
#ifndef CTRACK_SCENE_H
#define CTRACK_SCENE_H

namespace ctrack {

class SceneMotion {
public:
    // The factor (>= 1) on the variance of motion_noise's acceleration.
    double scale() const { return scale_; }
    // The factor on detection_noise: 1, or what learn(dt, true) learnt.
    double noise() const { return noise_; }
    // A confirmed track's centre innovation this step (its normalized
    // square, Track::centre_nis()).
    void observe(double nis);
    // A confirmed track's normalized centre innovations this step (nx, ny)
    // and at the step before (px, py), both updated by a detection.
    void observe_pair(double nx, double ny, double px, double py);
    // After a step of dt seconds: the scale moves toward the one under
    // which the innovations' mean normalized square is 1 (the filter's
    // consistency), by 1 - exp(-dt / kTimeConstant) of the way in log
    // terms, so that 7 and 30 frames/s learn alike in time. With whiten,
    // the noise factor too moves toward the one under which a track's
    // successive innovations are uncorrelated (Mehra's whiteness test of
    // an optimal filter): a filter that lags behind the boxes sees the same
    // error twice and trusts the detections more, one that chases their
    // jitter sees it change sign and trusts them less.
    void learn(double dt, bool whiten = false);
    void reset();

private:
    double scale_ = 1.0;
    double noise_ = 1.0;
    double sum_ = 0;
    int n_ = 0;
    double pairs_ = 0, squares_ = 0;
};

} // namespace ctrack

#endif
