/* Counting on lines and zones (ct_tracker_add_line(), ct_tracker_add_zone()):
 * the events and counts of synthetic tracks, and every refused input
 * changing nothing. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>

#include "common.h"

#define SEC 1000000LL
#define STEP (SEC / 10)

/* A person 100 pixels tall whose feet are at (x, y), seen by a detector
 * that is sure of them. */
static ct_detection feet_at(float x, float y)
{
    return test_det(x - 20, y - 100, 40, 100, 0.97f);
}

static ct_tracker *counting_tracker(void)
{
    ct_config cfg = test_config();
    cfg.min_hits = 3;
    ct_tracker *t = test_tracker(&cfg);
    ct_track out[64];
    test_step(t, 0, NULL, 0, out); /* the first step confirms at once */
    return t;
}

static int32_t add_line(ct_tracker *t, float x1, float y1, float x2, float y2, const char *name)
{
    ct_line l;
    ck_assert_int_eq(ct_line_default(&l, sizeof l), CT_OK);
    l.a.x = x1;
    l.a.y = y1;
    l.b.x = x2;
    l.b.y = y2;
    l.name = name;
    int32_t index = -1;
    ck_assert_msg(ct_tracker_add_line(t, &l, &index) == CT_OK, "%s", ct_tracker_last_error(t));
    return index;
}

static int32_t add_zone(ct_tracker *t, const ct_point *p, int n, const char *name)
{
    ct_zone z;
    ck_assert_int_eq(ct_zone_default(&z, sizeof z), CT_OK);
    z.points = p;
    z.n_points = n;
    z.name = name;
    int32_t index = -1;
    ck_assert_msg(ct_tracker_add_zone(t, &z, &index) == CT_OK, "%s", ct_tracker_last_error(t));
    return index;
}

/* The counting of one step: its events, appended to a log. */
typedef struct Log {
    ct_event events[256];
    int64_t step_us[256];
    size_t n;
} Log;

/* Feeds detections d[0..n-1] at time us, logging the step's events. */
static void feed(ct_tracker *t, int64_t us, const ct_detection *d, size_t n, Log *log)
{
    ct_frame f = test_frame(us, 640, 480);
    ck_assert_msg(ct_tracker_feed(t, &f, d, n) == CT_OK, "%s", ct_tracker_last_error(t));
    size_t count = 0;
    ck_assert_int_eq(ct_tracker_get_events(t, log->events + log->n, 256 - log->n,
                                           sizeof(ct_event), &count),
                     CT_OK);
    for (size_t i = 0; i < count; i++) {
        ck_assert_int_eq(log->events[log->n + i].timestamp_us, us);
        log->step_us[log->n + i] = us;
    }
    log->n += count;
}

/* Walks one person's feet from (x0, y0) to (x1, y1) in `steps` steps from
 * time *us on. */
static void walk(ct_tracker *t, int64_t *us, float x0, float y0, float x1, float y1, int steps,
                 Log *log)
{
    for (int k = 0; k <= steps; k++) {
        *us += STEP;
        ct_detection d = feet_at(x0 + (x1 - x0) * k / steps, y0 + (y1 - y0) * k / steps);
        feed(t, *us, &d, 1, log);
    }
}

static ct_line_count line_count(ct_tracker *t, int32_t index)
{
    ct_line_count c[CT_COUNT_MAX_LINES];
    size_t n = 0;
    ck_assert_int_eq(ct_tracker_get_line_counts(t, c, CT_COUNT_MAX_LINES, sizeof c[0], &n),
                     CT_OK);
    ck_assert_int_lt(index, (int32_t)n);
    ck_assert_int_eq(c[index].index, index);
    return c[index];
}

static ct_zone_count zone_count(ct_tracker *t, int32_t index)
{
    ct_zone_count c[CT_COUNT_MAX_ZONES];
    size_t n = 0;
    ck_assert_int_eq(ct_tracker_get_zone_counts(t, c, CT_COUNT_MAX_ZONES, sizeof c[0], &n),
                     CT_OK);
    ck_assert_int_lt(index, (int32_t)n);
    return c[index];
}

static size_t line_total(ct_tracker *t)
{
    size_t n = 99;
    const int st = ct_tracker_get_line_counts(t, NULL, 0, sizeof(ct_line_count), &n);
    ck_assert_int_eq(st, n == 0 ? CT_OK : CT_ERROR_BUFFER_TOO_SMALL);
    return n;
}

static size_t zone_total(ct_tracker *t)
{
    size_t n = 99;
    const int st = ct_tracker_get_zone_counts(t, NULL, 0, sizeof(ct_zone_count), &n);
    ck_assert_int_eq(st, n == 0 ? CT_OK : CT_ERROR_BUFFER_TOO_SMALL);
    return n;
}

START_TEST(crossing_each_way)
{
    ct_tracker *t = counting_tracker();
    const int32_t door = add_line(t, 100, 300, 540, 300, "door");
    ck_assert_int_eq(door, 0);
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 320, 200, 320, 400, 20, &log); /* down: to the right of a -> b */
    ck_assert_uint_eq(log.n, 1);
    ck_assert_int_eq(log.events[0].kind, CT_EVENT_LINE_IN);
    ck_assert_int_eq(log.events[0].index, door);
    ck_assert_uint_eq(log.events[0].track_id, 1);
    /* Counted when the feet are past the line by the hysteresis (10 px). */
    ck_assert_float_ge(log.events[0].y, 310 - 2);
    ck_assert_float_le(log.events[0].y, 330);
    walk(t, &us, 320, 400, 320, 200, 20, &log); /* and back up */
    ck_assert_uint_eq(log.n, 2);
    ck_assert_int_eq(log.events[1].kind, CT_EVENT_LINE_OUT);
    ct_line_count c = line_count(t, door);
    ck_assert_str_eq(c.name, "door");
    ck_assert_uint_eq(c.in, 1);
    ck_assert_uint_eq(c.out, 1);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(a_segment_not_a_line)
{
    /* Walking across the line's extension, past its end, counts nothing;
     * a line from right to left swaps in and out. */
    ct_tracker *t = counting_tracker();
    add_line(t, 100, 300, 300, 300, NULL);
    const int32_t back = add_line(t, 540, 300, 100, 300, NULL);
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 450, 200, 450, 400, 20, &log);
    ck_assert_uint_eq(log.n, 1);
    ck_assert_int_eq(log.events[0].index, back);
    ck_assert_int_eq(log.events[0].kind, CT_EVENT_LINE_OUT);
    ck_assert_str_eq(line_count(t, 0).name, "line0");
    ck_assert_str_eq(line_count(t, 1).name, "line1");
    ck_assert_uint_eq(line_count(t, 0).in + line_count(t, 0).out, 0);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(walk_along_the_line_counted_once)
{
    /* Across, then along the line with the feet a few pixels either side
     * of it (under the hysteresis): one crossing. */
    ct_tracker *t = counting_tracker();
    add_line(t, 0, 300, 640, 300, NULL);
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 100, 200, 100, 320, 12, &log);
    for (int k = 0; k < 40; k++) {
        us += STEP;
        ct_detection d = feet_at(100 + 10.0f * k, k % 2 ? 304.0f : 296.0f);
        feed(t, us, &d, 1, &log);
    }
    ck_assert_uint_eq(log.n, 1);
    ck_assert_uint_eq(line_count(t, 0).in, 1);
    ck_assert_uint_eq(line_count(t, 0).out, 0);
    /* Along it from the start, never farther than 6 pixels off: none. */
    ct_tracker *u = counting_tracker();
    add_line(u, 0, 300, 640, 300, NULL);
    Log none = {0};
    us = 0;
    for (int k = 0; k < 40; k++) {
        us += STEP;
        ct_detection d = feet_at(100 + 10.0f * k, k % 3 ? 306.0f : 294.0f);
        feed(u, us, &d, 1, &none);
    }
    ck_assert_uint_eq(none.n, 0);
    ct_tracker_destroy(u);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(never_confirmed_not_counted)
{
    /* Seen twice, once on each side, then gone: never confirmed. */
    ct_tracker *t = counting_tracker();
    add_line(t, 0, 300, 640, 300, NULL);
    const ct_point square[] = {{0, 0}, {640, 0}, {640, 480}, {0, 480}};
    add_zone(t, square, 4, "all");
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 320, 280, 320, 330, 1, &log);
    for (int k = 0; k < 30; k++) {
        us += STEP;
        feed(t, us, NULL, 0, &log);
    }
    ck_assert_uint_eq(log.n, 0);
    ck_assert_uint_eq(line_count(t, 0).in + line_count(t, 0).out, 0);
    ck_assert_uint_eq(zone_count(t, 0).entered + zone_count(t, 0).exited, 0);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(confirmed_just_after_crossing)
{
    /* First seen 8 px above the line, across it at the next step,
     * confirmed at the third: counted at the step that confirms it, from
     * the side of its first box. */
    ct_tracker *t = counting_tracker();
    add_line(t, 0, 300, 640, 300, NULL);
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 320, 292, 320, 332, 2, &log);
    ck_assert_uint_eq(log.n, 1);
    ck_assert_int_eq(log.events[0].kind, CT_EVENT_LINE_IN);
    ck_assert_int_eq(log.step_us[0], 3 * STEP);
    walk(t, &us, 320, 340, 320, 400, 6, &log);
    ck_assert_uint_eq(log.n, 1);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(zone_enter_exit_dwell)
{
    ct_tracker *t = counting_tracker();
    /* A pentagon, given clockwise; the same test passes anticlockwise. */
    const ct_point shop[] = {{200, 200}, {400, 200}, {450, 300}, {400, 400}, {200, 400}};
    const int32_t z = add_zone(t, shop, 5, "shop");
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 100, 300, 300, 300, 10, &log); /* in */
    ck_assert_uint_eq(log.n, 1);
    ck_assert_int_eq(log.events[0].kind, CT_EVENT_ZONE_ENTER);
    ck_assert_int_eq(log.events[0].index, z);
    const int64_t entered = log.step_us[0];
    for (int k = 0; k < 20; k++) { /* two seconds still */
        us += STEP;
        ct_detection d = feet_at(300, 300);
        feed(t, us, &d, 1, &log);
    }
    ct_occupant occ[4];
    size_t n = 0;
    ck_assert_int_eq(ct_tracker_get_occupants(t, occ, 4, sizeof occ[0], &n), CT_OK);
    ck_assert_uint_eq(n, 1);
    ck_assert_int_eq(occ[0].zone, z);
    ck_assert_uint_eq(occ[0].track_id, 1);
    ck_assert_double_eq_tol(occ[0].dwell, (double)(us - entered) / SEC, 1e-9);
    ck_assert_int_eq(zone_count(t, z).inside, 1);
    walk(t, &us, 300, 300, 300, 100, 10, &log); /* out through the top */
    ck_assert_uint_eq(log.n, 2);
    ck_assert_int_eq(log.events[1].kind, CT_EVENT_ZONE_EXIT);
    ck_assert_int_eq(log.events[1].ended, 0);
    ck_assert_double_eq_tol(log.events[1].dwell, (double)(log.step_us[1] - entered) / SEC,
                            1e-9);
    ck_assert_double_ge(log.events[1].dwell, 2.5);
    const ct_zone_count c = zone_count(t, z);
    ck_assert_str_eq(c.name, "shop");
    ck_assert_uint_eq(c.entered, 1);
    ck_assert_uint_eq(c.exited, 1);
    ck_assert_int_eq(c.inside, 0);
    ck_assert_int_eq(ct_tracker_get_occupants(t, occ, 4, sizeof occ[0], &n), CT_OK);
    ck_assert_uint_eq(n, 0);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(zone_started_inside_and_ended_inside)
{
    /* A person there from their first box is an occupant, not an entry;
     * their track ending in the zone is an exit marked ended. */
    ct_tracker *t = counting_tracker();
    const ct_point z[] = {{0, 0}, {640, 0}, {640, 480}, {0, 480}};
    add_zone(t, z, 4, NULL);
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 300, 300, 320, 300, 5, &log);
    ck_assert_uint_eq(log.n, 0);
    ck_assert_int_eq(zone_count(t, 0).inside, 1);
    ck_assert_str_eq(zone_count(t, 0).name, "zone0");
    for (int k = 0; k < 200 && log.n == 0; k++) { /* gone: lost, then ended */
        us += STEP;
        feed(t, us, NULL, 0, &log);
    }
    ck_assert_uint_eq(log.n, 1);
    ck_assert_int_eq(log.events[0].kind, CT_EVENT_ZONE_EXIT);
    ck_assert_int_eq(log.events[0].ended, 1);
    ck_assert_float_eq_tol(log.events[0].x, 320, 2);
    ck_assert_double_ge(log.events[0].dwell, 0.5);
    ck_assert_uint_eq(zone_count(t, 0).exited, 1);
    ck_assert_int_eq(zone_count(t, 0).inside, 0);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(reset_keeps_lines_and_counts)
{
    ct_tracker *t = counting_tracker();
    add_line(t, 0, 300, 640, 300, NULL);
    const ct_point z[] = {{0, 0}, {640, 0}, {640, 480}, {0, 480}};
    add_zone(t, z, 4, NULL);
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 320, 200, 320, 400, 20, &log);
    ck_assert_int_eq(zone_count(t, 0).inside, 1);
    ck_assert_int_eq(ct_tracker_reset(t), CT_OK);
    ck_assert_uint_eq(line_count(t, 0).in, 1);
    ck_assert_int_eq(zone_count(t, 0).inside, 0);
    size_t n = 9;
    ck_assert_int_eq(ct_tracker_get_events(t, NULL, 0, sizeof(ct_event), &n), CT_OK);
    ck_assert_uint_eq(n, 0);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(several_people_in_id_order)
{
    /* Two people crossing at once, one each way: two events, ids in
     * order, counts of both. */
    ct_tracker *t = counting_tracker();
    add_line(t, 0, 300, 640, 300, NULL);
    Log log = {0};
    int64_t us = 0;
    for (int k = 0; k <= 20; k++) {
        us += STEP;
        ct_detection d[2] = {feet_at(150, 200 + 10.0f * k), feet_at(450, 400 - 10.0f * k)};
        feed(t, us, d, 2, &log);
    }
    ck_assert_uint_eq(log.n, 2);
    ck_assert_uint_lt(log.events[0].track_id, log.events[1].track_id);
    ck_assert_uint_eq(line_count(t, 0).in, 1);
    ck_assert_uint_eq(line_count(t, 0).out, 1);
    ct_tracker_destroy(t);
}
END_TEST

/* Each bad line is refused with a message and leaves the tracker's lines
 * as they were. */
static void refuse_line(ct_tracker *t, const ct_line *l, int status, const char *words)
{
    const size_t before = line_total(t);
    int32_t index = 77;
    ck_assert_int_eq(ct_tracker_add_line(t, l, &index), status);
    ck_assert_int_eq(index, 77);
    ck_assert_msg(strstr(ct_tracker_last_error(t), words), "\"%s\" lacks \"%s\"",
                  ct_tracker_last_error(t), words);
    ck_assert_uint_eq(line_total(t), before);
}

static void refuse_zone(ct_tracker *t, const ct_zone *z, const char *words)
{
    const size_t before = zone_total(t);
    ck_assert_int_eq(ct_tracker_add_zone(t, z, NULL), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(ct_tracker_last_error(t), words), "\"%s\" lacks \"%s\"",
                  ct_tracker_last_error(t), words);
    ck_assert_uint_eq(zone_total(t), before);
}

START_TEST(bad_lines_refused)
{
    ct_tracker *t = counting_tracker();
    add_line(t, 0, 10, 100, 10, "taken");
    ct_line good;
    ct_line_default(&good, sizeof good);
    good.b.x = 50;
    ct_line l = good;
    l.a.x = NAN;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "line.a");
    l = good;
    l.b.y = INFINITY;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "line.b");
    l = good;
    l.b.x = 1e9f;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "not a point");
    l = good;
    l.b = l.a; /* degenerate */
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "under a pixel");
    l = good;
    l.b.x = 0.5f;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "under a pixel");
    l = good;
    l.hysteresis = NAN;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "hysteresis");
    l.hysteresis = -0.1f;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "hysteresis");
    l.hysteresis = 3;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "hysteresis");
    l = good;
    l.name = "taken";
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "already");
    l.name = "a name longer than thirty-one bytes";
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "at most 31");
    l.name = "line0"; /* the name line 0 would have had, but it has its own */
    ck_assert_int_eq(ct_tracker_add_line(t, &l, NULL), CT_OK);
    l.name = NULL; /* line2: free */
    ck_assert_int_eq(ct_tracker_add_line(t, &l, NULL), CT_OK);
    l = good;
    l.size = 4;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "line.size");
    l.size = (size_t)1 << 20;
    refuse_line(t, &l, CT_ERROR_INVALID_ARGUMENT, "line.size");
    refuse_line(t, NULL, CT_ERROR_INVALID_ARGUMENT, "NULL");
    ck_assert_int_eq(ct_tracker_add_line(NULL, &good, NULL), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_line_default(NULL, sizeof good), CT_ERROR_INVALID_ARGUMENT);
    /* A newer header's line with its unknown fields set is refused as
     * unsupported; with them zero, taken. */
    unsigned char bigger[sizeof(ct_line) + 8] = {0};
    ct_line_default((ct_line *)bigger, sizeof bigger);
    ((ct_line *)bigger)->b.x = 50;
    ((ct_line *)bigger)->name = "newer";
    ck_assert_int_eq(ct_tracker_add_line(t, (ct_line *)bigger, NULL), CT_OK);
    bigger[sizeof(ct_line) + 3] = 1;
    ((ct_line *)bigger)->name = "newest";
    refuse_line(t, (ct_line *)bigger, CT_ERROR_UNSUPPORTED, "newer fields");
    /* Up to CT_COUNT_MAX_LINES, then refused. */
    while (line_total(t) < CT_COUNT_MAX_LINES)
        ck_assert_int_eq(ct_tracker_add_line(t, &good, NULL), CT_OK);
    refuse_line(t, &good, CT_ERROR_INVALID_ARGUMENT, "at most 64 lines");
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(bad_zones_refused)
{
    ct_tracker *t = counting_tracker();
    const ct_point square[] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    add_zone(t, square, 4, "taken");
    ct_zone good;
    ct_zone_default(&good, sizeof good);
    good.points = square;
    good.n_points = 4;
    ct_zone z = good;
    const ct_point nan_corner[] = {{0, 0}, {100, NAN}, {100, 100}};
    z.points = nan_corner;
    z.n_points = 3;
    refuse_zone(t, &z, "zone.points[1]");
    const ct_point bowtie[] = {{0, 0}, {100, 100}, {100, 0}, {0, 100}};
    z.points = bowtie;
    z.n_points = 4;
    refuse_zone(t, &z, "cross or touch");
    const ct_point flat[] = {{0, 0}, {50, 50}, {100, 100}};
    z.points = flat;
    z.n_points = 3;
    refuse_zone(t, &z, "not a simple polygon");
    const ct_point folded[] = {{0, 0}, {100, 0}, {50, 0}, {50, 80}};
    z.points = folded;
    z.n_points = 4;
    refuse_zone(t, &z, "cross or touch");
    const ct_point twice[] = {{0, 0}, {100, 0}, {100, 0}, {0, 100}};
    z.points = twice;
    refuse_zone(t, &z, "coincide");
    const ct_point tiny[] = {{0, 0}, {1, 0}, {0, 1}};
    z.points = tiny;
    z.n_points = 3;
    refuse_zone(t, &z, "area");
    z = good;
    z.n_points = 2;
    refuse_zone(t, &z, "3 to 64");
    ct_point many[CT_ZONE_MAX_POINTS + 1];
    for (int k = 0; k <= CT_ZONE_MAX_POINTS; k++) { /* a convex polygon */
        const double a = 2 * 3.14159265358979 * k / (CT_ZONE_MAX_POINTS + 1);
        many[k].x = (float)(300 + 200 * cos(a));
        many[k].y = (float)(240 + 200 * sin(a));
    }
    z.points = many;
    z.n_points = CT_ZONE_MAX_POINTS + 1;
    refuse_zone(t, &z, "3 to 64");
    z.n_points = CT_ZONE_MAX_POINTS; /* at the limit: taken */
    ck_assert_int_eq(ct_tracker_add_zone(t, &z, NULL), CT_OK);
    z = good;
    z.points = NULL;
    refuse_zone(t, &z, "NULL");
    z = good;
    z.hysteresis = INFINITY;
    refuse_zone(t, &z, "hysteresis");
    z = good;
    z.name = "taken";
    refuse_zone(t, &z, "already");
    refuse_zone(t, NULL, "NULL");
    while (zone_total(t) < CT_COUNT_MAX_ZONES)
        ck_assert_int_eq(ct_tracker_add_zone(t, &good, NULL), CT_OK);
    refuse_zone(t, &good, "at most 64 zones");
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(getters_check_their_arguments)
{
    ct_tracker *t = counting_tracker();
    size_t n = 0;
    ct_event e[2];
    ck_assert_int_eq(ct_tracker_get_events(NULL, e, 2, sizeof e[0], &n),
                     CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_get_events(t, e, 2, sizeof e[0], NULL),
                     CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_get_events(t, e, 2, 3, &n), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_get_events(t, NULL, 2, sizeof e[0], &n),
                     CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_get_occupants(t, NULL, 0, sizeof(ct_occupant), &n), CT_OK);
    ck_assert_uint_eq(n, 0);
    ck_assert_int_eq(ct_tracker_get_zone_counts(NULL, NULL, 0, sizeof(ct_zone_count), &n),
                     CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_get_line_counts(t, NULL, 0, 1, &n), CT_ERROR_INVALID_ARGUMENT);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(a_line_added_while_tracks_run)
{
    /* The track's side is taken from its next box: no crossing counted
     * for where it was before the line existed. */
    ct_tracker *t = counting_tracker();
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 320, 200, 320, 350, 15, &log);
    add_line(t, 0, 300, 640, 300, NULL);
    walk(t, &us, 320, 360, 320, 400, 4, &log);
    ck_assert_uint_eq(log.n, 0);
    walk(t, &us, 320, 400, 320, 200, 20, &log);
    ck_assert_uint_eq(log.n, 1);
    ck_assert_int_eq(log.events[0].kind, CT_EVENT_LINE_OUT);
    ct_tracker_destroy(t);
}
END_TEST

/* An allocator that refuses its `refuse`-th block from now (counting from
 * 0; -1: none). */
static long refuse = -1;
static void *countdown_alloc(void *opaque, size_t size)
{
    (void)opaque;
    if (refuse >= 0 && refuse-- == 0)
        return NULL;
    return malloc(size);
}
static void countdown_free(void *opaque, void *p)
{
    (void)opaque;
    free(p);
}

START_TEST(refused_memory_changes_nothing)
{
    /* Each block that adding a zone, or a step that counts, takes is
     * refused in turn: the call fails with CT_ERROR_OUT_OF_MEMORY and the
     * counts, occupants and tracks are as before it. */
    ct_config cfg = test_config();
    cfg.min_hits = 3;
    ct_allocator a = {sizeof a, countdown_alloc, countdown_free, NULL};
    ct_tracker *t = NULL;
    ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, &a, &t), CT_OK);
    ct_track out[64];
    test_step(t, 0, NULL, 0, out);
    add_line(t, 0, 300, 640, 300, NULL);
    Log log = {0};
    int64_t us = 0;
    walk(t, &us, 320, 200, 320, 290, 9, &log);
    const ct_point z[] = {{0, 250}, {640, 250}, {640, 480}, {0, 480}};
    ct_zone zone;
    ct_zone_default(&zone, sizeof zone);
    zone.points = z;
    zone.n_points = 4;
    int failures = 0;
    for (refuse = 0;; refuse = failures) {
        const int st = ct_tracker_add_zone(t, &zone, NULL);
        if (st == CT_OK)
            break;
        ck_assert_int_eq(st, CT_ERROR_OUT_OF_MEMORY);
        ck_assert_uint_eq(zone_total(t), 0);
        failures++;
    }
    ck_assert_int_gt(failures, 0);
    refuse = -1;
    /* The step across the line, refused block by block. */
    us += STEP;
    ct_detection d = feet_at(320, 330);
    ct_frame f = test_frame(us, 640, 480);
    failures = 0;
    for (refuse = 0;; refuse = failures) {
        const int st = ct_tracker_feed(t, &f, &d, 1);
        if (st == CT_OK)
            break;
        ck_assert_int_eq(st, CT_ERROR_OUT_OF_MEMORY);
        ck_assert_uint_eq(line_count(t, 0).in, 0);
        ck_assert_int_eq(zone_count(t, 0).inside, 0); /* added since: from the next box */
        size_t n = 9;
        ck_assert_int_eq(ct_tracker_get_events(t, NULL, 0, sizeof(ct_event), &n), CT_OK);
        ck_assert_uint_eq(n, 0);
        failures++;
    }
    refuse = -1;
    ck_assert_int_gt(failures, 0);
    ck_assert_uint_eq(line_count(t, 0).in, 1);
    ck_assert_int_eq(zone_count(t, 0).inside, 1);
    ct_tracker_destroy(t);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("count");
    TCase *tc = tcase_create("count");
    tcase_add_test(tc, crossing_each_way);
    tcase_add_test(tc, a_segment_not_a_line);
    tcase_add_test(tc, walk_along_the_line_counted_once);
    tcase_add_test(tc, never_confirmed_not_counted);
    tcase_add_test(tc, confirmed_just_after_crossing);
    tcase_add_test(tc, zone_enter_exit_dwell);
    tcase_add_test(tc, zone_started_inside_and_ended_inside);
    tcase_add_test(tc, reset_keeps_lines_and_counts);
    tcase_add_test(tc, several_people_in_id_order);
    tcase_add_test(tc, bad_lines_refused);
    tcase_add_test(tc, bad_zones_refused);
    tcase_add_test(tc, getters_check_their_arguments);
    tcase_add_test(tc, a_line_added_while_tracks_run);
    tcase_add_test(tc, refused_memory_changes_nothing);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
