/* Helpers shared by the Check suites. */
#ifndef CT_TESTS_COMMON_H
#define CT_TESTS_COMMON_H

#include <check.h>
#include <stdlib.h>
#include <string.h>

#include "ctrack/ctrack.h"
#include "i420.h"

static inline ct_config test_config(void)
{
    ct_config cfg;
    ck_assert_int_eq(ct_config_default(&cfg, sizeof cfg), CT_OK);
    return cfg;
}

static inline ct_tracker *test_tracker(const ct_config *cfg)
{
    ct_tracker *t = NULL;
    ct_config def = test_config();
    ck_assert_int_eq(ct_tracker_create(cfg ? cfg : &def, &t), CT_OK);
    ck_assert_ptr_nonnull(t);
    return t;
}

/* A frame without pixels at time `us`, of an image of w x h (0 x 0: unknown). */
static inline ct_frame test_frame(int64_t us, int w, int h)
{
    ct_frame f;
    ck_assert_int_eq(ct_frame_default(&f, sizeof f), CT_OK);
    f.timestamp_us = us;
    f.width = w;
    f.height = h;
    return f;
}

/* An I420 frame at time `us` of w x h pixels, its planes' rows packed
 * (strides w, w / 2 and w / 2). */
static inline ct_frame test_i420(int64_t us, int w, int h, const uint8_t *y, const uint8_t *u,
                                 const uint8_t *v)
{
    ct_frame f = test_frame(us, w, h);
    set_i420_planes(&f, y, u, v);
    return f;
}

static inline ct_detection test_det(float l, float t, float w, float h, float score)
{
    ct_detection d;
    d.left = l;
    d.top = t;
    d.width = w;
    d.height = h;
    d.score = score;
    d.class_id = 0;
    return d;
}

/* Feeds one step and returns the reported tracks in out (capacity 64). */
static inline size_t test_step(ct_tracker *t, int64_t us, const ct_detection *d, size_t n,
                               ct_track *out)
{
    ct_frame f = test_frame(us, 0, 0);
    ck_assert_int_eq(ct_tracker_feed(t, &f, d, n), CT_OK);
    size_t count = 0;
    ck_assert_int_eq(ct_tracker_get_tracks(t, out, 64, sizeof *out, &count), CT_OK);
    return count;
}

/* Runs a Check suite and returns the process exit status. */
static inline int run_suite(Suite *s)
{
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

#endif
