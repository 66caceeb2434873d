// The assignment solver against a brute-force optimum on small random
// problems (internal API).
#include <check.h>

#include "common.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "track/assign.h"

using ctrack::Vec;

namespace {

// Cost of an assignment in the solver's convention: matched costs plus
// limit / 2 for every row and every column left unmatched.
double total(const Vec<double> &c, int n, int m, double limit,
             const Vec<int> &row_to_col)
{
    double s = 0;
    int matched = 0;
    for (int i = 0; i < n; i++)
        if (row_to_col[i] >= 0) {
            s += c[i * m + row_to_col[i]];
            matched++;
        }
    return s + (n + m - 2 * matched) * limit / 2;
}

// Tries every partial matching that uses only allowed pairs.
double brute_force(const Vec<double> &c, int n, int m, double limit)
{
    double best = INFINITY;
    Vec<int> r2c(n, -1);
    Vec<char> used(m, 0);
    std::function<void(int)> rec = [&](int i) {
        if (i == n) {
            best = std::min(best, total(c, n, m, limit, r2c));
            return;
        }
        r2c[i] = -1;
        rec(i + 1);
        for (int j = 0; j < m; j++)
            if (!used[j] && c[i * m + j] < limit) {
                used[j] = 1;
                r2c[i] = j;
                rec(i + 1);
                used[j] = 0;
                r2c[i] = -1;
            }
    };
    rec(0);
    return best;
}

// The pairs of a dense cost matrix that the limit allows.
Vec<ctrack::Pair> allowed(const Vec<double> &c, int n, int m, double limit)
{
    Vec<ctrack::Pair> p;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++)
            if (c[(size_t)i * m + j] < limit)
                p.push_back(ctrack::Pair{i, j, c[(size_t)i * m + j]});
    return p;
}

uint64_t rng_state = 88172645463325252ull;
double uniform()
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (rng_state >> 11) * (1.0 / 9007199254740992.0);
}

} // namespace

START_TEST(matches_brute_force)
{
    ctrack::Assigner a;
    Vec<int> r2c;
    for (int trial = 0; trial < 3000; trial++) {
        int n = (int)(uniform() * 7), m = (int)(uniform() * 7);
        double limit = 0.2 + 0.8 * uniform();
        Vec<double> c(n * m);
        for (double &x : c) {
            x = uniform();
            if (uniform() < 0.1)
                x = std::round(x * 4) / 4; // ties
        }
        a.solve(n, m, allowed(c, n, m, limit), limit, r2c);
        ck_assert_int_eq((int)r2c.size(), n);
        Vec<char> used(m, 0);
        for (int i = 0; i < n; i++) {
            int j = r2c[i];
            if (j < 0)
                continue;
            ck_assert_int_lt(j, m);
            ck_assert_msg(!used[j], "column %d used twice", j);
            used[j] = 1;
            ck_assert(c[i * m + j] < limit);
        }
        double got = total(c, n, m, limit, r2c), want = brute_force(c, n, m, limit);
        ck_assert_msg(std::fabs(got - want) < 1e-9, "trial %d (%dx%d): %g, optimum %g", trial,
                      n, m, got, want);
    }
}
END_TEST

// Separate groups of people are solved apart: many small components, each
// exact, give the diagonal answer of a problem far larger than any
// component; and one chain longer than kExactNodes, solved greedily, too.
START_TEST(block_diagonal)
{
    const int n = 3000;
    ctrack::Assigner a;
    Vec<int> r2c;
    Vec<ctrack::Pair> p;
    for (int i = 0; i < n; i++) {
        p.push_back(ctrack::Pair{i, i, 0.1});
        if (i % 3 != 2)
            p.push_back(ctrack::Pair{i, i + 1, 0.5});
    }
    a.solve(n, n, p, 0.8, r2c);
    for (int i = 0; i < n; i++)
        ck_assert_int_eq(r2c[i], i);
    p.clear();
    for (int i = 0; i < 300; i++) {
        p.push_back(ctrack::Pair{i, i, 0.1});
        if (i + 1 < 300)
            p.push_back(ctrack::Pair{i, i + 1, 0.5});
    }
    a.solve(300, 300, p, 0.8, r2c);
    for (int i = 0; i < 300; i++)
        ck_assert_int_eq(r2c[i], i);
}
END_TEST

// A component over kExactNodes is solved greedily: by increasing cost, each
// pair taken when both ends are free. Every row gets a column when it has
// one free, and no column is used twice.
START_TEST(large_component_greedy)
{
    const int n = 200, m = 400;
    Vec<double> c((size_t)n * m);
    for (double &x : c)
        x = uniform();
    const double limit = 0.9;
    const Vec<ctrack::Pair> p = allowed(c, n, m, limit);
    ctrack::Assigner a;
    Vec<int> r2c;
    a.solve(n, m, p, limit, r2c);
    Vec<char> used(m, 0);
    for (int i = 0; i < n; i++) {
        const int j = r2c[i];
        ck_assert_int_ge(j, 0); // 400 columns, each row allows 90% of them
        ck_assert(!used[j]);
        used[j] = 1;
        ck_assert(c[(size_t)i * m + j] < limit);
    }
    // Greedy: the cheapest pair of all is taken.
    const ctrack::Pair *best = &p[0];
    for (const ctrack::Pair &q : p)
        if (q.cost < best->cost)
            best = &q;
    ck_assert_int_eq(r2c[best->row], best->col);
}
END_TEST

START_TEST(nothing_allowed)
{
    ctrack::Assigner a;
    Vec<int> r2c;
    a.solve(2, 2, {}, 0.5, r2c);
    ck_assert_int_eq((int)r2c.size(), 2);
    ck_assert_int_eq(r2c[0], -1);
    ck_assert_int_eq(r2c[1], -1);
    a.solve(0, 5, {}, 0.5, r2c);
    ck_assert_int_eq((int)r2c.size(), 0);
}
END_TEST

int main()
{
    Suite *s = suite_create("assign");
    TCase *tc = tcase_create("assign");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, matches_brute_force);
    tcase_add_test(tc, block_diagonal);
    tcase_add_test(tc, large_component_greedy);
    tcase_add_test(tc, nothing_allowed);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
