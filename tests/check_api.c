/* Every entry point's bad arguments, frame and detection validation,
 * timestamps, status strings and the version. */
#include <math.h>
#include <stdio.h>

#include "common.h"

START_TEST(status_strings)
{
    const int codes[] = {CT_OK, CT_ERROR_INVALID_ARGUMENT, CT_ERROR_OUT_OF_MEMORY,
                         CT_ERROR_UNSUPPORTED, CT_ERROR_BUFFER_TOO_SMALL, CT_ERROR_BAD_STATE,
                         CT_ERROR_INTERNAL};
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++) {
        ck_assert_ptr_nonnull(ct_status_str(codes[i]));
        ck_assert_str_ne(ct_status_str(codes[i]), "unknown status");
    }
    ck_assert_str_eq(ct_status_str(12345), "unknown status");
    /* The values are pinned. */
    ck_assert_int_eq(CT_ERROR_INVALID_ARGUMENT, -1);
    ck_assert_int_eq(CT_ERROR_INTERNAL, -6);
}
END_TEST

START_TEST(version)
{
    char want[32];
    snprintf(want, sizeof want, "%d.%d.%d", CT_VERSION_MAJOR, CT_VERSION_MINOR, CT_VERSION_PATCH);
    ck_assert_str_eq(ct_version_string(), want);
    ck_assert_uint_eq(ct_version_number(), CT_VERSION_NUMBER);
    ck_assert_uint_eq(ct_abi_version(), CT_ABI_VERSION);
}
END_TEST

START_TEST(create_and_destroy_bad_arguments)
{
    ct_config cfg = test_config();
    ck_assert_int_eq(ct_tracker_create(&cfg, NULL), CT_ERROR_INVALID_ARGUMENT);
    ct_tracker *t = (ct_tracker *)&cfg;
    ck_assert_int_eq(ct_tracker_create(NULL, &t), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_ptr_null(t);
    ct_tracker_destroy(NULL);
    ck_assert_str_eq(ct_tracker_last_error(NULL), "");
}
END_TEST

START_TEST(null_tracker)
{
    ct_frame f = test_frame(0, 0, 0);
    ct_track out[4];
    size_t count = 99;
    ck_assert_int_eq(ct_tracker_feed(NULL, &f, NULL, 0), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_get_tracks(NULL, out, 4, sizeof out[0], &count),
                     CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_reset(NULL), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_frame_default(NULL, sizeof f), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_frame_default(&f, 1), CT_ERROR_INVALID_ARGUMENT);
}
END_TEST

START_TEST(get_tracks_bad_arguments)
{
    ct_tracker *t = test_tracker(NULL);
    ct_detection d[2] = {test_det(10, 10, 20, 40, 0.9f), test_det(100, 10, 20, 40, 0.9f)};
    ct_frame f = test_frame(0, 0, 0);
    ck_assert_int_eq(ct_tracker_feed(t, &f, d, 2), CT_OK);
    ct_track out[4];
    size_t count = 0;

    ck_assert_int_eq(ct_tracker_get_tracks(t, out, 4, sizeof out[0], NULL),
                     CT_ERROR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ct_tracker_last_error(t), "count"));
    ck_assert_int_eq(ct_tracker_get_tracks(t, out, 4, sizeof out[0] - 4, &count),
                     CT_ERROR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ct_tracker_last_error(t), "elem_size"));
    ck_assert_int_eq(ct_tracker_get_tracks(t, NULL, 4, sizeof out[0], &count),
                     CT_ERROR_INVALID_ARGUMENT);

    /* Too small: nothing copied, the count needed reported. */
    memset(out, 0x5A, sizeof out);
    ck_assert_int_eq(ct_tracker_get_tracks(t, out, 1, sizeof out[0], &count),
                     CT_ERROR_BUFFER_TOO_SMALL);
    ck_assert_uint_eq(count, 2);
    ck_assert_uint_eq(((unsigned char *)out)[0], 0x5A);
    ck_assert_int_eq(ct_tracker_get_tracks(t, NULL, 0, sizeof out[0], &count),
                     CT_ERROR_BUFFER_TOO_SMALL);
    ck_assert_uint_eq(count, 2);

    ck_assert_int_eq(ct_tracker_get_tracks(t, out, 4, sizeof out[0], &count), CT_OK);
    ck_assert_uint_eq(count, 2);
    ck_assert_str_eq(ct_tracker_last_error(t), "");
    ct_tracker_destroy(t);
}
END_TEST

/* A size field that is garbage (never set, or overwritten) is refused
 * before a byte past the caller's struct is read: the structs here are
 * exactly their size on the heap, so a read past them is a sanitizer's
 * report too. */
START_TEST(garbage_struct_sizes)
{
    const size_t garbage[] = {(size_t)1 << 20, (size_t)-1, (size_t)1 << 17};
    ct_config *cfg = malloc(sizeof *cfg);
    ct_frame *f = malloc(sizeof *f);
    ck_assert(cfg && f);
    ct_tracker *t = test_tracker(NULL);
    for (size_t i = 0; i < sizeof garbage / sizeof garbage[0]; i++) {
        ck_assert_int_eq(ct_config_default(cfg, sizeof *cfg), CT_OK);
        cfg->size = garbage[i];
        char msg[256];
        ck_assert_int_eq(ct_config_check(cfg, msg, sizeof msg), CT_ERROR_INVALID_ARGUMENT);
        ck_assert_ptr_nonnull(strstr(msg, "config.size"));
        ct_tracker *bad = (ct_tracker *)1;
        ck_assert_int_eq(ct_tracker_create(cfg, &bad), CT_ERROR_INVALID_ARGUMENT);
        ck_assert_ptr_null(bad);

        ck_assert_int_eq(ct_frame_default(f, sizeof *f), CT_OK);
        f->size = garbage[i];
        ck_assert_int_eq(ct_tracker_feed(t, f, NULL, 0), CT_ERROR_INVALID_ARGUMENT);
        ck_assert_ptr_nonnull(strstr(ct_tracker_last_error(t), "frame.size"));
    }
    ct_tracker_destroy(t);
    free(cfg);
    free(f);
}
END_TEST

/* A newer caller's bigger ct_track: the library fills what it knows and
 * zeroes the rest of each element. */
START_TEST(get_tracks_bigger_elements)
{
    ct_tracker *t = test_tracker(NULL);
    ct_detection d[2] = {test_det(10, 10, 20, 40, 0.9f), test_det(100, 10, 20, 40, 0.8f)};
    ct_frame f = test_frame(0, 0, 0);
    ck_assert_int_eq(ct_tracker_feed(t, &f, d, 2), CT_OK);
    struct big {
        ct_track t;
        uint64_t extra[3];
    } out[2];
    memset(out, 0x5A, sizeof out);
    size_t count = 0;
    ck_assert_int_eq(ct_tracker_get_tracks(t, &out[0].t, 2, sizeof out[0], &count), CT_OK);
    ck_assert_uint_eq(count, 2);
    ck_assert_uint_eq(out[1].t.id, out[0].t.id + 1);
    ck_assert_float_eq_tol(out[1].t.left, 100, 1e-3);
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 3; k++)
            ck_assert_uint_eq(out[i].extra[k], 0);
    ct_tracker_destroy(t);
}
END_TEST

/* Frames that must be refused, with the part of the message that names the
 * fault. Each leaves the tracker as it was. */
typedef struct {
    const char *needle;
    int status;
    void (*spoil)(ct_frame *);
} bad_frame;

static uint8_t pixels[64 * 48 * 3];

static void make_i420(ct_frame *f)
{
    f->format = CT_FORMAT_I420;
    f->width = 64;
    f->height = 48;
    f->planes[0] = pixels;
    f->planes[1] = pixels + 64 * 48;
    f->planes[2] = pixels + 64 * 48 + 32 * 24;
    f->strides[0] = 64;
    f->strides[1] = f->strides[2] = 32;
}

static void no_frame_size(ct_frame *f) { f->size = 0; }
static void unknown_tail(ct_frame *f) { (void)f; }
static void bad_format(ct_frame *f) { f->format = 0x12345678; }
static void i420_null_plane(ct_frame *f) { make_i420(f); f->planes[2] = NULL; }
static void i420_short_stride(ct_frame *f) { make_i420(f); f->strides[0] = 63; }
static void i420_short_chroma(ct_frame *f) { make_i420(f); f->strides[1] = 31; }
static void i420_negative_stride(ct_frame *f) { make_i420(f); f->strides[2] = -32; }
static void i420_zero_width(ct_frame *f) { make_i420(f); f->width = 0; }
static void i420_absurd_height(ct_frame *f) { make_i420(f); f->height = 1 << 20; }
static void nv12_short_uv(ct_frame *f) { make_i420(f); f->format = CT_FORMAT_NV12; f->strides[1] = 32; }
static void gray_null(ct_frame *f) { make_i420(f); f->format = CT_FORMAT_GRAY8; f->planes[0] = NULL; }
static void bgr_short_stride(ct_frame *f) { make_i420(f); f->format = CT_FORMAT_BGR24; f->strides[0] = 3 * 64 - 1; }
static void rgb_null(ct_frame *f) { make_i420(f); f->format = CT_FORMAT_RGB24; f->strides[0] = 3 * 64; f->planes[0] = NULL; }
static void rgb_negative_stride(ct_frame *f) { make_i420(f); f->format = CT_FORMAT_RGB24; f->strides[0] = -3 * 64; }
static void none_half_size(ct_frame *f) { f->width = 640; f->height = 0; }
static void none_negative(ct_frame *f) { f->width = -5; f->height = -5; }

static const bad_frame bad_frames[] = {
    {"frame.size", CT_ERROR_INVALID_ARGUMENT, no_frame_size},
    {"frame.size", CT_ERROR_UNSUPPORTED, unknown_tail},
    {"frame.format", CT_ERROR_UNSUPPORTED, bad_format},
    {"frame.planes[2]", CT_ERROR_INVALID_ARGUMENT, i420_null_plane},
    {"frame.strides[0]", CT_ERROR_INVALID_ARGUMENT, i420_short_stride},
    {"frame.strides[1]", CT_ERROR_INVALID_ARGUMENT, i420_short_chroma},
    {"frame.strides[2]", CT_ERROR_INVALID_ARGUMENT, i420_negative_stride},
    {"frame.width", CT_ERROR_INVALID_ARGUMENT, i420_zero_width},
    {"frame.width", CT_ERROR_INVALID_ARGUMENT, i420_absurd_height},
    {"frame.strides[1]", CT_ERROR_INVALID_ARGUMENT, nv12_short_uv},
    {"frame.planes[0]", CT_ERROR_INVALID_ARGUMENT, gray_null},
    {"frame.strides[0]: 191 bytes is less than the plane's width, 192 bytes, of a 64x48 BGR24",
     CT_ERROR_INVALID_ARGUMENT, bgr_short_stride},
    {"frame.planes[0]: NULL for a RGB24 frame", CT_ERROR_INVALID_ARGUMENT, rgb_null},
    {"frame.strides[0]", CT_ERROR_INVALID_ARGUMENT, rgb_negative_stride},
    {"frame.width", CT_ERROR_INVALID_ARGUMENT, none_half_size},
    {"frame.width", CT_ERROR_INVALID_ARGUMENT, none_negative},
};

/* Feeds one good step, then `bad`, and checks the refusal changed nothing:
 * the same tracks are reported, and the next good step goes on as if the
 * bad call never happened. */
static void assert_refused_changes_nothing(const ct_frame *bad, const ct_detection *bd,
                                           size_t bn, int status, const char *needle)
{
    ct_tracker *t = test_tracker(NULL), *ref = test_tracker(NULL);
    ct_detection d = test_det(10, 10, 20, 40, 0.9f);
    ct_track a[64], b[64];
    for (int k = 0; k < 3; k++) {
        test_step(t, 1000 * k, &d, 1, a);
        test_step(ref, 1000 * k, &d, 1, b);
    }
    ck_assert_int_eq(ct_tracker_feed(t, bad, bd, bn), status);
    const char *msg = ct_tracker_last_error(t);
    ck_assert_msg(strstr(msg, needle) != NULL, "message '%s' lacks '%s'", msg, needle);
    size_t na = 0, nb = 0;
    ck_assert_int_eq(ct_tracker_get_tracks(t, a, 64, sizeof a[0], &na), CT_OK);
    ck_assert_int_eq(ct_tracker_get_tracks(ref, b, 64, sizeof b[0], &nb), CT_OK);
    ck_assert_uint_eq(na, nb);
    ck_assert_mem_eq(a, b, na * sizeof a[0]);
    d.left += 2;
    na = test_step(t, 5000, &d, 1, a);
    nb = test_step(ref, 5000, &d, 1, b);
    ck_assert_uint_eq(na, nb);
    ck_assert_mem_eq(a, b, na * sizeof a[0]);
    ct_tracker_destroy(t);
    ct_tracker_destroy(ref);
}

START_TEST(bad_frame_is_refused)
{
    const bad_frame *bf = &bad_frames[_i];
    struct {
        ct_frame f;
        uint32_t tail;
    } big;
    memset(&big, 0, sizeof big);
    ct_frame_default(&big.f, sizeof big.f);
    big.f.timestamp_us = 4000;
    bf->spoil(&big.f);
    if (bf->spoil == unknown_tail) {
        big.f.size = sizeof big;
        big.tail = 7;
    }
    assert_refused_changes_nothing(&big.f, NULL, 0, bf->status, bf->needle);
}
END_TEST

START_TEST(null_frame)
{
    assert_refused_changes_nothing(NULL, NULL, 0, CT_ERROR_INVALID_ARGUMENT, "frame");
}
END_TEST

START_TEST(good_pixel_frames)
{
    ct_tracker *t = test_tracker(NULL);
    ct_frame f = test_frame(0, 0, 0);
    make_i420(&f);
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    f.format = CT_FORMAT_NV12;
    f.strides[1] = 64;
    f.timestamp_us = 1;
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    f.format = CT_FORMAT_GRAY8;
    f.planes[1] = f.planes[2] = NULL;
    f.timestamp_us = 2;
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    /* Odd sizes: chroma is (w + 1) / 2 wide. */
    make_i420(&f);
    f.width = 63;
    f.height = 47;
    f.strides[0] = 63;
    f.strides[1] = f.strides[2] = 32;
    f.timestamp_us = 3;
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    /* Packed colour (0.8.0), odd sizes too: 3 bytes a pixel. */
    f.format = CT_FORMAT_BGR24;
    f.planes[1] = f.planes[2] = NULL;
    f.strides[0] = 3 * 63;
    f.timestamp_us = 4;
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    f.format = CT_FORMAT_RGB24;
    f.width = 64;
    f.height = 48;
    f.strides[0] = 3 * 64;
    f.timestamp_us = 5;
    ck_assert_int_eq(ct_tracker_feed(t, &f, NULL, 0), CT_OK);
    ct_tracker_destroy(t);
}
END_TEST

typedef struct {
    const char *needle;
    ct_detection det;
} bad_det;

static const bad_det bad_dets[] = {
    {"dets[1].left", {NAN, 0, 10, 10, 0.9f, 0}},
    {"dets[1].top", {0, INFINITY, 10, 10, 0.9f, 0}},
    {"dets[1].width", {0, 0, 0, 10, 0.9f, 0}},
    {"dets[1].width", {0, 0, -3, 10, 0.9f, 0}},
    {"dets[1].height", {0, 0, 10, NAN, 0.9f, 0}},
    {"dets[1].height", {0, 0, 10, 1e30f, 0.9f, 0}},
    {"dets[1].left", {-1e9f, 0, 10, 10, 0.9f, 0}},
    {"dets[1].score", {0, 0, 10, 10, NAN, 0}},
    {"dets[1].score", {0, 0, 10, 10, -INFINITY, 0}},
};

START_TEST(bad_detection_is_refused)
{
    ct_detection d[2] = {test_det(10, 10, 20, 40, 0.9f), bad_dets[_i].det};
    ct_frame f = test_frame(4000, 0, 0);
    assert_refused_changes_nothing(&f, d, 2, CT_ERROR_INVALID_ARGUMENT, bad_dets[_i].needle);
}
END_TEST

START_TEST(null_detections_with_count)
{
    ct_frame f = test_frame(4000, 0, 0);
    assert_refused_changes_nothing(&f, NULL, 3, CT_ERROR_INVALID_ARGUMENT, "dets");
}
END_TEST

START_TEST(absurd_detection_count)
{
    ct_frame f = test_frame(4000, 0, 0);
    ct_detection d = test_det(10, 10, 20, 40, 0.9f);
    assert_refused_changes_nothing(&f, &d, (size_t)1 << 40, CT_ERROR_INVALID_ARGUMENT, "n:");
}
END_TEST

START_TEST(timestamp_must_increase)
{
    ct_frame same = test_frame(2000, 0, 0);
    assert_refused_changes_nothing(&same, NULL, 0, CT_ERROR_BAD_STATE, "timestamp");
    ct_frame back = test_frame(-5, 0, 0);
    assert_refused_changes_nothing(&back, NULL, 0, CT_ERROR_BAD_STATE, "timestamp");
}
END_TEST

/* Timestamps at the ends of int64_t, with detections and with frames: the
 * time between two of them does not fit in an int64_t. The steps succeed,
 * every reported number is finite, and the gap of 2^64 microseconds
 * (585,000 years) is longer than any track is kept: the track of before is
 * not reported after it (a difference that wrapped round read as -0.08 s
 * and continued it). */
START_TEST(extreme_timestamps)
{
    const int64_t ts[] = {INT64_MIN, INT64_MIN + 40000, INT64_MAX - 40000, INT64_MAX};
    for (int pixels = 0; pixels < 2; pixels++) {
        ct_tracker *t = test_tracker(NULL);
        for (int k = 0; k < 4; k++) {
            ct_frame f = test_frame(ts[k], 0, 0);
            if (pixels)
                make_i420(&f);
            ct_detection d = test_det(10 + 2 * k, 10, 20, 40, 0.9f);
            ck_assert_int_eq(ct_tracker_feed(t, &f, &d, 1), CT_OK);
            ct_track out[16];
            size_t n = 0;
            ck_assert_int_eq(ct_tracker_get_tracks(t, out, 16, sizeof out[0], &n), CT_OK);
            if (k < 2)
                ck_assert_uint_eq(n, 1);
            for (size_t i = 0; i < n; i++) {
                const float v[] = {out[i].left, out[i].top, out[i].width, out[i].height,
                                   out[i].barycenter_x, out[i].barycenter_y, out[i].velocity_x,
                                   out[i].velocity_y, out[i].confidence};
                for (size_t j = 0; j < sizeof v / sizeof v[0]; j++)
                    ck_assert_msg(isfinite(v[j]), "step %d (pixels %d), track %zu: value %zu is %g",
                                  k, pixels, i, j, (double)v[j]);
                ck_assert(isfinite(out[i].time_since_update) && out[i].time_since_update >= 0);
                ck_assert(out[i].confidence >= 0 && out[i].confidence <= 1);
                if (k >= 2)
                    ck_assert_msg(out[i].id != 1, "step %d (pixels %d): track 1 continued", k,
                                  pixels);
            }
        }
        ct_tracker_destroy(t);
    }
}
END_TEST

/* A fixed-seed stream of calls, good and bad mixed as a careless host would
 * make them: configurations (with pixels or not, mean shift, appearance and
 * verification on or off, few tracks allowed), frame sizes from 1 x 1 up,
 * strides past the width, every format, timestamps that sometimes go back,
 * detections with NaN, infinite, huge, negative or empty boxes, buffers too
 * small. Every call must return a status, a failed one with a message, and
 * what comes out must keep the header's promises. Under `make sanitize` this
 * is also a memory and undefined-behaviour check of every path. */
static uint64_t lcg_state;

static uint32_t lcg(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (uint32_t)(lcg_state >> 33);
}

static float odd_float(void)
{
    static const float odd[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f, 0, -1, 1e-40f};
    return lcg() % 3 ? (float)(lcg() % 2000) / 10 - 20 : odd[lcg() % 8];
}

START_TEST(random_calls_keep_their_promises)
{
    lcg_state = 2026;
    static uint8_t buf[(3 * 200 + 16) * 160 * 2];
    for (int run = 0; run < 24; run++) {
        ct_config c = test_config();
        c.source = (int32_t)(lcg() % 2);
        c.mean_shift = (int32_t)(lcg() % 2);
        c.appearance = (int32_t)(lcg() % 2);
        c.verify_detections = c.source == CT_SOURCE_DETECTIONS ? (int32_t)(lcg() % 2) : 0;
        c.max_tracks = lcg() % 3 ? 1000 : 1 + (int32_t)(lcg() % 3);
        c.clip_boxes = (int32_t)(lcg() % 2);
        ct_tracker *t = test_tracker(&c);
        int w = 1 + (int)(lcg() % 200), h = 1 + (int)(lcg() % 160);
        int64_t ts = (int64_t)(lcg() % 1000);
        for (int k = 0; k < 30; k++) {
            if (lcg() % 10 == 0) {
                w = 1 + (int)(lcg() % 200);
                h = 1 + (int)(lcg() % 160);
            }
            static const uint32_t formats[] = {CT_FORMAT_NONE, CT_FORMAT_I420, CT_FORMAT_NV12,
                                               CT_FORMAT_GRAY8, CT_FORMAT_BGR24, CT_FORMAT_RGB24};
            const uint32_t format = formats[lcg() % 6];
            const int packed = format == CT_FORMAT_BGR24 || format == CT_FORMAT_RGB24;
            const int stride = (packed ? 3 * w : w) + (int)(lcg() % 3) * 8;
            for (size_t i = 0; i < sizeof buf; i++)
                buf[i] = (uint8_t)(60 + (i * 7 + (size_t)k * 13) % 40);
            for (int y = h / 4; y < h / 4 + h / 2; y++) /* something moving */
                for (int x = (k * 3) % w; x < w && x < (k * 3) % w + w / 6 + 1; x++)
                    buf[(size_t)y * stride + x] = 230;
            ct_frame f = test_frame(ts, w, h);
            f.format = format;
            f.planes[0] = buf;
            f.strides[0] = stride;
            f.planes[1] = buf + (size_t)stride * h;
            f.strides[1] = f.format == CT_FORMAT_NV12 ? stride + (stride & 1) : (w + 1) / 2;
            f.planes[2] = f.planes[1] + (size_t)f.strides[1] * ((h + 1) / 2);
            f.strides[2] = (w + 1) / 2;
            if (lcg() % 25 == 0)
                f.strides[lcg() % 3] = (int32_t)(lcg() % 3) - 1;
            ts += lcg() % 25 == 0 ? -(int64_t)(lcg() % 100) : (int64_t)(lcg() % 200000);
            f.timestamp_us = ts;
            ct_detection d[8];
            size_t n = c.source == CT_SOURCE_PIXELS && lcg() % 8 ? 0 : lcg() % 9;
            for (size_t i = 0; i < n; i++)
                d[i] = test_det(lcg() % 5 ? (float)(lcg() % (unsigned)(w + 20)) - 10 : odd_float(),
                                lcg() % 5 ? (float)(lcg() % (unsigned)(h + 20)) - 10 : odd_float(),
                                lcg() % 5 ? (float)(1 + lcg() % (unsigned)w) : odd_float(),
                                lcg() % 5 ? (float)(1 + lcg() % (unsigned)h) : odd_float(),
                                lcg() % 5 ? (float)(lcg() % 100) / 100 : odd_float());
            const int st = ct_tracker_feed(t, &f, n ? d : NULL, n);
            ck_assert_msg(st == CT_OK || st == CT_ERROR_INVALID_ARGUMENT ||
                              st == CT_ERROR_BAD_STATE || st == CT_ERROR_UNSUPPORTED,
                          "run %d step %d: status %d", run, k, st);
            if (st != CT_OK)
                ck_assert_msg(ct_tracker_last_error(t)[0] != '\0', "run %d step %d: no message",
                              run, k);
            ct_track out[8];
            size_t cap = lcg() % 9, count = 0;
            const int gt = ct_tracker_get_tracks(t, out, cap, sizeof out[0], &count);
            ck_assert(gt == CT_OK || (gt == CT_ERROR_BUFFER_TOO_SMALL && count > cap));
            ck_assert_uint_le(count, (size_t)c.max_tracks);
            for (size_t i = 0; gt == CT_OK && i < count; i++) {
                const ct_track *r = &out[i];
                ck_assert(r->id > 0);
                ck_assert(r->state == CT_TRACK_CONFIRMED || r->state == CT_TRACK_LOST);
                ck_assert(isfinite(r->left) && isfinite(r->top) && isfinite(r->velocity_x) &&
                          isfinite(r->velocity_y) && isfinite(r->barycenter_x) &&
                          isfinite(r->barycenter_y));
                ck_assert(r->width > 0 && r->height > 0 && isfinite(r->width) &&
                          isfinite(r->height));
                ck_assert(r->confidence >= 0 && r->confidence <= 1);
                ck_assert(isfinite(r->time_since_update) && r->time_since_update >= 0);
                for (size_t j = 0; j < i; j++)
                    ck_assert(out[j].id != r->id);
            }
            ct_candidate cand[8];
            cap = lcg() % 9;
            const int gc = ct_tracker_get_candidates(t, cand, cap, sizeof cand[0], &count);
            ck_assert(gc == CT_OK || (gc == CT_ERROR_BUFFER_TOO_SMALL && count > cap));
            for (size_t i = 0; gc == CT_OK && i < count; i++) {
                ck_assert(cand[i].score >= 0 && cand[i].score <= 1);
                ck_assert(cand[i].voters >= 0 && cand[i].votes_yes >= 0 &&
                          cand[i].votes_yes <= cand[i].voters && cand[i].voters <= CT_REGIONS);
                ck_assert(cand[i].fill >= 0 && cand[i].fill <= 1);
                ck_assert(isfinite(cand[i].top_width) && cand[i].top_width >= 0);
            }
            if (lcg() % 40 == 0)
                ck_assert_int_eq(ct_tracker_reset(t), CT_OK);
        }
        ct_tracker_destroy(t);
    }
}
END_TEST

START_TEST(reset_forgets_time_and_tracks)
{
    ct_tracker *t = test_tracker(NULL);
    ct_detection d = test_det(10, 10, 20, 40, 0.9f);
    ct_track out[64];
    ck_assert_uint_eq(test_step(t, 1000000, &d, 1, out), 1);
    ck_assert_int_eq(ct_tracker_reset(t), CT_OK);
    size_t count = 7;
    ck_assert_int_eq(ct_tracker_get_tracks(t, out, 64, sizeof out[0], &count), CT_OK);
    ck_assert_uint_eq(count, 0);
    /* An earlier timestamp is fine after a reset. */
    ck_assert_uint_eq(test_step(t, 0, &d, 1, out), 1);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(stats)
{
    ct_tracker *t = test_tracker(NULL);
    ct_stats st;
    st.size = sizeof st;
    ck_assert_int_eq(ct_tracker_get_stats(NULL, &st), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_get_stats(t, NULL), CT_ERROR_INVALID_ARGUMENT);
    st.size = 8;
    ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ct_tracker_last_error(t), "stats.size"));

    ct_detection d[2] = {test_det(10, 10, 20, 40, 0.9f), test_det(100, 10, 20, 40, 0.9f)};
    ct_track out[64];
    for (int k = 0; k < 5; k++)
        test_step(t, 1000 * k, d, 2, out);
    ct_frame back = test_frame(0, 0, 0); /* refused: not a step */
    ck_assert_int_eq(ct_tracker_feed(t, &back, NULL, 0), CT_ERROR_BAD_STATE);

    /* A newer caller's bigger struct: the tail is zeroed, its size kept. */
    struct {
        ct_stats s;
        uint64_t extra;
    } big;
    memset(&big, 0x5A, sizeof big);
    big.s.size = sizeof big;
    ck_assert_int_eq(ct_tracker_get_stats(t, &big.s), CT_OK);
    ck_assert_uint_eq(big.s.size, sizeof big);
    ck_assert_uint_eq(big.extra, 0);
    ck_assert_uint_eq(big.s.steps, 5);
    ck_assert_uint_eq(big.s.live_tracks, 2);
    ck_assert_uint_gt(big.s.memory_bytes, 2 * sizeof(ct_track));
    ck_assert_uint_gt(big.s.feed_ns, 0);
    uint64_t sum = 0;
    for (int i = 0; i < CT_STATS_MAX_STAGES; i++) {
        sum += big.s.stage_ns[i];
        if (!ct_stage_name(i))
            ck_assert_uint_eq(big.s.stage_ns[i], 0);
    }
    ck_assert_uint_gt(sum, 0);
    ck_assert_uint_le(sum, big.s.feed_ns);
    ck_assert_str_eq(ct_stage_name(CT_STAGE_ASSOCIATE), "associate");
    ck_assert_ptr_null(ct_stage_name(-1));
    ck_assert_ptr_null(ct_stage_name(CT_STATS_MAX_STAGES));
    ct_tracker_destroy(t);
}
END_TEST

static Suite *api_suite(void)
{
    Suite *s = suite_create("api");
    TCase *tc = tcase_create("api");
    tcase_add_test(tc, status_strings);
    tcase_add_test(tc, version);
    tcase_add_test(tc, create_and_destroy_bad_arguments);
    tcase_add_test(tc, null_tracker);
    tcase_add_test(tc, get_tracks_bad_arguments);
    tcase_add_test(tc, garbage_struct_sizes);
    tcase_add_test(tc, get_tracks_bigger_elements);
    tcase_add_loop_test(tc, bad_frame_is_refused, 0, (int)(sizeof bad_frames / sizeof bad_frames[0]));
    tcase_add_test(tc, null_frame);
    tcase_add_test(tc, good_pixel_frames);
    tcase_add_loop_test(tc, bad_detection_is_refused, 0, (int)(sizeof bad_dets / sizeof bad_dets[0]));
    tcase_add_test(tc, null_detections_with_count);
    tcase_add_test(tc, absurd_detection_count);
    tcase_add_test(tc, timestamp_must_increase);
    tcase_add_test(tc, extreme_timestamps);
    tcase_add_test(tc, random_calls_keep_their_promises);
    tcase_add_test(tc, reset_forgets_time_and_tracks);
    tcase_add_test(tc, stats);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return run_suite(api_suite());
}
