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
    // A confirmed track's centre innovation this step (its normalized
    // square, Track::centre_nis()).
    void observe(double nis);
    // After a step of dt seconds: the scale moves toward the one under
    // which the innovations' mean normalized square is 1 (the filter's
    // consistency), by 1 - exp(-dt / kTimeConstant) of the way in log
    // terms, so that 7 and 30 frames/s learn alike in time.
    void learn(double dt);
    // How far the reported box of a track a detection updated goes from the
    // filter's estimate toward the detection, in [0, 1): 0 while the scene
    // moves as motion_noise says, toward 1 as it moves less predictably,
    // where the estimate lags behind the person.
    double follow() const;
    void reset();

private:
    double scale_ = 1.0;
    double sum_ = 0;
    int n_ = 0;
};

} // namespace ctrack

#endif
