/* ct-track: runs ctrack over a video file or standard input and writes
 * MOTChallenge tracks. See `ct-track --help` and docs/ct-track.md. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "ctrack/ctrack.h"
#include "detfile.h"
#include "input.h"
#include "overlay.h"
#include "peakmem.h"

enum { EXIT_RUNTIME = 1, EXIT_USAGE = 2 };

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
    {"tentative_match_iou", 'f', offsetof(ct_config, tentative_match_iou), "IoU gate for tentative tracks"},
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
            "  -s, --size WxH         raw video size; with detections only, the image size\n"
            "  -f, --format FMT       raw video format: i420 (default), nv12, gray\n"
            "  -r, --fps RATE         frame rate (default 25; a Y4M header's rate unless given)\n"
            "      --no-pixels        read the video for its frames but give the tracker\n"
            "                         detections only\n"
            "  -o, --output FILE      write tracks to FILE (default: standard output)\n"
            "      --overlay FILE     also write the frames as Y4M with boxes, ids and trails\n"
            "                         drawn (grey frames with detections only)\n"
            "      --overlay-candidates  also draw the blobs found in the pixels (or the\n"
            "                         detections, with verify_detections=1) with the\n"
            "                         contour template's score: white a pedestrian, red not\n"
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
            "parameters (defaults):\n");
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
            (p->type == 'i' && (v != floor(v) || fabs(v) > 2e9))) {
            fprintf(stderr, "ct-track: --param %s: '%s' is not a %s\n", p->name, eq + 1,
                    p->type == 'i' ? "whole number" : "number");
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

/* The library's own timers: per stage, per frame and, for mean shift, per
 * person. */
static void print_stats(const ct_tracker *tracker)
{
    ct_stats st;
    st.size = sizeof st;
    if (ct_tracker_get_stats(tracker, &st) != CT_OK || st.steps == 0)
        return;
    fprintf(stderr, "ct-track: %llu steps, %.2f us a step in ct_tracker_feed\n",
            (unsigned long long)st.steps, st.feed_ns * 1e-3 / st.steps);
    for (int i = 0; i < CT_STATS_MAX_STAGES; i++)
        if (ct_stage_name(i))
            fprintf(stderr, "ct-track:   %-12s %9.2f us a step\n", ct_stage_name(i),
                    st.stage_ns[i] * 1e-3 / st.steps);
    if (st.mean_shift_runs)
        fprintf(stderr, "ct-track:   mean shift %.2f us per person per step (%llu)\n",
                st.stage_ns[CT_STAGE_MEAN_SHIFT] * 1e-3 / st.mean_shift_runs,
                (unsigned long long)st.mean_shift_runs);
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

int main(int argc, char **argv)
{
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    const char *det_path = NULL, *out_path = NULL, *overlay_path = NULL, *candidates_path = NULL;
    int width = 0, height = 0, no_pixels = 0;
    int progress = isatty(STDERR_FILENO);
    uint32_t format = CT_FORMAT_I420;
    double fps = 0;

    enum {
        OPT_NO_PIXELS = 256, OPT_PROGRESS, OPT_OVERLAY, OPT_STATS, OPT_CANDIDATES,
        OPT_OVERLAY_CANDIDATES
    };
    int stats = 0, overlay_candidates = 0;
    static const struct option longopts[] = {
        {"detections", required_argument, NULL, 'd'},
        {"size", required_argument, NULL, 's'},
        {"format", required_argument, NULL, 'f'},
        {"fps", required_argument, NULL, 'r'},
        {"no-pixels", no_argument, NULL, OPT_NO_PIXELS},
        {"output", required_argument, NULL, 'o'},
        {"overlay", required_argument, NULL, OPT_OVERLAY},
        {"overlay-candidates", no_argument, NULL, OPT_OVERLAY_CANDIDATES},
        {"param", required_argument, NULL, 'p'},
        {"progress", no_argument, NULL, OPT_PROGRESS},
        {"stats", no_argument, NULL, OPT_STATS},
        {"candidates", required_argument, NULL, OPT_CANDIDATES},
        {"quiet", no_argument, NULL, 'q'},
        {"help", no_argument, NULL, 'h'},
        {"version", no_argument, NULL, 'V'},
        {NULL, 0, NULL, 0},
    };
    int c;
    while ((c = getopt_long(argc, argv, "d:s:f:r:o:p:qhV", longopts, NULL)) != -1) {
        switch (c) {
        case 'd': det_path = optarg; break;
        case 's':
            if (parse_size(optarg, &width, &height) < 0) {
                fprintf(stderr, "ct-track: --size: '%s' is not WxH with sides in [1, 16384]\n",
                        optarg);
                return EXIT_USAGE;
            }
            break;
        case 'f':
            if (!strcmp(optarg, "i420")) format = CT_FORMAT_I420;
            else if (!strcmp(optarg, "nv12")) format = CT_FORMAT_NV12;
            else if (!strcmp(optarg, "gray")) format = CT_FORMAT_GRAY8;
            else {
                fprintf(stderr, "ct-track: --format: '%s' is not i420, nv12 or gray\n", optarg);
                return EXIT_USAGE;
            }
            break;
        case 'r': {
            char *end;
            fps = strtod(optarg, &end);
            if (end == optarg || *end || !(fps > 0 && fps <= 10000)) {
                fprintf(stderr, "ct-track: --fps: '%s' is not a rate in (0, 10000]\n", optarg);
                return EXIT_USAGE;
            }
            break;
        }
        case OPT_NO_PIXELS: no_pixels = 1; break;
        case 'o': out_path = optarg; break;
        case OPT_OVERLAY: overlay_path = optarg; break;
        case OPT_OVERLAY_CANDIDATES: overlay_candidates = 1; break;
        case 'p':
            if (set_param(&cfg, optarg) < 0)
                return EXIT_USAGE;
            break;
        case OPT_PROGRESS: progress = 1; break;
        case OPT_STATS: stats = 1; break;
        case OPT_CANDIDATES: candidates_path = optarg; break;
        case 'q': progress = 0; break;
        case 'h': usage(stdout); return 0;
        case 'V': printf("ct-track %s\n", ct_version_string()); return 0;
        default: usage(stderr); return EXIT_USAGE;
        }
    }
    if (argc - optind > 1) {
        fprintf(stderr, "ct-track: one INPUT at most (got %d)\n", argc - optind);
        return EXIT_USAGE;
    }
    const char *input_path = optind < argc ? argv[optind] : NULL;
    if (!input_path && !det_path) {
        usage(stderr);
        return EXIT_USAGE;
    }
    /* Without detections, the tracker finds people in the pixels. */
    if (!det_path) {
        if (no_pixels) {
            fprintf(stderr, "ct-track: --no-pixels needs --detections: without either, there "
                            "is nothing to track\n");
            return EXIT_USAGE;
        }
        cfg.source = CT_SOURCE_PIXELS;
    }

    if (overlay_candidates && !overlay_path) {
        fprintf(stderr, "ct-track: --overlay-candidates draws on the overlay: give --overlay "
                        "FILE\n");
        return EXIT_USAGE;
    }
    if (overlay_path && !strcmp(overlay_path, "-") && (!out_path || !strcmp(out_path, "-"))) {
        fprintf(stderr, "ct-track: --overlay - and the tracks cannot both go to standard "
                        "output; give -o FILE\n");
        return EXIT_USAGE;
    }

    char msg[512];
    if (ct_config_check(&cfg, msg, sizeof msg) != CT_OK) {
        fprintf(stderr, "ct-track: %s\n", msg);
        return EXIT_USAGE;
    }

    int rc = EXIT_RUNTIME;
    ct_detfile df;
    memset(&df, 0, sizeof df);
    ct_input *in = NULL;
    FILE *cand_out = NULL;
    ct_candidate *cands = NULL;
    size_t cands_cap = 0;
    ct_tracker *tracker = NULL;
    ct_overlay *overlay = NULL;
    FILE *out = NULL;
    ct_track *tracks = NULL;
    size_t tracks_cap = 0;
    if (det_path && ct_detfile_load(det_path, &df, msg, sizeof msg) < 0) {
        fprintf(stderr, "ct-track: %s\n", msg);
        return EXIT_RUNTIME;
    }

    ct_input_info info;
    memset(&info, 0, sizeof info);
    long long frames;
    double rate_num = fps > 0 ? fps : 25, rate_den = 1;
    if (input_path) {
        ct_input_params ip = {width, height, format};
        if (ct_input_open(input_path, &ip, &in, &info, msg, sizeof msg) < 0) {
            fprintf(stderr, "ct-track: %s\n", msg);
            goto done;
        }
        width = info.width;
        height = info.height;
        if (fps <= 0 && info.rate_num > 0) {
            rate_num = info.rate_num;
            rate_den = info.rate_den;
        }
        frames = info.frames;
    } else {
        frames = df.max_frame;
    }

    if (ct_tracker_create(&cfg, &tracker) != CT_OK) {
        fprintf(stderr, "ct-track: cannot create the tracker\n");
        goto done;
    }
    if (candidates_path) {
        cand_out = fopen(candidates_path, "w");
        if (!cand_out) {
            fprintf(stderr, "ct-track: cannot write '%s': %s\n", candidates_path, strerror(errno));
            goto done;
        }
        fprintf(cand_out, "# frame,left,top,width,height,score,yes,voters,head,neck,shoulders,"
                          "chest,back,abdomen,buttocks,upper_limbs,lower_limbs,fill,top_width\n");
    }
    out = out_path ? fopen(out_path, "w") : stdout;
    if (!out) {
        fprintf(stderr, "ct-track: cannot write '%s': %s\n", out_path, strerror(errno));
        goto done;
    }

    if (overlay_path) {
        /* Y4M wants a rational rate: the header's, or --fps in thousandths. */
        long num = lround(rate_num * 1000), den = lround(rate_den * 1000);
        long a = num, b = den;
        while (b) {
            long r = a % b;
            a = b;
            b = r;
        }
        num /= a;
        den /= a;
        overlay = ct_overlay_open(overlay_path, width, height, (int)num, (int)den, msg, sizeof msg);
        if (!overlay) {
            fprintf(stderr, "ct-track: %s\n", msg);
            goto done;
        }
    }

    const double t0 = now_seconds();
    double next_progress = t0 + 0.5;
    const int tty = isatty(STDERR_FILENO);
    const char *lead = tty ? "\r" : "", *tail = tty ? "" : "\n";
    long long k = 0;
    for (;;) {
        ct_frame frame, picture;
        if (in) {
            int r = ct_input_read(in, &frame, msg, sizeof msg);
            if (r < 0) {
                fprintf(stderr, "ct-track: %s: %s\n", input_path, msg);
                goto done;
            }
            if (r == 0)
                break;
            picture = frame;
            if (no_pixels) {
                frame.format = CT_FORMAT_NONE;
                memset(frame.planes, 0, sizeof frame.planes);
                memset(frame.strides, 0, sizeof frame.strides);
            }
        } else {
            if (k >= frames)
                break;
            ct_frame_default(&frame, sizeof frame);
            frame.width = width;
            frame.height = height;
            picture = frame;
        }
        k++;
        /* Timestamps from the frame index and the rate, in microseconds. */
        frame.timestamp_us = (int64_t)llround((double)(k - 1) * 1e6 * rate_den / rate_num);
        size_t n = 0;
        const ct_detection *dets = det_path ? ct_detfile_frame(&df, (int)k, &n) : NULL;
        int st = ct_tracker_feed(tracker, &frame, dets, n);
        if (st != CT_OK) {
            fprintf(stderr, "ct-track: frame %lld: %s: %s\n", k, ct_status_str(st),
                    ct_tracker_last_error(tracker));
            goto done;
        }
        size_t count = 0;
        st = ct_tracker_get_tracks(tracker, tracks, tracks_cap, sizeof *tracks, &count);
        if (st == CT_ERROR_BUFFER_TOO_SMALL) {
            size_t ncap = count * 2;
            ct_track *nt = realloc(tracks, ncap * sizeof *nt);
            if (!nt) {
                fprintf(stderr, "ct-track: out of memory\n");
                goto done;
            }
            tracks = nt;
            tracks_cap = ncap;
            st = ct_tracker_get_tracks(tracker, tracks, tracks_cap, sizeof *tracks, &count);
        }
        if (st != CT_OK) {
            fprintf(stderr, "ct-track: frame %lld: %s: %s\n", k, ct_status_str(st),
                    ct_tracker_last_error(tracker));
            goto done;
        }
        size_t nc = 0;
        if (cand_out || overlay_candidates) {
            st = ct_tracker_get_candidates(tracker, cands, cands_cap, sizeof *cands, &nc);
            if (st == CT_ERROR_BUFFER_TOO_SMALL) {
                ct_candidate *nb = realloc(cands, nc * 2 * sizeof *nb);
                if (!nb) {
                    fprintf(stderr, "ct-track: out of memory\n");
                    goto done;
                }
                cands = nb;
                cands_cap = nc * 2;
                st = ct_tracker_get_candidates(tracker, cands, cands_cap, sizeof *cands, &nc);
            }
            if (st != CT_OK) {
                fprintf(stderr, "ct-track: frame %lld: %s: %s\n", k, ct_status_str(st),
                        ct_tracker_last_error(tracker));
                goto done;
            }
        }
        if (cand_out) {
            for (size_t i = 0; i < nc; i++) {
                const ct_candidate *c = &cands[i];
                fprintf(cand_out, "%lld,%.0f,%.0f,%.0f,%.0f,%.3f,%d,%d", k, c->left, c->top,
                        c->width, c->height, c->score, (int)c->votes_yes, (int)c->voters);
                for (int g = 0; g < CT_REGIONS; g++)
                    fprintf(cand_out, ",%.4f", c->region_distance[g]);
                fprintf(cand_out, ",%.3f,%.3f\n", c->fill, c->top_width);
            }
        }
        for (size_t i = 0; i < count; i++) {
            const ct_track *t = &tracks[i];
            fprintf(out, "%lld,%llu,%.2f,%.2f,%.2f,%.2f,%.3f,-1,-1,-1\n", k,
                    (unsigned long long)t->id, t->left, t->top, t->width, t->height,
                    t->confidence);
        }
        if (overlay && ct_overlay_write(overlay, &picture, tracks, count, cands,
                                        overlay_candidates ? nc : 0, msg, sizeof msg) < 0) {
            fprintf(stderr, "ct-track: %s\n", msg);
            goto done;
        }
        if (progress) {
            double now = now_seconds();
            if (now >= next_progress) {
                next_progress = now + 0.5;
                /* On a terminal each update overwrites the last; in a log
                 * each is a line of its own. */
                if (frames > 0)
                    fprintf(stderr, "%sct-track: frame %lld of %lld, %.0f frames/s%s", lead, k,
                            frames, k / (now - t0), tail);
                else
                    fprintf(stderr, "%sct-track: frame %lld, %.0f frames/s%s", lead, k,
                            k / (now - t0), tail);
            }
        }
    }
    if (progress) {
        double el = now_seconds() - t0;
        long rss = ct_peak_rss_kib();
        fprintf(stderr, "%sct-track: %lld frames in %.3f s, %.0f frames/s", lead, k, el,
                el > 0 ? k / el : 0.0);
        if (rss >= 0)
            fprintf(stderr, ", peak memory %.1f MiB", rss / 1024.0);
        fputc('\n', stderr);
    }
    if (stats)
        print_stats(tracker);
    if (det_path && df.max_frame > k)
        fprintf(stderr, "ct-track: warning: detections go to frame %d, the video has %lld\n",
                df.max_frame, k);
    if (fflush(out) != 0 || ferror(out)) {
        fprintf(stderr, "ct-track: error writing the tracks: %s\n", strerror(errno));
        goto done;
    }
    if (overlay) {
        int orc = ct_overlay_close(overlay, msg, sizeof msg);
        overlay = NULL;
        if (orc < 0) {
            fprintf(stderr, "ct-track: %s\n", msg);
            goto done;
        }
    }
    rc = 0;
done:
    if (overlay)
        ct_overlay_close(overlay, msg, sizeof msg);
    if (out && out != stdout) {
        if (fclose(out) != 0 && rc == 0) {
            fprintf(stderr, "ct-track: error writing '%s': %s\n", out_path, strerror(errno));
            rc = EXIT_RUNTIME;
        }
    }
    if (cand_out && fclose(cand_out) != 0 && rc == 0) {
        fprintf(stderr, "ct-track: error writing '%s': %s\n", candidates_path, strerror(errno));
        rc = EXIT_RUNTIME;
    }
    free(cands);
    free(tracks);
    ct_tracker_destroy(tracker);
    ct_input_close(in);
    ct_detfile_free(&df);
    return rc;
}
