/* Boxes fitted to the silhouette (ct_config.refine_boxes), on synthetic
 * frames with a detector's boxes: a box cut at the chest, where the coat is
 * the colour of the ground, grows to the feet; a box 30% too wide is
 * narrowed, one that runs past the feet ends near them, one that starts
 * far above the head ends at it (and at the feet, cut to one person and
 * fitted again), a short person under someone's head behind keeps their
 * own height, a person in front of another is fitted from the rows
 * below the other's box and one behind from their head above it, a faint
 * person's box is narrowed as the detector's others were, one too loose
 * to read is read again so narrowed, and one still too faint (a person
 * behind a sign) is placed from the head; on a camera that pans, the
 * boxes are as without the fit. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "common.h"

#define W 320
#define H 240
#define SEC 1000000LL
#define STEP (SEC / 25)

typedef struct {
    double x, feet, height, speed; /* centre, feet row, pixels; pixels a frame */
    int enter;                     /* the frame it comes in */
    bool coat_like_ground;         /* from 0.4 to 0.75 of its height */
    double box_cut;                /* the detector's box covers this share of its height */
    double box_wide;               /* ... and this times its width */
    double box_shift;              /* ... moved this many widths to the right */
    double box_above;              /* ... and starts this share of its height above its head */
    bool faint;                    /* only its head and feet differ from the ground */
    int above_from;                /* box_above holds from this frame on */
    bool undetected;               /* the detector gives no box for it */
    int hidden_from;               /* from this frame on (if not 0), hidden below its shoulders */
    double box_up;                 /* ... and its box moved up this share of its height */
    int below_from;                /* from this frame on (if not 0), its box runs on below */
    double box_below;              /* ... its feet by this share of its height */
} person;

/* A street: slabs of irregular widths and greys, a kerb, grain. */
static uint8_t ground(int x, int y, int pan)
{
    x += pan;
    const unsigned slab = (unsigned)(x >= 0 ? x : -x) / 11, row = (unsigned)y / 9;
    const unsigned grey = (slab * 2654435761u ^ row * 40503u) >> 26; /* 0 to 63 */
    return (uint8_t)(80 + grey + (y > 120 ? 20 : 0) + ((x * 7 + y * 3) & 3));
}

/* Whether (x, y) is on p; *coat when on its coat. */
static bool on_person(const person *p, double cx, double x, double y, bool *coat)
{
    const double h = p->height, top = p->feet - h, dy = y - top, dx = x - cx;
    *coat = false;
    if (dy < 0 || dy > h)
        return false;
    const double head = 0.06 * h;
    if (dy < 2 * head)
        return dx * dx + (dy - head) * (dy - head) < head * head;
    if (dy < 0.75 * h) {
        *coat = dy > 0.4 * h;
        return fabs(dx) < (dy < 0.2 * h ? 0.11 : 0.14) * h;
    }
    return fabs(dx - 0.04 * h) < 0.045 * h || fabs(dx + 0.04 * h) < 0.045 * h;
}

/* The person's silhouette width (its torso): what a true box is about. */
static double width_of(const person *p) { return 0.3 * p->height; }

static double centre_at(const person *p, int k) { return p->x + p->speed * (k - p->enter); }

/* Frame k: the ground panned by `pan` pixels a frame, the people in view;
 * their detections (true boxes, cut or widened as each says) into d. */
static size_t render(const person *ps, int n, int k, int pan, uint8_t *y, uint8_t *u, uint8_t *v,
                     ct_detection *d)
{
    for (int r = 0; r < H; r++)
        for (int c = 0; c < W; c++)
            y[r * W + c] = ground(c, r, pan * k);
    for (int i = 0; i < W / 2 * H / 2; i++)
        u[i] = v[i] = 128;
    size_t nd = 0;
    for (int i = 0; i < n; i++) {
        const person *p = &ps[i];
        if (k < p->enter)
            continue;
        const double cx = centre_at(p, k);
        for (int r = 0; r < H; r++)
            for (int c = 0; c < W; c++) {
                bool coat;
                if (!on_person(p, cx, c + 0.5, r + 0.5, &coat))
                    continue;
                if (coat && p->coat_like_ground)
                    continue;
                const double dy = r + 0.5 - (p->feet - p->height);
                if (p->faint && dy > 0.12 * p->height && dy < 0.85 * p->height)
                    continue;
                if (p->hidden_from && k >= p->hidden_from && dy > 0.35 * p->height)
                    continue;
                y[r * W + c] = (uint8_t)(20 + 8 * i);
                u[(r / 2) * (W / 2) + c / 2] = (uint8_t)(100 + 10 * i);
            }
        if (p->undetected)
            continue;
        const double above = k >= p->above_from ? p->box_above : 0;
        const double bw = width_of(p) * p->box_wide;
        const double below = p->below_from && k >= p->below_from ? p->box_below : 0;
        const double bh = p->height * (p->box_cut + above + below);
        const double up = p->hidden_from && k >= p->hidden_from ? p->box_up : 0;
        d[nd++] = test_det((float)(cx - bw / 2 + p->box_shift * width_of(p)),
                           (float)(p->feet - p->height * (1 + above + up)), (float)bw, (float)bh,
                           0.99f);
    }
    return nd;
}

/* Feeds t frame k of the scene with its detections; its tracks into out
 * (returns their count). */
static size_t feed(ct_tracker *t, const person *ps, int n, int k, int pan, ct_track *out)
{
    static uint8_t y[W * H], u[W * H / 4], v[W * H / 4];
    ct_detection d[16];
    const size_t nd = render(ps, n, k, pan, y, u, v, d);
    ct_frame f = test_i420(k * STEP, W, H, y, u, v);
    ck_assert_msg(ct_tracker_feed(t, &f, d, nd) == CT_OK, "%s", ct_tracker_last_error(t));
    size_t count = 0;
    ck_assert_int_eq(ct_tracker_get_tracks(t, out, 16, sizeof *out, &count), CT_OK);
    return count;
}

/* Runs the scene for `frames` frames with detections and pixels, the fit on
 * or off; the last step's tracks into out (returns their count). */
static size_t run(const person *ps, int n, int frames, int pan, int refine, ct_track *out)
{
    ct_config cfg = test_config();
    cfg.refine_boxes = refine;
    ct_tracker *t = test_tracker(&cfg);
    size_t count = 0;
    for (int k = 0; k < frames; k++)
        count = feed(t, ps, n, k, pan, out);
    ct_tracker_destroy(t);
    return count;
}

/* The track whose box centre is nearest x. */
static const ct_track *near_x(const ct_track *tr, size_t n, double x)
{
    const ct_track *best = NULL;
    for (size_t i = 0; i < n; i++)
        if (!best || fabs(tr[i].left + tr[i].width / 2 - x) <
                         fabs(best->left + best->width / 2 - x))
            best = &tr[i];
    ck_assert_ptr_nonnull(best);
    return best;
}

/* Of the tracks whose box centre is within 10 pixels of x, the one whose
 * box starts highest in the image (of two people one behind the other,
 * the one behind). */
static const ct_track *highest_near_x(const ct_track *tr, size_t n, double x)
{
    const ct_track *best = NULL;
    for (size_t i = 0; i < n; i++)
        if (fabs(tr[i].left + tr[i].width / 2 - x) < 10 && (!best || tr[i].top < best->top))
            best = &tr[i];
    ck_assert_ptr_nonnull(best);
    return best;
}

/* The crowd below and the person under test, the last of ps, run for 90
 * frames on a still camera with the fit and without: the last frame's
 * track nearest that person's centre in each. */
typedef struct {
    person ps[8];
    int n;
    ct_track on[16], off[16];
    const ct_track *fit, *raw;
} scene;

static void fit_and_not(scene *s)
{
    const size_t a = run(s->ps, s->n, 90, 0, 1, s->on), b = run(s->ps, s->n, 90, 0, 0, s->off);
    const double x = centre_at(&s->ps[s->n - 1], 89);
    s->fit = near_x(s->on, a, x);
    s->raw = near_x(s->off, b, x);
}

/* People at several depths in the left half who teach the tracker their
 * size (true boxes), walking slowly; the one under test comes in on the
 * right, alone. */
static int crowd(person *ps)
{
    const double feet[] = {150, 180, 210, 235};
    for (int i = 0; i < 4; i++) {
        ps[i] = (person){.x = 12 + 42 * i, .feet = feet[i], .height = 0.7 * feet[i] - 40,
                         .speed = 0.2, .enter = 0, .box_cut = 1, .box_wide = 1};
    }
    return 4;
}

/* The person under test: in on the right, walking left, alone; it enters
 * at frame `enter`, and its detector box is cut to `cut` of its height and
 * `wide` times its width. */
static person newcomer(int enter, double cut, double wide)
{
    return (person){.x = 250, .feet = 200, .height = 0.7 * 200 - 40, .speed = -0.8,
                    .enter = enter, .box_cut = cut, .box_wide = wide};
}

/* s set to the crowd and p after it; returns p's place, to be changed
 * before fit_and_not(). */
static person *crowd_and(scene *s, person p)
{
    s->n = crowd(s->ps);
    s->ps[s->n] = p;
    return &s->ps[s->n++];
}

/* Box b runs from p's head to its feet, to within 0.08 of its height. */
static void assert_head_to_feet(const ct_track *b, const person *p)
{
    const double tall = p->height, feet = p->feet;
    ck_assert_msg(fabs(b->top - (feet - tall)) < 0.08 * tall, "top %g, person's %g", b->top,
                  feet - tall);
    ck_assert_msg(fabs(b->top + b->height - feet) < 0.08 * tall, "feet %g, person's %g",
                  b->top + b->height, feet);
}

/* p's box a fifth of its width to the right: unfitted, more than 0.15 of
 * its width off its centre; fitted, under half as far. */
static void assert_moved_back(const scene *s, const person *p)
{
    const double x = centre_at(p, 89), w = width_of(p);
    const double raw_off = s->raw->left + s->raw->width / 2 - x;
    const double fit_off = s->fit->left + s->fit->width / 2 - x;
    ck_assert_msg(raw_off > 0.15 * w, "unfitted %g off", raw_off);
    ck_assert_msg(fabs(fit_off) < 0.5 * raw_off, "fitted %g off, unfitted %g", fit_off, raw_off);
}

START_TEST(cut_at_the_chest_grows_to_the_feet)
{
    scene s;
    /* In from frame 60, its coat the ground's colour, its box cut there. */
    person *p = crowd_and(&s, newcomer(60, 0.45, 1));
    p->coat_like_ground = true;
    fit_and_not(&s);
    const double tall = p->height;
    /* Unfitted: the cut box. Fitted: head to feet. */
    ck_assert_float_le(s.raw->height, 0.6 * tall);
    ck_assert_msg(fabs(s.fit->height - tall) < 0.15 * tall, "fitted height %g, person %g",
                  s.fit->height, tall);
    ck_assert_msg(fabs(s.fit->top - (p->feet - tall)) < 0.1 * tall, "top %g", s.fit->top);
}
END_TEST

START_TEST(too_wide_is_narrowed)
{
    scene s;
    const person *p = crowd_and(&s, newcomer(60, 1, 1.3));
    fit_and_not(&s);
    const double w = width_of(p);
    ck_assert_float_ge(s.raw->width, 1.25 * w);
    ck_assert_msg(s.fit->width <= 1.15 * w && s.fit->width >= 0.7 * w,
                  "fitted width %g, person %g", s.fit->width, w);
}
END_TEST

START_TEST(past_the_feet_ends_at_the_feet)
{
    /* A detector's box that runs a fifth of the person's height past the
     * feet ends near them: a line the feet have not reached is not
     * crossed. The box's top stays at the head. */
    scene s;
    const person *p = crowd_and(&s, newcomer(60, 1.2, 1));
    fit_and_not(&s);
    ck_assert_float_ge(s.raw->top + s.raw->height, p->feet + 0.15 * p->height);
    assert_head_to_feet(s.fit, p);
}
END_TEST

START_TEST(a_box_taller_than_a_person_ends_at_the_head)
{
    /* A detector's box that starts a third of the person's height above
     * their head (the head of someone behind, joined to theirs in one box,
     * or a loose top) is more than one person whose feet are at its bottom:
     * fitted, it is that person, head to feet; without the fit it stays. */
    scene s;
    person *p = crowd_and(&s, newcomer(60, 1, 1));
    p->box_above = 0.35;
    fit_and_not(&s);
    ck_assert_float_le(s.raw->top, p->feet - 1.25 * p->height);
    assert_head_to_feet(s.fit, p);
}
END_TEST

START_TEST(a_box_cut_to_one_person_is_fitted_again)
{
    /* A detector's box from a third of the person's height above their
     * head to an eighth of it past their feet: cut to one person from its
     * bottom row up, it would end that eighth below the feet and start as
     * far below the head. The cut box is fitted as one person's: head to
     * feet. */
    scene s;
    person *p = crowd_and(&s, newcomer(60, 1.12, 1));
    p->box_above = 0.35;
    fit_and_not(&s);
    ck_assert_float_ge(s.raw->top + s.raw->height, p->feet + 0.1 * p->height);
    assert_head_to_feet(s.fit, p);
}
END_TEST

START_TEST(a_short_person_keeps_their_own_height)
{
    /* A person 0.85 of the people's size at their feet walks alone, then
     * with someone's head and shoulders joined above theirs (someone
     * behind, whom the detector does not see), their detector box starting
     * in that head. The joined silhouette is more than one person tall,
     * and its feet are the box's bottom: the box moves toward the height of
     * a person standing there, and that is this person's own, read while
     * they walked alone, not the people's. The crowd's line is flatter here
     * than crowd()'s, so that a short person's box is not taken for one cut
     * at the chest. */
    scene s;
    const double feet[] = {150, 180, 195, 205, 235};
    for (s.n = 0; s.n < 5; s.n++)
        s.ps[s.n] = (person){.x = 12 + 25 * s.n, .feet = feet[s.n],
                             .height = 0.3 * feet[s.n] + 40, .speed = 0.2, .box_cut = 1,
                             .box_wide = 1};
    person *p = &s.ps[s.n++];
    *p = newcomer(10, 1, 1);
    p->height = 0.85 * (0.3 * p->feet + 40);
    p->box_above = 0.3;
    p->above_from = 60;
    const double top = p->feet - p->height;
    s.ps[s.n++] = (person){.x = centre_at(p, 60), .feet = top + 10,
                           .height = 0.3 * (top + 10) + 40, .speed = p->speed, .enter = 60,
                           .box_cut = 1, .box_wide = 1, .undetected = true};
    const size_t a = run(s.ps, s.n, 90, 0, 1, s.on);
    const ct_track *b = near_x(s.on, a, centre_at(p, 89));
    ck_assert_msg(fabs(b->top + b->height - p->feet) < 0.08 * p->height, "feet %g, person's %g",
                  b->top + b->height, p->feet);
    /* Drawn 0.7 of the way from the box's 1.3 heights toward 0.91 of the
     * people's size (the silhouette's share of it, as the fit read it):
     * 1.13 heights; toward the people's, it would be 1.21. */
    ck_assert_msg(b->height < 1.16 * p->height, "height %g, person's %g", b->height, p->height);
}
END_TEST

START_TEST(a_person_in_front_is_fitted_from_below_the_other)
{
    /* Two people walking together, one behind the other: the box of the
     * one behind covers the top of the front one's, whose detector box
     * sits a fifth of their width to the right and runs an eighth of their
     * height past their feet. The rows below the other box are the front
     * person's alone: the fit moves the box most of the way back across,
     * and to head and feet. Without the fit it stays where it was given. */
    scene s;
    crowd_and(&s, (person){.x = 232, .feet = 180, .height = 0.7 * 180 - 40, .speed = -0.8,
                           .enter = 60, .box_cut = 1, .box_wide = 1.5});
    person *p = &s.ps[s.n++];
    *p = newcomer(60, 1.12, 1);
    p->box_shift = 0.2;
    fit_and_not(&s);
    assert_moved_back(&s, p);
    ck_assert_float_ge(s.raw->top + s.raw->height, p->feet + 0.1 * p->height);
    assert_head_to_feet(s.fit, p);
}
END_TEST

START_TEST(a_faint_person_takes_the_detectors_learnt_width)
{
    /* A detector whose boxes are all 1.4 times too wide. The fit narrows
     * the crowd's and learns it; a person the colour of the ground but for
     * head and feet (too little foreground for a fit) is narrowed as the
     * others were, about the same centre; without the fit, not at all. */
    scene s;
    person *p = crowd_and(&s, newcomer(60, 1, 1.4));
    p->faint = true;
    for (int i = 0; i < s.n - 1; i++)
        s.ps[i].box_wide = 1.4;
    fit_and_not(&s);
    const double w = width_of(p);
    const ct_track *fit = s.fit, *raw = s.raw;
    ck_assert_float_ge(raw->width, 1.35 * w);
    ck_assert_msg(fit->width <= 1.25 * w && fit->width >= 0.8 * w, "width %g, person %g",
                  fit->width, w);
    ck_assert_msg(fabs(fit->left + fit->width / 2 - (raw->left + raw->width / 2)) < 0.1 * w,
                  "centre %g, unfitted %g", fit->left + fit->width / 2,
                  raw->left + raw->width / 2);
}
END_TEST

START_TEST(a_loose_box_is_read_again_at_the_learnt_width)
{
    /* A detector whose boxes are 1.6 times too wide: the fit narrows the
     * crowd's and learns it. The person under test gets a box 3 times
     * their width and a third of their width to their right, so loose
     * that they fill under 30% of it and the fit cannot read it; narrowed
     * as the detector's others were, it is read again there, and ends
     * about as wide as the person and most of the way to their centre.
     * Narrowed alone, it would stay 2.2 times their width, as far off. */
    scene s;
    person *p = crowd_and(&s, newcomer(60, 1, 3));
    p->box_shift = 0.35;
    for (int i = 0; i < s.n - 1; i++)
        s.ps[i].box_wide = 1.6;
    fit_and_not(&s);
    const double x = centre_at(p, 89), w = width_of(p);
    const double raw_off = s.raw->left + s.raw->width / 2 - x;
    const double fit_off = s.fit->left + s.fit->width / 2 - x;
    ck_assert_float_ge(s.raw->width, 2.9 * w);
    ck_assert_msg(s.fit->width <= 1.3 * w && s.fit->width >= 0.7 * w, "width %g, person %g",
                  s.fit->width, w);
    ck_assert_msg(raw_off > 0.3 * w, "unfitted %g off", raw_off);
    ck_assert_msg(fabs(fit_off) < 0.5 * raw_off, "fitted %g off, unfitted %g", fit_off, raw_off);
}
END_TEST

START_TEST(a_moving_camera_is_left_alone)
{
    /* The ground pans 4 pixels a frame: the boxes are as without the fit,
     * to the bit. */
    scene s;
    crowd_and(&s, newcomer(0, 0.45, 1.3));
    const size_t a = run(s.ps, s.n, 90, 4, 1, s.on), b = run(s.ps, s.n, 90, 4, 0, s.off);
    ck_assert_uint_eq(a, b);
    ck_assert_uint_gt(a, 0);
    for (size_t i = 0; i < a; i++) {
        ck_assert_float_eq(s.on[i].left, s.off[i].left);
        ck_assert_float_eq(s.on[i].top, s.off[i].top);
        ck_assert_float_eq(s.on[i].width, s.off[i].width);
        ck_assert_float_eq(s.on[i].height, s.off[i].height);
    }
}
END_TEST

START_TEST(a_box_to_the_side_moves_to_the_person)
{
    /* A detector whose boxes sit a fifth of a person's width to the right:
     * the fit moves them most of the way back; without it they stay. */
    scene s;
    person *p = crowd_and(&s, newcomer(60, 1, 1));
    p->box_shift = 0.2;
    fit_and_not(&s);
    assert_moved_back(&s, p);
}
END_TEST

START_TEST(clipped_boxes_stay_in_the_image)
{
    /* clip_boxes: a fitted box is clipped again, never moved out of the
     * image (a person at its right edge, a detector's box to its side). */
    person ps[6];
    int n = crowd(ps);
    for (int i = 0; i < n; i++) /* the crowd on the right */
        ps[i].x += 150;
    ps[n++] = (person){.x = 14, .feet = 200, .height = 0.7 * 200 - 40, .speed = -0.05,
                       .enter = 0, .box_cut = 1, .box_wide = 1, .box_shift = -0.4};
    ct_config cfg = test_config();
    cfg.clip_boxes = 1;
    ct_tracker *t = test_tracker(&cfg);
    ct_track out[16];
    size_t seen = 0;
    for (int k = 0; k < 90; k++) {
        const size_t count = feed(t, ps, n, k, 0, out);
        for (size_t i = 0; i < count; i++) {
            ck_assert_float_ge(out[i].left, 0);
            ck_assert_float_ge(out[i].top, 0);
            ck_assert_float_le(out[i].left + out[i].width, W + 1e-3);
            ck_assert_float_le(out[i].top + out[i].height, H + 1e-3);
            seen++;
        }
    }
    ck_assert_uint_gt(seen, 200);
    ct_tracker_destroy(t);
}
END_TEST

START_TEST(a_faint_box_is_placed_from_the_head)
{
    /* A person walks alone, seen whole, then behind a sign that hides all
     * below their shoulders, and the detector's box for them sits 0.15 of
     * their height too high. The box is too faint to fit (its foreground
     * under 0.3 of it); fitted, it moves to the head the silhouette still
     * shows and to the height of a person of their stature under it, read
     * while they walked in the open. Without the fit it stays too high. */
    scene s;
    person *p = crowd_and(&s, newcomer(10, 1, 1));
    p->hidden_from = 60;
    p->box_up = 0.15;
    fit_and_not(&s);
    ck_assert_float_le(s.raw->top, p->feet - 1.12 * p->height);
    assert_head_to_feet(s.fit, p);
}
END_TEST

START_TEST(a_person_behind_another_keeps_their_height)
{
    /* A person walks alone, then someone walks in front of them, lower in
     * the image, hiding their legs; the detector's box for the one behind
     * runs on into the legs of the one in front, 0.3 of a height below
     * their feet. The box another covers is not fitted whole; its head,
     * above the other box, and the stature read while they walked alone
     * place it: its top at the head, its bottom 0.7 of the way (the fit's
     * follow) from the detector's to the feet. Without the fit it runs on
     * below. */
    scene s;
    person *p = crowd_and(&s, newcomer(10, 1, 1));
    p->below_from = 60;
    p->box_below = 0.3;
    s.ps[s.n++] = (person){.x = centre_at(p, 45), .feet = 235, .height = 0.7 * 235 - 40,
                           .speed = p->speed, .enter = 45, .box_cut = 1, .box_wide = 1};
    const size_t a = run(s.ps, s.n, 90, 0, 1, s.on), b = run(s.ps, s.n, 90, 0, 0, s.off);
    const double x = centre_at(p, 89);
    /* The two boxes share a centre: the one behind is the one that starts higher. */
    const ct_track *fit = highest_near_x(s.on, a, x), *raw = highest_near_x(s.off, b, x);
    const double raw_off = raw->top + raw->height - p->feet;
    const double fit_off = fit->top + fit->height - p->feet;
    ck_assert_msg(raw_off > 0.2 * p->height, "unfitted bottom %g below the feet", raw_off);
    ck_assert_msg(fabs(fit_off) < 0.5 * raw_off, "fitted bottom %g off, unfitted %g", fit_off,
                  raw_off);
    ck_assert_msg(fabs(fit->top - (p->feet - p->height)) < 0.08 * p->height, "top %g, head %g",
                  fit->top, p->feet - p->height);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("fit");
    TCase *tc = tcase_create("fit");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, cut_at_the_chest_grows_to_the_feet);
    tcase_add_test(tc, too_wide_is_narrowed);
    tcase_add_test(tc, past_the_feet_ends_at_the_feet);
    tcase_add_test(tc, a_box_taller_than_a_person_ends_at_the_head);
    tcase_add_test(tc, a_box_cut_to_one_person_is_fitted_again);
    tcase_add_test(tc, a_short_person_keeps_their_own_height);
    tcase_add_test(tc, a_faint_box_is_placed_from_the_head);
    tcase_add_test(tc, a_person_behind_another_keeps_their_height);
    tcase_add_test(tc, a_person_in_front_is_fitted_from_below_the_other);
    tcase_add_test(tc, a_faint_person_takes_the_detectors_learnt_width);
    tcase_add_test(tc, a_loose_box_is_read_again_at_the_learnt_width);
    tcase_add_test(tc, a_moving_camera_is_left_alone);
    tcase_add_test(tc, a_box_to_the_side_moves_to_the_person);
    tcase_add_test(tc, clipped_boxes_stay_in_the_image);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
