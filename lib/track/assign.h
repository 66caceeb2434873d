// Assignment with a cost limit: rows (tracks) to columns (candidates), over
// the pairs a gate allowed.
#ifndef CTRACK_ASSIGN_H
#define CTRACK_ASSIGN_H

#include <cstddef>
#include <vector>

#include "base/memory.h"

namespace ctrack {

// An allowed pair and its cost (below the problem's limit).
struct Pair {
    int row, col;
    double cost;
};

// Solves min sum of matched costs + (unmatched rows + unmatched columns) *
// limit / 2, where only the pairs given may be matched (each with cost <
// limit: the convention of lapjv's cost_limit). On return row_to_col[i] is
// the column matched to row i, or -1.
//
// The graph of the pairs is split into connected components first, so crowds
// of people who do not overlap cost nothing extra. A component of at most
// kExactNodes rows and columns is solved exactly by shortest augmenting
// paths (Jonker-Volgenant / Kuhn-Munkres with potentials), in
// O(kExactNodes^3); a larger one, which only a flood of overlapping boxes
// makes, greedily: its pairs in order of cost (then row, then column), each
// taken when both ends are free, in O(p log p) for its p pairs. With N = n +
// m nodes and P pairs the whole call costs O(N log N + P log P + N *
// kExactNodes^2). The solver keeps its buffers between calls: after
// warm-up it does not allocate.
class Assigner {
public:
    static constexpr int kExactNodes = 64;

    void solve(int n, int m, const Vec<Pair> &pairs, double limit,
               Vec<int> &row_to_col);
    // Heap bytes held by the buffers.
    size_t memory_bytes() const;

private:
    void solve_exact(size_t first, size_t last, double limit);
    void solve_greedy(size_t first, size_t last);

    int n_ = 0;
    Vec<int> parent_, comp_, comp_rows_, comp_cols_, local_;
    Vec<size_t> comp_start_;
    Vec<Pair> by_comp_;
    Vec<double> sub_, u_, v_, minv_;
    Vec<int> p_, way_;
    Vec<char> used_;
    Vec<int> *out_ = nullptr;
};

} // namespace ctrack

#endif
