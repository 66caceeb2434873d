// The brute-force nearest-neighbour kernel (Dsp::nn_nearest) of the
// appearance templates' small point sets (appearance/nnindex.cc).
#include <cstdint>
#include <cstring>

#include "dsp/cpu.h"
#include "dsp/dsp.h"

namespace ctrack {

namespace {

// Every point's squared distance, the points in the vector lanes (the
// rows are padded to a multiple of 8 with points at infinity, never the
// nearest); the dimensions summed as flann::L2 does (four at a time, each
// group's sum added to the total, then the rest one by one), so that both
// searches see the same distances; then the nearest. Built for the portable
// path and for AVX2 (8 lanes): the same operations in the same order, no
// fused multiply-add, so the same bits (tests/check_dsp.cc).
CT_ALWAYS_INLINE int nearest(const float *__restrict by_dim, int stride, int dim,
                             const float *__restrict q, float *dist2)
{
    float acc[kNearestMaxPoints];
#if defined(__GNUC__)
    if (stride < 8 || stride > kNearestMaxPoints || stride % 8)
        __builtin_unreachable(); // the contract (dsp.h), which build() keeps
#endif
    for (int i = 0; i < stride; i++)
        acc[i] = 0;
    int d = 0;
    for (; d + 4 <= dim; d += 4) {
        const float *p0 = by_dim + (size_t)d * stride, *p1 = p0 + stride, *p2 = p1 + stride,
                    *p3 = p2 + stride;
        const float q0 = q[d], q1 = q[d + 1], q2 = q[d + 2], q3 = q[d + 3];
        for (int i = 0; i < stride; i++) {
            const float a0 = p0[i] - q0, a1 = p1[i] - q1, a2 = p2[i] - q2, a3 = p3[i] - q3;
            acc[i] += a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3;
        }
    }
    for (; d < dim; d++) {
        const float *p = by_dim + (size_t)d * stride, qd = q[d];
        for (int i = 0; i < stride; i++) {
            const float a = p[i] - qd;
            acc[i] += a * a;
        }
    }
    // The least, eight lanes at a time (each lane keeps its first least),
    // then the lanes' least, the first index of equals: the scalar scan's
    // answer. The padding's infinities are never less.
    constexpr int kLanes = kNearestLanes;
    float m[kLanes];
    int at[kLanes];
#if defined(__GNUC__)
    typedef float F8 __attribute__((vector_size(32)));
    typedef int32_t I8 __attribute__((vector_size(32)));
    F8 vm;
    I8 vat = {0, 1, 2, 3, 4, 5, 6, 7}, vi = vat;
    std::memcpy(&vm, acc, sizeof vm);
    for (int b = kLanes; b < stride; b += kLanes) {
        F8 v;
        std::memcpy(&v, acc + b, sizeof v);
        vi += kLanes;
        const I8 less = v < vm;
        vm = less ? v : vm;
        vat = less ? vi : vat;
    }
    std::memcpy(m, &vm, sizeof m);
    std::memcpy(at, &vat, sizeof at);
#else
    for (int k = 0; k < kLanes; k++) {
        m[k] = acc[k];
        at[k] = k;
    }
    for (int b = kLanes; b < stride; b += kLanes)
        for (int k = 0; k < kLanes; k++)
            if (acc[b + k] < m[k]) {
                m[k] = acc[b + k];
                at[k] = b + k;
            }
#endif
    int best = at[0];
    float bd = m[0];
    for (int k = 1; k < kLanes; k++)
        if (m[k] < bd || (m[k] == bd && at[k] < best)) {
            bd = m[k];
            best = at[k];
        }
    *dist2 = bd;
    return best;
}

} // namespace

int nn_nearest_c(const float *by_dim, int stride, int dim, const float *q, float *dist2)
{
    return nearest(by_dim, stride, dim, q, dist2);
}

namespace {

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) int nearest_avx2(const float *by_dim, int stride, int dim,
                                                 const float *q, float *dist2)
{
    return nearest(by_dim, stride, dim, q, dist2);
}
#endif

} // namespace

void nnindex_dsp_init(Dsp *dsp, unsigned flags)
{
    dsp->nn_nearest = nn_nearest_c;
#if defined(__x86_64__) && defined(__GNUC__)
    if (flags & kCpuAVX2)
        dsp->nn_nearest = nearest_avx2;
#endif
    (void)flags;
}

} // namespace ctrack
