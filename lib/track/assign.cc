#include "track/assign.h"
#include "base/unionfind.h"

#include <algorithm>

namespace ctrack {

void Assigner::solve(int n, int m, const Vec<Pair> &pairs, double limit,
                     Vec<int> &row_to_col)
{
    row_to_col.assign((size_t)n, -1);
    if (n == 0 || m == 0 || pairs.empty())
        return;
    out_ = &row_to_col;
    n_ = n;
    const size_t nodes = (size_t)n + (size_t)m;

    // Union-find over rows [0, n) and columns [n, n + m).
    parent_.resize(nodes);
    for (size_t i = 0; i < nodes; i++)
        parent_[i] = (int)i;
    for (const Pair &p : pairs) {
        const int a = find_root(parent_, p.row), b = find_root(parent_, n + p.col);
        if (a != b)
            parent_[a] = b;
    }

    // Each pair's component (numbered by its root), and the pairs counted
    // and placed by component: a counting sort, in the order given.
    comp_.assign(nodes, -1);
    int components = 0;
    for (const Pair &p : pairs) {
        const int r = find_root(parent_, p.row);
        if (comp_[r] < 0)
            comp_[r] = components++;
    }
    comp_start_.assign((size_t)components + 1, 0);
    for (const Pair &p : pairs)
        comp_start_[(size_t)comp_[find_root(parent_, p.row)] + 1]++;
    for (int c = 0; c < components; c++)
        comp_start_[(size_t)c + 1] += comp_start_[(size_t)c];
    by_comp_.resize(pairs.size());
    {
        // comp_ of a root is the component; the fill position per component
        // borrows comp_rows_ as a cursor.
        comp_rows_.assign(comp_start_.begin(), comp_start_.end() - 1);
        for (const Pair &p : pairs) {
            const int c = comp_[find_root(parent_, p.row)];
            by_comp_[(size_t)comp_rows_[(size_t)c]++] = p;
        }
    }

    local_.assign(nodes, -1);
    for (int c = 0; c < components; c++) {
        const size_t first = comp_start_[(size_t)c], last = comp_start_[(size_t)c + 1];
        // The component's rows and columns, each in increasing order.
        comp_rows_.clear();
        comp_cols_.clear();
        for (size_t k = first; k < last; k++) {
            const Pair &p = by_comp_[k];
            if (local_[(size_t)p.row] < 0) {
                local_[(size_t)p.row] = 0;
                comp_rows_.push_back(p.row);
            }
            if (local_[(size_t)n + p.col] < 0) {
                local_[(size_t)n + p.col] = 0;
                comp_cols_.push_back(p.col);
            }
        }
        std::sort(comp_rows_.begin(), comp_rows_.end());
        std::sort(comp_cols_.begin(), comp_cols_.end());
        if (comp_rows_.size() == 1 && comp_cols_.size() == 1)
            row_to_col[(size_t)comp_rows_[0]] = comp_cols_[0];
        else if (comp_rows_.size() + comp_cols_.size() <= (size_t)kExactNodes)
            solve_exact(first, last, limit);
        else
            solve_greedy(first, last);
        for (int r : comp_rows_)
            local_[(size_t)r] = -1;
        for (int col : comp_cols_)
            local_[(size_t)n + col] = -1;
    }
    out_ = nullptr;
}

size_t Assigner::memory_bytes() const
{
    return (parent_.capacity() + comp_.capacity() + comp_rows_.capacity() +
            comp_cols_.capacity() + local_.capacity() + p_.capacity() + way_.capacity()) *
               sizeof(int) +
           comp_start_.capacity() * sizeof(size_t) + by_comp_.capacity() * sizeof(Pair) +
           (sub_.capacity() + u_.capacity() + v_.capacity() + minv_.capacity()) * sizeof(double) +
           used_.capacity();
}

// Solves the component whose pairs are by_comp_[first, last), with its rows
// and columns in comp_rows_ and comp_cols_, exactly. Every row and column
// gets a dummy partner at limit / 2, which turns "may stay unmatched" into a
// square assignment problem of size r + c.
void Assigner::solve_exact(size_t first, size_t last, double limit)
{
    const int r = (int)comp_rows_.size(), c = (int)comp_cols_.size();
    const int N = r + c;
    const double big = 1e9, half = limit / 2;
    for (int i = 0; i < r; i++)
        local_[(size_t)comp_rows_[(size_t)i]] = i;
    for (int j = 0; j < c; j++)
        local_[(size_t)n_ + comp_cols_[(size_t)j]] = j;

    sub_.resize((size_t)N * N);
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            sub_[(size_t)i * N + j] = i < r && j < c ? big : (i < r || j < c) ? half : 0;
    for (size_t k = first; k < last; k++) {
        const Pair &p = by_comp_[k];
        sub_[(size_t)local_[(size_t)p.row] * N + local_[(size_t)n_ + p.col]] = p.cost;
    }

    // Shortest augmenting paths with potentials, 1-based as in the classic
    // formulation: p_[j] is the row matched to column j.
    u_.assign((size_t)N + 1, 0);
    v_.assign((size_t)N + 1, 0);
    p_.assign((size_t)N + 1, 0);
    way_.assign((size_t)N + 1, 0);
    for (int i = 1; i <= N; i++) {
        p_[0] = i;
        int j0 = 0;
        minv_.assign((size_t)N + 1, 1e18);
        used_.assign((size_t)N + 1, 0);
        do {
            used_[(size_t)j0] = 1;
            int i0 = p_[(size_t)j0], j1 = 0;
            double delta = 1e18;
            for (int j = 1; j <= N; j++)
                if (!used_[(size_t)j]) {
                    double cur = sub_[(size_t)(i0 - 1) * N + (j - 1)] - u_[(size_t)i0] -
                                 v_[(size_t)j];
                    if (cur < minv_[(size_t)j]) {
                        minv_[(size_t)j] = cur;
                        way_[(size_t)j] = j0;
                    }
                    if (minv_[(size_t)j] < delta) {
                        delta = minv_[(size_t)j];
                        j1 = j;
                    }
                }
            for (int j = 0; j <= N; j++)
                if (used_[(size_t)j]) {
                    u_[(size_t)p_[(size_t)j]] += delta;
                    v_[(size_t)j] -= delta;
                } else {
                    minv_[(size_t)j] -= delta;
                }
            j0 = j1;
        } while (p_[(size_t)j0] != 0);
        do {
            int j1 = way_[(size_t)j0];
            p_[(size_t)j0] = p_[(size_t)j1];
            j0 = j1;
        } while (j0);
    }

    for (int j = 1; j <= c; j++) {
        int i = p_[(size_t)j] - 1;
        if (i < r && sub_[(size_t)i * N + (j - 1)] < limit)
            (*out_)[(size_t)comp_rows_[(size_t)i]] = comp_cols_[(size_t)j - 1];
    }
}

// The component's pairs by increasing cost (then row, then column), each
// matched when its row and column are both still free.
void Assigner::solve_greedy(size_t first, size_t last)
{
    std::sort(by_comp_.begin() + (ptrdiff_t)first, by_comp_.begin() + (ptrdiff_t)last,
              [](const Pair &a, const Pair &b) {
                  if (a.cost != b.cost)
                      return a.cost < b.cost;
                  return a.row != b.row ? a.row < b.row : a.col < b.col;
              });
    for (size_t k = first; k < last; k++) {
        const Pair &p = by_comp_[k];
        int &col_taken = local_[(size_t)n_ + p.col]; // 0 free, 1 taken
        if ((*out_)[(size_t)p.row] >= 0 || col_taken)
            continue;
        (*out_)[(size_t)p.row] = p.col;
        col_taken = 1;
    }
}

} // namespace ctrack
