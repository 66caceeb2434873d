/* Determinism and thread independence, on the real public detections of
 * PETS09-S2L1 and TUD-Campus. */
#include <pthread.h>
#include <stdio.h>

#include "common.h"
#include "detfile.h"

static const char *data_dir;

typedef struct {
    const char *seq;
    int width, height;
    double fps;
    ct_track *out;   /* every reported track of every frame, in order */
    size_t count, cap;
    int status;
} run;

static void record(run *r, const ct_track *t, size_t n)
{
    if (r->count + n > r->cap) {
        r->cap = (r->count + n) * 2;
        r->out = realloc(r->out, r->cap * sizeof *r->out);
    }
    memcpy(r->out + r->count, t, n * sizeof *t);
    r->count += n;
}

static void *replay(void *arg)
{
    run *r = arg;
    char path[1024], err[512];
    snprintf(path, sizeof path, "%s/%s/det/det.txt", data_dir, r->seq);
    det_file df;
    r->status = -1;
    if (detfile_load(path, &df, err, sizeof err) < 0) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    ct_tracker *t = NULL;
    if (ct_tracker_create(&cfg, &t) != CT_OK)
        return NULL;
    ct_track tracks[256];
    for (int k = 1; k <= df.max_frame; k++) {
        ct_frame f;
        ct_frame_default(&f, sizeof f);
        f.width = r->width;
        f.height = r->height;
        f.timestamp_us = (int64_t)((k - 1) * 1e6 / r->fps);
        size_t n, count;
        const ct_detection *d = detfile_frame(&df, k, &n);
        if (ct_tracker_feed(t, &f, d, n) != CT_OK ||
            ct_tracker_get_tracks(t, tracks, 256, sizeof tracks[0], &count) != CT_OK)
            goto out;
        record(r, tracks, count);
    }
    r->status = 0;
out:
    ct_tracker_destroy(t);
    detfile_free(&df);
    return NULL;
}

static run make_run(const char *seq, int w, int h, double fps)
{
    run r;
    memset(&r, 0, sizeof r);
    r.seq = seq;
    r.width = w;
    r.height = h;
    r.fps = fps;
    return r;
}

static void assert_same(const run *a, const run *b)
{
    ck_assert_int_eq(a->status, 0);
    ck_assert_int_eq(b->status, 0);
    ck_assert_uint_gt(a->count, 100);
    ck_assert_uint_eq(a->count, b->count);
    ck_assert_mem_eq(a->out, b->out, a->count * sizeof *a->out);
}

START_TEST(deterministic)
{
    run a = make_run("PETS09-S2L1", 768, 576, 7), b = make_run("PETS09-S2L1", 768, 576, 7);
    replay(&a);
    replay(&b);
    assert_same(&a, &b);
    free(a.out);
    free(b.out);
}
END_TEST

START_TEST(two_threads_match_one_after_the_other)
{
    run seq_a = make_run("PETS09-S2L1", 768, 576, 7), seq_b = make_run("TUD-Campus", 640, 480, 25);
    replay(&seq_a);
    replay(&seq_b);
    for (int round = 0; round < 3; round++) {
        run par_a = make_run("PETS09-S2L1", 768, 576, 7), par_b = make_run("TUD-Campus", 640, 480, 25);
        run par_c = make_run("PETS09-S2L1", 768, 576, 7);
        pthread_t ta, tb, tc;
        ck_assert_int_eq(pthread_create(&ta, NULL, replay, &par_a), 0);
        ck_assert_int_eq(pthread_create(&tb, NULL, replay, &par_b), 0);
        ck_assert_int_eq(pthread_create(&tc, NULL, replay, &par_c), 0);
        pthread_join(ta, NULL);
        pthread_join(tb, NULL);
        pthread_join(tc, NULL);
        assert_same(&seq_a, &par_a);
        assert_same(&seq_b, &par_b);
        assert_same(&seq_a, &par_c);
        free(par_a.out);
        free(par_b.out);
        free(par_c.out);
    }
    free(seq_a.out);
    free(seq_b.out);
}
END_TEST

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: check_threads DATA_DIR (tests/data/mot15)\n");
        return 2;
    }
    data_dir = argv[1];
    Suite *s = suite_create("threads");
    TCase *tc = tcase_create("threads");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, deterministic);
    tcase_add_test(tc, two_threads_match_one_after_the_other);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
