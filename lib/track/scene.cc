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
// How fast the noise factor follows the innovations' correlation, in
// seconds, and the bounds it stays within: a detector's boxes from four
// times as sure to ten times less sure than detection_noise says.
CT_TUNABLE(kNoiseTime, "CTRACK_NOISE_TIME", 1.0);
constexpr double kMinNoise = 0.25;
constexpr double kMaxNoise = 10.0;

} // namespace

void SceneMotion::observe(double nis)
{
    sum_ += std::min(nis, kMaxNis);
    n_++;
}

void SceneMotion::observe_pair(double nx, double ny, double px, double py)
{
    pairs_ += nx * px + ny * py;
    squares_ += 0.5 * (nx * nx + ny * ny + px * px + py * py);
}

void SceneMotion::learn(double dt, bool whiten)
{
    if (n_ > 0 && dt > 0) {
        const double rate = 1.0 - std::exp(-dt / kTimeConstant);
        scale_ = std::min(kMaxScale, std::max(1.0, scale_ * std::pow(sum_ / n_, rate)));
    }
    if (whiten && squares_ > 0 && dt > 0) {
        // The correlation, in [-1, 1] (|ab| <= (a^2 + b^2) / 2), moves the
        // factor in log terms.
        const double rate = std::min(1.0, dt / kNoiseTime);
        noise_ = std::min(kMaxNoise,
                          std::max(kMinNoise, noise_ * std::exp(-rate * pairs_ / squares_)));
    }
    sum_ = 0;
    n_ = 0;
    pairs_ = 0;
    squares_ = 0;
}

void SceneMotion::reset()
{
    *this = SceneMotion();
}

} // namespace ctrack
