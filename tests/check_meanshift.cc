// Mean shift: the integer path against a float reference on real PETS09-S2L1
// clips, convergence on synthetic shifts and scales, and one step against
// OpenCV's cv::meanShift on the same weight image (internal API).
// OpenCV's headers go before check.h, whose fail() macro they would meet.
#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>

#include <check.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "common.h"
#include "test_image.h"
#include "meanshift/meanshift.h"

using namespace ctrack;

static std::string data_dir;

namespace {

struct Clip {
    std::string name;
    Image frames[2];
    double box[2][4]; // left, top, width, height
};

std::vector<Clip> load_clips()
{
    std::vector<Clip> clips;
    std::string dir = data_dir + "/pets09-crops/";
    FILE *f = std::fopen((dir + "crops.csv").c_str(), "r");
    ck_assert_msg(f, "cannot open %scrops.csv", dir.c_str());
    char line[512];
    while (std::fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        Clip c;
        char name[128];
        int frame;
        double *b0 = c.box[0], *b1 = c.box[1];
        if (std::sscanf(line, "%127[^,],%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", name, &frame, &b0[0],
                        &b0[1], &b0[2], &b0[3], &b1[0], &b1[1], &b1[2], &b1[3]) != 10)
            continue;
        c.name = name;
        read_clip(dir + c.name + ".y4m", c.frames, 2);
        clips.push_back(std::move(c));
    }
    std::fclose(f);
    ck_assert_int_ge((int)clips.size(), 5);
    return clips;
}

// ---- The float reference: the same algorithm in doubles. ----------------
struct FloatMS {
    const Planes &img;
    explicit FloatMS(const Planes &p) : img(p) {}

    static int step_of(double area, double target)
    {
        return std::max(1, (int)std::floor(std::sqrt(area / target)));
    }

    // Kernel-weighted normalised histogram of the ellipse; samples returned.
    std::vector<double> hist(double cx, double cy, double hw, double hh,
                             std::vector<std::array<int, 3>> *samples = nullptr) const
    {
        std::vector<double> p(kHistBins, 0.0);
        int s = step_of(M_PI * hw * hh, kTargetSamples);
        int x0 = std::max(0, (int)std::ceil(cx - hw)), x1 = std::min(img.width - 1, (int)std::floor(cx + hw));
        int y0 = std::max(0, (int)std::ceil(cy - hh)), y1 = std::min(img.height - 1, (int)std::floor(cy + hh));
        double total = 0;
        for (int y = y0; y <= y1; y += s)
            for (int x = x0; x <= x1; x += s) {
                double r2 = ((x - cx) / hw) * ((x - cx) / hw) + ((y - cy) / hh) * ((y - cy) / hh);
                if (r2 >= 1)
                    continue;
                int b = bin_of(img, x, y);
                p[b] += 1 - r2;
                total += 1 - r2;
                if (samples)
                    samples->push_back({x, y, b});
            }
        for (double &v : p)
            v = total > 0 ? v / total : 0;
        return p;
    }

    std::vector<double> model(double cx, double cy, double w, double h) const
    {
        std::vector<double> q = hist(cx, cy, w / 2, h / 2);
        // CBWH against the ring up to three times the area.
        double g = std::sqrt(3.0), ow = w * g / 2, oh = h * g / 2;
        int s = step_of(w * h * 2, kTargetRingSamples);
        std::vector<double> o(kHistBins, 0.0);
        double total = 0;
        for (int y = std::max(0, (int)std::ceil(cy - oh)); y <= std::min(img.height - 1, (int)std::floor(cy + oh)); y += s)
            for (int x = std::max(0, (int)std::ceil(cx - ow)); x <= std::min(img.width - 1, (int)std::floor(cx + ow)); x += s) {
                if (std::fabs(x - cx) < w / 2 && std::fabs(y - cy) < h / 2)
                    continue;
                o[bin_of(img, x, y)]++;
                total++;
            }
        double omin = 1;
        for (double &v : o) {
            v /= total;
            if (v > 0)
                omin = std::min(omin, v);
        }
        double sum = 0;
        for (int b = 0; b < kHistBins; b++) {
            q[b] *= o[b] > 0 ? std::min(1.0, omin / o[b]) : 1.0;
            sum += q[b];
        }
        for (double &v : q)
            v /= sum;
        return q;
    }

    static double rho(const std::vector<double> &p, const std::vector<double> &q)
    {
        double r = 0;
        for (int b = 0; b < kHistBins; b++)
            r += std::sqrt(p[b] * q[b]);
        return r;
    }

    // Mean shift with steps 7 and 8, no scales.
    void track(const std::vector<double> &q, double &cx, double &cy, double hw, double hh,
               double *rho_out) const
    {
        std::vector<std::array<int, 3>> smp;
        std::vector<double> p = hist(cx, cy, hw, hh, &smp);
        double r0 = rho(p, q);
        for (int it = 0; it < 10; it++) {
            double sw = 0, sx = 0, sy = 0;
            for (auto &s : smp) {
                double w = p[s[2]] > 0 ? std::sqrt(q[s[2]] / p[s[2]]) : 0;
                sw += w;
                sx += w * s[0];
                sy += w * s[1];
            }
            if (sw == 0)
                break;
            double nx = sx / sw, ny = sy / sw;
            smp.clear();
            p = hist(nx, ny, hw, hh, &smp);
            double r1 = rho(p, q);
            for (int k = 0; k < 4 && r1 < r0; k++) {
                nx = (cx + nx) / 2;
                ny = (cy + ny) / 2;
                smp.clear();
                p = hist(nx, ny, hw, hh, &smp);
                r1 = rho(p, q);
            }
            double moved = std::hypot(nx - cx, ny - cy);
            cx = nx;
            cy = ny;
            r0 = r1;
            if (moved < 0.5)
                break;
        }
        *rho_out = r0;
    }
};

MeanShiftParams no_scale()
{
    MeanShiftParams p;
    p.scale_step = 0;
    return p;
}

} // namespace

// The integer path agrees with the float reference on real clips: within a
// pixel in position and 0.02 in the Bhattacharyya coefficient.
START_TEST(integer_agrees_with_float_on_real_clips)
{
    MeanShift ms;
    for (const Clip &c : load_clips()) {
        Planes f0 = c.frames[0].planes(), f1 = c.frames[1].planes();
        const double *b = c.box[0];
        double cx = b[0] + b[2] / 2, cy = b[1] + b[3] / 2;
        ColorModel m;
        ms.build(f0, cx, cy, b[2], b[3], &m);
        ck_assert(m.valid);
        MeanShiftResult r = ms.track(f1, cx, cy, b[2], b[3], m, no_scale());

        FloatMS ref0(f0), ref1(f1);
        std::vector<double> q = ref0.model(cx, cy, b[2], b[3]);
        double fx = cx, fy = cy, frho;
        ref1.track(q, fx, fy, b[2] / 2, b[3] / 2, &frho);
        ck_assert_msg(std::hypot(r.cx - fx, r.cy - fy) <= 1.0,
                      "%s: integer (%.2f, %.2f), float (%.2f, %.2f)", c.name.c_str(), r.cx, r.cy,
                      fx, fy);
        ck_assert_msg(std::fabs(r.rho / 65536.0 - frho) <= 0.02, "%s: rho %.4f vs %.4f",
                      c.name.c_str(), r.rho / 65536.0, frho);
    }
}
END_TEST

// On the real clips mean shift moves the window towards where the person
// is two frames later: closer than where it started (all clips but one at
// most), and within a tenth of their height of the ground truth's centre.
START_TEST(follows_real_people)
{
    MeanShift ms;
    int improved = 0, n = 0;
    for (const Clip &c : load_clips()) {
        const double *b0 = c.box[0], *b1 = c.box[1];
        double cx = b0[0] + b0[2] / 2, cy = b0[1] + b0[3] / 2;
        double tx = b1[0] + b1[2] / 2, ty = b1[1] + b1[3] / 2;
        ColorModel m;
        ms.build(c.frames[0].planes(), cx, cy, b0[2], b0[3], &m);
        MeanShiftResult r = ms.track(c.frames[1].planes(), cx, cy, b0[2], b0[3], m,
                                     MeanShiftParams());
        double before = std::hypot(cx - tx, cy - ty), after = std::hypot(r.cx - tx, r.cy - ty);
        ck_assert_msg(after <= 0.1 * b1[3], "%s: %.1f px from the person (started %.1f px away)",
                      c.name.c_str(), after, before);
        improved += after < before;
        n++;
    }
    ck_assert_int_ge(improved, n - 1);
}
END_TEST

namespace {

// A textured scene with a "person": an ellipse of two coloured halves
// (shirt, trousers) with texture, on a textured background, centred at
// (cx, cy) and scaled by s.
Image scene(double cx, double cy, double s, unsigned seed)
{
    Image im;
    im.w = 200;
    im.h = 200;
    im.buf.assign((size_t)im.w * im.h * 3 / 2, 0);
    std::mt19937 rng(1234); // the same background in every frame
    std::uniform_int_distribution<int> n(-20, 20);
    for (int y = 0; y < im.h; y++)
        for (int x = 0; x < im.w; x++) {
            im.Y(x, y) = (uint8_t)(110 + n(rng) + 30 * ((x / 9 + y / 7) % 2));
            im.U(x, y) = (uint8_t)(120 + n(rng) / 4);
            im.V(x, y) = (uint8_t)(130 + n(rng) / 4);
        }
    std::mt19937 tex(seed);
    const double hw = 20 * s, hh = 40 * s;
    for (int y = 0; y < im.h; y++)
        for (int x = 0; x < im.w; x++) {
            double u = (x - cx) / hw, v = (y - cy) / hh;
            if (u * u + v * v > 1)
                continue;
            int t = (int)(tex() % 24) - 12;
            if (v < 0) { // shirt: red
                im.Y(x, y) = (uint8_t)(80 + t);
                im.U(x, y) = 90;
                im.V(x, y) = 220;
            } else { // trousers: blue
                im.Y(x, y) = (uint8_t)(50 + t);
                im.U(x, y) = 200;
                im.V(x, y) = 110;
            }
        }
    return im;
}

} // namespace

// A person 45 pixels away from the prediction is out of the window's reach
// (half its width is 20): the coarse search finds them.
START_TEST(coarse_to_fine_finds_fast_motion)
{
    MeanShift ms;
    Image a = scene(100, 100, 1.0, 7), b = scene(145, 104, 1.0, 7);
    ColorModel m;
    ms.build(a.planes(), 100, 100, 40, 80, &m);
    MeanShiftParams fine;
    MeanShiftResult r = ms.track(b.planes(), 100, 100, 40, 80, m, fine);
    ck_assert_msg(std::fabs(r.cx - 145) > 3, "the fine search alone found it (%.2f)", r.cx);
    MeanShiftParams coarse;
    coarse.coarse_below = (int)(0.9 * kQ16);
    r = ms.track(b.planes(), 100, 100, 40, 80, m, coarse);
    ck_assert_msg(std::fabs(r.cx - 145) <= 1 && std::fabs(r.cy - 104) <= 1,
                  "coarse to fine: (%.2f, %.2f)", r.cx, r.cy);
}
END_TEST

START_TEST(converges_on_synthetic_shifts)
{
    const double shifts[][2] = {{3, -2}, {7, 5}, {-6, 4}, {0, 9}, {-9, -3}};
    MeanShift ms;
    Image a = scene(100, 100, 1.0, 7);
    ColorModel m;
    ms.build(a.planes(), 100, 100, 40, 80, &m);
    for (const auto &d : shifts) {
        Image b = scene(100 + d[0], 100 + d[1], 1.0, 7);
        MeanShiftResult r = ms.track(b.planes(), 100, 100, 40, 80, m, MeanShiftParams());
        ck_assert_msg(std::fabs(r.cx - (100 + d[0])) <= 1 && std::fabs(r.cy - (100 + d[1])) <= 1,
                      "shift (%g, %g): found (%.2f, %.2f)", d[0], d[1], r.cx - 100, r.cy - 100);
        ck_assert_int_gt(r.rho, 60000);
    }
}
END_TEST

// Windows far larger than any frame, far outside it, or NaN (a track's box
// predicted far out): the kernel's integer arithmetic stays in range and
// doubles convert to ints only in range (the fuzzer found d^2 * 4096
// overflowing for windows of 60,000 pixels; make sanitize stops at such a
// report), and nothing out of the frame is read.
START_TEST(absurd_windows_stay_in_range)
{
    MeanShift ms;
    Image a = scene(100, 100, 1.0, 7);
    ColorModel m;
    ms.build(a.planes(), 100, 100, 40, 80, &m);
    const double windows[][4] = {
        {100, 100, 6e4, 6e4},  {100, 100, 3e6, 3e6},    {5e5, 5e5, 1.2e6, 1.2e6},
        {1e12, 100, 40, 80},
        {-1e12, -1e12, 1e13, 1e13}, {100, 1e9, 40, 1e9}, {NAN, 100, 40, 80},
        {100, 100, NAN, 80},   {100, 100, INFINITY, 80}};
    const MeanShiftParams p;
    for (const auto &w : windows) {
        ColorModel mw;
        ms.build(a.planes(), w[0], w[1], w[2], w[3], &mw); // samples, and the ring around
        const MeanShiftResult r = ms.track(a.planes(), w[0], w[1], w[2], w[3], m, p);
        // A similarity, a count of moves within the bound, and a window
        // that moved no farther than a finite start allows.
        ck_assert_int_ge(r.rho, 0);
        ck_assert_int_le(r.rho, (int)kQ16);
        ck_assert_int_ge(r.iterations, 0);
        ck_assert_int_le(r.iterations, p.max_iterations);
        const bool finite = std::isfinite(w[0]) && std::isfinite(w[1]) &&
                            std::isfinite(w[2]) && std::isfinite(w[3]);
        if (finite)
            ck_assert(std::isfinite(r.cx) && std::isfinite(r.cy));
        // A window with no pixel in the frame (NaN, or far outside) makes no
        // model and does not move; a model learns nothing from it.
        const bool outside = !finite || w[0] - w[2] / 2 > 200 || w[1] - w[3] / 2 > 200;
        if (outside) {
            ck_assert(!mw.valid);
            ck_assert_int_eq(r.iterations, 0);
            ck_assert_int_eq(r.rho, 0);
        }
        ColorModel before = m;
        const bool learnt = ms.learn(a.planes(), w[0], w[1], w[2], w[3], 26, 0, &before);
        if (outside) {
            ck_assert(!learnt);
            ck_assert_int_eq(memcmp(before.q, m.q, sizeof m.q), 0);
        }
    }
}
END_TEST

// A person grown by 10% is found within 5% in scale: the scale step moves
// 5% a frame, so two frames of tracking reach it.
START_TEST(finds_the_scale)
{
    for (double truth : {1.1, 0.9}) {
        MeanShift ms;
        Image a = scene(100, 100, 1.0, 7);
        ColorModel m;
        ms.build(a.planes(), 100, 100, 40, 80, &m);
        Image b = scene(103, 98, truth, 7);
        double cx = 100, cy = 100, w = 40, h = 80;
        for (int frame = 0; frame < 3; frame++) {
            MeanShiftResult r = ms.track(b.planes(), cx, cy, w, h, m, MeanShiftParams());
            ms.scale(b.planes(), m, MeanShiftParams(), &r);
            cx = r.cx;
            cy = r.cy;
            w = r.width;
            h = r.height;
        }
        ck_assert_msg(std::fabs(h / 80 - truth) / truth <= 0.05, "scale %.3f, truth %.2f",
                      h / 80, truth);
        ck_assert_msg(std::fabs(cx - 103) <= 1 && std::fabs(cy - 98) <= 1,
                      "centre (%.2f, %.2f)", cx, cy);
    }
}
END_TEST

// One step of ours equals one iteration of cv::meanShift on the same weight
// image: our window's weights at the pixels it samples (its ellipse, every
// s-th pixel), zero elsewhere; OpenCV's window the ellipse's bounding box.
START_TEST(step_agrees_with_opencv)
{
    MeanShift ms;
    for (const Clip &c : load_clips()) {
        const double *b = c.box[0];
        // Integer window corners so that both see the same pixels.
        double w = std::floor(b[2]), h = std::floor(b[3]);
        double cx = std::floor(b[0]) + w / 2, cy = std::floor(b[1]) + h / 2;
        ColorModel m;
        Planes f0 = c.frames[0].planes(), f1 = c.frames[1].planes();
        ms.build(f0, cx, cy, w, h, &m);
        uint32_t weights[kHistBins];
        double nx, ny;
        ck_assert(ms.step(f1, cx, cy, w / 2, h / 2, m, &nx, &ny, weights));

        const double hw = w / 2, hh = h / 2;
        const int s = FloatMS::step_of(M_PI * hw * hh, kTargetSamples);
        cv::Mat wimg(f1.height, f1.width, CV_32F, cv::Scalar(0));
        for (int y = (int)std::ceil(cy - hh); y <= (int)std::floor(cy + hh); y += s)
            for (int x = (int)std::ceil(cx - hw); x <= (int)std::floor(cx + hw); x += s) {
                double u = (x - cx) / hw, v = (y - cy) / hh;
                if (u * u + v * v < 1)
                    wimg.at<float>(y, x) = (float)weights[bin_of(f1, x, y)];
            }
        cv::Rect win((int)(cx - w / 2), (int)(cy - h / 2), (int)w + 1, (int)h + 1);
        cv::meanShift(wimg, win, cv::TermCriteria(cv::TermCriteria::COUNT, 1, 0));
        // OpenCV moves the window by the rounded shift of its centroid.
        double ox = win.x + w / 2, oy = win.y + h / 2;
        ck_assert_msg(std::fabs(nx - ox) <= 1.0 && std::fabs(ny - oy) <= 1.0,
                      "%s: ours (%.2f, %.2f), OpenCV (%.2f, %.2f)", c.name.c_str(), nx, ny, ox, oy);
    }
}
END_TEST

// The kernel's terms from a multiplication by 1 / h2 are the quotients of
// the division, on random windows from 1/256 of a pixel to 2^20 pixels
// (past 2^17 they divide), offsets inside, near the edge and far outside,
// and offsets next to whole quotients, where rounding shows (the product
// falls short of a whole quotient there; a random search of 40 million
// windows over 2^12 pixels never found it past one).
START_TEST(kernel_term_without_division)
{
    uint64_t seed = 12345;
    auto next = [&seed]() {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        return seed >> 11;
    };
    for (int t = 0; t < 20000; t++) {
        const int bits = 1 + (int)(next() % 28);
        const int64_t hw8 = 1 + (int64_t)(next() % ((uint64_t)1 << bits));
        const int64_t h2 = hw8 * hw8;
        const KernelTerm term(h2);
        for (int k = 0; k < 24; k++) {
            int64_t d;
            if (k % 3 == 0)
                d = (int64_t)(next() % (2 * (uint64_t)hw8 + 1)) - hw8;
            else if (k % 3 == 1)
                d = (int64_t)(next() % ((uint64_t)1 << 27)) - ((int64_t)1 << 26);
            else // d^2 * 4096 / h2 = a^2 when 64 divides hw8, and next to it
                d = hw8 * (int64_t)(next() % 65) / 64 + (int64_t)(next() % 3) - 1;
            ck_assert_msg(term(d) == kernel_term(d, h2), "d %lld, h2 %lld: %d, want %d",
                          (long long)d, (long long)h2, term(d), kernel_term(d, h2));
        }
    }
}
END_TEST

START_TEST(sqrt_table)
{
    for (uint32_t i : {0u, 1u, 2u, 100u, 16384u, 65535u}) {
        double want = std::sqrt(i / 65536.0) * 65536;
        ck_assert_msg(std::fabs(sqrt_q16(i) - want) <= 1.0, "sqrt_q16(%u) = %u, want %.1f", i,
                      sqrt_q16(i), want);
    }
}
END_TEST

// Grey frames use luma-only histograms; a model from a colour frame is not
// applied to a grey one.
START_TEST(grey_frames)
{
    Image a = scene(100, 100, 1.0, 7), b = scene(105, 103, 1.0, 7);
    Planes ga = a.planes(), gb = b.planes();
    ga.color = gb.color = false;
    MeanShift ms;
    ColorModel m;
    ms.build(ga, 100, 100, 40, 80, &m);
    ck_assert(m.valid && !m.color);
    for (int bin = 32; bin < kHistBins; bin++)
        ck_assert_int_eq(m.q[bin], 0);
    MeanShiftResult r = ms.track(gb, 100, 100, 40, 80, m, MeanShiftParams());
    ck_assert(std::fabs(r.cx - 105) <= 1.5 && std::fabs(r.cy - 103) <= 1.5);
    MeanShiftResult none = ms.track(b.planes(), 100, 100, 40, 80, m, MeanShiftParams());
    ck_assert_int_eq(none.iterations, 0);
}
END_TEST

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: check_meanshift DATA_DIR (tests/data)\n");
        return 2;
    }
    data_dir = argv[1];
    Suite *s = suite_create("meanshift");
    TCase *tc = tcase_create("meanshift");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, sqrt_table);
    tcase_add_test(tc, integer_agrees_with_float_on_real_clips);
    tcase_add_test(tc, follows_real_people);
    tcase_add_test(tc, converges_on_synthetic_shifts);
    tcase_add_test(tc, absurd_windows_stay_in_range);
    tcase_add_test(tc, coarse_to_fine_finds_fast_motion);
    tcase_add_test(tc, finds_the_scale);
    tcase_add_test(tc, step_agrees_with_opencv);
    tcase_add_test(tc, grey_frames);
    tcase_add_test(tc, kernel_term_without_division);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
