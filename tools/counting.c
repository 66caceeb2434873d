#include "counting.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Splits arg at commas into numbers, and a last field that is not a
 * number into name: at most max numbers. Returns how many numbers, or -1
 * with a message. */
static int split(const char *arg, const char *option, double *v, int max, char *name,
                 char *msg, size_t len)
{
    int n = 0;
    name[0] = '\0';
    const char *p = arg;
    for (;;) {
        const char *comma = strchr(p, ',');
        const size_t field = comma ? (size_t)(comma - p) : strlen(p);
        char buf[64], *end;
        snprintf(buf, sizeof buf, "%.*s", (int)(field < sizeof buf - 1 ? field : sizeof buf - 1),
                 p);
        errno = 0;
        const double x = strtod(buf, &end);
        const int number = field > 0 && field < sizeof buf - 1 && end != buf && !*end;
        if (!number) {
            if (comma || n == 0) {
                snprintf(msg, len, "%s '%s': '%.*s' is not a number%s", option, arg,
                         (int)field, p, comma ? "" : " (a name comes last, after the points)");
                return -1;
            }
            if (field >= CT_NAME_SIZE) {
                snprintf(msg, len, "%s '%s': the name has %zu bytes, at most %d", option, arg,
                         field, CT_NAME_SIZE - 1);
                return -1;
            }
            memcpy(name, p, field);
            name[field] = '\0';
            return n;
        }
        if (n == max) {
            snprintf(msg, len, "%s '%s': more than %d numbers", option, arg, max);
            return -1;
        }
        if (!isfinite(x)) {
            snprintf(msg, len, "%s '%s': '%s' is not a finite number", option, arg, buf);
            return -1;
        }
        v[n++] = x;
        if (!comma)
            return n;
        p = comma + 1;
    }
}

int counting_parse_line(counting_spec *s, const char *arg, char *msg, size_t len)
{
    if (s->n_lines == CT_COUNT_MAX_LINES) {
        snprintf(msg, len, "--line: at most %d lines", CT_COUNT_MAX_LINES);
        return -1;
    }
    double v[4];
    const int n = split(arg, "--line", v, 4, s->line_names[s->n_lines], msg, len);
    if (n < 0)
        return -1;
    if (n != 4) {
        snprintf(msg, len, "--line '%s': wants x1,y1,x2,y2[,name] (4 numbers, got %d)", arg, n);
        return -1;
    }
    ct_point *e = s->line_ends[s->n_lines++];
    e[0].x = (float)v[0];
    e[0].y = (float)v[1];
    e[1].x = (float)v[2];
    e[1].y = (float)v[3];
    return 0;
}

int counting_parse_zone(counting_spec *s, const char *arg, char *msg, size_t len)
{
    if (s->n_zones == CT_COUNT_MAX_ZONES) {
        snprintf(msg, len, "--zone: at most %d zones", CT_COUNT_MAX_ZONES);
        return -1;
    }
    double v[2 * CT_ZONE_MAX_POINTS];
    const int n = split(arg, "--zone", v, 2 * CT_ZONE_MAX_POINTS, s->zone_names[s->n_zones],
                        msg, len);
    if (n < 0)
        return -1;
    if (n < 6 || n % 2) {
        snprintf(msg, len,
                 "--zone '%s': wants x1,y1,x2,y2,x3,y3...[,name] (3 to %d corners, got %d "
                 "number%s)",
                 arg, CT_ZONE_MAX_POINTS, n, n == 1 ? "" : "s");
        return -1;
    }
    const int z = s->n_zones++;
    s->zone_n[z] = n / 2;
    for (int k = 0; k < n / 2; k++) {
        s->zone_points[z][k].x = (float)v[2 * k];
        s->zone_points[z][k].y = (float)v[2 * k + 1];
    }
    return 0;
}

int counting_add(const counting_spec *s, ct_tracker *tracker, char *msg, size_t len)
{
    for (int i = 0; i < s->n_lines; i++) {
        ct_line l;
        ct_line_default(&l, sizeof l);
        l.a = s->line_ends[i][0];
        l.b = s->line_ends[i][1];
        l.name = s->line_names[i];
        if (s->hysteresis >= 0)
            l.hysteresis = (float)s->hysteresis;
        if (ct_tracker_add_line(tracker, &l, NULL) != CT_OK) {
            snprintf(msg, len, "--line %d: %s", i + 1, ct_tracker_last_error(tracker));
            return -1;
        }
    }
    for (int i = 0; i < s->n_zones; i++) {
        ct_zone z;
        ct_zone_default(&z, sizeof z);
        z.points = s->zone_points[i];
        z.n_points = s->zone_n[i];
        z.name = s->zone_names[i];
        if (s->hysteresis >= 0)
            z.hysteresis = (float)s->hysteresis;
        if (ct_tracker_add_zone(tracker, &z, NULL) != CT_OK) {
            snprintf(msg, len, "--zone %d: %s", i + 1, ct_tracker_last_error(tracker));
            return -1;
        }
    }
    return 0;
}
