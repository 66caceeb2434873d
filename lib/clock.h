// A monotonic stopwatch for the per-stage timers.
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

} // namespace ctrack

#endif
