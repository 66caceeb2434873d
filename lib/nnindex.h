// Nearest-neighbour search over a small point set, with FLANN's single
// kd-tree. FLANN's headers stay in nnindex.cc alone: they do not mix with
// OpenCV's, and they are no business of the rest of the library.
#ifndef CTRACK_NNINDEX_H
#define CTRACK_NNINDEX_H

#include <cstddef>
#include <memory>
#include <vector>

namespace ctrack {

class NNIndex {
public:
    NNIndex();
    ~NNIndex();
    NNIndex(const NNIndex &other);
    NNIndex &operator=(const NNIndex &other);

    // Indexes n points of dim floats (row-major; copied). The single
    // kd-tree is deterministic, unlike FLANN's randomized trees, which draw
    // from the global std::rand().
    void build(const float *points, int n, int dim);
    bool empty() const { return n_ == 0; }
    int size() const { return n_; }

    // For each of nq queries: the index of its nearest point and the squared
    // distance to it. eps = 0 is exact; eps > 0 accepts a neighbour within
    // (1 + eps) of the nearest distance.
    void search(const float *queries, int nq, int *index, float *dist2, float eps = 0) const;

    size_t memory_bytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::vector<float> points_;
    int n_ = 0, dim_ = 0;
};

} // namespace ctrack

#endif
