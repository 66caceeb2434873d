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

/* The last frame number a detections file may name: about four days at 30
 * frames/s. A larger one is taken for garbage (with detections only,
 * ct-track would feed that many frames). */
#define DETFILE_MAX_FRAME 10000000

/* Loads a whole file. Every field is checked as the number the tracker
 * takes (boxes and scores as 32-bit floats: finite, sizes positive); a NUL
 * byte, a frame outside [1, DETFILE_MAX_FRAME] or a malformed line is an
 * error. Returns 0, or -1 with "FILE:LINE: what" in err. */
int detfile_load(const char *path, det_file *out, char *err, size_t err_len);

/* Parses one line of a detections file (its end of line stripped): 1 and
 * the detection in *frame and *det, 0 for a blank or comment line, -1 with
 * "FILE:LINE: what" in err. */
int detfile_parse_line(const char *line, size_t len, const char *path, size_t lineno,
                       int *frame, ct_detection *det, char *err, size_t err_len);

/* The detections of `frame` (frames must be asked in increasing order). */
const ct_detection *detfile_frame(det_file *df, int frame, size_t *n);

void detfile_free(det_file *df);

#ifdef __cplusplus
}
#endif

#endif
