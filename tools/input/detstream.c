#define _POSIX_C_SOURCE 200809L
#include "detstream.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "detfile.h"

struct det_stream {
    FILE *f;
    int owns_file;
    const char *path;
    char *line;
    size_t line_cap, lineno;
    /* The frame being gathered and its detections. */
    ct_detection *dets;
    size_t n, cap;
    /* A line read past the frame asked for: a later frame's detection, or
     * a marker (has_det 0). */
    int has_pending, pending_has_det;
    long long pending_frame;
    ct_detection pending_det;
    long long last_frame; /* the highest frame a line named */
    int ended;
};

int detstream_is_stream(const char *path)
{
    struct stat st;
    if (!strcmp(path, "-"))
        return 1;
    return stat(path, &st) == 0 && (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode) ||
                                    S_ISSOCK(st.st_mode));
}

int detstream_open(const char *path, det_stream **out, char *err, size_t err_len)
{
    *out = NULL;
    det_stream *ds = calloc(1, sizeof *ds);
    if (!ds) {
        snprintf(err, err_len, "out of memory");
        return -1;
    }
    ds->path = strcmp(path, "-") ? path : "standard input";
    if (!strcmp(path, "-")) {
        ds->f = stdin;
    } else {
        ds->f = fopen(path, "r");
        ds->owns_file = 1;
        if (!ds->f) {
            snprintf(err, err_len, "cannot open detections '%s': %s", path, strerror(errno));
            free(ds);
            return -1;
        }
    }
    *out = ds;
    return 0;
}

/* A line holding only a whole number: an end-of-frame marker, its frame in
 * *k. */
static int is_marker(const char *line, long long *k)
{
    const char *p = line + strspn(line, " \t");
    char *end;
    errno = 0;
    const long long v = strtoll(p, &end, 10);
    if (end == p || errno || v < 1 || v > DETFILE_MAX_FRAME)
        return 0;
    end += strspn(end, " \t\r");
    if (*end)
        return 0;
    *k = v;
    return 1;
}

static int add(det_stream *ds, const ct_detection *d, char *err, size_t err_len)
{
    if (ds->n == ds->cap) {
        const size_t cap = ds->cap ? 2 * ds->cap : 64;
        ct_detection *grown = realloc(ds->dets, cap * sizeof *grown);
        if (!grown) {
            snprintf(err, err_len, "out of memory reading %s", ds->path);
            return -1;
        }
        ds->dets = grown;
        ds->cap = cap;
    }
    ds->dets[ds->n++] = *d;
    return 0;
}

/* Reads one line into the stream: 1 with it parsed into (*frame, *det,
 * *has_det), 0 at the end, -1 on an error. Blank and comment lines are
 * skipped. */
static int next_line(det_stream *ds, long long *frame, ct_detection *det, int *has_det,
                     char *err, size_t err_len)
{
    for (;;) {
        ssize_t len = getline(&ds->line, &ds->line_cap, ds->f);
        if (len < 0) {
            if (ferror(ds->f)) {
                snprintf(err, err_len, "cannot read detections from %s: %s", ds->path,
                         strerror(errno));
                return -1;
            }
            return 0;
        }
        ds->lineno++;
        while (len > 0 && (ds->line[len - 1] == '\n' || ds->line[len - 1] == '\r'))
            ds->line[--len] = '\0';
        if (is_marker(ds->line, frame)) {
            *has_det = 0;
            return 1;
        }
        int f;
        const int got = detfile_parse_line(ds->line, (size_t)len, ds->path, ds->lineno, &f, det,
                                           err, err_len);
        if (got < 0)
            return -1;
        if (got > 0) {
            *frame = f;
            *has_det = 1;
            return 1;
        }
    }
}

int detstream_frame(det_stream *ds, long long k, const ct_detection **dets, size_t *n,
                    char *err, size_t err_len)
{
    ds->n = 0;
    *dets = NULL;
    *n = 0;
    for (;;) {
        long long frame;
        ct_detection det;
        int has_det;
        if (ds->has_pending) {
            frame = ds->pending_frame;
            det = ds->pending_det;
            has_det = ds->pending_has_det;
            ds->has_pending = 0;
        } else if (ds->ended) {
            break;
        } else {
            const int got = next_line(ds, &frame, &det, &has_det, err, err_len);
            if (got < 0)
                return -1;
            if (got == 0) {
                ds->ended = 1;
                break;
            }
            if (frame < ds->last_frame && has_det) {
                snprintf(err, err_len,
                         "%s:%zu: frame %lld after frame %lld: a stream of detections gives "
                         "its frames in order",
                         ds->path, ds->lineno, frame, ds->last_frame);
                return -1;
            }
            if (frame > ds->last_frame)
                ds->last_frame = frame;
        }
        if (frame < k) /* a late marker, or a line kept from a skipped frame */
            continue;
        if (frame > k || !has_det) {
            /* Frame k is complete: a later frame's line, or its marker. */
            if (frame > k) {
                ds->has_pending = 1;
                ds->pending_frame = frame;
                ds->pending_det = det;
                ds->pending_has_det = has_det;
            }
            *dets = ds->n ? ds->dets : NULL;
            *n = ds->n;
            return 1;
        }
        if (add(ds, &det, err, err_len) < 0)
            return -1;
    }
    /* The end of the stream: frame k exists if a line named it or a later
     * one. */
    if (k > ds->last_frame && ds->n == 0)
        return 0;
    *dets = ds->n ? ds->dets : NULL;
    *n = ds->n;
    return 1;
}

long long detstream_last_frame(const det_stream *ds)
{
    return ds->last_frame;
}

void detstream_close(det_stream *ds)
{
    if (!ds)
        return;
    if (ds->owns_file && ds->f)
        fclose(ds->f);
    free(ds->line);
    free(ds->dets);
    free(ds);
}
