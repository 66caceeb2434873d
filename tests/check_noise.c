/* Tracking from the pixels alone under sensor noise and changing light, on
 * synthetic I420 frames at 25 frames/s: the background model learns the
 * scene's noise and its exposure, so noise makes no candidate, a global step
 * of light starts no track, and a person walking through the noise is
 * still found. */
#include <math.h>
#include <stdbool.h>

#include "common.h"

#define W 320
#define H 240
#define FPS 25
#define SEC 1000000LL

typedef struct {
    uint8_t y[W * H], u[(W / 2) * (H / 2)], v[(W / 2) * (H / 2)];
} image;

static uint64_t rng = 0x853C49E6748FEA9Bull;

static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return ((rng >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

/* Gaussian noise of standard deviation sd (Box-Muller). */
static double gauss(double sd)
{
    return sd * sqrt(-2 * log(uniform())) * cos(6.283185307179586 * uniform());
}

static uint8_t clamp_byte(double v)
{
    return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : lround(v));
}

/* A textured grey scene seen through an exposure `gain`, with a person (an
 * ellipse 30 x 70, dark shirt, red trousers) centred at (cx, cy) unless
 * cx < 0, and sensor noise of standard deviation `sd` in every plane. */
static void draw(image *im, double gain, double cx, double cy, double sd)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double luma = 100 + 40 * (((x / 8) + (y / 6)) % 2) + (x * 7 + y * 13) % 11;
            double a = (x - cx) / 15, b = (y - cy) / 35;
            const bool person = cx >= 0 && a * a + b * b <= 1;
            if (person)
                luma = (y < cy ? 40 : 60) + (x * 5 + y * 3) % 9;
            im->y[y * W + x] = clamp_byte(gain * luma + gauss(sd));
            if (x % 2 == 0 && y % 2 == 0) {
                const int c = (y / 2) * (W / 2) + x / 2;
                im->u[c] = clamp_byte((person && y >= cy ? 110 : 128) + gauss(sd));
                im->v[c] = clamp_byte((person && y >= cy ? 200 : 128) + gauss(sd));
            }
        }
}

static ct_frame frame_of(const image *im, int64_t us)
{
    return test_i420(us, W, H, im->y, im->u, im->v);
}

static ct_tracker *pixels_tracker(void)
{
    ct_config cfg = test_config();
    cfg.source = CT_SOURCE_PIXELS;
    return test_tracker(&cfg);
}

static size_t candidates(const ct_tracker *t, ct_candidate *out, size_t cap)
{
    size_t n = 0;
    ck_assert_int_eq(ct_tracker_get_candidates(t, out, cap, sizeof *out, &n), CT_OK);
    return n;
}

/* Noise of standard deviation 12 grey levels in luma and chroma (worse than
 * ffmpeg's noise=alls=14, which gives 8: a cheap camera at dusk) on a still
 * scene: after its first second, no frame has a candidate. */
START_TEST(noise_on_a_still_scene_makes_no_candidate)
{
    static image im;
    ct_tracker *t = pixels_tracker();
    ct_candidate c[256];
    int with_candidates = 0;
    for (int k = 0; k < 5 * FPS; k++) {
        draw(&im, 1.0, -1, 0, 12.0);
        ct_frame f = frame_of(&im, k * SEC / FPS);
        ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
        if (k >= FPS && candidates(t, c, 256) > 0)
            with_candidates++;
    }
    ck_assert_msg(with_candidates == 0, "%d frames of noise with candidates", with_candidates);
    ct_tracker_destroy(t);
}
END_TEST

/* The exposure steps up by a quarter, and back down two seconds later (an
 * auto-exposure, a cloud): no frame after either step has a candidate, and
 * no track is ever started. */
START_TEST(a_step_of_light_starts_no_track)
{
    static image im;
    ct_tracker *t = pixels_tracker();
    ct_candidate c[256];
    ct_track out[64];
    int with_candidates = 0;
    for (int k = 0; k < 6 * FPS; k++) {
        const double gain = k >= 2 * FPS && k < 4 * FPS ? 1.25 : 1.0;
        draw(&im, gain, -1, 0, 1.0);
        ct_frame f = frame_of(&im, k * SEC / FPS);
        ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
        if (k >= FPS && candidates(t, c, 256) > 0)
            with_candidates++;
        size_t n = 0;
        ck_assert_int_eq(ct_tracker_get_tracks(t, out, 64, sizeof out[0], &n), CT_OK);
        ck_assert_msg(n == 0, "frame %d: %zu tracks", k, n);
    }
    ck_assert_msg(with_candidates == 0, "%d frames with candidates", with_candidates);
    ct_stats st;
    st.size = sizeof st;
    ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
    ck_assert_uint_eq(st.live_tracks, 0);
    ct_tracker_destroy(t);
}
END_TEST

static double iou(const ct_candidate *c, double x, double y, double w, double h)
{
    const double x0 = fmax(c->left, x), y0 = fmax(c->top, y);
    const double x1 = fmin(c->left + c->width, x + w), y1 = fmin(c->top + c->height, y + h);
    if (x1 <= x0 || y1 <= y0)
        return 0;
    const double i = (x1 - x0) * (y1 - y0);
    return i / (c->width * c->height + w * h - i);
}

/* A person walks right at 40 pixels a second through noise of 8: after
 * the model's first second, a candidate covers them (IoU >= 0.5) in at least
 * four frames of five. */
START_TEST(a_person_moving_through_noise_is_found)
{
    static image im;
    ct_tracker *t = pixels_tracker();
    ct_candidate c[256];
    int frames = 0, found = 0;
    for (int k = 0; k < 5 * FPS; k++) {
        const double cx = 60 + 40.0 * k / FPS, cy = 120;
        draw(&im, 1.0, k >= FPS ? cx : -1, cy, 8.0);
        ct_frame f = frame_of(&im, k * SEC / FPS);
        ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
        if (k < 2 * FPS)
            continue;
        frames++;
        const size_t n = candidates(t, c, 256);
        for (size_t i = 0; i < n; i++)
            if (iou(&c[i], cx - 15, cy - 35, 30, 70) >= 0.5) {
                found++;
                break;
            }
    }
    ck_assert_msg(found * 5 >= frames * 4, "found in %d of %d frames", found, frames);
    ct_tracker_destroy(t);
}
END_TEST

/* A flickering mask cannot multiply the work: a frame of 600 small dark
 * squares makes more blobs than a frame's cap (128; the smallest are
 * dropped and counted), and a frame of random luma, foreground
 * everywhere, gives no candidate (counted as flooded). */
START_TEST(flicker_is_bounded_and_counted)
{
    static image im;
    ct_tracker *t = pixels_tracker();
    ct_candidate c[256];
    ct_stats st;
    st.size = sizeof st;
    int k = 0;
    for (; k < 2 * FPS; k++) {
        draw(&im, 1.0, -1, 0, 1.0);
        ct_frame f = frame_of(&im, k * SEC / FPS);
        ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    }
    ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
    ck_assert_uint_eq(st.blobs_dropped, 0);
    ck_assert_uint_eq(st.masks_flooded, 0);
    for (int y = 4; y + 6 < H; y += 16)
        for (int x = 4; x + 6 < W; x += 12)
            for (int dy = 0; dy < 6; dy++)
                for (int dx = 0; dx < 6; dx++)
                    im.y[(y + dy) * W + x + dx] = 10;
    ct_frame f = frame_of(&im, k++ * SEC / FPS);
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
    ck_assert_uint_gt(st.blobs_dropped, 0);
    for (int i = 0; i < W * H; i++)
        im.y[i] = (uint8_t)(256 * uniform());
    f = frame_of(&im, k++ * SEC / FPS);
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
    ck_assert_uint_eq(st.masks_flooded, 1);
    ck_assert_uint_eq(candidates(t, c, 256), 0);
    ct_tracker_destroy(t);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("noise");
    TCase *tc = tcase_create("noise");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, noise_on_a_still_scene_makes_no_candidate);
    tcase_add_test(tc, a_step_of_light_starts_no_track);
    tcase_add_test(tc, a_person_moving_through_noise_is_found);
    tcase_add_test(tc, flicker_is_bounded_and_counted);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
