// Nearest-neighbour search over a small point set: up to kBruteForceMax
// points by comparing each query with every point, past that with FLANN's
// single kd-tree. FLANN's headers stay in nnindex.cc alone: they are no
// business of the rest of the library.
#ifndef CTRACK_NNINDEX_H
#define CTRACK_NNINDEX_H

#include <cstddef>
#include <memory>
#include <vector>

#include "base/memory.h"
#include "dsp/dsp.h"

namespace ctrack {

class NNIndex {
public:
    // At most this many points are searched without a tree. An appearance
    // template has 72; bench/ddis-bench measures both searches on it
    // (docs/bench.md): the comparison of all pairs takes a fraction of
    // FLANN's time and allocates nothing, where FLANN's findNeighbors
    // allocates on every query and its tree on every build.
    static constexpr int kBruteForceMax = 128;

    NNIndex();
    ~NNIndex();
    NNIndex(const NNIndex &other);
    NNIndex &operator=(const NNIndex &other);

    // Indexes n points of dim floats (row-major; copied). The single
    // kd-tree is deterministic, unlike FLANN's randomized trees, which draw
    // from the global std::rand().
    // With force_tree, FLANN indexes any number of points (tests compare
    // the two searches).
    void build(const float *points, int n, int dim, bool force_tree = false);
    bool empty() const { return n_ == 0; }
    int size() const { return n_; }

    // For each of nq queries: the index of its nearest point and the squared
    // distance to it. eps = 0 is exact; eps > 0 accepts a neighbour within
    // (1 + eps) of the nearest distance. Exact searches without the tree
    // sum the squared differences in FLANN's order (L2 over groups of four)
    // and keep the first of equal distances.
    // `dsp` (null: the portable build) picks the comparison's build.
    void search(const float *queries, int nq, int *index, float *dist2, float eps = 0,
                const Dsp *dsp = nullptr) const;

    size_t memory_bytes() const;

private:
    struct Impl;
    Owned<Impl> impl_;
    void brute_force(const float *query, int *index, float *dist2, const Dsp *dsp) const;
    Vec<float> points_;
    // Without the tree: the points by dimension (dim_ rows of n_ floats,
    // padded to the kernel's lanes), for comparing a query with all of them
    // at once.
    static constexpr int kLanes = kNearestLanes;
    Vec<float> by_dim_;
    int padded_ = 0; // by_dim_'s row length
    int n_ = 0, dim_ = 0;
};

} // namespace ctrack

#endif
