#define _POSIX_C_SOURCE 200809L
#include "options.h"

#include <errno.h>
#include <float.h>
#include <getopt.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "video.h"

typedef struct {
    const char *name;
    char type; /* 'f' float, 'd' double, 'i' int32 */
    size_t offset;
    const char *help;
} param_def;

static const param_def params[] = {
    {"high_score", 'f', offsetof(ct_config, high_score), "detections at or above are matched first and start tracks"},
    {"low_score", 'f', offsetof(ct_config, low_score), "detections below are ignored"},
    {"match_iou", 'f', offsetof(ct_config, match_iou), "IoU gate, high-score pass"},
    {"low_match_iou", 'f', offsetof(ct_config, low_match_iou), "IoU gate, low-score pass"},
    {"tentative_match_iou", 'f', offsetof(ct_config, tentative_match_iou), "IoU gate for tentative tracks (or within their reach)"},
    {"min_hits", 'i', offsetof(ct_config, min_hits), "matched steps that confirm a track"},
    {"lost_lifetime", 'd', offsetof(ct_config, lost_lifetime), "seconds a lost track is kept"},
    {"report_lost_time", 'd', offsetof(ct_config, report_lost_time), "seconds a lost track is still reported"},
    {"motion_noise", 'f', offsetof(ct_config, motion_noise), "acceleration noise, box heights/s^2"},
    {"detection_noise", 'f', offsetof(ct_config, detection_noise), "detection noise, box heights"},
    {"clip_boxes", 'i', offsetof(ct_config, clip_boxes), "1: clip reported boxes to the image"},
    {"max_tracks", 'i', offsetof(ct_config, max_tracks), "upper bound on live tracks"},
    {"mean_shift", 'i', offsetof(ct_config, mean_shift), "1: follow tracks on the pixels"},
    {"mean_shift_min_similarity", 'f', offsetof(ct_config, mean_shift_min_similarity), "similarity under which a track is lost"},
    {"mean_shift_max_time", 'd', offsetof(ct_config, mean_shift_max_time), "seconds mean shift carries a track"},
    {"model_learning_rate", 'f', offsetof(ct_config, model_learning_rate), "colour model learning rate (eq. 9)"},
    {"mean_shift_coarse_below", 'f', offsetof(ct_config, mean_shift_coarse_below), "coarse to fine under this similarity (0: off)"},
    {"appearance", 'i', offsetof(ct_config, appearance), "1: DDIS appearance templates"},
    {"appearance_weight", 'f', offsetof(ct_config, appearance_weight), "weight of 1 - DDIS in the cost"},
    {"reid_min_similarity", 'f', offsetof(ct_config, reid_min_similarity), "DDIS to re-identify a lost track"},
    {"reid_max_speed", 'f', offsetof(ct_config, reid_max_speed), "re-identification reach, box heights/s"},
    {"candidate_min_score", 'f', offsetof(ct_config, candidate_min_score), "pixels only: vote that starts tracks"},
    {"verify_detections", 'i', offsetof(ct_config, verify_detections), "1: the contour template checks each detection"},
    {"start_score", 'f', offsetof(ct_config, start_score), "detections at or above may start tracks"},
    {"report_lost_sd", 'f', offsetof(ct_config, report_lost_sd), "lost tracks reported only when hidden and this well predicted (0: all)"},
    {"pedestrian_test", 'i', offsetof(ct_config, pedestrian_test), "pixels only: 0 the contour template, 1 size and aspect alone"},
    {"size_gate", 'f', offsetof(ct_config, size_gate), "detections this far (log ratio) from the people's height are ignored (0: none)"},
    {"confirm_score", 'f', offsetof(ct_config, confirm_score), "a track is confirmed once one of its detections scored this"},
    {"refine_boxes", 'i', offsetof(ct_config, refine_boxes), "1: boxes fitted to the silhouette where the pixels are read"},
};

static void print_param_value(FILE *out, const ct_config *cfg, const param_def *p)
{
    const char *base = (const char *)cfg + p->offset;
    switch (p->type) {
    case 'f': fprintf(out, "%g", (double)*(const float *)base); break;
    case 'd': fprintf(out, "%g", *(const double *)base); break;
    default: fprintf(out, "%d", (int)*(const int32_t *)base); break;
    }
}

static void usage(FILE *out)
{
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    ct_line default_line;
    ct_line_default(&default_line, sizeof default_line);
    fprintf(out,
            "usage: ct-track [options] [INPUT]\n"
            "\n"
            "Tracks pedestrians and writes MOTChallenge lines\n"
            "(frame,id,left,top,width,height,conf,-1,-1,-1).\n"
            "\n"
            "INPUT is a Y4M file (recognised by its header), a raw video file (give\n"
            "--size), or '-' for standard input, e.g.\n"
            "  ffmpeg -i clip.mp4 -f yuv4mpegpipe -pix_fmt yuv420p - | ct-track -d det.txt -\n"
            "\n"
            "options:\n"
            "  -d, --detections FILE  MOTChallenge detections (frame,-1,left,top,w,h,score,...),\n"
            "                         frames 1-based. Without INPUT: detections only. Without\n"
            "                         this option ct-track finds people in the pixels itself.\n"
            "                         A FIFO, a pipe or '-' (standard input, when INPUT is a\n"
            "                         file) is read frame by frame as a live detector writes\n"
            "                         it: frame k's detections are complete at a line of a\n"
            "                         later frame, at a line holding only k, or at its end\n"
            "  -s, --size WxH         raw video size; with detections only, the image size\n"
            "  -f, --format FMT       raw video format: i420 (default), nv12, gray\n"
            "  -r, --fps RATE         frame rate (default 25; a Y4M header's rate unless given)\n"
            "      --no-pixels        read the video for its frames but give the tracker\n"
            "                         detections only\n"
            "      --prime SECONDS    a look-ahead for recorded files: where the tracker\n"
            "                         reads a background (without --detections, or\n"
            "                         verify_detections=1), learn it from the video's first\n"
            "                         SECONDS, then track from its first frame, so that\n"
            "                         frame 1's tracks depend on later frames (default 0:\n"
            "                         online, as a camera; %g is a usual length). The\n"
            "                         frames are kept in memory (512 MiB at most)\n"
            "  -o, --output FILE      write tracks to FILE (default: standard output)\n"
            "      --flush            write each frame's tracks as soon as it is tracked (the\n"
            "                         default when the output is a pipe, a FIFO or a terminal)\n"
            "      --overlay FILE     also write the frames as Y4M with boxes, ids and trails\n"
            "                         drawn (grey frames with detections only)\n"
            "      --overlay-candidates  also draw the blobs found in the pixels (or the\n"
            "                         detections, with verify_detections=1) with the\n"
            "                         contour template's score: white a pedestrian, red not\n"
            "      --overlay-size     also draw the people's size as the tracker learns it: a\n"
            "                         person's box at a few rows on both edges of the image,\n"
            "                         and the pixels' working scale at the bottom left\n"
            "      --line X1,Y1,X2,Y2[,NAME]  count the people who cross the segment from\n"
            "                         (X1,Y1) to (X2,Y2) (pixels), each way: in to its right\n"
            "                         as the image shows it (for a line drawn left to right,\n"
            "                         downward), out the other way (repeatable, %d at most)\n"
            "      --zone X1,Y1,X2,Y2,X3,Y3...[,NAME]  count the people who enter and leave\n"
            "                         the polygon with these corners (3 to %d) and those in\n"
            "                         it (repeatable, %d at most). The counts are printed at\n"
            "                         the end, and drawn on the overlay\n"
            "      --events FILE      write each crossing, entry and exit as a JSON line\n"
            "      --hysteresis H     how far past a line, or into or out of a zone, in\n"
            "                         heights of the person's box, the feet must go for a\n"
            "                         crossing, entry or exit to count (default %g)\n"
            "  -p, --param NAME=VALUE set a tracker parameter (repeatable), see below\n"
            "      --progress         print progress on standard error (default when it is\n"
            "                         a terminal)\n"
            "  -q, --quiet            no progress\n"
            "      --stats            print the library's time per stage at the end\n"
            "      --candidates FILE  without --detections: write the blobs found in the\n"
            "                         pixels, their contour-template vote, eq. (1)'s\n"
            "                         distance per region, their fill and top width, one\n"
            "                         line per blob and frame\n"
            "  -h, --help             this help\n"
            "  -V, --version          print the version\n"
            "\n"
            "parameters (defaults):\n",
            CT_PRIME_SECONDS, CT_COUNT_MAX_LINES, CT_ZONE_MAX_POINTS, CT_COUNT_MAX_ZONES,
            (double)default_line.hysteresis);
    for (size_t i = 0; i < sizeof params / sizeof params[0]; i++) {
        fprintf(out, "  %-26s ", params[i].name);
        print_param_value(out, &cfg, &params[i]);
        fprintf(out, "  %s\n", params[i].help);
    }
}

static int set_param(ct_config *cfg, const char *arg)
{
    const char *eq = strchr(arg, '=');
    if (!eq) {
        fprintf(stderr, "ct-track: --param wants NAME=VALUE, got '%s'\n", arg);
        return -1;
    }
    size_t len = (size_t)(eq - arg);
    for (size_t i = 0; i < sizeof params / sizeof params[0]; i++) {
        const param_def *p = &params[i];
        if (strlen(p->name) != len || strncmp(p->name, arg, len) != 0)
            continue;
        char *end;
        errno = 0;
        double v = strtod(eq + 1, &end);
        if (end == eq + 1 || *end || errno || !isfinite(v) ||
            (p->type == 'i' && v != floor(v))) {
            fprintf(stderr, "ct-track: --param %s: '%s' is not a %s\n", p->name, eq + 1,
                    p->type == 'i' ? "whole number" : "number");
            return -1;
        }
        if ((p->type == 'i' && (v < -2147483648.0 || v > 2147483647.0)) ||
            (p->type == 'f' && fabs(v) > FLT_MAX)) {
            fprintf(stderr, "ct-track: --param %s: '%s' is past the field's %s\n", p->name,
                    eq + 1, p->type == 'i' ? "32 bits" : "float");
            return -1;
        }
        char *base = (char *)cfg + p->offset;
        if (p->type == 'f')
            *(float *)base = (float)v;
        else if (p->type == 'd')
            *(double *)base = v;
        else
            *(int32_t *)base = (int32_t)v;
        return 0;
    }
    fprintf(stderr, "ct-track: --param: unknown parameter '%.*s' (see --help)\n", (int)len, arg);
    return -1;
}

/* A number in [lo, hi] that fills the whole of s into *v; -1 when not. */
static int parse_number(const char *s, double lo, double hi, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end == s || *end || !(*v >= lo && *v <= hi) ? -1 : 0;
}

static int parse_size(const char *s, int *w, int *h)
{
    char *end;
    long a = strtol(s, &end, 10);
    if (end == s || (*end != 'x' && *end != 'X'))
        return -1;
    const char *s2 = end + 1;
    long b = strtol(s2, &end, 10);
    if (end == s2 || *end || a < 1 || b < 1 || a > 16384 || b > 16384)
        return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

/* The lines and zones, as the library checks them: on a tracker of their
 * own, before anything is opened. */
static int check_counting(const options *o)
{
    if (o->counting.n_lines + o->counting.n_zones == 0)
        return -1;
    ct_tracker *t = NULL;
    char msg[600];
    if (ct_tracker_create(&o->cfg, &t) != CT_OK) {
        fprintf(stderr, "ct-track: cannot create the tracker\n");
        return EXIT_RUNTIME;
    }
    const int bad = counting_add(&o->counting, t, msg, sizeof msg) < 0;
    ct_tracker_destroy(t);
    if (bad) {
        fprintf(stderr, "ct-track: %s\n", msg);
        return EXIT_USAGE;
    }
    return -1;
}

/* The checks between options, once all are read. */
static int check_combination(options *o)
{
    if (!o->input_path && !o->det_path) {
        usage(stderr);
        return EXIT_USAGE;
    }
    /* Without detections, the tracker finds people in the pixels. */
    if (!o->det_path) {
        if (o->no_pixels) {
            fprintf(stderr, "ct-track: --no-pixels needs --detections: without either, there "
                            "is nothing to track\n");
            return EXIT_USAGE;
        }
        o->cfg.source = CT_SOURCE_PIXELS;
    }
    if ((o->overlay_candidates || o->overlay_size) && !o->overlay_path) {
        fprintf(stderr, "ct-track: --overlay-%s draws on the overlay: give --overlay FILE\n",
                o->overlay_candidates ? "candidates" : "size");
        return EXIT_USAGE;
    }
    if (o->det_path && !strcmp(o->det_path, "-") && o->input_path &&
        !strcmp(o->input_path, "-")) {
        fprintf(stderr, "ct-track: --detections - and the video cannot both be standard "
                        "input; give the detections a FIFO\n");
        return EXIT_USAGE;
    }
    /* One output at most on standard output. */
    const char *first = NULL;
    const char *const paths[] = {o->out_path ? o->out_path : "-", o->overlay_path,
                                 o->events_path};
    const char *const names[] = {"the tracks", "--overlay -", "--events -"};
    for (int i = 0; i < 3; i++) {
        if (!paths[i] || strcmp(paths[i], "-"))
            continue;
        if (first) {
            fprintf(stderr, "ct-track: %s and %s cannot both go to standard output; give "
                            "one a file (-o FILE for the tracks)\n",
                    first, names[i]);
            return EXIT_USAGE;
        }
        first = names[i];
    }
    if (o->events_path && o->counting.n_lines + o->counting.n_zones == 0) {
        fprintf(stderr, "ct-track: --events writes the crossings of --line and the entries "
                        "and exits of --zone: give one\n");
        return EXIT_USAGE;
    }
    char msg[512];
    if (ct_config_check(&o->cfg, msg, sizeof msg) != CT_OK) {
        fprintf(stderr, "ct-track: %s\n", msg);
        return EXIT_USAGE;
    }
    return check_counting(o);
}

enum {
    OPT_NO_PIXELS = 256, OPT_PROGRESS, OPT_OVERLAY, OPT_STATS, OPT_CANDIDATES,
    OPT_OVERLAY_CANDIDATES, OPT_OVERLAY_SIZE, OPT_PRIME, OPT_FLUSH, OPT_LINE, OPT_ZONE,
    OPT_EVENTS, OPT_HYSTERESIS
};
static const struct option longopts[] = {
    {"detections", required_argument, NULL, 'd'},
    {"size", required_argument, NULL, 's'},
    {"format", required_argument, NULL, 'f'},
    {"fps", required_argument, NULL, 'r'},
    {"no-pixels", no_argument, NULL, OPT_NO_PIXELS},
    {"prime", required_argument, NULL, OPT_PRIME},
    {"output", required_argument, NULL, 'o'},
    {"flush", no_argument, NULL, OPT_FLUSH},
    {"overlay", required_argument, NULL, OPT_OVERLAY},
    {"overlay-candidates", no_argument, NULL, OPT_OVERLAY_CANDIDATES},
    {"overlay-size", no_argument, NULL, OPT_OVERLAY_SIZE},
    {"line", required_argument, NULL, OPT_LINE},
    {"zone", required_argument, NULL, OPT_ZONE},
    {"events", required_argument, NULL, OPT_EVENTS},
    {"hysteresis", required_argument, NULL, OPT_HYSTERESIS},
    {"param", required_argument, NULL, 'p'},
    {"progress", no_argument, NULL, OPT_PROGRESS},
    {"stats", no_argument, NULL, OPT_STATS},
    {"candidates", required_argument, NULL, OPT_CANDIDATES},
    {"quiet", no_argument, NULL, 'q'},
    {"help", no_argument, NULL, 'h'},
    {"version", no_argument, NULL, 'V'},
    {NULL, 0, NULL, 0},
};

/* The options whose value is checked: -1 when the value is good, else
 * the exit status after a message. */
static int parse_checked(options *o, int c, const char *arg)
{
    switch (c) {
    case 's':
        if (parse_size(arg, &o->width, &o->height) < 0) {
            fprintf(stderr, "ct-track: --size: '%s' is not WxH with sides in [1, 16384]\n",
                    arg);
            return EXIT_USAGE;
        }
        break;
    case 'f':
        if (!strcmp(arg, "i420")) o->format = CT_FORMAT_I420;
        else if (!strcmp(arg, "nv12")) o->format = CT_FORMAT_NV12;
        else if (!strcmp(arg, "gray")) o->format = CT_FORMAT_GRAY8;
        else {
            fprintf(stderr, "ct-track: --format: '%s' is not i420, nv12 or gray\n", arg);
            return EXIT_USAGE;
        }
        break;
    case 'r':
        if (parse_number(arg, VIDEO_MIN_RATE, VIDEO_MAX_RATE, &o->fps) < 0) {
            fprintf(stderr, "ct-track: --fps: '%s' is not a rate in [%g, %g]\n", arg,
                    VIDEO_MIN_RATE, VIDEO_MAX_RATE);
            return EXIT_USAGE;
        }
        break;
    case OPT_PRIME:
        if (parse_number(arg, 0, 3600, &o->prime) < 0) {
            fprintf(stderr, "ct-track: --prime: '%s' is not a duration in [0, 3600] "
                            "seconds\n", arg);
            return EXIT_USAGE;
        }
        break;
    case OPT_LINE:
    case OPT_ZONE: {
        char msg[512];
        if ((c == OPT_LINE ? counting_parse_line : counting_parse_zone)(
                &o->counting, arg, msg, sizeof msg) < 0) {
            fprintf(stderr, "ct-track: %s\n", msg);
            return EXIT_USAGE;
        }
        break;
    }
    case OPT_HYSTERESIS:
        if (parse_number(arg, 0, 2, &o->counting.hysteresis) < 0) {
            fprintf(stderr, "ct-track: --hysteresis: '%s' is not a number in [0, 2] box "
                            "heights\n", arg);
            return EXIT_USAGE;
        }
        break;
    case 'p':
        if (set_param(&o->cfg, arg) < 0)
            return EXIT_USAGE;
        break;
    }
    return -1;
}

int options_parse(int argc, char **argv, options *o)
{
    memset(o, 0, sizeof *o);
    ct_config_default(&o->cfg, sizeof o->cfg);
    o->progress = isatty(STDERR_FILENO);
    o->format = CT_FORMAT_I420;
    o->prime = 0; /* online unless asked */
    o->counting.hysteresis = -1;

    int c;
    while ((c = getopt_long(argc, argv, "d:s:f:r:o:p:qhV", longopts, NULL)) != -1) {
        switch (c) {
        case 'd': o->det_path = optarg; break;
        case OPT_NO_PIXELS: o->no_pixels = 1; break;
        case 'o': o->out_path = optarg; break;
        case OPT_FLUSH: o->flush = 1; break;
        case OPT_OVERLAY: o->overlay_path = optarg; break;
        case OPT_OVERLAY_CANDIDATES: o->overlay_candidates = 1; break;
        case OPT_OVERLAY_SIZE: o->overlay_size = 1; break;
        case OPT_EVENTS: o->events_path = optarg; break;
        case OPT_PROGRESS: o->progress = 1; break;
        case OPT_STATS: o->stats = 1; break;
        case OPT_CANDIDATES: o->candidates_path = optarg; break;
        case 'q': o->progress = 0; break;
        case 'h': usage(stdout); return 0;
        case 'V': printf("ct-track %s\n", ct_version_string()); return 0;
        case '?': usage(stderr); return EXIT_USAGE;
        default: {
            const int stop = parse_checked(o, c, optarg);
            if (stop >= 0)
                return stop;
        }
        }
    }
    if (argc - optind > 1) {
        fprintf(stderr, "ct-track: one INPUT at most (got %d)\n", argc - optind);
        return EXIT_USAGE;
    }
    o->input_path = optind < argc ? argv[optind] : NULL;
    return check_combination(o);
}
