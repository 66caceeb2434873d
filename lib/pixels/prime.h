// A recording's background before tracking it (ct_tracker_prime()): each
// byte's median over a few of its first frames, and those frames with the
// people in them put back to the median.
#ifndef CTRACK_PRIME_H
#define CTRACK_PRIME_H

#include <cstddef>
#include <cstdint>

#include "base/memory.h"
#include "base/tunable.h"

#include "ctrack/ctrack.h"

namespace ctrack {

// A byte more than this many times its plane's noise from the median is
// taken for a person and put back to the median (docs/tuning.md, "A
// recording's start").
CT_TUNABLE(kPrimeClean, "CTRACK_PRIME_CLEAN", 5.0);

// The most frames ct_tracker_prime() takes (18 minutes at 60 frames/s):
// more is a count gone wrong.
constexpr size_t kPrimeMaxFrames = CT_PRIME_MAX_FRAMES;

// At most this many of the frames (evenly spaced) give the median.
constexpr size_t kPrimeMedianFrames = 31;

// A frame's pixels in one tightly packed buffer, in its own format: the
// median, and the cleaned frames fed to the tracker.
class PackedFrame {
public:
    // Sizes the buffer for frames like `like` (validated, with pixels) and
    // describes it in frame(), with like's timestamp.
    void shape(const ct_frame &like);
    const ct_frame &frame() const { return frame_; }

private:
    Vec<uint8_t> bytes_;
    ct_frame frame_{};
};

// Into `median`, each byte's median over the frames, or over
// kPrimeMedianFrames of them evenly spaced when there are more (of an even
// count, the upper of the two middle values). Frames are validated, of one
// size and format, n >= 1.
void median_frame(const ct_frame *frames, size_t n, PackedFrame *median);

// Into `out`, `frame` with every byte that differs from the median's by more
// than k times its plane's noise (1.4826 times the median absolute
// difference, at least 1) set to the median's: the people who walk through
// are taken out, and the frame keeps its noise. out takes frame's timestamp.
void clean_frame(const ct_frame &frame, const PackedFrame &median, double k, PackedFrame *out);

} // namespace ctrack

#endif
