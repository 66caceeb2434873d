/* Reading video for ct-track: raw I420 / NV12 / GRAY8 files, Y4M files, and
 * either from standard input ("-"). */
#ifndef CT_TOOLS_VIDEO_H
#define CT_TOOLS_VIDEO_H

#include <stddef.h>
#include <stdint.h>

#include "ctrack/ctrack.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct video_input video_input;

/* The frame rates ct-track takes, from --fps or a Y4M header, in frames
 * per second: slower ones would overflow the timestamps of long videos. */
#define VIDEO_MIN_RATE 0.001
#define VIDEO_MAX_RATE 10000.0

typedef struct video_params {
    /* Raw input only: the size and format (CT_FORMAT_*). Y4M carries its own
     * and these are ignored. */
    int width, height;
    uint32_t format;
} video_params;

typedef struct video_info {
    int width, height;
    uint32_t format;
    /* Frame rate from the Y4M header (0/0 for raw input). */
    int rate_num, rate_den;
    /* Frames in the file when known from its size (regular files; for Y4M
     * the count if no FRAME line carries parameters), else -1. */
    long long frames;
} video_info;

/* Opens `path` ("-" for standard input). Recognises Y4M by its signature.
 * Returns 0, or -1 with a message in err. */
int video_open(const char *path, const video_params *params, video_input **out,
               video_info *info, char *err, size_t err_len);

/* Reads the next frame into *frame (planes point into the reader's buffer,
 * valid until the next read). Returns 1 for a frame, 0 at a clean end, -1 on
 * an error with a message in err (a truncated frame is an error); after an
 * error every read fails with it (after the kept frames, when replaying). */
int video_read(video_input *in, ct_frame *frame, char *err, size_t err_len);

/* Keeps a copy of the next `frames` frames read (from the first), for
 * video_replay(). Returns 0, or -1 with a message in err (too many for
 * memory, or frames already read). */
int video_keep(video_input *in, long long frames, char *err, size_t err_len);

/* From the next read on, the kept frames are read again, then the input
 * goes on where it was. Returns how many frames were kept. */
long long video_replay(video_input *in);

/* Kept frame i (from 0) into *frame, its planes in the reader's memory;
 * returns 1, or 0 when there is no such frame. */
int video_kept(video_input *in, long long i, ct_frame *frame);

void video_close(video_input *in);

/* Bytes of one frame of the given format and size (0 for bad values). */
size_t frame_bytes(uint32_t format, int width, int height);

/* The I420 frame f as packed BGR (BT.601 back from limited range) in out,
 * 3 * width bytes a row: the packed frames of the tests and benchmarks. */
void i420_to_bgr24(const ct_frame *f, uint8_t *out);

#ifdef __cplusplus
}
#endif

#endif
