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

/* The same flood with pixels: appearance (DDIS) and mean shift run, and
 * the work per step stays bounded (at most kMaxDdisPairs, 1024, DDIS for
 * each association pass and for re-identification). */
START_TEST(flood_with_pixels)
{
    enum { W = 1920, H = 1088, N = 5000 };
    ct_tracker *t = test_tracker(NULL);
    static ct_detection people[PEOPLE];
    flood_people(people, PEOPLE);
    uint8_t *grey = malloc((size_t)W * H);
    ck_assert_ptr_nonnull(grey);
    for (size_t i = 0; i < (size_t)W * H; i++)
        grey[i] = (uint8_t)(64 + (i * 2654435761u >> 26)); /* texture */
    ct_frame f;
    ct_frame_default(&f, sizeof f);
    f.format = CT_FORMAT_GRAY8;
    f.width = W;
    f.height = H;
    f.planes[0] = grey;
    f.strides[0] = W;
    int64_t us = 0;
    for (int k = 0; k < 4; k++, us += 40000) { /* confirmed, with templates */
        f.timestamp_us = us;
        ck_assert_int_eq(ct_tracker_feed(t, &f, people, PEOPLE), CT_OK);
    }
    ct_detection *boxes = malloc(N * sizeof *boxes);
    ck_assert_ptr_nonnull(boxes);
    flood_boxes(boxes, N, PEOPLE);
    ct_stats st;
    st.size = sizeof st;
    for (int step = 0; step < 2; step++, us += 40000) {
        ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
        const uint64_t before = st.ddis_runs;
        f.timestamp_us = us;
        ck_assert_int_eq(ct_tracker_feed(t, &f, boxes, N), CT_OK);
        ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
        ck_assert_msg(st.ddis_runs - before <= 4 * 1024, "%llu DDIS in one step",
                      (unsigned long long)(st.ddis_runs - before));
    }
    free(boxes);
    free(grey);
    ct_tracker_destroy(t);
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
    tcase_add_test(tc, flood_with_pixels);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
