#define _POSIX_C_SOURCE 200809L
#include "overlay.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TRAIL 24      /* barycenters kept per track */
#define MAX_TRAILS 256

typedef struct {
    uint64_t id;
    int len, head;    /* ring of the last `len` points */
    float x[TRAIL], y[TRAIL];
    long long last_seen;
} trail;

struct overlay_writer {
    FILE *f;
    int owns;
    int w, h, cw, ch;
    uint8_t *y, *u, *v;
    trail trails[MAX_TRAILS];
    long long frame;
    int has_size;
    ct_person_size size;
    /* Counting (overlay_set_counting()): the caller's arrays. */
    const ct_point (*ends)[2];
    const ct_line_count *lc;
    int nl;
    const ct_point (*points)[CT_ZONE_MAX_POINTS];
    const int *n_points;
    const ct_zone_count *zc;
    int nz;
};

/* 12 distinguishable colours as (Y, U, V), BT.601 limited range. */
static const uint8_t palette[12][3] = {
    {81, 90, 240},  {145, 54, 34},  {41, 240, 110}, {210, 16, 146}, {170, 166, 16},
    {106, 202, 222},{162, 44, 142}, {90, 150, 60},  {180, 110, 200},{60, 200, 170},
    {130, 80, 80},  {200, 128, 128},
};

/* A 3x5 font for the digits 0-9, one row a byte (3 low bits). */
static const uint8_t digits[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
};

overlay_writer *overlay_open(const char *path, int w, int h, int rate_num, int rate_den,
                            char *err, size_t err_len)
{
    if (w < 1 || h < 1 || w > 16384 || h > 16384) {
        snprintf(err, err_len, "--overlay needs the image size (give --size WxH)");
        return NULL;
    }
    overlay_writer *ov = calloc(1, sizeof *ov);
    if (!ov) {
        snprintf(err, err_len, "out of memory");
        return NULL;
    }
    ov->w = w;
    ov->h = h;
    ov->cw = (w + 1) / 2;
    ov->ch = (h + 1) / 2;
    ov->y = malloc((size_t)w * h + 2 * (size_t)ov->cw * ov->ch);
    if (!ov->y) {
        snprintf(err, err_len, "out of memory");
        free(ov);
        return NULL;
    }
    ov->u = ov->y + (size_t)w * h;
    ov->v = ov->u + (size_t)ov->cw * ov->ch;
    if (!strcmp(path, "-")) {
        ov->f = stdout;
    } else {
        ov->f = fopen(path, "wb");
        ov->owns = 1;
    }
    if (!ov->f) {
        snprintf(err, err_len, "cannot write overlay '%s': %s", path, strerror(errno));
        free(ov->y);
        free(ov);
        return NULL;
    }
    fprintf(ov->f, "YUV4MPEG2 W%d H%d F%d:%d Ip A1:1 C420jpeg\n", w, h, rate_num, rate_den);
    return ov;
}

static void copy_planes(overlay_writer *ov, const ct_frame *fr)
{
    const int w = ov->w, h = ov->h, cw = ov->cw, ch = ov->ch;
    if (fr->format == CT_FORMAT_NONE) {
        memset(ov->y, 96, (size_t)w * h);
        memset(ov->u, 128, (size_t)cw * ch * 2);
        return;
    }
    for (int r = 0; r < h; r++)
        memcpy(ov->y + (size_t)r * w, fr->planes[0] + (size_t)r * fr->strides[0], w);
    for (int r = 0; r < ch; r++) {
        uint8_t *u = ov->u + (size_t)r * cw, *v = ov->v + (size_t)r * cw;
        if (fr->format == CT_FORMAT_I420) {
            memcpy(u, fr->planes[1] + (size_t)r * fr->strides[1], cw);
            memcpy(v, fr->planes[2] + (size_t)r * fr->strides[2], cw);
        } else if (fr->format == CT_FORMAT_NV12) {
            const uint8_t *uv = fr->planes[1] + (size_t)r * fr->strides[1];
            for (int c = 0; c < cw; c++) {
                u[c] = uv[2 * c];
                v[c] = uv[2 * c + 1];
            }
        } else {
            memset(u, 128, cw);
            memset(v, 128, cw);
        }
    }
}

static void put(overlay_writer *ov, int x, int y, const uint8_t *c)
{
    if (x < 0 || y < 0 || x >= ov->w || y >= ov->h)
        return;
    ov->y[(size_t)y * ov->w + x] = c[0];
    ov->u[(size_t)(y / 2) * ov->cw + x / 2] = c[1];
    ov->v[(size_t)(y / 2) * ov->cw + x / 2] = c[2];
}

static void fill(overlay_writer *ov, int x0, int y0, int x1, int y1, const uint8_t *c)
{
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            put(ov, x, y, c);
}

static void line(overlay_writer *ov, int x0, int y0, int x1, int y1, const uint8_t *c)
{
    int dx = abs(x1 - x0), dy = -abs(y1 - y0);
    int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, e = dx + dy;
    for (int guard = 0; guard < 100000; guard++) {
        fill(ov, x0, y0, x0 + 2, y0 + 2, c);
        if (x0 == x1 && y0 == y1)
            break;
        int e2 = 2 * e;
        if (e2 >= dy) { e += dy; x0 += sx; }
        if (e2 <= dx) { e += dx; y0 += sy; }
    }
}

static const uint8_t white[3] = {235, 128, 128};

/* A number in white digits of `scale` pixels on a box of colour c. */
static void label(overlay_writer *ov, int x, int y, uint64_t id, const uint8_t *c, int scale)
{
    char s[24];
    int n = snprintf(s, sizeof s, "%llu", (unsigned long long)id);
    const int cw = 4 * scale;
    fill(ov, x, y, x + n * cw + scale, y + 7 * scale, c);
    for (int i = 0; i < n; i++)
        for (int r = 0; r < 5; r++)
            for (int b = 0; b < 3; b++)
                if (digits[s[i] - '0'][r] & (4 >> b))
                    fill(ov, x + scale + i * cw + b * scale, y + scale + r * scale,
                         x + scale + i * cw + (b + 1) * scale, y + scale + (r + 1) * scale, white);
}

/* The outline of the box [x0, x1) x [y0, y1), th pixels thick. */
static void frame_box(overlay_writer *ov, int x0, int y0, int x1, int y1, int th, const uint8_t *c)
{
    fill(ov, x0, y0, x1, y0 + th, c);
    fill(ov, x0, y1 - th, x1, y1, c);
    fill(ov, x0, y0, x0 + th, y1, c);
    fill(ov, x1 - th, y0, x1, y1, c);
}

static trail *trail_of(overlay_writer *ov, uint64_t id)
{
    trail *oldest = &ov->trails[0];
    for (int i = 0; i < MAX_TRAILS; i++) {
        trail *t = &ov->trails[i];
        if (t->id == id)
            return t;
        if (t->last_seen < oldest->last_seen)
            oldest = t;
    }
    memset(oldest, 0, sizeof *oldest);
    oldest->id = id;
    return oldest;
}

static int clampi(double v, int lo, int hi)
{
    if (!(v > lo)) return lo;
    if (v > hi) return hi;
    return (int)v;
}

void overlay_set_person_size(overlay_writer *ov, const ct_person_size *size)
{
    ov->has_size = size != NULL;
    if (size)
        ov->size = *size;
}

/* The people's size: at feet rows from a third of the image down, the box
 * of a person standing there, yellow, on both edges; and the working scale
 * of the pixels (frame pixels a working pixel), a yellow number at the
 * bottom left. */
static void draw_person_size(overlay_writer *ov)
{
    static const uint8_t yellow[3] = {210, 16, 146};
    const ct_person_size *s = &ov->size;
    if (s->working_scale > 0 && ov->h > 20)
        label(ov, 2, ov->h - 16, (uint64_t)s->working_scale, yellow, 2);
    if (!s->known)
        return;
    for (int k = 0; k < 4; k++) {
        const double feet = ov->h * (0.4 + 0.18 * k);
        const double tall = s->height_slope * feet + s->height_intercept;
        if (!(tall >= 4) || tall > ov->h)
            continue;
        const int w = clampi(s->width_ratio * tall, 2, ov->w / 4);
        const int y0 = clampi(feet - tall, 0, ov->h), y1 = clampi(feet, 0, ov->h);
        frame_box(ov, 2, y0, 2 + w, y1, 1, yellow);
        frame_box(ov, ov->w - 2 - w, y0, ov->w - 2, y1, 1, yellow);
    }
}

void overlay_set_counting(overlay_writer *ov, const ct_point (*ends)[2], const ct_line_count *lc,
                          int nl, const ct_point (*points)[CT_ZONE_MAX_POINTS], const int *n,
                          const ct_zone_count *zc, int nz)
{
    ov->ends = ends;
    ov->lc = lc;
    ov->nl = nl;
    ov->points = points;
    ov->n_points = n;
    ov->zc = zc;
    ov->nz = nz;
}

static void draw_counting(overlay_writer *ov)
{
    static const uint8_t orange[3] = {151, 42, 201}, green[3] = {112, 72, 58},
                         cyan[3] = {170, 166, 16};
    const int big = ov->h >= 400 ? 2 : 1;
    for (int i = 0; i < ov->nz; i++) {
        const ct_point *p = ov->points[i];
        const int n = ov->n_points[i];
        double cx = 0, cy = 0;
        for (int k = 0; k < n; k++) {
            const ct_point a = p[k], b = p[(k + 1) % n];
            line(ov, clampi(a.x, -1, ov->w), clampi(a.y, -1, ov->h), clampi(b.x, -1, ov->w),
                 clampi(b.y, -1, ov->h), cyan);
            cx += a.x / n;
            cy += a.y / n;
        }
        label(ov, clampi(cx, 0, ov->w - 8), clampi(cy, 0, ov->h - 8),
              (uint64_t)ov->zc[i].inside, cyan, big);
    }
    for (int i = 0; i < ov->nl; i++) {
        const ct_point a = ov->ends[i][0], b = ov->ends[i][1];
        line(ov, clampi(a.x, -1, ov->w), clampi(a.y, -1, ov->h), clampi(b.x, -1, ov->w),
             clampi(b.y, -1, ov->h), orange);
        /* The right-hand side of a -> b, as the image shows it. */
        const double len = hypot(b.x - a.x, b.y - a.y), off = 10 * big;
        const double nx = -(b.y - a.y) / len, ny = (b.x - a.x) / len;
        const double mx = (a.x + b.x) / 2, my = (a.y + b.y) / 2;
        label(ov, clampi(mx + nx * off - 4 * big, 0, ov->w - 8),
              clampi(my + ny * off - 3 * big, 0, ov->h - 8), ov->lc[i].in, green, big);
        label(ov, clampi(mx - nx * off - 8 * big, 0, ov->w - 8),
              clampi(my - ny * off - 4 * big, 0, ov->h - 8), ov->lc[i].out, orange, big);
    }
}

int overlay_write(overlay_writer *ov, const ct_frame *frame, const ct_track *tracks, size_t n,
                     const ct_candidate *cands, size_t nc, char *err, size_t err_len)
{
    ov->frame++;
    copy_planes(ov, frame);
    if (ov->has_size)
        draw_person_size(ov);
    draw_counting(ov);
    static const uint8_t red[3] = {82, 90, 240}, dark[3] = {16, 128, 128};
    for (size_t i = 0; i < nc; i++) {
        const ct_candidate *c = &cands[i];
        const int x0 = clampi(c->left, -4, ov->w + 4), y0 = clampi(c->top, -4, ov->h + 4);
        const int x1 = clampi(c->left + c->width, -4, ov->w + 4);
        const int y1 = clampi(c->top + c->height, -4, ov->h + 4);
        const int pedestrian = c->score > 0.5f;
        frame_box(ov, x0, y0, x1, y1, 1, pedestrian ? white : red);
        label(ov, x0, y1 + 1, (uint64_t)clampi(100.0 * c->score + 0.5, 0, 100),
              pedestrian ? dark : red, 1);
    }
    for (size_t i = 0; i < n; i++) {
        const ct_track *t = &tracks[i];
        const uint8_t *c = palette[t->id % 12];
        trail *tr = trail_of(ov, t->id);
        tr->last_seen = ov->frame;
        tr->x[tr->head] = t->barycenter_x;
        tr->y[tr->head] = t->barycenter_y;
        tr->head = (tr->head + 1) % TRAIL;
        if (tr->len < TRAIL)
            tr->len++;
        for (int k = 1; k < tr->len; k++) {
            int a = (tr->head - k + TRAIL) % TRAIL, b = (tr->head - k - 1 + TRAIL) % TRAIL;
            line(ov, clampi(tr->x[a], -1, ov->w), clampi(tr->y[a], -1, ov->h),
                 clampi(tr->x[b], -1, ov->w), clampi(tr->y[b], -1, ov->h), c);
        }
        int x0 = clampi(t->left, -4, ov->w + 4), y0 = clampi(t->top, -4, ov->h + 4);
        int x1 = clampi(t->left + t->width, -4, ov->w + 4);
        int y1 = clampi(t->top + t->height, -4, ov->h + 4);
        const int th = t->state == CT_TRACK_LOST ? 1 : 2; /* thin while predicted */
        frame_box(ov, x0, y0, x1, y1, th, c);
        label(ov, x0, y0 - 14 >= 0 ? y0 - 14 : y0, t->id, c, 2);
    }
    size_t bytes = (size_t)ov->w * ov->h + 2 * (size_t)ov->cw * ov->ch;
    if (fputs("FRAME\n", ov->f) == EOF || fwrite(ov->y, 1, bytes, ov->f) != bytes) {
        snprintf(err, err_len, "error writing the overlay: %s", strerror(errno));
        return -1;
    }
    return 0;
}

int overlay_close(overlay_writer *ov, char *err, size_t err_len)
{
    if (!ov)
        return 0;
    int rc = 0;
    if (fflush(ov->f) != 0 || ferror(ov->f)) {
        snprintf(err, err_len, "error writing the overlay: %s", strerror(errno));
        rc = -1;
    }
    if (ov->owns && fclose(ov->f) != 0 && rc == 0) {
        snprintf(err, err_len, "error closing the overlay: %s", strerror(errno));
        rc = -1;
    }
    free(ov->y);
    free(ov);
    return rc;
}
