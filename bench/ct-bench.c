/* ct-bench: times libctrack on real and synthetic detections, per stage,
 * and counts its memory and heap allocations. Run on one core
 * (taskset -c 0); bench/bench.py drives it beside the baselines.
 *
 *   ct-bench [--json FILE] [--passes N] DATA_DIR     (DATA_DIR: tests/data/mot15)
 */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ctrack/ctrack.h"
#include "alloc_count.h"
#include "detfile.h"
#include "video.h"
#include "progress.h"
#include "flood.h"

/* Every heap allocation of the process is counted by alloc_count.c. */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* --- a sequence of detections in memory --- */
typedef struct {
    int frames;
    size_t *start, *count; /* per frame, into dets */
    ct_detection *dets;
} sequence;

static sequence from_detfile(det_file *df, double sx, double sy)
{
    sequence s;
    s.frames = df->max_frame;
    s.start = calloc(s.frames + 1, sizeof *s.start);
    s.count = calloc(s.frames + 1, sizeof *s.count);
    s.dets = malloc((df->count + 1) * sizeof *s.dets);
    df->cursor = 0;
    size_t at = 0;
    for (int k = 1; k <= s.frames; k++) {
        size_t n;
        const ct_detection *d = detfile_frame(df, k, &n);
        s.start[k] = at;
        s.count[k] = n;
        for (size_t i = 0; i < n; i++, at++) {
            s.dets[at] = d[i];
            s.dets[at].left *= sx;
            s.dets[at].width *= sx;
            s.dets[at].top *= sy;
            s.dets[at].height *= sy;
        }
    }
    return s;
}

/* n people walking across a w x h image at constant velocities, bouncing at
 * the edges, with a little detector jitter. Deterministic. */
static sequence synthetic(int people, int frames, int w, int h)
{
    sequence s;
    s.frames = frames;
    s.start = calloc(frames + 1, sizeof *s.start);
    s.count = calloc(frames + 1, sizeof *s.count);
    s.dets = malloc(((size_t)people * frames + 1) * sizeof *s.dets);
    double *x = malloc(people * sizeof *x), *y = malloc(people * sizeof *y);
    double *vx = malloc(people * sizeof *vx), *vy = malloc(people * sizeof *vy);
    unsigned seed = 12345;
#define RND() ((seed = seed * 1103515245u + 12345u) >> 8 & 0xFFFF) / 65536.0
    for (int i = 0; i < people; i++) {
        x[i] = RND() * (w - 40);
        y[i] = RND() * (h - 90);
        vx[i] = (RND() - 0.5) * 6;
        vy[i] = (RND() - 0.5) * 3;
    }
    size_t at = 0;
    for (int k = 1; k <= frames; k++) {
        s.start[k] = at;
        for (int i = 0; i < people; i++) {
            x[i] += vx[i];
            y[i] += vy[i];
            if (x[i] < 0 || x[i] > w - 40) vx[i] = -vx[i];
            if (y[i] < 0 || y[i] > h - 90) vy[i] = -vy[i];
            ct_detection d = {(float)(x[i] + RND()), (float)(y[i] + RND()), 40, 90,
                              (float)(0.7 + 0.3 * RND()), 0};
            s.dets[at++] = d;
        }
        s.count[k] = people;
    }
#undef RND
    free(x);
    free(y);
    free(vx);
    free(vy);
    return s;
}

static void free_sequence(sequence *s)
{
    free(s->start);
    free(s->count);
    free(s->dets);
}

/* Real frames in memory, for the runs with pixels. */
typedef struct {
    int width, height, frames;
    uint8_t *data;   /* frames * bytes */
    size_t bytes;    /* one frame */
    uint32_t format; /* CT_FORMAT_I420 or CT_FORMAT_BGR24 */
} video;

static video load_video(const char *path, int max_frames)
{
    video v;
    memset(&v, 0, sizeof v);
    video_params ip = {0, 0, CT_FORMAT_I420};
    video_input *in = NULL;
    video_info info;
    char err[512];
    if (video_open(path, &ip, &in, &info, err, sizeof err) < 0) {
        fprintf(stderr, "ct-bench: %s\n", err);
        exit(1);
    }
    v.width = info.width;
    v.height = info.height;
    v.format = CT_FORMAT_I420;
    v.bytes = frame_bytes(CT_FORMAT_I420, v.width, v.height);
    v.data = malloc(v.bytes * max_frames);
    ct_frame f;
    while (v.frames < max_frames && video_read(in, &f, err, sizeof err) == 1) {
        if (f.format != CT_FORMAT_I420) {
            fprintf(stderr, "ct-bench: %s is not 4:2:0 colour\n", path);
            exit(1);
        }
        memcpy(v.data + v.bytes * v.frames, f.planes[0], v.bytes);
        v.frames++;
    }
    video_close(in);
    return v;
}

/* The same frames as packed BGR, as a host whose camera or decoder gives
 * BGR hands them over. */
static video to_bgr24(const video *v)
{
    video b = *v;
    b.format = CT_FORMAT_BGR24;
    b.bytes = (size_t)3 * v->width * v->height;
    b.data = malloc(b.bytes * v->frames);
    const size_t luma = (size_t)v->width * v->height;
    const size_t chroma = (size_t)((v->width + 1) / 2) * ((v->height + 1) / 2);
    for (int k = 0; k < v->frames; k++) {
        ct_frame f;
        ct_frame_default(&f, sizeof f);
        f.format = CT_FORMAT_I420;
        f.width = v->width;
        f.height = v->height;
        f.planes[0] = v->data + v->bytes * k;
        f.planes[1] = f.planes[0] + luma;
        f.planes[2] = f.planes[1] + chroma;
        f.strides[0] = v->width;
        f.strides[1] = f.strides[2] = (v->width + 1) / 2;
        i420_to_bgr24(&f, b.data + b.bytes * k);
    }
    return b;
}

typedef struct {
    double us_per_frame;          /* median over passes */
    double stage_us[CT_STATS_MAX_STAGES];
    double allocs_per_frame;      /* in the last pass (steady state) */
    unsigned long long tracker_bytes_created, tracker_bytes_after;
    unsigned long long memory_bytes;
    double mean_shift_us_per_person; /* 0 without pixels */
    unsigned long long mean_shift_runs;
} result;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Runs the sequence `passes` times through one tracker (timestamps going on),
 * with the real frames of `v` (then only as many frames as it has) or
 * without pixels (v NULL, an image of w x h). */
static result run(const sequence *s, int passes, double fps, int w, int h, const video *v,
                  int source)
{
    result r;
    memset(&r, 0, sizeof r);
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    cfg.source = source;
    long long before = ct_live_bytes;
    ct_tracker *t = NULL;
    if (ct_tracker_create(&cfg, &t) != CT_OK) {
        fprintf(stderr, "ct-bench: create failed\n");
        exit(1);
    }
    r.tracker_bytes_created = (unsigned long long)(ct_live_bytes - before);
    ct_frame f;
    ct_frame_default(&f, sizeof f);
    f.width = w;
    f.height = h;
    const int frames = v && v->frames < s->frames ? v->frames : s->frames;
    if (v) {
        size_t cw = (w + 1) / 2;
        f.format = v->format;
        f.strides[0] = v->format == CT_FORMAT_BGR24 ? 3 * w : w;
        f.strides[1] = f.strides[2] = (int32_t)cw;
    }
    ct_track *out = malloc(4096 * sizeof *out);
    double *times = malloc(passes * sizeof *times);
    long long step = 0;
    unsigned long long allocs_last = 0;
    for (int p = 0; p < passes; p++) {
        unsigned long long a0 = ct_allocations;
        double t0 = now();
        for (int k = 1; k <= frames; k++, step++) {
            f.timestamp_us = (int64_t)llround(step * 1e6 / fps);
            if (v) {
                const uint8_t *p = v->data + v->bytes * (k - 1);
                size_t luma = (size_t)w * h, chroma = (size_t)((w + 1) / 2) * ((h + 1) / 2);
                f.planes[0] = p;
                f.planes[1] = p + luma;
                f.planes[2] = p + luma + chroma;
            }
            size_t count;
            const int own = source == CT_SOURCE_PIXELS; /* the tracker finds its candidates */
            if (ct_tracker_feed(t, &f, own ? NULL : s->dets + s->start[k], own ? 0 : s->count[k]) != CT_OK ||
                ct_tracker_get_tracks(t, out, 4096, sizeof *out, &count) != CT_OK) {
                fprintf(stderr, "ct-bench: %s\n", ct_tracker_last_error(t));
                exit(1);
            }
        }
        times[p] = (now() - t0) / frames * 1e6;
        allocs_last = ct_allocations - a0;
    }
    qsort(times, passes, sizeof *times, cmp_double);
    r.us_per_frame = times[passes / 2];
    r.allocs_per_frame = (double)allocs_last / frames;
    ct_stats st;
    st.size = sizeof st;
    ct_tracker_get_stats(t, &st);
    for (int i = 0; i < CT_STATS_MAX_STAGES; i++)
        r.stage_us[i] = st.stage_ns[i] * 1e-3 / (double)st.steps;
    r.memory_bytes = st.memory_bytes;
    r.mean_shift_runs = st.mean_shift_runs;
    if (st.mean_shift_runs)
        r.mean_shift_us_per_person = st.stage_ns[CT_STAGE_MEAN_SHIFT] * 1e-3 / st.mean_shift_runs;
    free(times);
    free(out);
    /* What the tracker holds is what destroying it gives back. */
    long long held = ct_live_bytes;
    ct_tracker_destroy(t);
    r.tracker_bytes_after = (unsigned long long)(held - ct_live_bytes);
        return r;
}

static void print_result(FILE *json, const char *name, const result *r, int people,
                         int first)
{
    printf("%-30s %8.2f us/frame %9.0f frames/s  allocs/frame %.2f  tracker %llu B"
           " (new %llu B)\n", name, r->us_per_frame, 1e6 / r->us_per_frame,
           r->allocs_per_frame, r->tracker_bytes_after, r->tracker_bytes_created);
    printf("%-30s", "");
    for (int i = 0; i < CT_STATS_MAX_STAGES; i++)
        if (ct_stage_name(i))
            printf(" %s %.2f", ct_stage_name(i), r->stage_us[i]);
    printf(" (us/frame)\n");
    if (r->mean_shift_runs)
        printf("%-30s mean shift %.2f us per person per frame (%llu windows)\n", "",
               r->mean_shift_us_per_person, r->mean_shift_runs);
    if (!json)
        return;
    fprintf(json, "%s    {\"name\": \"%s\", \"people\": %d, \"us_per_frame\": %.4f, "
                  "\"frames_per_second\": %.1f, \"allocs_per_frame\": %.4f, "
                  "\"tracker_bytes_created\": %llu, \"tracker_bytes_after\": %llu, "
                  "\"memory_bytes\": %llu, \"mean_shift_us_per_person\": %.4f, "
                  "\"stages_us\": {",
            first ? "" : ",\n", name, people, r->us_per_frame, 1e6 / r->us_per_frame,
            r->allocs_per_frame, r->tracker_bytes_created, r->tracker_bytes_after,
            r->memory_bytes, r->mean_shift_us_per_person);
    int f2 = 1;
    for (int i = 0; i < CT_STATS_MAX_STAGES; i++)
        if (ct_stage_name(i)) {
            fprintf(json, "%s\"%s\": %.4f", f2 ? "" : ", ", ct_stage_name(i), r->stage_us[i]);
            f2 = 0;
        }
    fprintf(json, "}}");
}

/* One feed of n overlapping detections into a tracker holding 1,000 live
 * tracks (tests/flood.h): milliseconds, the median of 5 trackers. */
static double flood_ms(size_t n)
{
    enum { PEOPLE = 1000, RUNS = 5 };
    static ct_detection people[PEOPLE];
    flood_people(people, PEOPLE);
    ct_detection *boxes = malloc(n * sizeof *boxes);
    flood_boxes(boxes, n, PEOPLE);
    double ms[RUNS];
    for (int run = 0; run < RUNS; run++) {
        ct_config cfg;
        ct_config_default(&cfg, sizeof cfg);
        ct_tracker *t = NULL;
        ct_frame f;
        ct_frame_default(&f, sizeof f);
        if (ct_tracker_create(&cfg, &t) != CT_OK || ct_tracker_feed(t, &f, people, PEOPLE) != CT_OK) {
            fprintf(stderr, "ct-bench: flood: %s\n", ct_tracker_last_error(t));
            exit(1);
        }
        f.timestamp_us = 40000;
        const double t0 = now();
        if (ct_tracker_feed(t, &f, boxes, n) != CT_OK) {
            fprintf(stderr, "ct-bench: flood: %s\n", ct_tracker_last_error(t));
            exit(1);
        }
        ms[run] = (now() - t0) * 1e3;
        ct_tracker_destroy(t);
    }
    free(boxes);
    qsort(ms, RUNS, sizeof ms[0], cmp_double);
    return ms[RUNS / 2];
}

int main(int argc, char **argv)
{
    const char *json_path = NULL, *data = NULL, *video_path = NULL, *video_hd_path = NULL;
    int passes = 15;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--json") && i + 1 < argc)
            json_path = argv[++i];
        else if (!strcmp(argv[i], "--video") && i + 1 < argc)
            video_path = argv[++i];
        else if (!strcmp(argv[i], "--video-hd") && i + 1 < argc)
            video_hd_path = argv[++i];
        else if (!strcmp(argv[i], "--passes") && i + 1 < argc)
            passes = atoi(argv[++i]);
        else
            data = argv[i];
    }
    if (!data || passes < 1) {
        fprintf(stderr, "usage: ct-bench [--json FILE] [--passes N] [--video PETS09.y4m]\n"
                        "                [--video-hd PETS09-1080p.y4m] DATA_DIR\n");
        return 2;
    }
    FILE *json = json_path ? fopen(json_path, "w") : NULL;
    if (json_path && !json) {
        perror(json_path);
        return 1;
    }
    char path[1024], err[512];
    snprintf(path, sizeof path, "%s/PETS09-S2L1/det/det.txt", data);
    det_file df;
    if (detfile_load(path, &df, err, sizeof err) < 0) {
        fprintf(stderr, "ct-bench: %s\n", err);
        return 1;
    }
    if (json)
        fprintf(json, "{\"ctrack\": \"%s\", \"runs\": [\n", ct_version_string());

    printf("ctrack %s, %d passes each, median\n\n", ct_version_string(), passes);
    printf("PETS09-S2L1 public detections (795 frames, 7 fps):\n");
    sequence pets = from_detfile(&df, 1, 1);
    sequence pets_hd = from_detfile(&df, 1920.0 / 768, 1080.0 / 576);
    result r = run(&pets, passes, 7, 768, 576, NULL, CT_SOURCE_DETECTIONS);
    print_result(json, "detections 768x576", &r, 0, 1);
    r = run(&pets_hd, passes, 7, 1920, 1080, NULL, CT_SOURCE_DETECTIONS);
    print_result(json, "detections 1920x1080", &r, 0, 0);
    /* With the real frames: the first 200 (768x576) and 60 (1920x1080). */
    if (video_path) {
        video v = load_video(video_path, 200);
        r = run(&pets, passes > 5 ? 5 : passes, 7, v.width, v.height, &v, CT_SOURCE_DETECTIONS);
        print_result(json, "detections+pixels 768x576", &r, 0, 0);
        r = run(&pets, passes > 5 ? 5 : passes, 7, v.width, v.height, &v, CT_SOURCE_PIXELS);
        print_result(json, "pixels only 768x576", &r, 0, 0);
        /* The same from packed BGR, which the library converts (the stage
         * "convert"). */
        video bgr = to_bgr24(&v);
        r = run(&pets, passes > 5 ? 5 : passes, 7, v.width, v.height, &bgr, CT_SOURCE_PIXELS);
        print_result(json, "pixels only 768x576 BGR24", &r, 0, 0);
        free(bgr.data);
        free(v.data);
    }
    if (video_hd_path) {
        video v = load_video(video_hd_path, 60);
        r = run(&pets_hd, passes > 5 ? 5 : passes, 7, v.width, v.height, &v, CT_SOURCE_DETECTIONS);
        print_result(json, "detections+pixels 1920x1080", &r, 0, 0);
        free(v.data);
    }

    printf("\nScaling with the number of people (synthetic walkers, 1920x1080, 25 fps):\n");
    const int crowd[] = {1, 2, 5, 10, 20, 50, 100, 200};
    for (size_t i = 0; i < sizeof crowd / sizeof crowd[0]; i++) {
        sequence syn = synthetic(crowd[i], 300, 1920, 1080);
        char name[64];
        snprintf(name, sizeof name, "people %d", crowd[i]);
        r = run(&syn, passes > 5 ? 5 : passes, 25, 1920, 1080, NULL, CT_SOURCE_DETECTIONS);
        print_result(json, name, &r, crowd[i], 0);
        free_sequence(&syn);
    }
    printf("\nBounded work: one feed of overlapping detections into a tracker holding 1000 "
           "live tracks (median of 5):\n");
    const double flood5k = flood_ms(5000), flood50k = flood_ms(50000);
    printf("flood 5000 detections           %8.2f ms a feed\n", flood5k);
    printf("flood 50000 detections          %8.2f ms a feed\n", flood50k);
    long rss = peak_rss_kib();
    printf("\npeak RSS of ct-bench: %ld KiB\n", rss);
    if (json) {
        fprintf(json, "\n], \"flood_ms\": {\"5000\": %.3f, \"50000\": %.3f}, "
                      "\"peak_rss_kib\": %ld}\n", flood5k, flood50k, rss);
        fclose(json);
    }
    free_sequence(&pets);
    free_sequence(&pets_hd);
    detfile_free(&df);
    return 0;
}
