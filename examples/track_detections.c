/* A complete host: reads MOTChallenge detections (sorted by frame) on
 * standard input and prints the tracks of each frame.
 *
 *   cc track_detections.c $(pkg-config --cflags --libs ctrack) -o track
 *   ./track 7 < det.txt        # the sequence's frame rate
 */
#include <stdio.h>
#include <stdlib.h>

#include <ctrack/ctrack.h>

#define MAX_DETS 1024

static int step(ct_tracker *tr, int frame, double fps, const ct_detection *dets, size_t n)
{
    ct_frame f;
    ct_frame_default(&f, sizeof f); /* no pixels: detections only */
    f.timestamp_us = (int64_t)((frame - 1) * 1e6 / fps);
    int st = ct_tracker_feed(tr, &f, dets, n);
    if (st != CT_OK) {
        fprintf(stderr, "frame %d: %s: %s\n", frame, ct_status_str(st), ct_tracker_last_error(tr));
        return st;
    }
    ct_track tracks[256];
    size_t count;
    st = ct_tracker_get_tracks(tr, tracks, 256, sizeof tracks[0], &count);
    if (st != CT_OK) {
        fprintf(stderr, "frame %d: %s\n", frame, ct_tracker_last_error(tr));
        return st;
    }
    for (size_t i = 0; i < count; i++)
        printf("%d,%llu,%.1f,%.1f,%.1f,%.1f,%.2f,-1,-1,-1\n", frame,
               (unsigned long long)tracks[i].id, tracks[i].left, tracks[i].top,
               tracks[i].width, tracks[i].height, tracks[i].confidence);
    return CT_OK;
}

int main(int argc, char **argv)
{
    double fps = argc > 1 ? atof(argv[1]) : 25;
    if (!(fps > 0)) {
        fprintf(stderr, "usage: %s [FPS] < det.txt\n", argv[0]);
        return 2;
    }
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    ct_tracker *tr;
    if (ct_tracker_create(&cfg, &tr) != CT_OK) {
        char why[256];
        ct_config_check(&cfg, why, sizeof why);
        fprintf(stderr, "ctrack: %s\n", why);
        return 1;
    }
    static ct_detection dets[MAX_DETS];
    size_t n = 0;
    int frame = 1, f, rc = 0;
    float l, t, w, h, s;
    char line[512];
    while (fgets(line, sizeof line, stdin)) {
        if (sscanf(line, "%d,%*f,%f,%f,%f,%f,%f", &f, &l, &t, &w, &h, &s) != 6)
            continue;
        while (frame < f) { /* frames with no line have no detections */
            if (step(tr, frame++, fps, dets, n) != CT_OK) {
                rc = 1;
                goto out;
            }
            n = 0;
        }
        if (n < MAX_DETS)
            dets[n++] = (ct_detection){l, t, w, h, s, 0};
    }
    if (n > 0 && step(tr, frame, fps, dets, n) != CT_OK)
        rc = 1;
out:
    ct_tracker_destroy(tr);
    return rc;
}
