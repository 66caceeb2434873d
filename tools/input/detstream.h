/* Detections read frame by frame as they arrive, from a FIFO, a pipe or
 * standard input: a live detector's. Frame k's detections are complete when
 * a line of a later frame arrives, when a line holding only the number k
 * arrives (an end-of-frame marker: a frame without detections costs no
 * wait), or at the end of the stream. Lines come in frame order. */
#ifndef CT_TOOLS_DETSTREAM_H
#define CT_TOOLS_DETSTREAM_H

#include <stddef.h>

#include "ctrack/ctrack.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct det_stream det_stream;

/* Whether path names a stream to be read frame by frame ("-", a FIFO, a
 * pipe, a character device) rather than a file read whole. */
int detstream_is_stream(const char *path);

/* Opens path ("-": standard input). Returns 0, or -1 with a message. */
int detstream_open(const char *path, det_stream **out, char *err, size_t err_len);

/* Waits until frame k's detections are complete (frames asked in
 * increasing order) and points *dets at them (*n of them, valid until the
 * next call). Returns 1; 0 when the stream ended before any line of frame k
 * or later (no frame k); -1 with "FILE:LINE: what" in err for a malformed
 * line or one of an earlier frame than a line before it. */
int detstream_frame(det_stream *ds, long long k, const ct_detection **dets, size_t *n,
                    char *err, size_t err_len);

/* The last frame a line named, 0 if none yet. */
long long detstream_last_frame(const det_stream *ds);

void detstream_close(det_stream *ds);

#ifdef __cplusplus
}
#endif

#endif
