// The closing's row kernels (Dsp::close_row3, close_rows), for the
// morphology of pixels/regions.cc.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "dsp/cpu.h"
#include "dsp/dsp.h"

namespace ctrack {

namespace {

// Written once, built portable (the reference) and for AVX2, which
// dsp_init() picks by the CPU; the compiler vectorises each loop for its
// target (tests/check_dsp.cc checks the builds against each other).
template <bool Max> CT_ALWAYS_INLINE uint8_t op(uint8_t a, uint8_t b)
{
    return Max ? std::max(a, b) : std::min(a, b);
}

// dst[x] = max (or min) of src[x - 1], src[x], src[x + 1] for x in [1, n - 1).
template <bool Max> CT_ALWAYS_INLINE void row3(const uint8_t *src, uint8_t *dst, int n)
{
    const uint8_t *__restrict s = src;
    uint8_t *__restrict d = dst;
    for (int x = 1; x < n - 1; x++)
        d[x] = op<Max>(op<Max>(s[x - 1], s[x]), s[x + 1]);
}

// dst = max (or min) of the `rows` rows (1 to 5) of n bytes at src, stride
// apart: one pass, the missing rows standing in for the first (max and
// min are idempotent).
template <bool Max>
CT_ALWAYS_INLINE void rows_op(const uint8_t *src, size_t stride, int rows, uint8_t *dst, int n)
{
    const uint8_t *p[5];
    for (int r = 0; r < 5; r++)
        p[r] = src + (r < rows ? (size_t)r * stride : 0);
    const uint8_t *__restrict s0 = p[0], *__restrict s1 = p[1], *__restrict s2 = p[2];
    const uint8_t *__restrict s3 = p[3], *__restrict s4 = p[4];
    uint8_t *__restrict d = dst;
    for (int x = 0; x < n; x++)
        d[x] = op<Max>(op<Max>(op<Max>(s0[x], s1[x]), op<Max>(s2[x], s3[x])), s4[x]);
}

void row3_c(const uint8_t *src, uint8_t *dst, int n, bool max)
{
    max ? row3<true>(src, dst, n) : row3<false>(src, dst, n);
}
void rows_c(const uint8_t *src, size_t stride, int rows, uint8_t *dst, int n, bool max)
{
    max ? rows_op<true>(src, stride, rows, dst, n) : rows_op<false>(src, stride, rows, dst, n);
}
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) void row3_avx2(const uint8_t *src, uint8_t *dst, int n, bool max)
{
    max ? row3<true>(src, dst, n) : row3<false>(src, dst, n);
}
__attribute__((target("avx2"))) void rows_avx2(const uint8_t *src, size_t stride, int rows,
                                               uint8_t *dst, int n, bool max)
{
    max ? rows_op<true>(src, stride, rows, dst, n) : rows_op<false>(src, stride, rows, dst, n);
}
#endif

} // namespace

void regions_dsp_init(Dsp *dsp, unsigned flags)
{
    dsp->close_row3 = row3_c;
    dsp->close_rows = rows_c;
#if defined(__x86_64__) && defined(__GNUC__)
    if (flags & kCpuAVX2) {
        dsp->close_row3 = row3_avx2;
        dsp->close_rows = rows_avx2;
    }
#endif
    (void)flags;
}

} // namespace ctrack
