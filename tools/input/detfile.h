/* MOTChallenge detection files: frame,id,left,top,width,height,score,... */
#ifndef CT_TOOLS_DETFILE_H
#define CT_TOOLS_DETFILE_H

#include <stddef.h>

#include "ctrack/ctrack.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct det_file {
    ct_detection *dets; /* sorted by frame, file order within a frame */
    int *frames;        /* 1-based frame of each detection */
    size_t count;
    int max_frame;      /* 0 when the file is empty */
    size_t cursor;      /* next detection for detfile_frame() */
} det_file;

/* Loads a whole file. Returns 0, or -1 with "FILE:LINE: what" in err. */
int detfile_load(const char *path, det_file *out, char *err, size_t err_len);

/* The detections of `frame` (frames must be asked in increasing order). */
const ct_detection *detfile_frame(det_file *df, int frame, size_t *n);

void detfile_free(det_file *df);

#ifdef __cplusplus
}
#endif

#endif
