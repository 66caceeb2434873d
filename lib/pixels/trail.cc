#include "pixels/trail.h"

#include <algorithm>
#include <cmath>

#include "base/tunable.h"

namespace ctrack {

namespace {

// The samples are remembered over about this long (a time constant).
CT_TUNABLE(kTrailTime, "CTRACK_TRAIL_TIME", 2.0);
// A weight is a peak of the ratios between these bins (0.1 to 0.75):
// without a filter the ratios only grow toward 1 (people's own pixels),
// and a pixel the person left falls to about 0.
constexpr int kLowBin = 2, kHighBin = 14;
// The peak stands this many times over the least of the kAfter bins above
// it, with at least kTrailMin samples in it (Background samples every 4th
// row): a person's own texture rises toward 1 without a peak. The bins
// above it hold as many samples again: the people's own pixels, whose
// texture and the sensor's noise move their differences a little from one
// frame to the next, outnumber their trail's. Flat drawn frames have none,
// and their edges' pixels, part person and part background, would make a
// peak of their own.
CT_TUNABLE(kTrailPeak, "CTRACK_TRAIL_PEAK", 1.5);
constexpr int kAfter = 4;
CT_TUNABLE(kTrailMin, "CTRACK_TRAIL_MIN", 50);
// Pixels up to this above the weight are the trail's.
CT_TUNABLE(kTrailMargin, "CTRACK_TRAIL_MARGIN", 0.2);

} // namespace

void TrailWeight::begin()
{
    std::fill(frame_, frame_ + kBins, 0u);
}

void TrailWeight::end(double dt)
{
    const double keep = kTrailTime > 0 ? std::exp(-std::max(0.0, dt) / kTrailTime) : 0;
    for (int b = 0; b < kBins; b++)
        hist_[b] = hist_[b] * keep + frame_[b];
    int peak = kLowBin;
    for (int b = kLowBin + 1; b <= kHighBin; b++)
        if (hist_[b] > hist_[peak])
            peak = b;
    double above = hist_[peak + 1], kept = 0;
    for (int b = peak + 2; b <= std::min(kBins - 1, peak + kAfter); b++)
        above = std::min(above, hist_[b]);
    for (int b = peak + 1; b < kBins; b++)
        kept += hist_[b];
    if (hist_[peak] >= kTrailMin && hist_[peak] >= kTrailPeak * above && kept >= hist_[peak]) {
        weight_ = (peak + 0.5) / kBins;
        limit_q8_ = (int)std::lround(256 * (weight_ + kTrailMargin));
    } else {
        weight_ = 0;
        limit_q8_ = 0;
    }
}

void TrailWeight::reset()
{
    *this = TrailWeight();
}

} // namespace ctrack
