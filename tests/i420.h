/* An I420 frame's planes, rows packed (strides w, w / 2 and w / 2): the
 * tests' frames (common.h, test_i420()) and the soak run's (bench/ct-soak.c)
 * point a frame at them alike. */
#ifndef CT_TESTS_I420_H
#define CT_TESTS_I420_H

#include <stdint.h>

#include "ctrack/ctrack.h"

/* f's width must be set: the strides follow it. */
static inline void set_i420_planes(ct_frame *f, const uint8_t *y, const uint8_t *u,
                                   const uint8_t *v)
{
    f->format = CT_FORMAT_I420;
    f->planes[0] = y;
    f->planes[1] = u;
    f->planes[2] = v;
    f->strides[0] = f->width;
    f->strides[1] = f->strides[2] = f->width / 2;
}

#endif
