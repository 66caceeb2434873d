/* ct-track --overlay: writes the frames with each track's box, id and a
 * short trail of its barycenter drawn on them, as I420 Y4M. */
#ifndef CT_TOOLS_OVERLAY_H
#define CT_TOOLS_OVERLAY_H

#include <stddef.h>

#include "ctrack/ctrack.h"

typedef struct overlay_writer overlay_writer;

/* Opens `path` ("-" for standard output) for frames of w x h at the rate
 * num/den. Returns NULL with a message in err. */
overlay_writer *overlay_open(const char *path, int w, int h, int rate_num, int rate_den,
                            char *err, size_t err_len);

/* Writes one frame: `frame`'s pixels (or mid grey when it has none) with the
 * candidates (nc of them, may be 0) and the tracks drawn: each candidate a
 * thin box, white when the contour template takes it for a pedestrian (score
 * above 0.5), red when not, with its score in percent. Returns 0, or -1 with
 * a message in err. */
int overlay_write(overlay_writer *ov, const ct_frame *frame, const ct_track *tracks, size_t n,
                     const ct_candidate *cands, size_t nc, char *err, size_t err_len);

/* Draws `size` (the people's size the tracker learnt, or NULL for none) on
 * the frames written from now on: at a few rows, the box of a person whose
 * feet are on that row, on the image's left and right edges. */
void overlay_set_person_size(overlay_writer *ov, const ct_person_size *size);

/* Draws counting lines (from ends[i][0] to ends[i][1]) and zones (the
 * corners points[i][0..n[i]-1]) on the frames written from now on, with
 * the counts in lc and zc (indexed alike; read at each write, so the
 * caller keeps them current): a line in orange with its "in" count on its
 * right-hand side and its "out" count on its left, a zone's edges in cyan
 * with the people in it now at its centre. */
void overlay_set_counting(overlay_writer *ov, const ct_point (*ends)[2], const ct_line_count *lc,
                          int nl, const ct_point (*points)[CT_ZONE_MAX_POINTS], const int *n,
                          const ct_zone_count *zc, int nz);

/* Closes the file; returns -1 with a message if a write failed. */
int overlay_close(overlay_writer *ov, char *err, size_t err_len);

#endif
