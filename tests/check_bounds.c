/* Bounded work: a flood of overlapping detections into a tracker holding
 * 1,000 live tracks. The assignment is gated and sparse, and a component
 * too large to solve exactly is solved greedily, so each feed returns at
 * once; meson's timeout on this test is the hang check (no elapsed time is
 * asserted here: make bench measures it). */
#include "common.h"
#include "flood.h"

#include <stdio.h>

enum { PEOPLE = 1000 };

/* Feeds the people, then a flood of n boxes; checks the tracks. */
static void flood(size_t n)
{
    ct_tracker *t = test_tracker(NULL);
    static ct_detection people[PEOPLE];
    flood_people(people, PEOPLE);
    ct_frame f = test_frame(0, 0, 0);
    ck_assert_int_eq(ct_tracker_feed(t, &f, people, PEOPLE), CT_OK);

    ct_detection *boxes = malloc(n * sizeof *boxes);
    ck_assert_ptr_nonnull(boxes);
    flood_boxes(boxes, n, PEOPLE);
    static ct_track tracks[PEOPLE + 1];
    for (int step = 1; step <= 2; step++) {
        f.timestamp_us = 40000 * step;
        ck_assert_int_eq(ct_tracker_feed(t, &f, boxes, n), CT_OK);
        size_t count = 0;
        ck_assert_int_eq(ct_tracker_get_tracks(t, tracks, PEOPLE + 1, sizeof tracks[0], &count),
                         CT_OK);
        /* max_tracks (1000) is reached: the flood starts no track. */
        ct_stats st;
        st.size = sizeof st;
        ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
        ck_assert_uint_eq(st.live_tracks, PEOPLE);
        ck_assert_uint_le(count, PEOPLE);
        /* Every detection was considered: each person has boxes over it,
         * and nearly every track takes one, none taken twice. */
        char *used = calloc(n, 1);
        size_t matched = 0;
        for (size_t i = 0; i < count; i++) {
            const int d = tracks[i].detection_index;
            if (d < 0)
                continue;
            ck_assert_int_lt(d, (int)n);
            ck_assert_msg(!used[d], "detection %d matched twice", d);
            used[d] = 1;
            matched++;
        }
        free(used);
        ck_assert_msg(matched >= PEOPLE * 9 / 10, "%zu of %d tracks matched at step %d",
                      matched, PEOPLE, step);
    }
    free(boxes);
    ct_tracker_destroy(t);
}

START_TEST(flood_of_5000)
{
    flood(5000);
}
END_TEST

START_TEST(flood_of_50000)
{
    flood(50000);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("bounds");
    TCase *tc = tcase_create("bounds");
    /* The hang check is meson's timeout on the whole program. */
    tcase_set_timeout(tc, 0);
    tcase_add_test(tc, flood_of_5000);
    tcase_add_test(tc, flood_of_50000);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
