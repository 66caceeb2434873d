#include "track/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "base/tunable.h"

namespace ctrack {

namespace {

// How fast the scale follows the innovations, in seconds.
CT_TUNABLE(kTimeConstant, "CTRACK_SCENE_TIME", 0.3);
// One innovation counts at most this much (a wrong match, a person who
// turns): about three standard deviations.
constexpr double kMaxNis = 9.0;
// The largest scale: an acceleration noise 30 times motion_noise's.
constexpr double kMaxScale = 900.0;
// The scale's excess over 1 at which the reported box goes halfway from the
// estimate to the detection.
CT_TUNABLE(kFollowHalf, "CTRACK_SCENE_FOLLOW", 20.0);

} // namespace

void SceneMotion::observe(double nis)
{
    sum_ += std::min(nis, kMaxNis);
    n_++;
}

void SceneMotion::learn(double dt)
{
    if (n_ > 0 && dt > 0) {
        const double rate = 1.0 - std::exp(-dt / kTimeConstant);
        scale_ = std::min(kMaxScale, std::max(1.0, scale_ * std::pow(sum_ / n_, rate)));
    }
    sum_ = 0;
    n_ = 0;
}

double SceneMotion::follow() const
{
    return (scale_ - 1.0) / (scale_ - 1.0 + kFollowHalf);
}

void SceneMotion::reset()
{
    *this = SceneMotion();
}

} // namespace ctrack
