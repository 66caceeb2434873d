// A monotonic stopwatch for the per-stage timers, and the time between two
// of the frames' timestamps.
#ifndef CTRACK_CLOCK_H
#define CTRACK_CLOCK_H

#include <chrono>
#include <cstdint>

namespace ctrack {

class Stopwatch {
public:
    Stopwatch() : last_(std::chrono::steady_clock::now()) {}
    // Nanoseconds since construction or the previous lap.
    uint64_t lap()
    {
        auto now = std::chrono::steady_clock::now();
        auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now - last_).count();
        last_ = now;
        return (uint64_t)ns;
    }

private:
    std::chrono::steady_clock::time_point last_;
};

// The time from `earlier` to `later` (later >= earlier: the timestamps of
// the feeds increase). It may not fit in an int64_t (from INT64_MIN to
// INT64_MAX), so it is computed unsigned.
inline uint64_t elapsed_us(int64_t later, int64_t earlier)
{
    return (uint64_t)later - (uint64_t)earlier;
}
inline double elapsed_s(int64_t later, int64_t earlier)
{
    return (double)elapsed_us(later, earlier) * 1e-6;
}

} // namespace ctrack

#endif
