// Appearance: DDIS with FLANN against a brute-force reference, the
// approximate search's tolerance, and what DDIS tells apart on real
// PETS09-S2L1 crossings chosen from the ground truth (internal API).
#include <check.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "appearance/appearance.h"
#include "common.h"
#include "describe_reference.h"
#include "test_image.h"

using namespace ctrack;

static std::string data_dir;

namespace {

// One crossing: two people a, b, apart before and after; boxes[0..3] are
// a before, b before, a after, b after.
struct Crossing {
    std::string name;
    Image frames[2];
    double boxes[4][4];
    std::vector<float> desc[4];
};

std::vector<Crossing> load_crossings()
{
    std::vector<Crossing> out;
    std::string dir = data_dir + "/pets09-crops/";
    FILE *f = std::fopen((dir + "crossings.csv").c_str(), "r");
    ck_assert_msg(f, "cannot open %scrossings.csv", dir.c_str());
    char line[1024];
    while (std::fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        Crossing c;
        char name[128];
        int frame;
        double *b = &c.boxes[0][0];
        if (std::sscanf(line,
                        "%127[^,],%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf",
                        name, &frame, b, b + 1, b + 2, b + 3, b + 4, b + 5, b + 6, b + 7, b + 8,
                        b + 9, b + 10, b + 11, b + 12, b + 13, b + 14, b + 15) != 18)
            continue;
        c.name = name;
        read_clip(dir + c.name + ".y4m", c.frames, 2);
        for (int i = 0; i < 4; i++) {
            c.desc[i].resize((size_t)kPoints * kDescDim);
            const double *x = c.boxes[i];
            describe(c.frames[i / 2].planes(), x[0], x[1], x[2], x[3], c.desc[i].data());
        }
        out.push_back(std::move(c));
    }
    std::fclose(f);
    ck_assert_int_ge((int)out.size(), 5);
    return out;
}

// Brute force: each query's nearest point (the first of equals) and the
// squared distance.
void brute_force(const float *p, const float *q, int *index, float *dist2)
{
    for (int j = 0; j < kPoints; j++) {
        float best = INFINITY;
        int bi = -1;
        for (int i = 0; i < kPoints; i++) {
            float d = 0;
            for (int k = 0; k < kDescDim; k++) {
                float t = q[j * kDescDim + k] - p[i * kDescDim + k];
                d += t * t;
            }
            if (d < best) {
                best = d;
                bi = i;
            }
        }
        index[j] = bi;
        dist2[j] = best;
    }
}

// DDIS from given neighbours, straight from the formula.
double ddis_of(const int *index)
{
    int kappa[kPoints] = {0};
    for (int j = 0; j < kPoints; j++)
        kappa[index[j]]++;
    double s = 0;
    for (int j = 0; j < kPoints; j++) {
        int i = index[j];
        double dx = i % kGridX - j % kGridX, dy = i / kGridX - j / kGridX;
        s += std::exp(1.0 - kappa[i]) / (1 + std::sqrt(dx * dx + dy * dy));
    }
    return s / kPoints;
}

} // namespace

// On random descriptors (no ties) exact FLANN search gives exactly the
// brute-force DDIS.
// Describer equals the block-by-block reference to the bit: boxes on a
// real PETS09-S2L1 frame inside, across the edges and outside the image,
// from a pixel to larger than the frame, at whole and fractional positions;
// I420, NV12 and grey. One Describer for all, so its kept row of sums is
// reused at every width.
START_TEST(describer_equals_the_reference)
{
    const std::vector<Crossing> cs = load_crossings();
    const Image &im = cs[0].frames[0];
    const Planes i420 = im.planes();
    Planes grey = i420;
    grey.color = false;
    grey.u = grey.v = nullptr;
    const int cw = (im.w + 1) / 2, ch = (im.h + 1) / 2;
    std::vector<uint8_t> uv((size_t)2 * cw * ch);
    for (size_t i = 0; i < (size_t)cw * ch; i++) {
        uv[2 * i] = i420.u[i];
        uv[2 * i + 1] = i420.v[i];
    }
    Planes nv12 = i420;
    nv12.u = uv.data();
    nv12.v = uv.data() + 1;
    nv12.u_stride = nv12.v_stride = 2 * cw;
    nv12.c_step = 2;
    const Planes *kinds[] = {&i420, &nv12, &grey};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u01(0, 1);
    Describer describer;
    std::vector<float> a((size_t)kPoints * kDescDim), b(a.size());
    for (int trial = 0; trial < 3000; trial++) {
        const Planes &p = *kinds[trial % 3];
        double left = (u01(rng) * 1.4 - 0.3) * p.width, top = (u01(rng) * 1.4 - 0.3) * p.height;
        double width = std::exp(u01(rng) * std::log(1.5 * p.width));
        double height = std::exp(u01(rng) * std::log(1.5 * p.height));
        if (trial % 4 == 0) {
            left = std::round(left);
            top = std::round(top);
            width = std::round(width) + 1;
            height = std::round(height) + 1;
        }
        describer.describe(p, left, top, width, height, a.data());
        describe_reference::describe(p, left, top, width, height, b.data());
        ck_assert_msg(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0,
                      "trial %d, box (%.3f, %.3f, %.3f, %.3f): differs from the reference",
                      trial, left, top, width, height);
    }
}
END_TEST

START_TEST(exact_search_equals_brute_force_on_random_points)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 255);
    std::vector<float> p((size_t)kPoints * kDescDim), q(p.size());
    Ddis d;
    for (int trial = 0; trial < 50; trial++) {
        for (float &x : p)
            x = u(rng);
        for (float &x : q)
            x = u(rng);
        Template t;
        t.build(p.data());
        int index[kPoints];
        float dist2[kPoints];
        brute_force(p.data(), q.data(), index, dist2);
        ck_assert_double_eq_tol(d.ddis(t, q.data()), ddis_of(index), 1e-12);
    }
}
END_TEST

// On real crops (with ties: pixel values repeat) exact FLANN search finds
// neighbours at the brute-force distance for every query, and the same DDIS
// whenever no query had two neighbours at the same distance.
START_TEST(exact_search_equals_brute_force_on_real_crops)
{
    int untied = 0;
    for (const Crossing &c : load_crossings())
        for (int a = 0; a < 2; a++)
            for (int b = 2; b < 4; b++) {
                Template t;
                t.build(c.desc[a].data());
                int fi[kPoints], bi[kPoints];
                float fd[kPoints], bd[kPoints];
                t.index.search(c.desc[b].data(), kPoints, fi, fd);
                brute_force(c.desc[a].data(), c.desc[b].data(), bi, bd);
                bool ties = false;
                for (int j = 0; j < kPoints; j++) {
                    ck_assert_msg(std::fabs(fd[j] - bd[j]) <= 1e-3f * std::max(1.0f, bd[j]),
                                  "%s: query %d at %g, brute force %g", c.name.c_str(), j,
                                  (double)fd[j], (double)bd[j]);
                    ties |= fi[j] != bi[j];
                }
                Ddis d;
                if (!ties) {
                    ck_assert_double_eq_tol(d.ddis(t, c.desc[b].data()), ddis_of(bi), 1e-12);
                    untied++;
                }
            }
    ck_assert_int_gt(untied, 0);
}
END_TEST

// The two searches of NNIndex, all pairs (a template's kPoints) and
// FLANN's kd-tree, see the same distances to the bit: on random points they
// choose the same neighbours; on real crops, where pixel values repeat, a
// query's neighbours may differ only between points at the same distance.
START_TEST(all_pairs_equals_the_kd_tree)
{
    auto compare = [](const float *p, const float *q, bool ties_allowed) {
        Template pairs, tree;
        pairs.build(p);
        tree.build(p, true);
        int pi[kPoints], ti[kPoints];
        float pd[kPoints], td[kPoints];
        pairs.index.search(q, kPoints, pi, pd);
        tree.index.search(q, kPoints, ti, td);
        int tied = 0;
        for (int j = 0; j < kPoints; j++) {
            ck_assert_msg(pd[j] == td[j], "query %d: all pairs %.9g, kd-tree %.9g", j,
                          (double)pd[j], (double)td[j]);
            if (pi[j] == ti[j])
                continue;
            ck_assert_msg(ties_allowed, "query %d: points %d and %d", j, pi[j], ti[j]);
            // Both at the distance found: the kd-tree's choice is as near.
            int i2[1];
            float d2[1];
            NNIndex one;
            one.build(p + (size_t)ti[j] * kDescDim, 1, kDescDim);
            one.search(q + (size_t)j * kDescDim, 1, i2, d2);
            ck_assert_float_eq(d2[0], pd[j]);
            ck_assert_int_lt(pi[j], ti[j]); // all pairs keeps the first of equals
            tied++;
        }
        return tied;
    };
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0, 255);
    std::vector<float> p((size_t)kPoints * kDescDim), q(p.size());
    for (int trial = 0; trial < 50; trial++) {
        for (float &x : p)
            x = u(rng);
        for (float &x : q)
            x = u(rng);
        compare(p.data(), q.data(), false);
    }
    int tied = 0, pairs = 0;
    for (const Crossing &c : load_crossings())
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++, pairs++)
                tied += compare(c.desc[a].data(), c.desc[b].data(), true);
    std::printf("all pairs against the kd-tree: %d queries of %d tied\n", tied,
                pairs * kPoints);
}
END_TEST

// Past kBruteForceMax points the index is FLANN's kd-tree, and exact.
START_TEST(large_sets_use_the_kd_tree)
{
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(0, 255);
    const int n = NNIndex::kBruteForceMax * 3 + 5, dim = 7;
    std::vector<float> p((size_t)n * dim), q((size_t)50 * dim);
    for (float &x : p)
        x = u(rng);
    for (float &x : q)
        x = u(rng);
    NNIndex index;
    index.build(p.data(), n, dim);
    ck_assert_int_eq(index.size(), n);
    std::vector<int> found(50);
    std::vector<float> dist(50);
    index.search(q.data(), 50, found.data(), dist.data());
    for (int j = 0; j < 50; j++) {
        float best = INFINITY;
        int bi = -1;
        for (int i = 0; i < n; i++) {
            float d = 0;
            for (int k = 0; k < dim; k++) {
                const float t = q[j * dim + k] - p[i * dim + k];
                d += t * t;
            }
            if (d < best) {
                best = d;
                bi = i;
            }
        }
        ck_assert_int_eq(found[j], bi);
        ck_assert_float_eq_tol(dist[j], best, 1e-3f * best);
    }
    // A copy searches alike.
    NNIndex copy(index);
    std::vector<int> again(50);
    copy.search(q.data(), 50, again.data(), dist.data());
    ck_assert(again == found);
}
END_TEST

// Approximate search with the kd-tree (eps = 1: a neighbour within twice
// the nearest distance) stays within 0.05 of the exact DDIS on real crops.
START_TEST(approximate_search_within_tolerance)
{
    Ddis d;
    double worst = 0;
    for (const Crossing &c : load_crossings())
        for (int a = 0; a < 2; a++)
            for (int b = 0; b < 4; b++) {
                Template t;
                t.build(c.desc[a].data(), true);
                double exact = d.ddis(t, c.desc[b].data());
                double approx = d.ddis(t, c.desc[b].data(), 1.0f);
                worst = std::max(worst, std::fabs(exact - approx));
            }
    ck_assert_msg(worst <= 0.05, "approximate DDIS off by %.3f", worst);
}
END_TEST

// A patch is most like itself: DDIS 1 (at least 0.9 where equal
// descriptors tie), above every other person's and the same person's a
// dozen frames later.
START_TEST(highest_for_the_same_patch)
{
    Ddis d;
    for (const Crossing &c : load_crossings())
        for (int a = 0; a < 4; a++) {
            Template t;
            t.build(c.desc[a].data());
            double self = d.ddis(t, c.desc[a].data());
            ck_assert_msg(self >= 0.9, "%s: DDIS with itself %.3f", c.name.c_str(), self);
            for (int b = 0; b < 4; b++)
                if (b != a)
                    ck_assert(d.ddis(t, c.desc[b].data()) < self);
        }
}
END_TEST

// Each person's template ranks them above the other person after the
// crossing, in all but at most one of the 2 x (number of crossings) cases,
// and the right pairing always scores more than the swapped one, which is
// what association compares.
START_TEST(ranks_the_right_person_after_a_crossing)
{
    Ddis d;
    int right = 0, cases = 0;
    for (const Crossing &c : load_crossings()) {
        Template a, b;
        a.build(c.desc[0].data());
        b.build(c.desc[1].data());
        double aa = d.ddis(a, c.desc[2].data()), ab = d.ddis(a, c.desc[3].data());
        double bb = d.ddis(b, c.desc[3].data()), ba = d.ddis(b, c.desc[2].data());
        right += (aa > ab) + (bb > ba);
        cases += 2;
        ck_assert_msg(aa + bb > ab + ba, "%s: right pairing %.3f, swapped %.3f", c.name.c_str(),
                      aa + bb, ab + ba);
    }
    ck_assert_msg(right >= cases - 1, "%d of %d ranked right", right, cases);
}
END_TEST

// DDIS and DIS (eq. 3, the same neighbours without the deformation term):
// DDIS never exceeds DIS (each of its terms is at most what DIS counts, so it
// falls at least as fast when a person deforms: see docs/notes/appearance.md), but
// it tells the same, deformed person from another one by a wider margin.
START_TEST(against_dis)
{
    Ddis d;
    double ddis_ratio = 0, dis_ratio = 0;
    int n = 0;
    for (const Crossing &c : load_crossings())
        for (int a = 0; a < 2; a++) {
            Template t;
            t.build(c.desc[a].data());
            const float *same = c.desc[a + 2].data(), *other = c.desc[3 - a].data();
            for (const float *q : {same, other})
                ck_assert(d.ddis(t, q) <= d.dis(t, q) + 1e-12);
            ddis_ratio += d.ddis(t, same) / d.ddis(t, other);
            dis_ratio += d.dis(t, same) / d.dis(t, other);
            n++;
        }
    ck_assert_msg(ddis_ratio / n > dis_ratio / n,
                  "same/other: DDIS %.3f, DIS %.3f", ddis_ratio / n, dis_ratio / n);
}
END_TEST

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: check_appearance DATA_DIR (tests/data)\n");
        return 2;
    }
    data_dir = argv[1];
    Suite *s = suite_create("appearance");
    TCase *tc = tcase_create("appearance");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, describer_equals_the_reference);
    tcase_add_test(tc, exact_search_equals_brute_force_on_random_points);
    tcase_add_test(tc, exact_search_equals_brute_force_on_real_crops);
    tcase_add_test(tc, all_pairs_equals_the_kd_tree);
    tcase_add_test(tc, large_sets_use_the_kd_tree);
    tcase_add_test(tc, approximate_search_within_tolerance);
    tcase_add_test(tc, highest_for_the_same_patch);
    tcase_add_test(tc, ranks_the_right_person_after_a_crossing);
    tcase_add_test(tc, against_dis);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
