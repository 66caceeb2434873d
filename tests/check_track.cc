// The tracking models on their own (internal API): the constant-velocity
// filter, the association's gates, and what the tracker learns as it runs
// (the size gate, the detector's scale of scores, the people's size, the
// scene's motion).
#include <check.h>

#include "common.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "pixels/box_fit.h"
#include "track/gate.h"
#include "track/motion.h"
#include "track/person_size.h"
#include "track/scene.h"
#include "track/score_noise.h"
#include "track/score_scale.h"
#include "track/size_gate.h"
#include "track/track.h"

using namespace ctrack;

// ---------------------------------------------------------------------------
// The filter (motion.h).

// Noise-free positions of a walk at constant velocity: the estimate reaches
// the walk's position and velocity.
START_TEST(filter_learns_a_constant_velocity)
{
    Axis a;
    a.init(100, 5, 50);
    double t = 0;
    for (int k = 1; k <= 60; k++) {
        a.predict(0.1, 1.0);
        t += 0.1;
        a.update(100 + 30 * t, 2);
    }
    ck_assert_double_eq_tol(a.v, 30, 0.3);
    ck_assert_double_eq_tol(a.x, 100 + 30 * t, 0.05);
}
END_TEST

// The covariance grows by the white acceleration's, in time: the closed
// form after one prediction, and nothing for dt <= 0.
START_TEST(filter_prediction_grows_with_time)
{
    Axis a;
    a.init(0, 2, 3);
    a.v = 10;
    Axis same = a;
    same.predict(0, 4);
    same.predict(-1, 4);
    ck_assert_double_eq(same.x, 0);
    ck_assert_double_eq(same.p00, 4);
    const double dt = 0.25, q = 16;
    a.predict(dt, 4);
    ck_assert_double_eq_tol(a.x, 2.5, 1e-12);
    ck_assert_double_eq_tol(a.p00, 4 + dt * dt * 9 + q * std::pow(dt, 4) / 4, 1e-12);
    ck_assert_double_eq_tol(a.p01, dt * 9 + q * std::pow(dt, 3) / 2, 1e-12);
    ck_assert_double_eq_tol(a.p11, 9 + q * dt * dt, 1e-12);
    // Without process noise two half steps are one whole one.
    Axis h1, h2;
    h1.init(3, 1, 2);
    h1.v = -4;
    h2 = h1;
    h1.predict(0.5, 0);
    h1.predict(0.5, 0);
    h2.predict(1.0, 0);
    ck_assert_double_eq_tol(h1.x, h2.x, 1e-12);
    ck_assert_double_eq_tol(h1.p00, h2.p00, 1e-12);
    ck_assert_double_eq_tol(h1.p11, h2.p11, 1e-12);
}
END_TEST

// A measurement pulls the estimate by the Kalman gain and shrinks the
// variance; one innovation standard deviation away is a normalized
// innovation squared of 1.
START_TEST(filter_update_weighs_the_measurement)
{
    Axis a;
    a.init(10, 3, 1); // variance 9
    const double r = 4; // measurement variance, sd 2
    ck_assert_double_eq_tol(a.innovation_var(2), 13, 1e-12);
    ck_assert_double_eq_tol(a.nis(10 + std::sqrt(13.0), 2), 1, 1e-12);
    a.update(23, 2);
    ck_assert_double_eq_tol(a.x, 10 + 9.0 / 13 * 13, 1e-12);
    ck_assert_double_eq_tol(a.p00, 9 * r / (9 + r), 1e-12);
    ck_assert(a.p00 < 9);
}
END_TEST

// A track's box follows its detections; a detection's noise is in box
// heights, so a tall person's box is trusted to more pixels.
START_TEST(track_follows_its_detections)
{
    Track t;
    ct_detection d = test_det(100, 50, 40, 100, 0.9f);
    t.start(d, 0.05, 0, 0);
    for (int k = 1; k <= 20; k++) {
        t.predict(0.1, 0.5, 0.5);
        d.left += 2;
        t.correct(d, 0.05, 0.05, 0, k * 100000);
    }
    const Box b = t.box();
    ck_assert_double_eq_tol(b.left, d.left, 1.0);
    // The reported box's model, under the same noises, is the same.
    ck_assert_double_eq_tol(t.shown.box().left, b.left, 1e-9);
    ck_assert_double_eq_tol(b.height, 100, 0.5);
    ck_assert_double_eq_tol(t.cx.v, 20, 2); // 2 px a step of 0.1 s
    ck_assert_int_eq(t.hits, 21);
    ck_assert(t.centre_innovation_sd(0.05) > 0.05 * 100);
}
END_TEST

// ---------------------------------------------------------------------------
// The gates (gate.h), against comparing every pair.

START_TEST(gate_finds_every_overlap)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(0, 600), size(10, 120);
    std::uniform_real_distribution<double> share(0, 0.5);
    for (int trial = 0; trial < 50; trial++) {
        Vec<ct_detection> dets;
        Vec<int> cols;
        for (int j = 0; j < 40; j++) {
            const float h = size(rng);
            dets.push_back(test_det(pos(rng), pos(rng), h * 0.4f, h, 0.9f));
            if (j % 3 != 0) // a subset, named by position
                cols.push_back(j);
        }
        Gate g;
        g.index(dets.data(), cols);
        const Box box{pos(rng), pos(rng), 50, 120};
        // Plain, and with every box widened by a buffer (buffered_iou()).
        for (double buffer : {0.0, share(rng)})
            for (double min_iou : {0.05, 0.2, 0.5}) {
                Vec<Pair> pairs;
                g.overlapping(3, box, min_iou, pairs, 0, buffer);
                std::set<int> want, got;
                for (size_t k = 0; k < cols.size(); k++)
                    if (buffered_iou(box, det_box(dets[(size_t)cols[k]]), buffer) >= min_iou)
                        want.insert((int)k);
                for (const Pair &p : pairs) {
                    ck_assert_int_eq(p.row, 3);
                    ck_assert_double_eq_tol(
                        p.cost,
                        1 - buffered_iou(box, det_box(dets[(size_t)cols[(size_t)p.col]]), buffer),
                        1e-9);
                    got.insert(p.col);
                }
                ck_assert(want.size() <= (size_t)kMaxPairsPerTrack);
                ck_assert(want == got);
            }
    }
}
END_TEST

// Widened alike, two boxes of one size offset by 0.75 of their width
// overlap as if offset by 0.75 / (1 + 2 buffer): half a width at a
// quarter. A buffer of 0 is the plain IoU.
START_TEST(buffered_iou_discounts_the_offset)
{
    const Box a{0, 0, 40, 100}, b{30, 0, 40, 100};
    ck_assert_double_eq_tol(buffered_iou(a, b, 0.25), iou(a, Box{20, 0, 40, 100}), 1e-12);
    ck_assert(iou(a, b) < 0.2 && buffered_iou(a, b, 0.25) > 0.2);
    ck_assert_double_eq(buffered_iou(a, b, 0), iou(a, b));
    // A size ratio counts as much as without the buffer.
    const Box c{-10, -25, 60, 150};
    ck_assert_double_eq_tol(buffered_iou(a, c, 0.3), iou(a, c), 1e-12);
}
END_TEST

// A buffer reaches no neighbour: after separate_buffers(), each box widened
// by its buffer stays clear of every other box widened by the same share,
// or its buffer is 0 where the two already overlap; and it is the largest
// such buffer up to the one asked (compared with every pair).
START_TEST(separate_buffers_keeps_each_box_clear_of_its_neighbours)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> pos(0, 1000), size(20, 150);
    std::uniform_real_distribution<double> share(0, 0.5);
    for (int trial = 0; trial < 200; trial++) {
        const int n = 1 + trial % 30;
        Vec<Box> boxes;
        Vec<double> buffers, asked;
        Vec<int> order;
        for (int k = 0; k < n; k++) {
            const float h = size(rng);
            boxes.push_back(Box{pos(rng), pos(rng) * 0.5f, h * 0.4f, h});
            asked.push_back(share(rng));
        }
        buffers = asked;
        separate_buffers(boxes, buffers, order);
        for (int i = 0; i < n; i++) {
            double want = asked[(size_t)i];
            const Box &p = boxes[(size_t)i];
            for (int j = 0; j < n; j++) {
                if (j == i)
                    continue;
                const Box &q = boxes[(size_t)j];
                const double gx = std::max(q.left - (p.left + p.width), p.left - (q.left + q.width));
                const double gy = std::max(q.top - (p.top + p.height), p.top - (q.top + q.height));
                want = std::min(want, std::max(0.0, std::max(gx / (p.width + q.width),
                                                             gy / (p.height + q.height))));
                ck_assert(buffered_iou(p, q, buffers[(size_t)i] * (1 - 1e-9)) == 0 ||
                          (iou(p, q) > 0 && buffers[(size_t)i] == 0));
            }
            ck_assert_double_eq_tol(buffers[(size_t)i], want, 1e-12);
        }
    }
}
END_TEST

// A flood of identical boxes: one track keeps kMaxPairsPerTrack of them,
// the first ones.
START_TEST(gate_bounds_a_flood)
{
    Vec<ct_detection> dets(200, test_det(100, 100, 40, 100, 0.9f));
    Vec<int> cols;
    for (int j = 0; j < 200; j++)
        cols.push_back(j);
    Gate g;
    g.index(dets.data(), cols);
    Vec<Pair> pairs;
    g.overlapping(0, Box{100, 100, 40, 100}, 0.5, pairs);
    ck_assert_int_eq((int)pairs.size(), kMaxPairsPerTrack);
    for (int k = 0; k < kMaxPairsPerTrack; k++)
        ck_assert_int_eq(pairs[(size_t)k].col, k);
}
END_TEST

// A new track's reach: a detection that misses the IoU gate is paired when
// its centre is within reach at a similar height, at a cost between half
// the gate's and the gate's; not at twice the height, nor beyond reach.
START_TEST(gate_reach_pairs_a_person_who_walked_on)
{
    Vec<ct_detection> dets = {test_det(200, 100, 40, 100, 0.9f),  // 150 px on
                              test_det(200, 100, 80, 200, 0.9f),  // as far, twice as tall
                              test_det(400, 100, 40, 100, 0.9f)}; // too far
    Vec<int> cols = {0, 1, 2};
    Gate g;
    g.index(dets.data(), cols);
    const Box box{50, 100, 40, 100};
    Vec<Pair> none, some;
    g.overlapping(0, box, 0.3, none);
    ck_assert_int_eq((int)none.size(), 0);
    g.overlapping(0, box, 0.3, some, 200);
    ck_assert_int_eq((int)some.size(), 1);
    ck_assert_int_eq(some[0].col, 0);
    ck_assert(some[0].cost >= 0.35 - 1e-9 && some[0].cost <= 0.7 + 1e-9);
    Vec<Pair> near;
    g.near(5, 70, 150, 200, 100, near);
    ck_assert_int_eq((int)near.size(), 1);
    ck_assert_int_eq(near[0].row, 5);
    ck_assert_double_eq_tol(near[0].cost, 150, 1e-9);
}
END_TEST

// ---------------------------------------------------------------------------
// The size gate (size_gate.h).

// People whose height grows with the row of their feet (h = 0.4 y): once
// enough boxes are seen the line is known, and a box far off it is set
// aside; before that, and with no gate, every box is let through.
START_TEST(size_gate_learns_the_line_and_sets_aside_what_is_off_it)
{
    SizeGate g;
    g.set_gate(0.35f);
    const ct_detection giant = test_det(0, 100, 80, 200, 0.9f); // feet at 300: 120 expected
    ck_assert(g.admits(giant));
    for (int k = 0; k < 30; k++) {
        const double foot = 200 + 10 * k, h = 0.4 * foot;
        g.observe(foot - h, h);
    }
    ck_assert(g.known());
    ck_assert_double_eq_tol(g.height_at(300), 120, 1e-6);
    ck_assert(!g.admits(giant));
    ck_assert(g.admits(test_det(0, 300 - 130, 50, 130, 0.9f))); // 8% taller
    ck_assert(!g.admits(test_det(0, 300 - 80, 30, 80, 0.9f)));  // a third shorter
    SizeGate open = g;
    open.set_gate(0);
    ck_assert(open.admits(giant));
    // Bad boxes teach it nothing.
    SizeGate same = g;
    same.observe(NAN, 100);
    same.observe(100, -5);
    same.observe(100, INFINITY);
    ck_assert_double_eq(same.height_at(300), g.height_at(300));
}
END_TEST

// Its samples fade in time (half a second's time constant): after seconds
// without a person the line is unknown again, and a camera that moved is
// learnt anew.
START_TEST(size_gate_forgets_in_time)
{
    SizeGate g;
    g.set_gate(0.35f);
    for (int k = 0; k < 30; k++)
        g.observe(100, 100);
    ck_assert(g.known());
    g.age(0.1);
    ck_assert(g.known());
    g.age(2.0);
    ck_assert(!g.known());
    g.age(-1); // no time passes
    g.age(NAN);
    for (int k = 0; k < 40; k++)
        g.observe(100, 50);
    ck_assert_double_eq_tol(g.height_at(150), 50, 5);
    g.reset();
    ck_assert(!g.known());
}
END_TEST

// ---------------------------------------------------------------------------
// The detector's scale of scores (score_scale.h).

START_TEST(score_scale_bounds_confirmation_by_the_detector_best_boxes)
{
    ScoreScale s;
    ck_assert_float_eq(s.confirm(0.95f), 0.95f); // nothing seen: as asked
    // A detector never surer than 0.9: its boxes confirm at 0.9.
    for (int k = 0; k < 100; k++)
        s.observe(0.9f);
    ck_assert_float_eq_tol(s.confirm(0.95f), 0.9f, 1e-6);
    ck_assert_float_eq(s.confirm(0.5f), 0.5f); // never above what is asked
    // Scores spread evenly: the best 40% start at 0.6.
    s.reset();
    for (int k = 0; k < 1000; k++)
        s.observe((k + 0.5f) / 1000);
    ck_assert_float_eq_tol(s.confirm(0.95f), 0.59f, 0.011);
    // Scores off the scale count at its ends.
    s.reset();
    for (int k = 0; k < 10; k++) {
        s.observe(NAN);
        s.observe(-3);
        s.observe(7);
    }
    ck_assert_float_eq_tol(s.confirm(0.95f), 0.0f, 1e-6);
}
END_TEST

// The score the best 40% of a detector's boxes reach, and how many it has
// learnt: the scale on which high_score and start_score are read.
START_TEST(score_scale_knows_the_detector_best_boxes)
{
    ScoreScale s;
    ck_assert_float_eq(s.best(), 1.0f); // nothing seen: the top of the scale
    ck_assert_uint_eq(s.count(), 0);
    for (int k = 0; k < 1000; k++)
        s.observe(0.3f + 0.4f * (k + 0.5f) / 1000); // spread over [0.3, 0.7]
    ck_assert_uint_eq(s.count(), 1000);
    ck_assert_float_eq_tol(s.best(), 0.54f, 0.011);
    ck_assert_float_eq_tol(s.confirm(0.95f), s.best(), 1e-6);
    ck_assert_float_eq(s.confirm(0.5f), 0.5f);
}
END_TEST

// A long run keeps learning: the counts halve rather than overflow, and a
// detector whose scores drop is followed.
START_TEST(score_scale_keeps_learning)
{
    ScoreScale s;
    for (int k = 0; k < (1 << 21); k++)
        s.observe(0.99f);
    ck_assert_float_eq_tol(s.confirm(1.0f), 0.99f, 1e-6);
    for (int k = 0; k < (1 << 21); k++)
        s.observe(0.7f);
    ck_assert_float_eq_tol(s.confirm(1.0f), 0.7f, 1e-6);
}
END_TEST

// A detector whose boxes scoring 0.6 stray twice as far as those scoring
// 0.97 (their squared innovations 4 times larger): the factors on their
// noise differ twice over, whatever the scale of the scores; a score never
// seen keeps the mean's, 1.
static void feed_two_scores(ScoreNoise &s, float sure, float unsure, int n)
{
    std::mt19937 rng(7);
    std::exponential_distribution<double> e(1.0);
    for (int k = 0; k < n; k++) {
        s.observe(sure, 0.001 * e(rng));
        s.observe(unsure, 0.004 * e(rng));
    }
}

START_TEST(score_noise_learns_how_far_each_score_strays)
{
    ScoreNoise s;
    ck_assert_double_eq(s.factor(0.3f), 1.0); // nothing seen: as configured
    feed_two_scores(s, 0.97f, 0.6f, 20); // 40 < kMinSamples
    ck_assert_double_eq(s.factor(0.6f), 1.0);
    feed_two_scores(s, 0.97f, 0.6f, 2000);
    ck_assert_double_eq_tol(s.factor(0.6f) / s.factor(0.97f), 2.0, 0.15);
    ck_assert(s.factor(0.97f) < 1 && s.factor(0.6f) > 1);
    ck_assert_double_eq_tol(s.factor(0.3f), 1.0, 1e-12);
    // The same detector on another scale (its scores squared).
    ScoreNoise squared;
    feed_two_scores(squared, 0.97f * 0.97f, 0.6f * 0.6f, 2022);
    ck_assert_double_eq_tol(squared.factor(0.36f) / squared.factor(0.94f), 2.0, 0.15);
    // What is not a squared innovation is ignored; scores off the scale
    // count at its ends.
    const double before = s.factor(0.6f);
    s.observe(0.6f, NAN);
    s.observe(0.6f, INFINITY);
    s.observe(0.6f, -1);
    ck_assert_double_eq(s.factor(0.6f), before);
    s.observe(NAN, 0.002);
    s.observe(7, 0.002);
    ck_assert(std::isfinite(s.factor(NAN)) && std::isfinite(s.factor(7)));
    // Bounded: a few boxes far worse than the many (a root of 4.5 times
    // the mean), and those many far better (0.23 times).
    s.reset();
    for (int k = 0; k < 1000; k++)
        s.observe(0.97f, 1e-3);
    for (int k = 0; k < 30; k++)
        s.observe(0.5f, 1.0);
    ck_assert_double_eq(s.factor(0.5f), ScoreNoise::kMaxFactor);
    ck_assert_double_eq(s.factor(0.97f), ScoreNoise::kMinFactor);
}
END_TEST

// ---------------------------------------------------------------------------
// The people's size (person_size.h).

// Boxes of people on a flat ground (h = 0.3 y + 20, widths 0.35 h): the
// line is found within the bins' 10%, and the width three in four stay
// under.
START_TEST(person_size_fits_the_ground_line)
{
    PersonSize p;
    p.reset(480);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> foot(120, 470), ratio(0.25, 0.45);
    for (int k = 0; k < 19; k++) {
        const double y = foot(rng), h = 0.3 * y + 20;
        p.observe(y - h, h, ratio(rng) * h);
    }
    p.learn();
    ck_assert(!p.known()); // fewer than 20 boxes
    ck_assert_double_eq(p.height_at(300), 0);
    for (int k = 0; k < 400; k++) {
        const double y = foot(rng), h = 0.3 * y + 20;
        p.observe(y - h, h, ratio(rng) * h);
    }
    p.learn();
    ck_assert(p.known());
    for (double y : {150.0, 300.0, 450.0})
        ck_assert_double_eq_tol(p.height_at(y), 0.3 * y + 20, 0.1 * (0.3 * y + 20));
    ck_assert_double_eq_tol(p.aspect(), 0.40, 0.04);
    ck_assert_double_eq_tol(p.width_at(300), p.aspect() * p.height_at(300), 1e-9);
    ck_assert(p.height_at(0) < p.typical_height() && p.typical_height() < p.height_at(480));
    ck_assert_uint_eq(p.samples(), 419);
    p.reset(480);
    ck_assert(!p.known());
    ck_assert_uint_eq(p.samples(), 0);
}
END_TEST

// A camera over no flat ground (people smaller lower in the image) gets a
// constant height; boxes before the image's height is known, or without a
// size, teach it nothing.
START_TEST(person_size_never_slopes_the_wrong_way)
{
    PersonSize p;
    p.observe(100, 80, 30); // image height unknown
    p.reset(480);
    p.observe(100, 0, 30);
    p.observe(100, 80, -1);
    p.observe(100, NAN, 30);
    ck_assert_uint_eq(p.samples(), 0);
    for (int k = 0; k < 200; k++) {
        const double y = 100 + k * 1.8, h = 200 - 0.3 * y;
        p.observe(y - h, h, 0.4 * h);
    }
    p.learn();
    ck_assert(p.known());
    ck_assert_double_eq(p.slope(), 0);
    ck_assert_double_eq(p.height_at(100), p.height_at(450));
    ck_assert(p.height_at(0) >= PersonSize::kPriorMinHeight * 0.25);
}
END_TEST

// ---------------------------------------------------------------------------
// The scene's motion (scene.h).

// Innovations as the filter expects them leave the scale at 1 and boxes at
// the estimate; larger ones raise it in time (0.3 s's time constant, in
// log terms).
START_TEST(scene_motion_follows_the_innovations_in_time)
{
    SceneMotion m;
    for (int k = 0; k < 50; k++) {
        m.observe(1.0);
        m.learn(0.04);
    }
    ck_assert_double_eq_tol(m.scale(), 1, 1e-9);
    ck_assert_double_eq(m.noise(), 1);
    // A scene four times less predictable than motion_noise says: the
    // innovations' normalized square is 4 over the scale learnt so far.
    // After 0.3 s at 10 and at 30 frames/s, the same scale: 4^(1 - 1/e).
    SceneMotion a, b;
    for (int k = 0; k < 3; k++) {
        a.observe(4.0 / a.scale());
        a.learn(0.1);
    }
    for (int k = 0; k < 9; k++) {
        b.observe(4.0 / b.scale());
        b.learn(0.1 / 3);
    }
    const double want = std::pow(4.0, 1 - std::exp(-1.0));
    ck_assert_double_eq_tol(a.scale(), want, 1e-9);
    ck_assert_double_eq_tol(b.scale(), want, 1e-9);
    // No innovation, or no time, changes nothing; one wild innovation
    // counts as about three standard deviations (a normalized square of 9).
    SceneMotion c = a;
    c.learn(0.5);
    ck_assert_double_eq(c.scale(), a.scale());
    c.observe(1e9);
    c.learn(0);
    ck_assert_double_eq(c.scale(), a.scale());
    c.observe(1e9);
    c.learn(10);
    ck_assert_double_eq_tol(c.scale(), 9.0 * a.scale(), 1e-6);
    c.reset();
    ck_assert_double_eq(c.scale(), 1);
}
END_TEST

// The reported boxes' noise factor: successive innovations of one sign (a
// filter that lags) lower it, of alternating signs (one that chases the
// jitter) raise it, uncorrelated ones leave it; at the same rate in time
// at 10 and 30 frames/s; within its bounds; and only when asked to whiten.
START_TEST(scene_noise_whitens_the_innovations)
{
    SceneMotion lag, lag30, chase, white, off;
    for (int k = 0; k < 10; k++) {
        lag.observe_pair(1, 1, 1, 1);
        lag.learn(0.1, true);
        chase.observe_pair(1, -1, -1, 1);
        chase.learn(0.1, true);
        white.observe_pair(1, 0, 0, 1);
        white.learn(0.1, true);
        off.observe_pair(1, 1, 1, 1);
        off.learn(0.1);
    }
    for (int k = 0; k < 30; k++) {
        lag30.observe_pair(1, 1, 1, 1);
        lag30.learn(0.1 / 3, true);
    }
    // A correlation of 1 for 1 s: a factor of 1/e.
    ck_assert_double_eq_tol(lag.noise(), std::exp(-1.0), 1e-9);
    ck_assert_double_eq_tol(lag30.noise(), lag.noise(), 1e-9);
    ck_assert_double_eq_tol(chase.noise(), std::exp(1.0), 1e-9);
    ck_assert_double_eq(white.noise(), 1);
    ck_assert_double_eq(off.noise(), 1);
    for (int k = 0; k < 100; k++) {
        lag.observe_pair(2, 0, 3, 0);
        lag.learn(0.1, true);
        chase.observe_pair(-3, 0, 2, 0);
        chase.learn(0.1, true);
    }
    ck_assert_double_eq_tol(lag.noise(), 0.25, 1e-12);
    ck_assert_double_eq_tol(chase.noise(), 10, 1e-9);
    lag.reset();
    ck_assert_double_eq(lag.noise(), 1);
}
END_TEST

// ---------------------------------------------------------------------------
// What the fit does to a detector's boxes (box_fit.h).

// A detector whose boxes are 1.4 times a person's width and start 5% of
// their height too high: once 20 boxes were fitted, a box is narrowed and
// moved down as the fit moved them, about its own centre across; before,
// it is left as it is. Bad boxes teach nothing.
START_TEST(fit_bias_learns_what_the_fit_does)
{
    FitBias f;
    const Box det{100, 50, 56, 100};
    const Box fitted{108, 55, 40, 100}; // 40/56 wide, 5% lower
    for (int k = 0; k < 19; k++)
        f.learn(det, fitted);
    ck_assert(!f.known());
    const Box b{300, 200, 70, 140};
    Box same = f.apply(b);
    ck_assert_double_eq(same.left, b.left);
    ck_assert_double_eq(same.width, b.width);
    ck_assert_double_eq(same.top, b.top);
    f.learn(Box{0, 0, 0, 100}, fitted); // no width: ignored
    f.learn(Box{0, 0, NAN, 100}, fitted);
    ck_assert(!f.known());
    f.learn(det, fitted);
    ck_assert(f.known());
    const Box a = f.apply(b);
    ck_assert_double_eq_tol(a.width, 70 * 40.0 / 56, 1e-9);
    ck_assert_double_eq_tol(a.left + a.width / 2, b.left + b.width / 2, 1e-9);
    ck_assert_double_eq_tol(a.top, b.top + 0.05 * 140, 1e-9);
    ck_assert_double_eq(a.height, b.height);
    // A detector that changes: the mean follows it within some 50 boxes.
    for (int k = 0; k < 300; k++)
        f.learn(det, det);
    ck_assert_double_eq_tol(f.apply(b).width, 70, 0.1);
}
END_TEST

// The people's size learnt from 400 boxes whose feet are on rows 100 to
// 199, each slope * (feet row) + offset pixels tall.
static void learn_line(PersonSize &size, double slope, double offset)
{
    for (int k = 0; k < 400; k++) {
        const double y = 100 + k % 100, h = slope * y + offset;
        size.observe(y - h, h, 0.35 * h);
    }
    size.learn();
}

// The people's size of a 200-row image, learnt from that line.
static PersonSize line_of(double slope, double offset)
{
    PersonSize size;
    size.reset(200);
    learn_line(size, slope, offset);
    return size;
}

// A person's silhouette in a 100 x 200 mask (scale 1): head, torso and legs,
// its head's top at `top` and its feet at row 160, centred on column 50;
// with `behind`, another person's head and shoulders just above, joined to
// it (someone behind, farther up the image).
static void draw_standing(uint8_t *m, int top, bool behind)
{
    std::fill(m, m + 100 * 200, 0);
    auto disc = [&](double cx, double cy, double r) {
        for (int y = 0; y < 200; y++)
            for (int x = 0; x < 100; x++)
                if ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) < r * r)
                    m[y * 100 + x] = 255;
    };
    auto rect = [&](int x0, int x1, int y0, int y1) {
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++)
                m[y * 100 + x] = 255;
    };
    const int h = 160 - top;
    disc(50, top + 0.06 * h, 0.06 * h);
    rect(40, 60, top + (int)(0.12 * h), top + (int)(0.75 * h));
    rect(41, 49, top + (int)(0.75 * h), 160);
    rect(51, 59, top + (int)(0.75 * h), 160);
    if (behind) {
        disc(50, top - 5, 5);
        rect(42, 58, top - 1, top + 1);
    }
}

// The fit moves a box up or down to the silhouette's head-to-feet extent
// only where that extent is one person's: with the people's size known
// (96 pixels tall at feet row 160), an extent from another person's head
// behind down to this one's feet (110 pixels) does not move the box up.
// A detector's box whose bottom is at those feet takes, `follow` of the
// way, the height of a person standing there; one whose bottom is 20 rows
// past them, and a blob's own box, keep their rows. Without that head the
// box is moved to the person.
START_TEST(fit_moves_a_box_only_to_one_persons_extent)
{
    PersonSize size;
    size.reset(200);
    learn_line(size, 0.6, 0);
    ck_assert(size.known() && size.speaks_at(160));
    ck_assert_double_eq_tol(size.height_at(160), 96, 5);
    static uint8_t m[100 * 200];
    const Box b{36, 60, 28, 100}; // a detector's box, its top at the head
    Box out;
    draw_standing(m, 60, true);
    // Without the size the joined extent (rows 50-159) moves the box up.
    ck_assert(fit_box(m, 100, 200, 1, b, kFitFollow, nullptr, true, &out));
    ck_assert_double_lt(out.top, b.top - 3);
    // With it, the box keeps its bottom at the feet and shrinks toward a
    // person standing there, its top moving down, not up.
    ck_assert(fit_box(m, 100, 200, 1, b, kFitFollow, &size, true, &out));
    ck_assert_double_eq_tol(out.top + out.height, 160, 0.5);
    ck_assert_double_eq_tol(out.height, b.height + kFitFollow * (size.height_at(160) - b.height),
                            0.5);
    ck_assert_double_gt(out.top, b.top + 1);
    // A blob's own box is its extent already, and keeps its rows.
    ck_assert(fit_box(m, 100, 200, 1, b, kFitFollow, &size, false, &out));
    ck_assert_double_eq_tol(out.top, b.top, 0.5);
    ck_assert_double_eq_tol(out.height, b.height, 0.5);
    // Its bottom 20 rows past the feet: neither the extent nor the feet
    // are known to be this box's person's, and the box keeps its rows.
    const Box past{36, 60, 28, 120};
    ck_assert(fit_box(m, 100, 200, 1, past, kFitFollow, &size, true, &out));
    ck_assert_double_eq_tol(out.top, past.top, 0.5);
    ck_assert_double_eq_tol(out.height, past.height, 0.5);
    // One person alone, the box 8 rows too low: moved up toward the head.
    draw_standing(m, 64, false);
    const Box low{36, 72, 28, 96};
    ck_assert(fit_box(m, 100, 200, 1, low, kFitFollow, &size, true, &out));
    ck_assert_double_lt(out.top, low.top - 4);
}
END_TEST

// A detector's box above its person and a little tall (its top 16 rows
// above the head, more than 0.15 of its height; its bottom 8 rows past the
// feet):
// the head is too far from the top for the fit to trust it, unless the
// people's size says the head-to-feet extent is one whole person at its
// feet. Not for a blob's own box, nor for an extent under kSizedExtent (0.8)
// of a person.
START_TEST(fit_takes_a_far_head_where_the_size_vouches)
{
    PersonSize size;
    size.reset(200);
    learn_line(size, 0.6, 0);
    ck_assert_double_eq_tol(size.height_at(160), 96, 5);
    static uint8_t m[100 * 200];
    draw_standing(m, 64, false); // head at row 64, feet at 160: 96 rows
    const Box high{36, 48, 28, 104};
    Box out;
    // Without the size the head is no one's in particular: rows kept.
    ck_assert(fit_box(m, 100, 200, 1, high, kFitFollow, nullptr, true, &out));
    ck_assert_double_eq_tol(out.top, high.top, 0.5);
    ck_assert_double_eq_tol(out.height, high.height, 0.5);
    // With it, the box moves the follow's share of the way to the extent.
    ck_assert(fit_box(m, 100, 200, 1, high, kFitFollow, &size, true, &out));
    const double centre = out.top + out.height / 2;
    ck_assert_double_eq_tol(centre, 100 + kFitFollow * (112 - 100), 1);
    ck_assert_double_eq_tol(out.height, 104 + kFitFollow * (96 - 104), 1);
    // A blob's own box keeps its rows.
    ck_assert(fit_box(m, 100, 200, 1, high, kFitFollow, &size, false, &out));
    ck_assert_double_eq_tol(out.top, high.top, 0.5);
    ck_assert_double_eq_tol(out.height, high.height, 0.5);
    // Where people standing at those feet are 125 rows tall, the 96-row
    // extent is under 0.8 of one (a fragment, a child): rows kept.
    PersonSize taller;
    taller.reset(200);
    learn_line(taller, 0.3, 77);
    ck_assert_double_eq_tol(taller.height_at(160), 125, 6);
    ck_assert(fit_box(m, 100, 200, 1, high, kFitFollow, &taller, true, &out));
    ck_assert_double_eq_tol(out.top, high.top, 0.5);
    ck_assert_double_eq_tol(out.height, high.height, 0.5);
}
END_TEST

// A short person (82 rows, 0.85 of the people's 96 at their feet, row 160)
// with someone's head joined above theirs: the joined extent, 92 rows, is
// under 1.1 of the people's height but over 1.1 of this person's own. With
// their stature known it is not one person's: a detector's box from that
// head to the feet moves toward their own height, from the feet up, and
// does not keep the joined extent. The extent is still read as a stature
// against the people's size, so that a stature read low once is corrected.
START_TEST(one_person_is_judged_by_their_own_stature)
{
    const PersonSize size = line_of(0.6, 0);
    static uint8_t m[100 * 200];
    draw_standing(m, 78, true);
    const Box b{36, 68, 28, 92};
    Box out;
    Stature unknown;
    ck_assert(fit_box(m, 100, 200, 1, b, kFitFollow, &size, true, &out, &unknown));
    ck_assert_double_eq_tol(out.height, 92, 2);
    ck_assert_double_eq_tol(unknown.seen, 92.0 / 96, 0.03);
    Stature own;
    own.known = 0.85;
    ck_assert(fit_box(m, 100, 200, 1, b, kFitFollow, &size, true, &out, &own));
    ck_assert_double_eq_tol(out.height, 92 + kFitFollow * (0.85 * 96 - 92), 2);
    ck_assert_double_eq_tol(out.top + out.height, 160, 1.5);
    ck_assert_double_eq_tol(own.seen, 92.0 / 96, 0.03);
}
END_TEST

// A person behind a sign (the 100 x 200 mask shows their head, its top at
// row 64, and their shoulders down to row 98; the people's size puts a
// person of the line's height, 96 rows, under that head): a detector's box
// 12 rows too high holds too little foreground for fit_box(). fit_faint()
// moves it the follow's share of the way to the head and to the height of
// a person of their stature under it. Not without a head near the box's
// top, nor where the line is as steep as the rows (a camera at street
// level: no one under a head), nor a box fit_box() reads.
START_TEST(fit_faint_places_a_box_from_its_persons_head)
{
    const PersonSize size = line_of(0.6, 0);
    ck_assert_double_eq_tol(size.height_under_head(64), 96, 4);
    ck_assert_double_eq_tol(size.height_under_head(64, 0.9), 75, 4);
    static uint8_t m[100 * 200];
    draw_standing(m, 64, false);
    std::fill(m + 98 * 100, m + 200 * 100, 0);
    const Box high{36, 52, 28, 96};
    Box out;
    ck_assert(!fit_box(m, 100, 200, 1, high, kFitFollow, &size, true, &out));
    ck_assert(fit_faint(m, 100, 200, 1, high, kFitFollow, size, 1, &out));
    ck_assert_double_eq_tol(out.top, 52 + kFitFollow * (64 - 52), 1.5);
    ck_assert_double_eq_tol(out.height, 96, 2);
    ck_assert_double_eq_tol(out.left + out.width / 2, 50, 1);
    // A shorter person's own stature: toward their height.
    ck_assert(fit_faint(m, 100, 200, 1, high, kFitFollow, size, 0.9, &out));
    ck_assert_double_eq_tol(out.height, 96 + kFitFollow * (75 - 96), 3);
    // No head within a quarter of the box below its top.
    const Box far{36, 20, 28, 96};
    ck_assert(!fit_faint(m, 100, 200, 1, far, kFitFollow, size, 1, &out));
    // A line as steep as the rows puts no one under a head.
    const PersonSize steep = line_of(1.3, -100);
    ck_assert(steep.known() && steep.slope() > 1);
    ck_assert(!fit_faint(m, 100, 200, 1, high, kFitFollow, steep, 1, &out));
    // The whole silhouette is fit_box()'s.
    draw_standing(m, 64, false);
    ck_assert(!fit_faint(m, 100, 200, 1, high, kFitFollow, size, 1, &out));
}
END_TEST

// A person behind another (the 100 x 200 mask: their head's top at row 64,
// 96 rows above their feet on the people's line; the one in front a block
// from row 90 down, whose box starts there): a detector's box for the one
// behind from 12 rows above their head down into the other's legs, row 192,
// moves the follow's share of the way to their head and to the height of
// a person of their stature under it, from the rows above the other box.
// Not a box whose head is under the other's top, nor one that ends below
// the other's bottom (in front), nor where the line is as steep as the rows.
START_TEST(fit_behind_places_a_box_from_the_head_above_the_other)
{
    const PersonSize size = line_of(0.6, 0);
    static uint8_t m[100 * 200];
    draw_standing(m, 64, false);
    for (int y = 90; y < 200; y++)
        for (int x = 30; x < 70; x++)
            m[y * 100 + x] = 255;
    const Box b{36, 52, 28, 140};
    Box out;
    ck_assert(fit_behind(m, 100, 200, 1, b, 90, 200, kFitFollow, size, 1, &out));
    ck_assert_double_eq_tol(out.top, 52 + kFitFollow * (64 - 52), 1.5);
    ck_assert_double_eq_tol(out.height, 140 + kFitFollow * (96 - 140), 2);
    ck_assert_double_eq_tol(out.left, b.left, 1e-9);
    ck_assert_double_eq_tol(out.width, b.width, 1e-9);
    // A shorter person's own stature: toward their height.
    ck_assert(fit_behind(m, 100, 200, 1, b, 90, 200, kFitFollow, size, 0.9, &out));
    ck_assert_double_eq_tol(out.height, 140 + kFitFollow * (75 - 140), 3);
    // The other box starts above this one: no head of its own above it.
    ck_assert(!fit_behind(m, 100, 200, 1, b, 50, 200, kFitFollow, size, 1, &out));
    // This one ends below the other: its person is in front.
    ck_assert(!fit_behind(m, 100, 200, 1, b, 90, 190, kFitFollow, size, 1, &out));
    const PersonSize steep = line_of(1.3, -100);
    ck_assert(!fit_behind(m, 100, 200, 1, b, 90, 200, kFitFollow, steep, 1, &out));
}
END_TEST

// A person whose legs run off the image's bottom (a 100 x 200 mask, the
// head's top at row 100, the legs down to the last row): a detector's box
// that ends above the edge (row 192) moves the follow's share of the way
// to the extent from the head to the edge. Not a box that runs past the
// edge (nothing says where the feet are), nor a blob's own box.
START_TEST(fit_takes_the_extent_to_the_image_edge)
{
    static uint8_t m[100 * 200];
    std::fill(m, m + 100 * 200, 0);
    for (int y = 100; y < 200; y++)
        for (int x = 0; x < 100; x++) {
            const bool head = y < 112 && x >= 45 && x < 55;
            const bool torso = y >= 112 && y < 170 && x >= 40 && x < 60;
            const bool legs = y >= 170 && ((x >= 41 && x < 49) || (x >= 51 && x < 59));
            if (head || torso || legs)
                m[y * 100 + x] = 255;
        }
    const Box above{36, 100, 28, 92};
    Box out;
    ck_assert(fit_box(m, 100, 200, 1, above, kFitFollow, nullptr, true, &out));
    const double centre = out.top + out.height / 2;
    ck_assert_double_eq_tol(centre, 146 + kFitFollow * (150 - 146), 0.5);
    ck_assert_double_eq_tol(out.height, 92 + kFitFollow * (100 - 92), 0.5);
    const Box past{36, 100, 28, 110};
    ck_assert(fit_box(m, 100, 200, 1, past, kFitFollow, nullptr, true, &out));
    ck_assert_double_eq_tol(out.top, past.top, 0.5);
    ck_assert_double_eq_tol(out.height, past.height, 0.5);
    ck_assert(fit_box(m, 100, 200, 1, above, kFitFollow, nullptr, false, &out));
    ck_assert_double_eq_tol(out.top, above.top, 0.5);
    ck_assert_double_eq_tol(out.height, above.height, 0.5);
}
END_TEST

// A walker in mid-stride: the same head and torso as draw_standing() (head
// at row 60), the front leg straight down to row 151 and the rear leg
// slanting back to a foot on row 159, its columns 34-40, some 12 columns
// (0.12 of the person's height) left of the body's axis at column 49.
static void draw_striding(uint8_t *m)
{
    draw_standing(m, 60, false);
    for (int y = 135; y < 160; y++)
        for (int x = 40; x < 60; x++)
            m[y * 100 + x] = 0;
    for (int y = 135; y < 152; y++)
        for (int x = 51; x < 59; x++)
            m[y * 100 + x] = 255;
    for (int y = 135; y < 160; y++) {
        const int x0 = 42 - (y - 135) * 9 / 25; // the rear leg, slanting back
        for (int x = x0; x < x0 + 7; x++)
            m[y * 100 + x] = 255;
    }
}

// The feet are sought across a stride: a detector's box from the head to
// the rear foot keeps its bottom there, not at the front foot near the
// axis, 8 rows higher (a band of 0.1 box heights each side of the axis
// found that one, and the box's bottom moved 5.6 rows up).
START_TEST(fit_finds_the_feet_across_a_stride)
{
    static uint8_t m[100 * 200];
    draw_striding(m);
    const Box b{33, 60, 30, 100};
    Box out;
    ck_assert(fit_box(m, 100, 200, 1, b, kFitFollow, nullptr, true, &out));
    ck_assert_msg(std::fabs(out.top + out.height - 160) <= 1, "bottom at %.1f, the feet at 160",
                  out.top + out.height);
    ck_assert_double_eq_tol(out.top, 60, 1);
}
END_TEST

// A box whose top another box covers is read below that box where its
// person is in front: across to the legs' axis (column 50) and to the feet
// (row 160), then a person's height there where the size speaks. Not where
// its bottom is above the other's, nor at a cover's bottom that is no
// number.
START_TEST(fit_in_front_reads_below_the_other_box)
{
    static uint8_t m[100 * 200];
    draw_standing(m, 60, false);
    const Box b{36, 60, 36, 110}; // centre 54, bottom 170
    Box out;
    ck_assert(fit_in_front(m, 100, 200, 1, b, 120, 1, nullptr, &out));
    ck_assert_double_eq_tol(out.left + out.width / 2, 50, 1);
    ck_assert_double_eq_tol(out.top + out.height, 160, 1);
    ck_assert_double_eq_tol(out.height, 110, 1e-9);
    PersonSize size;
    size.reset(200);
    learn_line(size, 0.6, 0);
    ck_assert(fit_in_front(m, 100, 200, 1, b, 120, 1, &size, &out));
    ck_assert_double_eq_tol(out.top + out.height, 160, 1);
    ck_assert_double_eq_tol(out.height, size.height_at(out.top + out.height), 1e-9);
    const Box untouched = out;
    ck_assert(!fit_in_front(m, 100, 200, 1, b, 175, 1, &size, &out));
    ck_assert(!fit_in_front(m, 100, 200, 1, b, std::nan(""), 1, &size, &out));
    ck_assert(!fit_in_front(m, 100, 200, 1, Box{36, 60, std::nan(""), 110}, 120, 1, &size,
                            &out));
    ck_assert_double_eq(out.top, untouched.top);
    ck_assert_double_eq(out.left, untouched.left);
}
END_TEST

// A box cut short of a person grows to the height a person whose head is at
// its top has, only where the people's line holds that height at their
// feet (PersonSize::line_holds_at()): with a slope near 1, the height
// under a head at row 60 of a 200-row image is past the tallest person the
// line may give (400 rows: PersonSize::max_height()), and the box keeps
// its rows; with the line of people 0.6 of their feet's row tall it grows
// to that person (90 rows).
START_TEST(a_cut_box_grows_only_to_a_height_the_line_holds)
{
    static uint8_t m[100 * 200];
    draw_standing(m, 60, false);
    const Box cut{36, 60, 28, 40}; // cut at the chest
    Box out;
    PersonSize steep;
    steep.reset(200);
    learn_line(steep, 0.95, -10);
    ck_assert(steep.known() && steep.slope() < 1);
    ck_assert_double_gt(steep.height_under_head(60), steep.max_height());
    ck_assert(fit_box(m, 100, 200, 1, cut, kFitFollow, &steep, true, &out));
    ck_assert_msg(out.height <= 200, "grown to %.0f rows", out.height);
    PersonSize size;
    size.reset(200);
    learn_line(size, 0.6, 0);
    ck_assert(fit_box(m, 100, 200, 1, cut, kFitFollow, &size, true, &out));
    ck_assert_double_gt(out.height, 80);
}
END_TEST

// A detector's box more than a tenth taller than the person whose feet are
// at its bottom row becomes that person; a box within a tenth, or where
// the people's size does not speak (above the highest feet it has seen by
// more than a person), keeps its rows.
START_TEST(a_box_over_more_than_one_person_is_cut_to_one)
{
    PersonSize size;
    size.reset(200);
    Box b{36, 40, 28, 120};
    ck_assert(!cut_to_one_person(size, &b)); // the size is not known yet
    learn_line(size, 0.6, 0);
    const double tall = size.height_at(160);
    ck_assert_double_eq_tol(tall, 96, 5);
    ck_assert(cut_to_one_person(size, &b)); // 120 rows, feet at 160
    ck_assert_double_eq_tol(b.top + b.height, 160, 1e-9);
    ck_assert_double_eq_tol(b.height, tall, 1e-9);
    ck_assert_double_eq_tol(b.left, 36, 1e-9);
    ck_assert_double_eq_tol(b.width, 28, 1e-9);
    Box one{36, 160 - 1.05 * tall, 28, 1.05 * tall};
    const Box before = one;
    ck_assert(!cut_to_one_person(size, &one));
    ck_assert_double_eq_tol(one.top, before.top, 1e-9);
    ck_assert_double_eq_tol(one.height, before.height, 1e-9);
    ck_assert(!size.speaks_at(10));
    Box high{36, 0, 28, 10};
    ck_assert(!cut_to_one_person(size, &high));
    ck_assert_double_eq_tol(high.height, 10, 1e-9);
}
END_TEST

// Where the size's line runs past its bound (the image's height, or 400
// pixels on a smaller image), its height is held there and measures no
// one: a box there keeps its rows; where the line is its own, a box 1.3
// times its height is cut.
START_TEST(a_box_where_the_size_is_held_at_its_bound_is_not_cut)
{
    PersonSize size;
    size.reset(480);
    for (int k = 0; k < 400; k++) {
        const double y = 300 + 1.7 * (k % 100), h = 2 * y - 400; // 200 to 536
        size.observe(y - h, h, 0.35 * h);
    }
    size.learn();
    ck_assert_double_eq(size.max_height(), 480);
    ck_assert(size.known() && size.speaks_at(470));
    ck_assert_double_eq_tol(size.height_at(470), 480, 1e-9);
    ck_assert(!size.line_holds_at(470));
    Box held{100, 470 - 1.3 * 480, 200, 1.3 * 480};
    const Box before = held;
    ck_assert(!cut_to_one_person(size, &held));
    ck_assert_double_eq_tol(held.top, before.top, 1e-9);
    ck_assert_double_eq_tol(held.height, before.height, 1e-9);
    ck_assert(size.line_holds_at(350));
    const double tall = size.height_at(350);
    ck_assert_double_eq_tol(tall, 300, 30);
    Box two{100, 350 - 1.3 * tall, 120, 1.3 * tall};
    ck_assert(cut_to_one_person(size, &two));
    ck_assert_double_eq_tol(two.height, tall, 1e-9);
}
END_TEST

// On a high-definition camera, people close to it are far taller than the
// prior's 400 pixels: the size follows them up to the image's height.
START_TEST(person_size_knows_people_taller_than_the_prior)
{
    PersonSize p;
    p.reset(1080);
    for (int k = 0; k < 400; k++) {
        const double y = 500 + 5 * (k % 100), h = 0.6 * y; // 300 to 597
        p.observe(y - h, h, 0.35 * h);
    }
    p.learn();
    ck_assert_double_eq(p.max_height(), 1080);
    ck_assert_double_eq_tol(p.height_at(1000), 600, 60);
    ck_assert(p.line_holds_at(1000));
    ck_assert(p.typical_height() > PersonSize::kPriorMaxHeight);
    p.reset(240);
    ck_assert_double_eq(p.max_height(), PersonSize::kPriorMaxHeight);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("track");
    TCase *tc = tcase_create("models");
    tcase_add_test(tc, filter_learns_a_constant_velocity);
    tcase_add_test(tc, fit_bias_learns_what_the_fit_does);
    tcase_add_test(tc, fit_moves_a_box_only_to_one_persons_extent);
    tcase_add_test(tc, fit_takes_a_far_head_where_the_size_vouches);
    tcase_add_test(tc, fit_takes_the_extent_to_the_image_edge);
    tcase_add_test(tc, one_person_is_judged_by_their_own_stature);
    tcase_add_test(tc, fit_faint_places_a_box_from_its_persons_head);
    tcase_add_test(tc, fit_behind_places_a_box_from_the_head_above_the_other);
    tcase_add_test(tc, fit_finds_the_feet_across_a_stride);
    tcase_add_test(tc, fit_in_front_reads_below_the_other_box);
    tcase_add_test(tc, a_cut_box_grows_only_to_a_height_the_line_holds);
    tcase_add_test(tc, a_box_over_more_than_one_person_is_cut_to_one);
    tcase_add_test(tc, a_box_where_the_size_is_held_at_its_bound_is_not_cut);
    tcase_add_test(tc, filter_prediction_grows_with_time);
    tcase_add_test(tc, filter_update_weighs_the_measurement);
    tcase_add_test(tc, track_follows_its_detections);
    tcase_add_test(tc, gate_finds_every_overlap);
    tcase_add_test(tc, buffered_iou_discounts_the_offset);
    tcase_add_test(tc, separate_buffers_keeps_each_box_clear_of_its_neighbours);
    tcase_add_test(tc, gate_bounds_a_flood);
    tcase_add_test(tc, gate_reach_pairs_a_person_who_walked_on);
    tcase_add_test(tc, size_gate_learns_the_line_and_sets_aside_what_is_off_it);
    tcase_add_test(tc, size_gate_forgets_in_time);
    tcase_add_test(tc, score_scale_bounds_confirmation_by_the_detector_best_boxes);
    tcase_add_test(tc, score_scale_keeps_learning);
    tcase_add_test(tc, score_scale_knows_the_detector_best_boxes);
    tcase_add_test(tc, score_noise_learns_how_far_each_score_strays);
    tcase_add_test(tc, person_size_fits_the_ground_line);
    tcase_add_test(tc, person_size_never_slopes_the_wrong_way);
    tcase_add_test(tc, person_size_knows_people_taller_than_the_prior);
    tcase_add_test(tc, scene_motion_follows_the_innovations_in_time);
    tcase_add_test(tc, scene_noise_whitens_the_innovations);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
