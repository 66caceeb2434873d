/* make soak: one tracker for a long run, its memory and time per frame at the
 * start, the middle and the end.
 *
 *   ct-soak [DETECTION_FRAMES [PIXEL_FRAMES [MARGIN_KIB]]]
 *
 * Detections only: DETECTION_FRAMES (default 1,000,000) steps of a 640x480
 * scene where people keep entering on the left and leaving on the right, a
 * few at a time, each walking for a few seconds. Pixels only: PIXEL_FRAMES
 * (default 100,000) synthetic 320x240 I420 frames of walkers (head, torso,
 * legs) crossing a textured background. For each run it prints the resident
 * memory (RSS) and the mean time per frame over the first, middle and last
 * tenth, and the tracks started. It fails (exit 1) when the RSS at the end
 * is more than MARGIN_KIB (default 2,048) above the RSS at the middle: a
 * leak or a structure that keeps growing. */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ctrack/ctrack.h"
#include "i420.h"

static long rss_kib(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long pages = 0, resident = 0;
    if (!f)
        return 0;
    if (fscanf(f, "%ld %ld", &pages, &resident) != 2)
        resident = 0;
    fclose(f);
    return resident * 4;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* A person of the scene: enters at frame `start`, walks `speed` pixels a
 * frame from x0 for `frames` frames, at row `y`. */
typedef struct {
    long start, frames;
    float x0, y, speed, h;
} walker;

/* A new person every kPeriod frames, in as many lanes as the image's
 * height holds without overlap, each crossing in 60 to 99 frames. */
enum { kPeriod = 20 };

static walker walker_of(long k, int width, int height, float tall)
{
    walker w;
    const int lanes = (int)((float)height / (tall * 1.05f));
    w.start = k * kPeriod;
    w.frames = 60 + (k * 37) % 40;
    w.speed = (float)(width + tall) / (float)w.frames;
    w.x0 = -tall / 2;
    w.h = tall;
    w.y = (float)height / (float)lanes * (float)((k * 5) % lanes);
    return w;
}

typedef struct {
    long rss[3];
    double us[3];
    uint64_t tracks;
} soak_result;

static int frame_of(long i, long n)
{
    return i < n / 10 ? 0 : (i >= n / 2 - n / 20 && i < n / 2 + n / 20) ? 1 : i >= n - n / 10 ? 2 : -1;
}

/* Pixels: a textured background and the walkers of this frame. */
static void draw(uint8_t *y, uint8_t *u, uint8_t *v, int w, int h, long i, float tall)
{
    for (int r = 0; r < h; r++)
        for (int c = 0; c < w; c++)
            y[r * w + c] = (uint8_t)(110 + 30 * (((c / 8) + (r / 6)) % 2) + (c * 7 + r * 13) % 9);
    memset(u, 128, (size_t)(w / 2) * (h / 2));
    memset(v, 128, (size_t)(w / 2) * (h / 2));
    for (long k = i / kPeriod - 6; k <= i / kPeriod; k++) {
        if (k < 0)
            continue;
        const walker p = walker_of(k, w, h, tall);
        const long t = i - p.start;
        if (t < 0 || t >= p.frames)
            continue;
        const float cx = p.x0 + p.speed * (float)t, top = p.y;
        const int swing = (int)(t % 8) - 4;
        for (int r = (int)top; r < (int)(top + tall) && r < h; r++) {
            const float f = ((float)r - top) / tall;
            for (int c = (int)(cx - tall * 0.2f); c <= (int)(cx + tall * 0.2f); c++) {
                if (c < 0 || c >= w || r < 0)
                    continue;
                const float dx = ((float)c - cx) / tall;
                int in;
                if (f < 0.13f)
                    in = dx * dx / 0.0036f + (f - 0.065f) * (f - 0.065f) / 0.0042f <= 1;
                else if (f < 0.55f)
                    in = dx > -0.12f && dx < 0.12f;
                else {
                    const float spread = 0.012f * (float)swing * (f - 0.55f) / 0.45f;
                    in = (dx > -0.1f - spread && dx < -0.01f - spread) ||
                         (dx > 0.01f + spread && dx < 0.1f + spread);
                }
                if (!in)
                    continue;
                y[r * w + c] = (uint8_t)(50 + (c * 5 + r * 3) % 7);
                u[(r / 2) * (w / 2) + c / 2] = f < 0.55f ? 90 : 150;
                v[(r / 2) * (w / 2) + c / 2] = f < 0.55f ? 200 : 110;
            }
        }
    }
}

static int soak(long n, int pixels, soak_result *res)
{
    const int w = pixels ? 320 : 640, h = pixels ? 240 : 480;
    const float tall = pixels ? 60.0f : 120.0f;
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    if (pixels)
        cfg.source = CT_SOURCE_PIXELS;
    ct_tracker *t = NULL;
    if (ct_tracker_create(&cfg, &t) != CT_OK)
        return -1;
    uint8_t *y = malloc((size_t)w * h * 3 / 2);
    uint8_t *u = y + w * h, *v = u + (w / 2) * (h / 2);
    ct_track out[64];
    uint64_t last_id = 0;
    double seg_s[3] = {0, 0, 0};
    long seg_n[3] = {0, 0, 0};
    for (long i = 0; i < n; i++) {
        ct_frame f;
        ct_frame_default(&f, sizeof f);
        f.width = w;
        f.height = h;
        f.timestamp_us = (int64_t)i * 100000 / 3; /* 30 frames/s */
        ct_detection d[8];
        size_t nd = 0;
        if (pixels) {
            draw(y, u, v, w, h, i, tall);
            set_i420_planes(&f, y, u, v);
        } else {
            for (long k = i / kPeriod - 6; k <= i / kPeriod && nd < 8; k++) {
                if (k < 0)
                    continue;
                const walker p = walker_of(k, w, h, tall);
                const long s = i - p.start;
                if (s < 0 || s >= p.frames || (i * 7 + k) % 13 == 0) /* a miss now and then */
                    continue;
                const float cx = p.x0 + p.speed * (float)s;
                d[nd++] = (ct_detection){cx - tall * 0.2f, p.y, tall * 0.4f, tall, 0.9f, 0};
            }
        }
        const int seg = frame_of(i, n);
        const double t0 = seg >= 0 ? now_s() : 0;
        size_t count = 0;
        if (ct_tracker_feed(t, &f, pixels ? NULL : d, nd) != CT_OK ||
            ct_tracker_get_tracks(t, out, 64, sizeof out[0], &count) != CT_OK) {
            fprintf(stderr, "ct-soak: frame %ld: %s\n", i, ct_tracker_last_error(t));
            return -1;
        }
        if (seg >= 0) {
            seg_s[seg] += now_s() - t0;
            seg_n[seg]++;
            if (i == n / 10 - 1 || i == n / 2 + n / 20 - 1 || i == n - 1)
                res->rss[seg] = rss_kib();
        }
        for (size_t j = 0; j < count; j++)
            if (out[j].id > last_id)
                last_id = out[j].id;
    }
    for (int s = 0; s < 3; s++)
        res->us[s] = seg_n[s] ? 1e6 * seg_s[s] / (double)seg_n[s] : 0;
    res->tracks = last_id;
    free(y);
    ct_tracker_destroy(t);
    return 0;
}

int main(int argc, char **argv)
{
    const long det_frames = argc > 1 ? atol(argv[1]) : 1000000;
    const long pix_frames = argc > 2 ? atol(argv[2]) : 100000;
    const long margin = argc > 3 ? atol(argv[3]) : 2048;
    if (det_frames < 100 || pix_frames < 100 || margin < 0) {
        fprintf(stderr, "usage: ct-soak [DETECTION_FRAMES [PIXEL_FRAMES [MARGIN_KIB]]] "
                        "(frames at least 100)\n");
        return 2;
    }
    int failed = 0;
    printf("| run | frames | tracks started | RSS start / middle / end (KiB) | "
           "us a frame, start / middle / end |\n|---|---|---|---|---|\n");
    for (int pixels = 0; pixels < 2; pixels++) {
        soak_result r;
        memset(&r, 0, sizeof r);
        const long n = pixels ? pix_frames : det_frames;
        if (soak(n, pixels, &r) < 0)
            return 1;
        printf("| %s | %ld | %llu | %ld / %ld / %ld | %.1f / %.1f / %.1f |\n",
               pixels ? "pixels only, 320x240" : "detections only, 640x480", n,
               (unsigned long long)r.tracks, r.rss[0], r.rss[1], r.rss[2], r.us[0], r.us[1],
               r.us[2]);
        if (r.rss[2] > r.rss[1] + margin) {
            fprintf(stderr, "ct-soak: %s: RSS grew by %ld KiB from the middle to the end "
                            "(margin %ld)\n",
                    pixels ? "pixels" : "detections", r.rss[2] - r.rss[1], margin);
            failed = 1;
        }
        if (r.tracks < (uint64_t)(n / kPeriod / 4)) {
            fprintf(stderr, "ct-soak: %s: only %llu tracks for %ld people\n",
                    pixels ? "pixels" : "detections", (unsigned long long)r.tracks, n / kPeriod);
            failed = 1;
        }
    }
    return failed;
}
