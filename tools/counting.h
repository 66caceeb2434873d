/* ct-track's counting: the lines and zones of --line and --zone, read from
 * the command line and added to a tracker. */
#ifndef CT_TOOLS_COUNTING_H
#define CT_TOOLS_COUNTING_H

#include <stddef.h>

#include "ctrack/ctrack.h"

typedef struct counting_spec {
    int n_lines, n_zones;
    ct_point line_ends[CT_COUNT_MAX_LINES][2];
    char line_names[CT_COUNT_MAX_LINES][CT_NAME_SIZE];
    ct_point zone_points[CT_COUNT_MAX_ZONES][CT_ZONE_MAX_POINTS];
    int zone_n[CT_COUNT_MAX_ZONES];
    char zone_names[CT_COUNT_MAX_ZONES][CT_NAME_SIZE];
    double hysteresis; /* --hysteresis; negative: the library's default */
} counting_spec;

/* Reads "x1,y1,x2,y2[,name]" (--line) or "x1,y1,x2,y2,x3,y3...[,name]"
 * (--zone) into *s. Returns 0, or -1 with a message in msg. */
int counting_parse_line(counting_spec *s, const char *arg, char *msg, size_t len);
int counting_parse_zone(counting_spec *s, const char *arg, char *msg, size_t len);

/* Adds s's lines and zones to the tracker. Returns 0, or -1 with the
 * library's reason, naming the option, in msg. */
int counting_add(const counting_spec *s, ct_tracker *tracker, char *msg, size_t len);

#endif
