#include "track/score_scale.h"

#include <algorithm>

#include "base/tunable.h"

namespace ctrack {

namespace {

// The share of the scores below the one asked for at most: the best 40%
// of boxes reach it (docs/tuning.md, "Confirmation").
CT_TUNABLE(kBelow, "CTRACK_CONFIRM_BELOW", 0.6);
// The counts are halved when their total reaches this: a long run keeps
// learning, and no count overflows.
constexpr uint32_t kMaxTotal = 1u << 20;

} // namespace

void ScoreScale::reset()
{
    std::fill(count_, count_ + kBins, 0u);
    total_ = 0;
}

void ScoreScale::observe(float score)
{
    count_[score_bin(score, kBins)]++;
    if (++total_ >= kMaxTotal) {
        total_ = 0;
        for (uint32_t &c : count_) {
            c /= 2;
            total_ += c;
        }
    }
}

float ScoreScale::best() const
{
    if (total_ == 0)
        return 1.0f;
    // The lower edge of the bin in which kBelow of the scores are reached.
    const double below = kBelow * total_;
    uint32_t sum = 0;
    int b = 0;
    for (; b < kBins - 1; b++) {
        sum += count_[b];
        if (sum >= below)
            break;
    }
    return (float)b / kBins;
}

} // namespace ctrack
