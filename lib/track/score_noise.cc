#include "track/score_noise.h"

#include <algorithm>
#include <cmath>

#include "base/tunable.h"
#include "track/score_scale.h"

namespace ctrack {

namespace {

// How many innovations' worth of the mean of all a score's own mean starts
// from (docs/tuning.md: 5 to 80 score alike).
CT_TUNABLE(kPrior, "CTRACK_SCORE_NOISE_PRIOR", 20.0);
// The sums are halved when their count reaches this: a long run keeps
// learning (a detector's light changes), and nothing overflows.
constexpr double kMaxCount = 1 << 16;

} // namespace

void ScoreNoise::reset()
{
    *this = ScoreNoise();
}

void ScoreNoise::observe(float score, double innovation2)
{
    if (!std::isfinite(innovation2) || innovation2 < 0)
        return;
    const int b = score_bin(score, kBins);
    sum_[b] += innovation2;
    count_[b] += 1;
    sum_all_ += innovation2;
    count_all_ += 1;
    if (count_all_ >= kMaxCount) {
        for (int i = 0; i < kBins; i++) {
            sum_[i] /= 2;
            count_[i] /= 2;
        }
        sum_all_ /= 2;
        count_all_ /= 2;
    }
}

double ScoreNoise::factor(float score) const
{
    if (count_all_ < kMinSamples || !(sum_all_ > 0))
        return 1.0;
    const double all = sum_all_ / count_all_;
    const int b = score_bin(score, kBins);
    const double mine = (sum_[b] + kPrior * all) / (count_[b] + kPrior);
    return std::min(kMaxFactor, std::max(kMinFactor, std::sqrt(mine / all)));
}

} // namespace ctrack
