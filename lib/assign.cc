#include "assign.h"

#include <algorithm>

namespace ctrack {

namespace {

int find_root(std::vector<int> &parent, int x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

} // namespace

void Assigner::solve(const double *cost, int n, int m, double limit,
                     std::vector<int> &row_to_col)
{
    row_to_col.assign(n, -1);
    if (n == 0 || m == 0)
        return;
    out_ = &row_to_col;

    // Union-find over rows [0, n) and columns [n, n + m).
    parent_.resize(n + m);
    for (int i = 0; i < n + m; i++)
        parent_[i] = i;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++)
            if (cost[i * m + j] < limit) {
                int a = find_root(parent_, i), b = find_root(parent_, n + j);
                if (a != b)
                    parent_[a] = b;
            }

    // Nodes ordered by component root, so each component is a run.
    order_.resize(n + m);
    root_.resize(n + m);
    for (int i = 0; i < n + m; i++) {
        order_[i] = i;
        root_[i] = find_root(parent_, i);
    }
    std::sort(order_.begin(), order_.end(), [this](int a, int b) {
        return root_[a] != root_[b] ? root_[a] < root_[b] : a < b;
    });

    for (size_t s = 0; s < order_.size();) {
        size_t e = s;
        comp_rows_.clear();
        comp_cols_.clear();
        while (e < order_.size() && root_[order_[e]] == root_[order_[s]]) {
            int node = order_[e++];
            if (node < n)
                comp_rows_.push_back(node);
            else
                comp_cols_.push_back(node - n);
        }
        s = e;
        if (comp_rows_.empty() || comp_cols_.empty())
            continue;
        if (comp_rows_.size() == 1 && comp_cols_.size() == 1) {
            row_to_col[comp_rows_[0]] = comp_cols_[0];
            continue;
        }
        solve_component(cost, m, limit);
    }
    out_ = nullptr;
}

size_t Assigner::memory_bytes() const
{
    return (parent_.capacity() + root_.capacity() + comp_rows_.capacity() +
            comp_cols_.capacity() + order_.capacity() + p_.capacity() + way_.capacity()) *
               sizeof(int) +
           (sub_.capacity() + u_.capacity() + v_.capacity() + minv_.capacity()) * sizeof(double) +
           used_.capacity();
}

// Solves the component in comp_rows_ x comp_cols_ exactly. Every row and
// column gets a dummy partner at limit / 2, which turns "may stay unmatched"
// into a square assignment problem of size r + c.
void Assigner::solve_component(const double *cost, int m, double limit)
{
    const int r = (int)comp_rows_.size(), c = (int)comp_cols_.size();
    const int N = r + c;
    const double big = 1e9, half = limit / 2;

    sub_.resize((size_t)N * N);
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            double x;
            if (i < r && j < c) {
                x = cost[comp_rows_[i] * m + comp_cols_[j]];
                if (!(x < limit))
                    x = big;
            } else if (i < r || j < c) {
                x = half;
            } else {
                x = 0;
            }
            sub_[(size_t)i * N + j] = x;
        }

    // Shortest augmenting paths with potentials, 1-based as in the classic
    // formulation: p_[j] is the row matched to column j.
    u_.assign(N + 1, 0);
    v_.assign(N + 1, 0);
    p_.assign(N + 1, 0);
    way_.assign(N + 1, 0);
    for (int i = 1; i <= N; i++) {
        p_[0] = i;
        int j0 = 0;
        minv_.assign(N + 1, 1e18);
        used_.assign(N + 1, 0);
        do {
            used_[j0] = 1;
            int i0 = p_[j0], j1 = 0;
            double delta = 1e18;
            for (int j = 1; j <= N; j++)
                if (!used_[j]) {
                    double cur = sub_[(size_t)(i0 - 1) * N + (j - 1)] - u_[i0] - v_[j];
                    if (cur < minv_[j]) {
                        minv_[j] = cur;
                        way_[j] = j0;
                    }
                    if (minv_[j] < delta) {
                        delta = minv_[j];
                        j1 = j;
                    }
                }
            for (int j = 0; j <= N; j++)
                if (used_[j]) {
                    u_[p_[j]] += delta;
                    v_[j] -= delta;
                } else {
                    minv_[j] -= delta;
                }
            j0 = j1;
        } while (p_[j0] != 0);
        do {
            int j1 = way_[j0];
            p_[j0] = p_[j1];
            j0 = j1;
        } while (j0);
    }

    for (int j = 1; j <= c; j++) {
        int i = p_[j] - 1;
        if (i < r && sub_[(size_t)i * N + (j - 1)] < limit)
            (*out_)[comp_rows_[i]] = comp_cols_[j - 1];
    }
}

} // namespace ctrack
