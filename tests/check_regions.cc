// lib/pixels/regions.h against OpenCV: the closing against morphologyEx, the outer
// regions' boxes against findContours(RETR_EXTERNAL) and boundingRect(), to
// the bit and in order, on random masks made of people-like bars, specks,
// rings with regions in their holes and foreground on the image's edges,
// cut to the area the blob finder gives them.
// OpenCV first: check.h's macros would break its headers.
#include <opencv2/imgproc.hpp>

#include <check.h>

#include "common.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "pixels/regions.h"
#include "template/shape.h"
#include "shape_reference.h"

using namespace ctrack;

namespace {

// A random mask of w x h: a few filled boxes and ellipses, rings (with
// something inside, sometimes), single pixels, and a scatter of noise at a
// random density; every value 0 or 255.
cv::Mat random_mask(std::mt19937 &rng, int w, int h)
{
    cv::Mat m(h, w, CV_8UC1, cv::Scalar(0));
    auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const int shapes = u(0, 12);
    for (int k = 0; k < shapes; k++) {
        const int x = u(-5, w + 2), y = u(-5, h + 2), bw = u(1, w / 3 + 1), bh = u(1, h / 2 + 1);
        switch (u(0, 3)) {
        case 0:
            cv::rectangle(m, cv::Rect(x, y, bw, bh), cv::Scalar(255), cv::FILLED);
            break;
        case 1:
            cv::ellipse(m, cv::Point(x, y), cv::Size(bw / 2 + 1, bh / 2 + 1), u(0, 90), 0, 360,
                        cv::Scalar(255), cv::FILLED);
            break;
        case 2:
            cv::rectangle(m, cv::Rect(x, y, bw + 6, bh + 6), cv::Scalar(255), u(1, 3));
            if (u(0, 1))
                cv::rectangle(m, cv::Rect(x + 4, y + 4, std::max(1, bw - 2), std::max(1, bh - 2)),
                              cv::Scalar(255), cv::FILLED);
            break;
        default:
            m.at<uint8_t>(std::clamp(y, 0, h - 1), std::clamp(x, 0, w - 1)) = 255;
        }
    }
    const double density = std::uniform_real_distribution<double>(0, 0.3)(rng);
    std::bernoulli_distribution noise(density * density);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (noise(rng))
                m.at<uint8_t>(y, x) = 255;
    return m;
}

// A random box inside a w x h image, at least one pixel.
Rect random_box(std::mt19937 &rng, int w, int h)
{
    auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const int x0 = u(0, w - 1), y0 = u(0, h - 1);
    const int x1 = u(x0 + 1, w), y1 = u(y0 + 1, h);
    return Rect{x0, y0, x1, y1};
}

// The foreground's bounds with the blob finder's margin (2 columns, 4
// rows), or an empty box.
Rect area_of(const cv::Mat &m)
{
    const cv::Rect b = cv::boundingRect(m);
    if (b.empty())
        return Rect{0, 0, 0, 0};
    return Rect{std::max(0, b.x - 2), std::max(0, b.y - 4), std::min(m.cols, b.x + b.width + 2),
                std::min(m.rows, b.y + b.height + 4)};
}

} // namespace

// The closing over the area is the whole mask's closing everywhere (0
// outside the area), on 2,000 random masks of sizes from 1 x 1 up.
START_TEST(closing_equals_opencv)
{
    std::mt19937 rng(21);
    const cv::Mat k = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 5));
    Closing closing;
    int nonempty = 0;
    for (int trial = 0; trial < 2000; trial++) {
        const int w = std::uniform_int_distribution<int>(1, 90)(rng);
        const int h = std::uniform_int_distribution<int>(1, 70)(rng);
        const cv::Mat in = random_mask(rng, w, h);
        cv::Mat want;
        cv::morphologyEx(in, want, cv::MORPH_CLOSE, k);
        cv::Mat got(h, w, CV_8UC1, cv::Scalar(0));
        const Rect a = area_of(in);
        closing.run(in.data, got.data, w, h, a);
        nonempty += a.x1 > a.x0;
        ck_assert_msg(cv::countNonZero(want != got) == 0,
                      "trial %d (%d x %d, area %d,%d-%d,%d): %d pixels differ", trial, w, h, a.x0,
                      a.y0, a.x1, a.y1, cv::countNonZero(want != got));
    }
    ck_assert_int_gt(nonempty, 1500);
}
END_TEST

// The outer regions' boxes, in findContours' order, from the closed masks
// as the blob finder calls it (the area's copy, offset to the whole mask).
START_TEST(outer_regions_equal_opencv)
{
    std::mt19937 rng(22);
    const cv::Mat k = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 5));
    OuterRegions regions;
    Vec<Rect> got;
    int nested = 0, total = 0;
    for (int trial = 0; trial < 3000; trial++) {
        const int w = std::uniform_int_distribution<int>(1, 90)(rng);
        const int h = std::uniform_int_distribution<int>(1, 70)(rng);
        cv::Mat m = random_mask(rng, w, h);
        if (trial % 2)
            cv::morphologyEx(m, m, cv::MORPH_CLOSE, k);
        const Rect a = area_of(m);
        std::vector<cv::Rect> want;
        if (a.x1 > a.x0) {
            const cv::Rect roi(a.x0, a.y0, a.x1 - a.x0, a.y1 - a.y0);
            cv::Mat work = m(roi).clone();
            std::vector<std::vector<cv::Point>> contours;
            cv::findContours(work, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE, roi.tl());
            for (const auto &c : contours)
                want.push_back(cv::boundingRect(c));
            // Two levels: every region's outer border at the top, holes
            // below; more regions than outer ones means some lie in holes.
            std::vector<std::vector<cv::Point>> all;
            std::vector<cv::Vec4i> tree;
            work = m(roi).clone();
            cv::findContours(work, all, tree, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
            size_t outer = 0;
            for (const cv::Vec4i &t : tree)
                outer += t[3] < 0;
            nested += outer > want.size();
        }
        regions.find(m.data, w, a, got);
        ck_assert_msg(got.size() == want.size(), "trial %d (%d x %d): %zu boxes, OpenCV %zu",
                      trial, w, h, got.size(), want.size());
        for (size_t i = 0; i < got.size(); i++) {
            const cv::Rect &r = want[i];
            ck_assert_msg(got[i].x0 == r.x && got[i].y0 == r.y && got[i].x1 == r.x + r.width &&
                              got[i].y1 == r.y + r.height,
                          "trial %d box %zu: %d,%d-%d,%d, OpenCV %d,%d %dx%d", trial, i,
                          got[i].x0, got[i].y0, got[i].x1, got[i].y1, r.x, r.y, r.width,
                          r.height);
        }
        total += (int)got.size();
    }
    // The masks had regions inside holes, which both leave out.
    ck_assert_int_gt(nested, 100);
    ck_assert_int_gt(total, 10000);
}
END_TEST

// The contour template's shape (its profile, fill and outline distance map)
// from the box's runs and row-wise chamfer passes is the shape as first
// written (per-pixel flood fill, cell-by-cell chamfer), to the bit, on
// random boxes of random masks: blobs cut by the box, rings, holes, noise.
START_TEST(shape_equals_the_reference)
{
    std::mt19937 rng(24);
    Shape got;
    reference::RefShape want;
    int holes = 0;
    for (int trial = 0; trial < 3000; trial++) {
        const int w = std::uniform_int_distribution<int>(1, 90)(rng);
        const int h = std::uniform_int_distribution<int>(1, 120)(rng);
        const cv::Mat m = random_mask(rng, w, h);
        const Rect b = random_box(rng, w, h);
        const int x0 = b.x0, y0 = b.y0, x1 = b.x1, y1 = b.y1;
        shape_of(m.data, w, x0, y0, x1, y1, &got);
        reference::ref_shape_of(m.data, w, x0, y0, x1, y1, &want);
        ck_assert_msg(std::memcmp(&got.profile, &want.profile, sizeof want.profile) == 0,
                      "trial %d: profiles differ (fill %.9g, reference %.9g)", trial,
                      (double)got.profile.fill, (double)want.profile.fill);
        ck_assert_msg(std::memcmp(&got.outline, &want.outline, sizeof want.outline) == 0,
                      "trial %d: outlines differ", trial);
        for (uint8_t c : want.cells)
            if (c == 0) { // a hole: background the box's border does not reach
                holes++;
                break;
            }
    }
    ck_assert_int_gt(holes, 40);
}
END_TEST

// The outline row by row (for_each_outline) is on_outline()'s, pixel by
// pixel and in raster order, on random boxes of random masks.
START_TEST(outline_rows_equal_the_pixel_test)
{
    std::mt19937 rng(25);
    long pixels = 0;
    for (int trial = 0; trial < 2000; trial++) {
        const int w = std::uniform_int_distribution<int>(1, 80)(rng);
        const int h = std::uniform_int_distribution<int>(1, 80)(rng);
        const cv::Mat m = random_mask(rng, w, h);
        const Rect b = random_box(rng, w, h);
        const int x0 = b.x0, y0 = b.y0, x1 = b.x1, y1 = b.y1;
        std::vector<int> want, got;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++)
                if (on_outline(m.data, (size_t)w, x0, y0, x1, y1, x, y))
                    want.push_back(y * w + x);
        for_each_outline(m.data, (size_t)w, x0, y0, x1, y1,
                         [&](int x, int y) { got.push_back(y * w + x); });
        ck_assert_msg(got == want, "trial %d: %zu outline pixels, the pixel test %zu", trial,
                      got.size(), want.size());
        pixels += (long)want.size();
    }
    ck_assert_int_gt(pixels, 20000);
}
END_TEST

// An empty area gives nothing, and the buffers stay once grown.
START_TEST(buffers_are_kept)
{
    std::mt19937 rng(23);
    OuterRegions regions;
    Closing closing;
    Vec<Rect> got;
    regions.find(nullptr, 0, Rect{0, 0, 0, 0}, got);
    ck_assert_int_eq((int)got.size(), 0);
    const cv::Mat m = random_mask(rng, 80, 60);
    cv::Mat out(60, 80, CV_8UC1, cv::Scalar(0));
    const Rect a{0, 0, 80, 60};
    closing.run(m.data, out.data, 80, 60, a);
    regions.find(out.data, 80, a, got);
    const size_t bytes = closing.memory_bytes() + regions.memory_bytes();
    for (int i = 0; i < 5; i++) {
        closing.run(m.data, out.data, 80, 60, a);
        regions.find(out.data, 80, a, got);
    }
    ck_assert_uint_eq(closing.memory_bytes() + regions.memory_bytes(), bytes);
}
END_TEST

int main(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    Suite *s = suite_create("regions");
    TCase *tc = tcase_create("regions");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, closing_equals_opencv);
    tcase_add_test(tc, outer_regions_equal_opencv);
    tcase_add_test(tc, shape_equals_the_reference);
    tcase_add_test(tc, outline_rows_equal_the_pixel_test);
    tcase_add_test(tc, buffers_are_kept);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
