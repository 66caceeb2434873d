/* Configuration: defaults, the size field, and each field's checks. */
#include <math.h>
#include <stdio.h>

#include "common.h"

START_TEST(defaults_are_valid)
{
    ct_config cfg = test_config();
    ck_assert_uint_eq(cfg.size, sizeof cfg);
    ck_assert_int_eq(cfg.source, CT_SOURCE_DETECTIONS);
    ck_assert(cfg.lost_lifetime > 0);
    ck_assert(cfg.report_lost_time <= cfg.lost_lifetime);
    ck_assert(cfg.low_score <= cfg.high_score);
    char msg[256] = "x";
    ck_assert_int_eq(ct_config_check(&cfg, msg, sizeof msg), CT_OK);
    ck_assert_str_eq(msg, "");
}
END_TEST

START_TEST(default_rejects_null_and_tiny_sizes)
{
    ct_config cfg;
    ck_assert_int_eq(ct_config_default(NULL, sizeof cfg), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_config_default(&cfg, 0), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_config_default(&cfg, sizeof(size_t) - 1), CT_ERROR_INVALID_ARGUMENT);
}
END_TEST

/* An older caller's smaller struct is filled only as far as its size. */
START_TEST(default_fills_only_the_callers_size)
{
    unsigned char buf[sizeof(ct_config) + 16];
    memset(buf, 0xAB, sizeof buf);
    size_t small = offsetof(ct_config, high_score);
    ck_assert_int_eq(ct_config_default((ct_config *)buf, small), CT_OK);
    ck_assert_uint_eq(((ct_config *)buf)->size, small);
    for (size_t i = small; i < sizeof buf; i++)
        ck_assert_uint_eq(buf[i], 0xAB);
}
END_TEST

/* A newer caller's bigger struct: the unknown tail is zeroed by default() and
 * then accepted; a non-zero unknown field is refused as unsupported. */
START_TEST(newer_caller_struct)
{
    unsigned char buf[sizeof(ct_config) + 16];
    memset(buf, 0xAB, sizeof buf);
    ck_assert_int_eq(ct_config_default((ct_config *)buf, sizeof buf), CT_OK);
    ck_assert_uint_eq(((ct_config *)buf)->size, sizeof buf);
    for (size_t i = sizeof(ct_config); i < sizeof buf; i++)
        ck_assert_uint_eq(buf[i], 0);
    char msg[256];
    ck_assert_int_eq(ct_config_check((ct_config *)buf, msg, sizeof msg), CT_OK);
    ct_tracker *t = NULL;
    ck_assert_int_eq(ct_tracker_create((ct_config *)buf, &t), CT_OK);
    ct_tracker_destroy(t);

    buf[sizeof(ct_config) + 3] = 1;
    ck_assert_int_eq(ct_config_check((ct_config *)buf, msg, sizeof msg), CT_ERROR_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(msg, "config.size"));
    t = (ct_tracker *)&msg; /* must be reset to NULL on failure */
    ck_assert_int_eq(ct_tracker_create((ct_config *)buf, &t), CT_ERROR_UNSUPPORTED);
    ck_assert_ptr_null(t);
}
END_TEST

/* A caller built against 0.1.0's header: its ct_config ends at max_tracks.
 * The fields added since take their defaults. */
START_TEST(older_caller_struct)
{
    ct_config full = test_config();
    unsigned char buf[sizeof(ct_config)];
    memset(buf, 0xEE, sizeof buf); /* garbage past the old size */
    ct_config *old = (ct_config *)buf;
    memcpy(buf, &full, offsetof(ct_config, mean_shift));
    old->size = offsetof(ct_config, mean_shift);
    old->min_hits = 5;
    char msg[256];
    ck_assert_int_eq(ct_config_check(old, msg, sizeof msg), CT_OK);
    ct_tracker *t = NULL;
    ck_assert_int_eq(ct_tracker_create(old, &t), CT_OK);
    ct_tracker_destroy(t);
    old->size = offsetof(ct_config, mean_shift) - 1;
    ck_assert_int_eq(ct_config_check(old, msg, sizeof msg), CT_ERROR_INVALID_ARGUMENT);
}
END_TEST

START_TEST(too_small_size_is_refused)
{
    ct_config cfg = test_config();
    cfg.size = 4;
    char msg[256];
    ck_assert_int_eq(ct_config_check(&cfg, msg, sizeof msg), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(msg, "config.size"));
    cfg.size = 0;
    ck_assert_int_eq(ct_config_check(&cfg, msg, sizeof msg), CT_ERROR_INVALID_ARGUMENT);
}
END_TEST

START_TEST(check_handles_null_and_short_buffers)
{
    char msg[8];
    ck_assert_int_eq(ct_config_check(NULL, msg, sizeof msg), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_uint_lt(strlen(msg), sizeof msg); /* truncated, terminated */
    ct_config cfg = test_config();
    cfg.min_hits = 0;
    ck_assert_int_eq(ct_config_check(&cfg, NULL, 0), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_config_check(&cfg, msg, 1), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_str_eq(msg, "");
}
END_TEST

/* Each bad value is refused by check and by create, and the message names
 * the field. */
typedef struct {
    const char *field;
    void (*spoil)(ct_config *);
    int status;
} bad_case;

static void bad_source(ct_config *c) { c->source = 7; }
static void low_candidate_score(ct_config *c) { c->candidate_min_score = c->low_score / 2; }
static void verify_two(ct_config *c) { c->verify_detections = 2; }
static void test_two(ct_config *c) { c->pedestrian_test = 2; }
static void test_negative(ct_config *c) { c->pedestrian_test = -1; }
static void nan_size_gate(ct_config *c) { c->size_gate = NAN; }
static void negative_size_gate(ct_config *c) { c->size_gate = -0.1f; }
static void huge_size_gate(ct_config *c) { c->size_gate = 11; }
static void nan_confirm_score(ct_config *c) { c->confirm_score = NAN; }
static void negative_confirm_score(ct_config *c) { c->confirm_score = -0.1f; }
static void huge_confirm_score(ct_config *c) { c->confirm_score = 1.5f; }
static void nan_high(ct_config *c) { c->high_score = NAN; }
static void high_above_one(ct_config *c) { c->high_score = 1.5f; }
static void low_above_high(ct_config *c) { c->low_score = c->high_score + 0.1f; }
static void negative_low(ct_config *c) { c->low_score = -0.1f; }
static void zero_iou(ct_config *c) { c->match_iou = 0; }
static void big_low_iou(ct_config *c) { c->low_match_iou = 2; }
static void inf_tentative_iou(ct_config *c) { c->tentative_match_iou = INFINITY; }
static void zero_hits(ct_config *c) { c->min_hits = 0; }
static void absurd_hits(ct_config *c) { c->min_hits = 1000000; }
static void negative_lifetime(ct_config *c) { c->lost_lifetime = -1; }
static void nan_lifetime(ct_config *c) { c->lost_lifetime = NAN; }
static void absurd_lifetime(ct_config *c) { c->lost_lifetime = 1e9; }
static void report_beyond_lifetime(ct_config *c) { c->report_lost_time = c->lost_lifetime + 1; }
static void zero_motion(ct_config *c) { c->motion_noise = 0; }
static void nan_motion(ct_config *c) { c->motion_noise = NAN; }
static void negative_detection_noise(ct_config *c) { c->detection_noise = -1; }
static void bad_clip(ct_config *c) { c->clip_boxes = 2; }
static void zero_max_tracks(ct_config *c) { c->max_tracks = 0; }
static void bad_mean_shift(ct_config *c) { c->mean_shift = -1; }
static void zero_similarity(ct_config *c) { c->mean_shift_min_similarity = 0; }
static void nan_similarity(ct_config *c) { c->mean_shift_min_similarity = NAN; }
static void negative_ms_time(ct_config *c) { c->mean_shift_max_time = -0.5; }
static void big_learning_rate(ct_config *c) { c->model_learning_rate = 1.5f; }
static void coarse_one(ct_config *c) { c->mean_shift_coarse_below = 1; }
static void bad_appearance(ct_config *c) { c->appearance = 3; }
static void negative_weight(ct_config *c) { c->appearance_weight = -0.1f; }
static void nan_weight(ct_config *c) { c->appearance_weight = NAN; }
static void zero_reid(ct_config *c) { c->reid_min_similarity = 0; }
static void one_reid(ct_config *c) { c->reid_min_similarity = 1; }
static void inf_reid_speed(ct_config *c) { c->reid_max_speed = INFINITY; }

static const bad_case bad_cases[] = {
    {"config.source", bad_source, CT_ERROR_INVALID_ARGUMENT},
    {"config.candidate_min_score", low_candidate_score, CT_ERROR_INVALID_ARGUMENT},
    {"config.verify_detections", verify_two, CT_ERROR_INVALID_ARGUMENT},
    {"config.pedestrian_test", test_two, CT_ERROR_INVALID_ARGUMENT},
    {"config.pedestrian_test", test_negative, CT_ERROR_INVALID_ARGUMENT},
    {"config.size_gate", nan_size_gate, CT_ERROR_INVALID_ARGUMENT},
    {"config.size_gate", negative_size_gate, CT_ERROR_INVALID_ARGUMENT},
    {"config.size_gate", huge_size_gate, CT_ERROR_INVALID_ARGUMENT},
    {"config.confirm_score", nan_confirm_score, CT_ERROR_INVALID_ARGUMENT},
    {"config.confirm_score", negative_confirm_score, CT_ERROR_INVALID_ARGUMENT},
    {"config.confirm_score", huge_confirm_score, CT_ERROR_INVALID_ARGUMENT},
    {"config.high_score", nan_high, CT_ERROR_INVALID_ARGUMENT},
    {"config.high_score", high_above_one, CT_ERROR_INVALID_ARGUMENT},
    {"config.low_score", low_above_high, CT_ERROR_INVALID_ARGUMENT},
    {"config.low_score", negative_low, CT_ERROR_INVALID_ARGUMENT},
    {"config.match_iou", zero_iou, CT_ERROR_INVALID_ARGUMENT},
    {"config.low_match_iou", big_low_iou, CT_ERROR_INVALID_ARGUMENT},
    {"config.tentative_match_iou", inf_tentative_iou, CT_ERROR_INVALID_ARGUMENT},
    {"config.min_hits", zero_hits, CT_ERROR_INVALID_ARGUMENT},
    {"config.min_hits", absurd_hits, CT_ERROR_INVALID_ARGUMENT},
    {"config.lost_lifetime", negative_lifetime, CT_ERROR_INVALID_ARGUMENT},
    {"config.lost_lifetime", nan_lifetime, CT_ERROR_INVALID_ARGUMENT},
    {"config.lost_lifetime", absurd_lifetime, CT_ERROR_INVALID_ARGUMENT},
    {"config.report_lost_time", report_beyond_lifetime, CT_ERROR_INVALID_ARGUMENT},
    {"config.motion_noise", zero_motion, CT_ERROR_INVALID_ARGUMENT},
    {"config.motion_noise", nan_motion, CT_ERROR_INVALID_ARGUMENT},
    {"config.detection_noise", negative_detection_noise, CT_ERROR_INVALID_ARGUMENT},
    {"config.clip_boxes", bad_clip, CT_ERROR_INVALID_ARGUMENT},
    {"config.max_tracks", zero_max_tracks, CT_ERROR_INVALID_ARGUMENT},
    {"config.mean_shift", bad_mean_shift, CT_ERROR_INVALID_ARGUMENT},
    {"config.mean_shift_min_similarity", zero_similarity, CT_ERROR_INVALID_ARGUMENT},
    {"config.mean_shift_min_similarity", nan_similarity, CT_ERROR_INVALID_ARGUMENT},
    {"config.mean_shift_max_time", negative_ms_time, CT_ERROR_INVALID_ARGUMENT},
    {"config.model_learning_rate", big_learning_rate, CT_ERROR_INVALID_ARGUMENT},
    {"config.mean_shift_coarse_below", coarse_one, CT_ERROR_INVALID_ARGUMENT},
    {"config.appearance", bad_appearance, CT_ERROR_INVALID_ARGUMENT},
    {"config.appearance_weight", negative_weight, CT_ERROR_INVALID_ARGUMENT},
    {"config.appearance_weight", nan_weight, CT_ERROR_INVALID_ARGUMENT},
    {"config.reid_min_similarity", zero_reid, CT_ERROR_INVALID_ARGUMENT},
    {"config.reid_min_similarity", one_reid, CT_ERROR_INVALID_ARGUMENT},
    {"config.reid_max_speed", inf_reid_speed, CT_ERROR_INVALID_ARGUMENT},
};

START_TEST(bad_field_is_named)
{
    const bad_case *bc = &bad_cases[_i];
    ct_config cfg = test_config();
    bc->spoil(&cfg);
    char msg[256];
    ck_assert_int_eq(ct_config_check(&cfg, msg, sizeof msg), bc->status);
    ck_assert_msg(strncmp(msg, bc->field, strlen(bc->field)) == 0,
                  "message '%s' does not name %s", msg, bc->field);
    ct_tracker *t = NULL;
    ck_assert_int_eq(ct_tracker_create(&cfg, &t), bc->status);
    ck_assert_ptr_null(t);
}
END_TEST

/* An integer field's value is written whole in the message (%g wrote
 * 2147483647 as 2.14748e+09); a float's as %g does. */
START_TEST(message_writes_the_value_as_given)
{
    ct_config cfg = test_config();
    cfg.max_tracks = INT32_MAX;
    char msg[256];
    ck_assert_int_eq(ct_config_check(&cfg, msg, sizeof msg), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_str_eq(msg, "config.max_tracks: 2147483647 is not in [1, 100000] tracks");
    cfg = test_config();
    cfg.high_score = 1.5f;
    ck_assert_int_eq(ct_config_check(&cfg, msg, sizeof msg), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_str_eq(msg, "config.high_score: 1.5 is not in [0, 1]");
}
END_TEST

static Suite *config_suite(void)
{
    Suite *s = suite_create("config");
    TCase *tc = tcase_create("config");
    tcase_add_test(tc, defaults_are_valid);
    tcase_add_test(tc, default_rejects_null_and_tiny_sizes);
    tcase_add_test(tc, default_fills_only_the_callers_size);
    tcase_add_test(tc, newer_caller_struct);
    tcase_add_test(tc, older_caller_struct);
    tcase_add_test(tc, too_small_size_is_refused);
    tcase_add_test(tc, check_handles_null_and_short_buffers);
    tcase_add_test(tc, message_writes_the_value_as_given);
    tcase_add_loop_test(tc, bad_field_is_named, 0, (int)(sizeof bad_cases / sizeof bad_cases[0]));
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return run_suite(config_suite());
}
