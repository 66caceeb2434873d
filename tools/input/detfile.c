#define _POSIX_C_SOURCE 200809L
#include "detfile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int frame;
    size_t order;
    ct_detection det;
} entry;

static int by_frame(const void *a, const void *b)
{
    const entry *x = a, *y = b;
    if (x->frame != y->frame)
        return x->frame < y->frame ? -1 : 1;
    return x->order < y->order ? -1 : x->order > y->order;
}

/* Parses the comma-separated numbers of one line into v (at most max).
 * Returns how many, or -1 when a field is not a number. */
static int parse_fields(const char *line, double *v, int max)
{
    int n = 0;
    const char *p = line;
    for (;;) {
        while (*p == ' ' || *p == '\t')
            p++;
        char *end;
        errno = 0;
        double x = strtod(p, &end);
        if (end == p || errno == ERANGE)
            return -1;
        if (n < max)
            v[n] = x;
        n++;
        p = end;
        while (*p == ' ' || *p == '\t' || *p == '\r')
            p++;
        if (*p == '\0')
            return n;
        if (*p != ',')
            return -1;
        p++;
    }
}

int detfile_parse_line(const char *line, size_t len, const char *path, size_t lineno,
                       int *frame, ct_detection *det, char *err, size_t err_len)
{
    if (memchr(line, '\0', len)) {
        snprintf(err, err_len, "%s:%zu: a NUL byte in the line (is it a text file?)", path,
                 lineno);
        return -1;
    }
    size_t lead = strspn(line, " \t");
    if (line[lead] == '\0' || line[lead] == '#')
        return 0;
    double v[10];
    int n = parse_fields(line, v, 10);
    if (n < 7) {
        snprintf(err, err_len,
                 "%s:%zu: malformed detection line (want frame,id,left,top,width,height,"
                 "score,...): '%.60s'",
                 path, lineno, line);
        return -1;
    }
    if (!(v[0] >= 1 && v[0] <= DETFILE_MAX_FRAME) || v[0] != floor(v[0])) {
        snprintf(err, err_len, "%s:%zu: frame %.10g is not a whole number in [1, %d]", path,
                 lineno, v[0], DETFILE_MAX_FRAME);
        return -1;
    }
    /* The box and score as the tracker takes them: 32-bit floats. */
    const float box[5] = {(float)v[2], (float)v[3], (float)v[4], (float)v[5], (float)v[6]};
    for (int k = 0; k < 5; k++)
        if (!isfinite(box[k]) || fabsf(box[k]) > 1e6f) {
            snprintf(err, err_len, "%s:%zu: field %d (%g) is not a finite number within +-1e6",
                     path, lineno, k + 3, v[k + 2]);
            return -1;
        }
    if (!(box[2] > 0) || !(box[3] > 0)) {
        snprintf(err, err_len, "%s:%zu: box size %gx%g is not positive (as a 32-bit float)",
                 path, lineno, v[4], v[5]);
        return -1;
    }
    *frame = (int)v[0];
    *det = (ct_detection){box[0], box[1], box[2], box[3], box[4], 0};
    return 1;
}

/* The entries sorted by frame (file order within a frame) into out. */
static int fill(det_file *out, entry *list, size_t count, const char *path, char *err,
                size_t err_len)
{
    if (count) /* qsort's pointer must not be NULL, even for no elements */
        qsort(list, count, sizeof *list, by_frame);
    out->dets = malloc((count ? count : 1) * sizeof *out->dets);
    out->frames = malloc((count ? count : 1) * sizeof *out->frames);
    if (!out->dets || !out->frames) {
        snprintf(err, err_len, "out of memory reading '%s'", path);
        detfile_free(out);
        return -1;
    }
    for (size_t i = 0; i < count; i++) {
        out->dets[i] = list[i].det;
        out->frames[i] = list[i].frame;
    }
    out->count = count;
    out->max_frame = count ? list[count - 1].frame : 0;
    return 0;
}

int detfile_load(const char *path, det_file *out, char *err, size_t err_len)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, err_len, "cannot open detections '%s': %s", path, strerror(errno));
        return -1;
    }
    entry *list = NULL;
    size_t count = 0, cap = 0, lineno = 0;
    char *line = NULL;
    size_t line_cap = 0;
    int rc = -1;
    ssize_t len;
    while ((len = getline(&line, &line_cap, f)) >= 0) {
        lineno++;
        while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r'))
            line[--len] = '\0';
        int frame;
        ct_detection det;
        const int got =
            detfile_parse_line(line, (size_t)len, path, lineno, &frame, &det, err, err_len);
        if (got < 0)
            goto out;
        if (got == 0)
            continue;
        if (count == cap) {
            size_t ncap = cap ? cap * 2 : 1024;
            entry *nl = realloc(list, ncap * sizeof *nl);
            if (!nl) {
                snprintf(err, err_len, "out of memory reading '%s'", path);
                goto out;
            }
            list = nl;
            cap = ncap;
        }
        list[count] = (entry){frame, count, det};
        count++;
    }
    if (ferror(f)) {
        snprintf(err, err_len, "cannot read detections '%s': %s", path, strerror(errno));
        goto out;
    }
    rc = fill(out, list, count, path, err, err_len);
out:
    free(line);
    free(list);
    fclose(f);
    return rc;
}

const ct_detection *detfile_frame(det_file *df, int frame, size_t *n)
{
    while (df->cursor < df->count && df->frames[df->cursor] < frame)
        df->cursor++;
    size_t start = df->cursor;
    while (df->cursor < df->count && df->frames[df->cursor] == frame)
        df->cursor++;
    *n = df->cursor - start;
    return *n ? df->dets + start : NULL;
}

void detfile_free(det_file *df)
{
    free(df->dets);
    free(df->frames);
    memset(df, 0, sizeof *df);
}
