/* A flood of overlapping detections, as a detector without non-maximum
 * suppression gives: the bounded-work test (check_bounds) and the bench
 * (ct-bench --flood) feed it into a tracker holding many live tracks. */
#ifndef CT_TESTS_FLOOD_H
#define CT_TESTS_FLOOD_H

#include <stddef.h>
#include <stdint.h>

#include "ctrack/ctrack.h"

/* The people: `people` boxes of 40 x 80 on a grid 40 wide with 48 x 40
 * pixels between them (each overlaps its neighbours above and below). */
static inline void flood_people(ct_detection *out, int people)
{
    for (int i = 0; i < people; i++) {
        ct_detection d = {(float)(48 * (i % 40)), (float)(40 * (i / 40)), 40.0f, 80.0f, 0.9f, 0};
        out[i] = d;
    }
}

/* n detections scattered over the people's area (fixed seed): each a box of
 * 32 to 48 by 64 to 96 pixels anywhere on it, so that every person's box
 * overlaps dozens, and the gate's graph is one component. */
static inline void flood_boxes(ct_detection *out, size_t n, int people)
{
    uint64_t s = 0x9E3779B97F4A7C15ull;
    const float w = 48.0f * 40, h = 40.0f * (float)((people + 39) / 40) + 40;
    for (size_t i = 0; i < n; i++) {
        float r[4];
        for (int k = 0; k < 4; k++) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            r[k] = (float)(s >> 40) / (float)(1 << 24);
        }
        ct_detection d = {r[0] * w, r[1] * h, 32 + 16 * r[2], 64 + 32 * r[3],
                          0.5f + 0.5f * r[2], 0};
        out[i] = d;
    }
}

#endif
