// The only file that includes FLANN.
#include "appearance/nnindex.h"

#include "dsp/dsp.h"

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

static_assert(NNIndex::kBruteForceMax <= kNearestMaxPoints,
              "the brute-force search's rows fit the kernel (dsp.h)");

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

void NNIndex::brute_force(const float *q, int *index, float *dist2, const Dsp *dsp) const
{
    if (n_ == 0) {
        *index = -1;
        *dist2 = std::numeric_limits<float>::infinity();
        return;
    }
    *index = (dsp ? dsp->nn_nearest : nn_nearest_c)(by_dim_.data(), padded_, dim_, q, dist2);
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
