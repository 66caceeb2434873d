// Appearance templates and Deformable Diversity Similarity (DDIS; Talmi,
// Mechrez and Zelnik-Manor, CVPR 2017; the paper's eq. 2-6;
// docs/algorithm.md, "Appearance"), the nearest neighbours from nnindex.h.
#ifndef CTRACK_APPEARANCE_H
#define CTRACK_APPEARANCE_H

#include <cstdint>
#include <vector>

#include "base/memory.h"

#include "dsp/dsp.h"
#include "appearance/nnindex.h"
#include "base/planes.h"

namespace ctrack {

// A box is described on a grid of kGridX x kGridY cells; each cell's
// descriptor is the luma at 3 x 3 points inside it and the chroma (U, V)
// at its centre: kDescDim numbers. Grey frames give chroma 0.
constexpr int kGridX = 6;
constexpr int kGridY = 12;
constexpr int kPoints = kGridX * kGridY;
constexpr int kDescDim = 11;

// Describes the box (left, top, width, height) of the frame into out
// (kPoints * kDescDim floats): each number the mean of a block of pixels,
// the luma's 3 x 3 sub-blocks of a cell and the cell's chroma. Blocks
// outside the image read its edge. Keeps a row of column sums as wide as
// the widest frame it has seen.
class Describer {
public:
    void describe(const Planes &img, double left, double top, double width, double height,
                  float *out);
    size_t memory_bytes() const { return cols_.capacity() * sizeof(uint32_t); }

private:
    Vec<uint32_t> cols_;
};

// The same with a Describer of its own (which allocates): for tests and
// tools.
void describe(const Planes &img, double left, double top, double width, double height,
              float *out);

// One template: the descriptors of a box and the index that finds their
// nearest neighbours (no tree at kPoints: see NNIndex::kBruteForceMax).
struct Template {
    Vec<float> desc;
    NNIndex index;
    // With tree, a FLANN kd-tree indexes them however few (for comparisons).
    void build(const float *descriptors, bool tree = false);
};

// The scratch of DDIS computations; keeps its buffers.
class Ddis {
public:
    Ddis();
    // DDIS(Q, P) in [0, 1]: Q's points' nearest neighbours in P by
    // appearance, kappa(p) how many of Q chose p, r_j the distance in grid
    // cells between q_j and its neighbour;
    // DDIS = 1 / min(m, n) * sum_j exp(1 - kappa(NN(q_j))) / (1 + r_j).
    // eps > 0 allows approximate neighbours (see NNIndex::search).
    double ddis(const Template &p, const float *q, float eps = 0);
    // The same neighbours without the deformation term: DIS, eq. (3), the
    // number of distinct neighbours over min(m, n).
    double dis(const Template &p, const float *q, float eps = 0);

private:
    void neighbours(const Template &p, const float *q, float eps);
    Dsp dsp_; // this CPU's builds, as a tracker's (dsp.h)
    int index_[kPoints];
    float dist2_[kPoints];
    int kappa_[kPoints];
    double exp_[kPoints + 1]; // exp(1 - k)
};

} // namespace ctrack

#endif
