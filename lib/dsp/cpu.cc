#include "dsp/cpu.h"

#include <atomic>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace ctrack {

namespace {

std::atomic<unsigned> g_mask{~0u};

unsigned detect()
{
    unsigned flags = 0;
#if defined(__x86_64__) || defined(__i386__)
    unsigned a, b, c, d;
    if (__get_cpuid(1, &a, &b, &c, &d)) {
        if (c & bit_SSSE3)
            flags |= kCpuSSSE3;
        // AVX2 needs the CPU's bit and the OS's saving of the YMM registers
        // (OSXSAVE, then XCR0's SSE and AVX state bits).
        const bool osxsave = (c & bit_OSXSAVE) != 0;
        if (osxsave && __get_cpuid_count(7, 0, &a, &b, &c, &d) && (b & bit_AVX2)) {
            unsigned lo, hi;
            __asm__("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
            if ((lo & 6) == 6)
                flags |= kCpuAVX2;
        }
    }
#elif defined(__aarch64__)
    flags |= kCpuNEON;
#endif
    return flags;
}

} // namespace

unsigned cpu_flags()
{
    static const unsigned detected = detect(); // once, thread-safe (C++11)
    return detected & g_mask.load(std::memory_order_relaxed);
}

void set_cpu_mask(unsigned mask)
{
    g_mask.store(mask, std::memory_order_relaxed);
}

} // namespace ctrack
