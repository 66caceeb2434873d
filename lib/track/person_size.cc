#include "track/person_size.h"

#include <algorithm>
#include <cmath>

#include "base/tunable.h"

namespace ctrack {

namespace {

// Heights from kLowest pixels up, each bin kStep times the one before (48
// bins to 1,024 pixels: 10% apart); aspects (width over height) likewise
// from 0.1 (48 bins to 1.5: 6% apart).
constexpr double kLowest = 8, kStep = 1.1063;
constexpr double kLowestAspect = 0.1, kAspectStep = 1.0580;
// A band speaks once it holds this many samples; the model once it holds
// this many in all.
constexpr uint32_t kMinBand = 5, kMinSamples = 20;
// The width a person is given: the width three people in four stay under, so
// that a group is split into no more people than it holds (docs/tuning.md,
// "The people's size: its constants": the median splits
// TUD-Campus's groups into too many).
CT_TUNABLE(kWidthQuantile, "CTRACK_WIDTH_QUANTILE", 0.75);
// How far above the highest feet seen, in the height of a person there,
// the model speaks for a blob's size (PersonSize::speaks_at(); docs/tuning.md,
// "Where the people's size speaks").
CT_TUNABLE(kFeetMargin, "CTRACK_FEET_MARGIN", 1.0);
// Nor where its line's person is under kMinShrink of the person at those
// feet: a line fitted to a narrow band of feet rows can fall to a few
// pixels within that margin, and a blob there would be taken for a group
// of such people and cut into slivers a column wide (docs/tuning.md,
// "Where the people's size speaks").
CT_TUNABLE(kMinShrink, "CTRACK_MIN_SHRINK", 0.7);
// A band's counts are halved past this, so that the model keeps learning.
constexpr uint32_t kMaxBand = 1000;
// A band weighs at most this many samples in the fit.
constexpr double kMaxWeight = 50;

int bin_of(double v, double lowest, double step, int bins)
{
    const int b = (int)std::floor(std::log(v / lowest) / std::log(step));
    return std::min(bins - 1, std::max(0, b));
}

// The q-quantile bin of a histogram of n counts, as the value at its
// centre.
double quantile_of(const uint16_t *hist, int bins, uint32_t n, double q, double lowest,
                   double step)
{
    uint32_t below = 0;
    for (int b = 0; b < bins; b++) {
        if (below + hist[b] >= q * n)
            return lowest * std::pow(step, b + 0.5);
        below += hist[b];
    }
    return lowest * std::pow(step, bins - 0.5);
}

double median_of(const uint16_t *hist, int bins, uint32_t n, double lowest, double step)
{
    return quantile_of(hist, bins, n, 0.5, lowest, step);
}

} // namespace

void PersonSize::reset(int image_height)
{
    *this = PersonSize();
    image_height_ = image_height;
}

void PersonSize::observe(double top, double height, double width)
{
    if (image_height_ <= 0 || !(height > 0) || !(width > 0))
        return;
    const double foot = top + height;
    const int band = std::min(kBands - 1, std::max(0, (int)(foot * kBands / image_height_)));
    hist_[band][bin_of(height, kLowest, kStep, kBins)]++;
    foot_sum_[band] += foot;
    if (++count_[band] > kMaxBand) {
        const uint32_t before = count_[band];
        count_[band] = 0;
        for (uint16_t &c : hist_[band]) {
            c = (uint16_t)(c / 2);
            count_[band] += c;
        }
        foot_sum_[band] *= (double)count_[band] / before;
    }
    aspect_hist_[bin_of(width / height, kLowestAspect, kAspectStep, kBins)]++;
    if (++aspect_count_ > kMaxBand) {
        aspect_count_ = 0;
        for (uint16_t &c : aspect_hist_) {
            c = (uint16_t)(c / 2);
            aspect_count_ += c;
        }
    }
    samples_++;
}

void PersonSize::learn()
{
    // Weighted least squares through each band's median height, at the
    // band's mean feet row.
    double sw = 0, sy = 0, sh = 0, syy = 0, syh = 0;
    uint32_t total = 0;
    int bands = 0;
    top_feet_ = image_height_;
    for (int b = 0; b < kBands; b++) {
        total += count_[b];
        if (count_[b] < kMinBand)
            continue;
        const double h = median_of(hist_[b], kBins, count_[b], kLowest, kStep);
        const double y = foot_sum_[b] / count_[b];
        top_feet_ = std::min(top_feet_, y);
        const double w = std::min<double>(count_[b], kMaxWeight);
        sw += w;
        sy += w * y;
        sh += w * h;
        syy += w * y * y;
        syh += w * y * h;
        bands++;
    }
    if (bands == 0 || total < kMinSamples)
        return;
    const double my = sy / sw, mh = sh / sw, vy = syy / sw - my * my;
    // One band, or a line sloping the wrong way (people smaller nearer the
    // bottom: no flat ground seen from above): a constant height.
    slope_ = bands >= 2 && vy > 0 ? std::max(0.0, (syh / sw - my * mh) / vy) : 0.0;
    intercept_ = mh - slope_ * my;
    typical_ = std::min(max_height(), std::max(kLowest, mh));
    aspect_ = quantile_of(aspect_hist_, kBins, aspect_count_, kWidthQuantile, kLowestAspect,
                          kAspectStep);
    known_ = true;
}

bool PersonSize::speaks_at(double y) const
{
    if (!known_)
        return false;
    const double at_feet = height_at(top_feet_);
    return y >= top_feet_ - kFeetMargin * at_feet && line_at(y) >= kMinShrink * at_feet;
}

double PersonSize::height_under_head(double y, double stature) const
{
    if (!known_ || !(stature > 0) || std::fabs(1 - stature * slope_) < 1e-6)
        return 0;
    const double tall = stature * (slope_ * y + intercept_) / (1 - stature * slope_);
    return tall > 0 ? tall : 0;
}

double PersonSize::max_height() const
{
    return std::max(kPriorMaxHeight, (double)image_height_);
}

bool PersonSize::line_holds_at(double y) const
{
    const double h = line_at(y);
    return known_ && h >= kLowest && h < max_height();
}

double PersonSize::height_at(double y) const
{
    if (!known_)
        return 0;
    return std::min(max_height(), std::max(kLowest, line_at(y)));
}

} // namespace ctrack
