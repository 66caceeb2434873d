/* Determinism and thread independence, on the real public detections of
 * PETS09-S2L1 and TUD-Campus, and on TUD-Campus's real frames (decoded by
 * ffmpeg) in the three modes. make tsan runs this suite under
 * ThreadSanitizer. */
#include <pthread.h>
#include <stdio.h>

#include "common.h"
#include "detfile.h"

static const char *data_dir;

typedef struct {
    const char *seq;
    int width, height;
    double fps;
    /* 0 detections only; with TUD-Campus's frames (load_tud_frames()),
     * 1 detections + pixels, 2 pixels only. */
    int mode;
    ct_track *out;   /* every reported track of every frame, in order */
    size_t count, cap;
    int status;
} run;

static void record(run *r, const ct_track *t, size_t n)
{
    if (n == 0)
        return;
    if (r->count + n > r->cap) {
        r->cap = (r->count + n) * 2;
        r->out = realloc(r->out, r->cap * sizeof *r->out);
    }
    memcpy(r->out + r->count, t, n * sizeof *t);
    r->count += n;
}

/* TUD-Campus's frames, I420, decoded once by ffmpeg for every thread. */
enum { TUD_W = 640, TUD_H = 480, TUD_FRAME = TUD_W * TUD_H * 3 / 2 };
static uint8_t *tud_frames;
static int tud_count;

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
    if (r->mode == 2)
        cfg.source = CT_SOURCE_PIXELS;
    ct_tracker *t = NULL;
    if (ct_tracker_create(&cfg, &t) != CT_OK) {
        detfile_free(&df);
        return NULL;
    }
    ct_track tracks[256];
    const int frames = r->mode > 0 ? tud_count : df.max_frame;
    for (int k = 1; k <= frames; k++) {
        ct_frame f;
        ct_frame_default(&f, sizeof f);
        f.width = r->width;
        f.height = r->height;
        f.timestamp_us = (int64_t)((k - 1) * 1e6 / r->fps);
        if (r->mode > 0) {
            uint8_t *y = tud_frames + (size_t)(k - 1) * TUD_FRAME;
            f.format = CT_FORMAT_I420;
            f.planes[0] = y;
            f.planes[1] = y + TUD_W * TUD_H;
            f.planes[2] = y + TUD_W * TUD_H * 5 / 4;
            f.strides[0] = TUD_W;
            f.strides[1] = f.strides[2] = TUD_W / 2;
        }
        size_t n, count;
        const ct_detection *d = detfile_frame(&df, k, &n);
        if (r->mode == 2) {
            d = NULL;
            n = 0;
        }
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

static void load_tud_frames(void)
{
    char cmd[1400];
    snprintf(cmd, sizeof cmd,
             "ffmpeg -v error -nostdin -i '%s/TUD-Campus/video.mp4' -f rawvideo -pix_fmt "
             "yuv420p -",
             data_dir);
    FILE *p = popen(cmd, "r");
    ck_assert_msg(p != NULL, "cannot run ffmpeg");
    size_t cap = 0;
    for (;;) {
        if ((size_t)(tud_count + 1) * TUD_FRAME > cap) {
            cap = (size_t)(tud_count + 1) * TUD_FRAME * 2;
            tud_frames = realloc(tud_frames, cap);
        }
        if (fread(tud_frames + (size_t)tud_count * TUD_FRAME, 1, TUD_FRAME, p) != TUD_FRAME)
            break;
        tud_count++;
    }
    ck_assert_int_eq(pclose(p), 0);
    ck_assert_int_eq(tud_count, 71);
}

/* Four threads on TUD-Campus's frames at once, in the three modes (one
 * mode twice), give what each gives alone. */
START_TEST(four_threads_on_real_frames)
{
    load_tud_frames();
    run alone[3];
    for (int m = 0; m < 3; m++) {
        alone[m] = make_run("TUD-Campus", TUD_W, TUD_H, 25);
        alone[m].mode = m;
        replay(&alone[m]);
        ck_assert_int_eq(alone[m].status, 0);
        ck_assert_uint_gt(alone[m].count, 50);
    }
    run par[4];
    pthread_t th[4];
    for (int i = 0; i < 4; i++) {
        par[i] = make_run("TUD-Campus", TUD_W, TUD_H, 25);
        par[i].mode = i % 3;
        ck_assert_int_eq(pthread_create(&th[i], NULL, replay, &par[i]), 0);
    }
    for (int i = 0; i < 4; i++)
        pthread_join(th[i], NULL);
    for (int i = 0; i < 4; i++) {
        assert_same(&alone[i % 3], &par[i]);
        free(par[i].out);
    }
    for (int m = 0; m < 3; m++)
        free(alone[m].out);
    free(tud_frames);
    tud_frames = NULL;
    tud_count = 0;
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
    tcase_add_test(tc, four_threads_on_real_frames);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
