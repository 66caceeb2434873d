// The CPU's vector features, detected once, and the mask through which
// tests force slower paths (dav1d's dav1d_get_cpu_flags and its mask).
#ifndef CTRACK_CPU_H
#define CTRACK_CPU_H

namespace ctrack {

enum CpuFlag : unsigned {
    kCpuSSSE3 = 1u << 0, // x86-64: byte shuffles
    kCpuAVX2 = 1u << 1,  // x86-64: 256-bit integer vectors (the OS saves them)
    kCpuNEON = 1u << 2,  // aarch64: always
};

// The features of this CPU that the mask lets through. Thread-safe; the
// detection itself runs once, at the first call (never before main(), so
// every sanitizer's runtime is up by then).
unsigned cpu_flags();

// Internal, for tests: only the features in mask are used by trackers
// created afterwards (0: the portable path everywhere). All by default.
void set_cpu_mask(unsigned mask);

} // namespace ctrack

#endif
