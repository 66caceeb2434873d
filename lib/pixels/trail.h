// A walker's trail: a camera's temporal noise filter that blends each
// frame with the ones before leaves a fading copy of a moving person where
// they were the frame before. There this frame's difference from the
// background is the last frame's, on the same side, times the filter's
// weight; where the person still stands it is about the same or larger.
// The weight is learnt online from the frames (docs/tuning.md, "A walker's
// trail"): a camera without such a filter shows none, nor does a
// motion-adaptive one or a slow shutter's smear, and their pixels are left
// as they are.
#ifndef CTRACK_TRAIL_H
#define CTRACK_TRAIL_H

#include <cstdint>

namespace ctrack {

// The ratios of the differences over a few seconds, and the weight they
// show.
class TrailWeight {
public:
    // The ratios over [0, 1) in kBins bins.
    static constexpr int kBins = 20;
    // This frame's samples start.
    void begin();
    // A pixel foreground the frame before whose difference from the
    // background fell from `then` to `now` (0 < now < then), on the same
    // side.
    void sample(int now, int then) { frame_[now * kBins / then]++; }
    // The frame's samples into the estimate, dt seconds after the last.
    void end(double dt);
    // Whether the frames show a trail, and such a pixel is in it.
    bool known() const { return weight_ > 0; }
    bool trail(int now, int then) const { return now * 256 <= limit_q8_ * then; }
    double weight() const { return weight_; }
    void reset();

private:
    uint32_t frame_[kBins] = {};
    double hist_[kBins] = {};
    double weight_ = 0;
    int limit_q8_ = 0; // the highest ratio of a trail, in 256ths (0: none)
};

} // namespace ctrack

#endif
