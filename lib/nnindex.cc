// The only file that includes FLANN.
#include "nnindex.h"

#include "cpu.h"
#include "dsp.h"

// Every standard header FLANN includes, first: the malloc macro below must
// reach FLANN's own code only.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits.h>
#include <limits>
#include <lz4.h>
#include <lz4hc.h>
#include <map>
#include <new>
#include <ostream>
#include <random>
#include <set>
#include <stdexcept>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <string>
#include <typeinfo>
#include <vector>

namespace {

// FLANN's PooledAllocator (the kd-tree's nodes) takes its blocks from
// malloc and does not check it: on a failed allocation it returns NULL,
// and `new (pool) Node()` constructs at address 0. Its mallocs come here
// instead, where a failure throws std::bad_alloc like any other
// allocation of the library (the feed then fails and changes nothing;
// tests/check_oom.cc fails each of them).
void *checked_malloc(size_t n)
{
    void *p = std::malloc(n);
    if (!p)
        throw std::bad_alloc();
    return p;
}

} // namespace

// Only what the single kd-tree needs. Its virtual saveIndex() still pulls in
// FLANN's serialisation, so the library links lz4 (lib/meson.build).
#define malloc(n) checked_malloc(n)
#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>
#include <flann/util/matrix.h>
#include <flann/util/result_set.h>
#undef malloc

namespace ctrack {

struct NNIndex::Impl {
    using Index = flann::KDTreeSingleIndex<flann::L2<float>>;
    Impl(float *data, int n, int dim)
        : matrix(data, (size_t)n, (size_t)dim),
          index(matrix, flann::KDTreeSingleIndexParams(8, false))
    {
        index.buildIndex();
    }
    flann::Matrix<float> matrix;
    Index index;
};

NNIndex::NNIndex() = default;
NNIndex::~NNIndex() = default;

NNIndex::NNIndex(const NNIndex &other)
{
    *this = other;
}

NNIndex &NNIndex::operator=(const NNIndex &other)
{
    if (this == &other)
        return *this;
    if (other.n_ == 0) {
        impl_.reset();
        points_.clear();
        by_dim_.clear();
        n_ = dim_ = 0;
        return *this;
    }
    build(other.points_.data(), other.n_, other.dim_, other.impl_ && other.n_ <= kBruteForceMax);
    return *this;
}

void NNIndex::build(const float *points, int n, int dim, bool force_tree)
{
    // Empty until the index stands: if an allocation fails on the way, the
    // index is left empty, never half built.
    impl_.reset();
    n_ = dim_ = 0;
    points_.assign(points, points + (size_t)n * dim);
    if (n > 0 && (force_tree || n > kBruteForceMax)) {
        by_dim_.clear();
        impl_ = make_owned<Impl>(points_.data(), n, dim);
    } else {
        padded_ = (n + kLanes - 1) / kLanes * kLanes;
        by_dim_.assign((size_t)padded_ * dim, std::numeric_limits<float>::infinity());
        for (int i = 0; i < n; i++)
            for (int d = 0; d < dim; d++)
                by_dim_[(size_t)d * padded_ + i] = points_[(size_t)i * dim + d];
    }
    n_ = n;
    dim_ = dim;
}

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
    float acc[NNIndex::kBruteForceMax];
#if defined(__GNUC__)
    if (stride < 8 || stride > NNIndex::kBruteForceMax || stride % 8)
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
    constexpr int kLanes = 8;
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

int nearest_c(const float *by_dim, int stride, int dim, const float *q, float *dist2)
{
    return nearest(by_dim, stride, dim, q, dist2);
}
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
    dsp->nn_nearest = nearest_c;
#if defined(__x86_64__) && defined(__GNUC__)
    if (flags & kCpuAVX2)
        dsp->nn_nearest = nearest_avx2;
#endif
    (void)flags;
}

void NNIndex::brute_force(const float *q, int *index, float *dist2, const Dsp *dsp) const
{
    if (n_ == 0) {
        *index = -1;
        *dist2 = std::numeric_limits<float>::infinity();
        return;
    }
    *index = (dsp ? dsp->nn_nearest : nearest_c)(by_dim_.data(), padded_, dim_, q, dist2);
}

void NNIndex::search(const float *queries, int nq, int *index, float *dist2, float eps,
                     const Dsp *dsp) const
{
    if (!impl_) {
        // Exact whatever eps asks: the comparison of all pairs is the
        // cheapest search there is at this size.
        for (int q = 0; q < nq; q++)
            brute_force(queries + (size_t)q * dim_, index + q, dist2 + q, dsp);
        return;
    }
    flann::KNNSimpleResultSet<float> result(1);
    flann::SearchParams params(-1, eps);
    for (int q = 0; q < nq; q++) {
        result.clear();
        impl_->index.findNeighbors(result, queries + (size_t)q * dim_, params);
        size_t i = 0;
        float d = 0;
        result.copy(&i, &d, 1);
        index[q] = (int)i;
        dist2[q] = d;
    }
}

size_t NNIndex::memory_bytes() const
{
    // The tree's nodes are FLANN's; about two per leaf of 8 points.
    return (points_.capacity() + by_dim_.capacity()) * sizeof(float) +
           (impl_ ? (size_t)n_ / 4 * 64 + 256 : 0);
}

} // namespace ctrack
