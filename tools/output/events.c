#include "events.h"

#include <math.h>

/* s as a JSON string. */
static void json_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\')
            fprintf(out, "\\%c", *p);
        else if (*p < 0x20)
            fprintf(out, "\\u%04x", *p);
        else
            fputc(*p, out);
    }
    fputc('"', out);
}

void events_write(FILE *out, long long frame, double time, const ct_event *ev, size_t n,
                  const ct_line_count *lines, const ct_zone_count *zones)
{
    for (size_t i = 0; i < n; i++) {
        const ct_event *e = &ev[i];
        const int line = e->kind == CT_EVENT_LINE_IN || e->kind == CT_EVENT_LINE_OUT;
        const int in = e->kind == CT_EVENT_LINE_IN || e->kind == CT_EVENT_ZONE_ENTER;
        fprintf(out, "{\"frame\": %lld, \"time\": %.6f, \"track\": %llu, \"%s\": ", frame, time,
                (unsigned long long)e->track_id, line ? "line" : "zone");
        json_string(out, line ? lines[e->index].name : zones[e->index].name);
        fprintf(out, ", \"kind\": \"%s\", \"direction\": \"%s\"",
                line ? "cross" : in ? "enter" : "exit", in ? "in" : "out");
        if (e->kind == CT_EVENT_ZONE_EXIT)
            fprintf(out, ", \"dwell\": %.6f, \"ended\": %s", e->dwell,
                    e->ended ? "true" : "false");
        fprintf(out, ", \"x\": %.1f, \"y\": %.1f}\n", e->x, e->y);
    }
}

void counts_print(FILE *out, const char *prefix, const ct_line_count *lines, size_t nl,
                  const ct_zone_count *zones, size_t nz)
{
    for (size_t i = 0; i < nl; i++)
        fprintf(out, "%sline %s: %llu in, %llu out\n", prefix, lines[i].name,
                (unsigned long long)lines[i].in, (unsigned long long)lines[i].out);
    for (size_t i = 0; i < nz; i++)
        fprintf(out, "%szone %s: %llu entered, %llu exited, %d inside\n", prefix,
                zones[i].name, (unsigned long long)zones[i].entered,
                (unsigned long long)zones[i].exited, (int)zones[i].inside);
}
