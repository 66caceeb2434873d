/* A complete host without a person detector: reads raw I420 frames (as a
 * camera hands them over) on standard input, lets ctrack find the people in
 * the pixels alone, and prints the tracks of each frame as ct-track does
 * (frame,id,left,top,width,height,confidence,-1,-1,-1). It tracks the
 * frames as they come, as ct-track --prime 0 does: a recording can be
 * primed first (ct_tracker_prime() on its first seconds; docs/API.md).
 *
 *   cc track_frames.c $(pkg-config --cflags --libs ctrack) -lm -o track_frames
 *   ffmpeg -i clip.mp4 -f rawvideo -pix_fmt yuv420p - | ./track_frames 640 480 25
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <ctrack/ctrack.h>

int main(int argc, char **argv)
{
    const int w = argc == 4 ? atoi(argv[1]) : 0, h = argc == 4 ? atoi(argv[2]) : 0;
    const double fps = argc == 4 ? atof(argv[3]) : 0;
    if (w <= 0 || h <= 0 || !(fps > 0)) {
        fprintf(stderr, "usage: %s WIDTH HEIGHT FPS < frames.i420\n", argv[0]);
        return 2;
    }
    /* One I420 frame: Y, then U and V at half the size, rounded up. */
    const size_t cw = ((size_t)w + 1) / 2, ch = ((size_t)h + 1) / 2;
    const size_t luma = (size_t)w * h, size = luma + 2 * cw * ch;

    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    cfg.source = CT_SOURCE_PIXELS; /* no detections: the pixels alone */
    ct_tracker *tr;
    int st = ct_tracker_create(&cfg, &tr);
    if (st != CT_OK) {
        fprintf(stderr, "ctrack: %s\n", ct_status_str(st));
        return 1;
    }
    uint8_t *buf = malloc(size);
    size_t cap = 64;
    ct_track *tracks = malloc(cap * sizeof *tracks);
    int rc = 0;
    if (!buf || !tracks) {
        fprintf(stderr, "out of memory\n");
        rc = 1;
        goto out;
    }

    size_t got;
    for (long long k = 1; (got = fread(buf, 1, size, stdin)) == size; k++) {
        ct_frame f;
        ct_frame_default(&f, sizeof f);
        f.format = CT_FORMAT_I420;
        f.width = w;
        f.height = h;
        f.planes[0] = buf;
        f.planes[1] = buf + luma;
        f.planes[2] = buf + luma + cw * ch;
        f.strides[0] = w;
        f.strides[1] = f.strides[2] = (int32_t)cw;
        f.timestamp_us = (int64_t)llround((double)(k - 1) * 1e6 / fps);
        st = ct_tracker_feed(tr, &f, NULL, 0);
        if (st != CT_OK) {
            fprintf(stderr, "frame %lld: %s: %s\n", k, ct_status_str(st),
                    ct_tracker_last_error(tr));
            rc = 1;
            goto out;
        }
        size_t count;
        st = ct_tracker_get_tracks(tr, tracks, cap, sizeof *tracks, &count);
        if (st == CT_ERROR_BUFFER_TOO_SMALL) { /* count says how many there are */
            ct_track *more = realloc(tracks, count * sizeof *more);
            if (!more) {
                fprintf(stderr, "out of memory\n");
                rc = 1;
                goto out;
            }
            tracks = more;
            cap = count;
            st = ct_tracker_get_tracks(tr, tracks, cap, sizeof *tracks, &count);
        }
        if (st != CT_OK) {
            fprintf(stderr, "frame %lld: %s\n", k, ct_tracker_last_error(tr));
            rc = 1;
            goto out;
        }
        for (size_t i = 0; i < count; i++)
            printf("%lld,%llu,%.2f,%.2f,%.2f,%.2f,%.3f,-1,-1,-1\n", k,
                   (unsigned long long)tracks[i].id, tracks[i].left, tracks[i].top,
                   tracks[i].width, tracks[i].height, tracks[i].confidence);
    }
    if (ferror(stdin)) {
        perror("standard input");
        rc = 1;
    } else if (got > 0) {
        fprintf(stderr, "the last frame is cut short (%zu of %zu bytes): not tracked\n", got,
                size);
        rc = 1;
    }
out:
    free(tracks);
    free(buf);
    ct_tracker_destroy(tr);
    return rc;
}
