/* MOTChallenge text output: the tracks ct-track writes, and its
 * --candidates lines. */
#ifndef CT_TOOLS_MOT_H
#define CT_TOOLS_MOT_H

#include <stddef.h>
#include <stdio.h>

#include "ctrack/ctrack.h"

/* One line a track: frame,id,left,top,width,height,confidence,-1,-1,-1
 * (frames from 1). */
void mot_write_tracks(FILE *out, long long frame, const ct_track *tracks, size_t n);

/* The --candidates file: a header line naming the columns, then one line a
 * candidate: frame, box, score, yes votes, voters, eq. (1)'s distance per
 * region, fill and top width. */
void mot_write_candidates_header(FILE *out);
void mot_write_candidates(FILE *out, long long frame, const ct_candidate *cands, size_t n);

#endif
