// What the tracker learns of its people's size as it runs: a standing
// person's height in pixels as a function of the image row of their feet.
// On a static camera over a flat ground, that height is close to a * (y_foot
// - y_horizon) (Renno, Orwell and Jones 2002; Hoiem, Efros and Hebert 2008);
// the model fits that line robustly to the boxes of confident single-person
// tracks, and until it has seen enough it only knows a weak prior: people
// are 30 to 400 pixels tall (then, up to the image's height where that is
// more).
#ifndef CTRACK_PERSON_SIZE_H
#define CTRACK_PERSON_SIZE_H

#include <cstdint>

namespace ctrack {

class PersonSize {
public:
    // The prior: people are between these heights, in frame pixels (the
    // most, on an image taller than it, the image's height: max_height()).
    static constexpr double kPriorMinHeight = 30, kPriorMaxHeight = 400;

    // Forgets everything; the image is `image_height` rows tall.
    void reset(int image_height);
    // A box (frame pixels) believed to hold one whole standing person.
    void observe(double top, double height, double width);
    // Fits the line to what was observed (once a step; cheap).
    void learn();

    // Whether enough was observed for the fit to speak.
    bool known() const { return known_; }
    // Whether it speaks for a person whose feet are at row y: known, y no
    // higher than a person's height above the highest feet it has seen, and
    // its line's person at y not much smaller than the one at those feet.
    // Above them its line is an extrapolation that falls to nothing at the
    // horizon it guesses, which on a street-level camera, whose people's
    // feet fill a narrow band of rows, it guesses badly.
    bool speaks_at(double y) const;
    // The expected height (frame pixels) of a person whose feet are at row
    // y, and the width three people in four there stay under; 0 while
    // unknown.
    double height_at(double y) const;
    double width_at(double y) const { return aspect_ * height_at(y); }
    // The height (frame pixels) of the person the fitted line puts under a
    // head at row y: h with h = slope * (y + h) + intercept, their feet at
    // y + h; 0 where there is none (unknown, a line as steep as the rows
    // themselves, or a head above the horizon it guesses). Not held at the
    // bounds: callers judge the person it gives. With `stature`, of a
    // person that many times the line's height at their feet.
    double height_under_head(double y, double stature = 1) const;
    // Whether height_at(y) is the fitted line's own, not held at its
    // bounds (max_height() above: where the line runs past the image's
    // height, height_at() says that height).
    bool line_holds_at(double y) const;
    // The tallest person the model allows: the prior's 400 pixels, or the
    // image's height where that is more (a high-definition camera shows
    // people close to it far taller than 400 pixels).
    double max_height() const;
    // A typical person's height where people are seen (frame pixels): the
    // line's height at the mean feet row of what was observed (the bands
    // weighed as in the fit); 0 while unknown.
    double typical_height() const { return known_ ? typical_ : 0; }
    // The fitted line: height = slope * y + intercept (frame pixels), and the
    // samples behind it.
    double slope() const { return slope_; }
    double intercept() const { return intercept_; }
    // Width over height: the ratio three people in four stay under.
    double aspect() const { return aspect_; }
    uint64_t samples() const { return samples_; }
    int image_height() const { return image_height_; }

private:
    // The fitted line's height at feet row y, unbounded.
    double line_at(double y) const { return slope_ * y + intercept_; }
    // Heights are kept per band of rows, as counts of log-spaced bins.
    static constexpr int kBands = 16;
    static constexpr int kBins = 48;
    uint16_t hist_[kBands][kBins] = {};
    uint32_t count_[kBands] = {};
    double foot_sum_[kBands] = {}; // the band's feet rows, summed
    uint16_t aspect_hist_[kBins] = {};
    uint32_t aspect_count_ = 0;
    int image_height_ = 0;
    uint64_t samples_ = 0;
    bool known_ = false;
    double slope_ = 0, intercept_ = 0, aspect_ = 0.4, typical_ = 0;
    double top_feet_ = 0; // the highest band's mean feet row
};

} // namespace ctrack

#endif
