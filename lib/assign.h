// Optimal assignment with a cost limit: rows (tracks) to columns (candidates).
#ifndef CTRACK_ASSIGN_H
#define CTRACK_ASSIGN_H

#include <cstddef>
#include <vector>

namespace ctrack {

// Solves min sum of matched costs + (unmatched rows + unmatched columns) *
// limit / 2, where only pairs with cost < limit may be matched (the
// convention of lapjv's cost_limit). `cost` is row-major n x m. On return
// row_to_col[i] is the column matched to row i, or -1. The gate graph is
// split into connected components first, so crowds of people who do not
// overlap cost nothing extra; each component is solved exactly by the
// shortest augmenting path method (Jonker-Volgenant / Kuhn-Munkres with
// potentials). The solver keeps its buffers between calls: after warm-up
// it does not allocate.
class Assigner {
public:
    void solve(const double *cost, int n, int m, double limit,
               std::vector<int> &row_to_col);
    // Heap bytes held by the buffers.
    size_t memory_bytes() const;

private:
    void solve_component(const double *cost, int m, double limit);

    std::vector<int> parent_, root_, comp_rows_, comp_cols_, order_;
    std::vector<double> sub_, u_, v_, minv_;
    std::vector<int> p_, way_;
    std::vector<char> used_;
    std::vector<int> *out_ = nullptr;
};

} // namespace ctrack

#endif
