/* ct-track's counting output: --events, one JSON object a line for each
 * crossing, entry and exit; and the counts printed at the end. */
#ifndef CT_TOOLS_EVENTS_H
#define CT_TOOLS_EVENTS_H

#include <stddef.h>
#include <stdio.h>

#include "ctrack/ctrack.h"

/* The events of frame `frame` (from 1) at `time` seconds, named from the
 * lines' and zones' counts (indexed by the events' index):
 *   {"frame": 12, "time": 1.714286, "track": 5, "line": "door",
 *    "kind": "cross", "direction": "in", "x": 320.5, "y": 410.0}
 *   {"frame": 40, ..., "zone": "shop", "kind": "exit", "direction": "out",
 *    "dwell": 3.142857, "ended": false, ...} */
void events_write(FILE *out, long long frame, double time, const ct_event *ev, size_t n,
                  const ct_line_count *lines, const ct_zone_count *zones);

/* One line a line ("door: 12 in, 9 out") and a zone ("shop: 5 entered, 4
 * exited, 1 inside"), each after `prefix`. */
void counts_print(FILE *out, const char *prefix, const ct_line_count *lines, size_t nl,
                  const ct_zone_count *zones, size_t nz);

#endif
