/* ct-track: runs ctrack over a video file or standard input and writes
 * MOTChallenge tracks. See `ct-track --help` and docs/ct-track.md. */
#define _XOPEN_SOURCE 700 /* POSIX.1-2008 with realpath() */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ctrack/ctrack.h"
#include "detfile.h"
#include "detstream.h"
#include "events.h"
#include "mot.h"
#include "options.h"
#include "overlay.h"
#include "progress.h"
#include "video.h"

/* A run's inputs, tracker and outputs. */
typedef struct run {
    const options *o;
    det_file df;
    det_stream *ds; /* -d names a stream (a FIFO, a pipe): read frame by frame */
    int flush;      /* each frame's lines written out as it is tracked */
    video_input *in;
    ct_tracker *tracker;
    FILE *out, *cand_out, *events_out;
    overlay_writer *overlay;
    int width, height;
    uint32_t format; /* the video's */
    double rate_num, rate_den;
    long long frames; /* in the input when known, else <= 0 */
    /* This step's tracks and candidates, in buffers that grow as needed. */
    ct_track *tracks;
    size_t tracks_cap, n_tracks;
    ct_candidate *cands;
    size_t cands_cap, n_cands;
    /* Counting (--line, --zone): this step's events, and the counts. */
    int counting;
    ct_event *events;
    size_t events_cap, n_events;
    ct_line_count lines[CT_COUNT_MAX_LINES];
    ct_zone_count zones[CT_COUNT_MAX_ZONES];
    size_t n_lines, n_zones;
} run;

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

/* Opens the overlay at the run's rate: the Y4M header's, or --fps in
 * thousandths (Y4M wants a rational rate). */
static overlay_writer *open_overlay(const run *r, char *msg, size_t len)
{
    long num = lround(r->rate_num * 1000), den = lround(r->rate_den * 1000);
    long a = num, b = den;
    while (b) {
        long t = a % b;
        a = b;
        b = t;
    }
    return overlay_open(r->o->overlay_path, r->width, r->height, (int)(num / a),
                        (int)(den / a), msg, len);
}

/* A file ct-track reads or writes, and the option that names it. */
typedef struct {
    const char *option, *path;
} named_file;

/* Whether the file at path (standard input for "-") exists, and its
 * device and inode. */
static int identify(const char *path, struct stat *st)
{
    return strcmp(path, "-") == 0 ? fstat(STDIN_FILENO, st) == 0 : stat(path, st) == 0;
}

/* The absolute path a file not yet made would have: its folder resolved,
 * its name as given. Empty when the folder cannot be resolved. */
static void future_path(const char *path, char *out, size_t len)
{
    const char *slash = strrchr(path, '/');
    char dir[4096];
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) : 1, slash ? path : ".");
    if (slash == path)
        snprintf(dir, sizeof dir, "/");
    char *real = realpath(dir, NULL);
    snprintf(out, len, "%s/%s", real ? real : "", real ? (slash ? slash + 1 : path) : "");
    free(real);
}

/* Whether two paths name the same file: by device and inode when both
 * exist, by their resolved path when neither does yet. */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    const int ea = identify(a, &sa), eb = identify(b, &sb);
    if (ea && eb)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    if (ea || eb || strcmp(a, "-") == 0 || strcmp(b, "-") == 0)
        return 0;
    char fa[8192], fb[8192];
    future_path(a, fa, sizeof fa);
    future_path(b, fb, sizeof fb);
    return fa[0] && strcmp(fa, fb) == 0;
}

/* Refuses, before anything is opened for writing, an output that is an
 * input (writing would truncate what is to be read) or another output:
 * the same file whatever the path's spelling. Returns 0, or -1 with the
 * reason printed. */
static int outputs_are_not_inputs(const options *o)
{
    const named_file in[] = {{"INPUT", o->input_path}, {"--detections", o->det_path}};
    const named_file out[] = {{"--output", o->out_path},
                              {"--overlay", o->overlay_path},
                              {"--candidates", o->candidates_path},
                              {"--events", o->events_path}};
    const size_t n_in = sizeof in / sizeof in[0], n_out = sizeof out / sizeof out[0];
    for (size_t i = 0; i < n_out; i++) {
        if (!out[i].path || strcmp(out[i].path, "-") == 0)
            continue;
        for (size_t j = 0; j < n_in + i; j++) {
            const named_file *other = j < n_in ? &in[j] : &out[j - n_in];
            if (other->path && same_file(out[i].path, other->path)) {
                fprintf(stderr, "ct-track: %s '%s' is the file %s '%s' names: ct-track "
                                "would overwrite it; give another path\n",
                        out[i].option, out[i].path, other->option, other->path);
                return -1;
            }
        }
    }
    return 0;
}

/* Opens the detections, the video, the tracker and the outputs; on failure
 * prints why and returns -1. */
static int open_run(run *r)
{
    const options *o = r->o;
    char msg[512];
    if (outputs_are_not_inputs(o) < 0)
        return -1;
    if (o->det_path && detstream_is_stream(o->det_path)) {
        if (detstream_open(o->det_path, &r->ds, msg, sizeof msg) < 0) {
            fprintf(stderr, "ct-track: %s\n", msg);
            return -1;
        }
    } else if (o->det_path && detfile_load(o->det_path, &r->df, msg, sizeof msg) < 0) {
        fprintf(stderr, "ct-track: %s\n", msg);
        return -1;
    }
    r->width = o->width;
    r->height = o->height;
    r->rate_num = o->fps > 0 ? o->fps : 25;
    r->rate_den = 1;
    if (o->input_path) {
        video_params vp = {o->width, o->height, o->format};
        video_info info;
        if (video_open(o->input_path, &vp, &r->in, &info, msg, sizeof msg) < 0) {
            fprintf(stderr, "ct-track: %s\n", msg);
            return -1;
        }
        r->width = info.width;
        r->height = info.height;
        r->format = info.format;
        if (o->fps <= 0 && info.rate_num > 0) {
            r->rate_num = info.rate_num;
            r->rate_den = info.rate_den;
        }
        r->frames = info.frames;
        /* Detections far past the video's end are another video's. */
        if (o->det_path && r->frames > 0 && r->df.max_frame > 2 * r->frames + 1000) {
            fprintf(stderr, "ct-track: %s: detections go to frame %d, far past the %lld frames "
                            "of %s: is it the video's detections file?\n",
                    o->det_path, r->df.max_frame, r->frames, o->input_path);
            return -1;
        }
    } else {
        /* Detections alone: as many frames as they name (a stream: until it
         * ends). */
        r->frames = r->ds ? -1 : r->df.max_frame;
    }
    if (ct_tracker_create(&o->cfg, &r->tracker) != CT_OK) {
        fprintf(stderr, "ct-track: cannot create the tracker\n");
        return -1;
    }
    r->counting = o->counting.n_lines + o->counting.n_zones > 0;
    if (r->counting && counting_add(&o->counting, r->tracker, msg, sizeof msg) < 0) {
        fprintf(stderr, "ct-track: %s\n", msg);
        return -1;
    }
    if (o->events_path) {
        r->events_out = strcmp(o->events_path, "-") ? fopen(o->events_path, "w") : stdout;
        if (!r->events_out) {
            fprintf(stderr, "ct-track: cannot write '%s': %s\n", o->events_path,
                    strerror(errno));
            return -1;
        }
    }
    if (o->candidates_path) {
        r->cand_out = fopen(o->candidates_path, "w");
        if (!r->cand_out) {
            fprintf(stderr, "ct-track: cannot write '%s': %s\n", o->candidates_path,
                    strerror(errno));
            return -1;
        }
        mot_write_candidates_header(r->cand_out);
    }
    r->out = o->out_path && strcmp(o->out_path, "-") ? fopen(o->out_path, "w") : stdout;
    if (!r->out) {
        fprintf(stderr, "ct-track: cannot write '%s': %s\n", o->out_path, strerror(errno));
        return -1;
    }
    /* Live use: a pipe, a FIFO or a terminal gets each frame's lines as it
     * is tracked, not when a block fills. */
    struct stat st;
    r->flush = o->flush || isatty(fileno(r->out)) ||
               (fstat(fileno(r->out), &st) == 0 && (S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)));
    if (o->overlay_path) {
        r->overlay = open_overlay(r, msg, sizeof msg);
        if (!r->overlay) {
            fprintf(stderr, "ct-track: %s\n", msg);
            return -1;
        }
        if (r->counting)
            overlay_set_counting(r->overlay, o->counting.line_ends, r->lines,
                                 o->counting.n_lines, o->counting.zone_points,
                                 o->counting.zone_n, r->zones, o->counting.n_zones);
    }
    return 0;
}

/* Frame k (from 1) into *frame for the tracker and *picture for the
 * overlay: from the video, or an empty frame of the image's size with
 * detections only. Returns 1, 0 at the end, -1 on an error (printed). */
static int next_frame(run *r, long long k, ct_frame *frame, ct_frame *picture)
{
    if (r->in) {
        char msg[512];
        const int got = video_read(r->in, frame, msg, sizeof msg);
        if (got < 0)
            fprintf(stderr, "ct-track: %s: %s\n", r->o->input_path, msg);
        if (got <= 0)
            return got;
        *picture = *frame;
        if (r->o->no_pixels) {
            frame->format = CT_FORMAT_NONE;
            memset(frame->planes, 0, sizeof frame->planes);
            memset(frame->strides, 0, sizeof frame->strides);
        }
    } else {
        if (r->frames >= 0 && k > r->frames)
            return 0;
        ct_frame_default(frame, sizeof *frame);
        frame->width = r->width;
        frame->height = r->height;
        *picture = *frame;
    }
    /* Timestamps from the frame index and the rate, in microseconds. */
    frame->timestamp_us = (int64_t)llround((double)(k - 1) * 1e6 * r->rate_den / r->rate_num);
    return 1;
}

/* ct_tracker_get_tracks() and ct_tracker_get_candidates() into a buffer
 * that grows to the count the library asks for. */
typedef int (*getter)(const ct_tracker *t, void *out, size_t cap, size_t *count);

static int get_tracks(const ct_tracker *t, void *out, size_t cap, size_t *count)
{
    return ct_tracker_get_tracks(t, out, cap, sizeof(ct_track), count);
}

static int get_candidates(const ct_tracker *t, void *out, size_t cap, size_t *count)
{
    return ct_tracker_get_candidates(t, out, cap, sizeof(ct_candidate), count);
}

static int get_events(const ct_tracker *t, void *out, size_t cap, size_t *count)
{
    return ct_tracker_get_events(t, out, cap, sizeof(ct_event), count);
}

static int get_all(const run *r, long long k, getter get, size_t elem, void **buf, size_t *cap,
                   size_t *count)
{
    int st = get(r->tracker, *buf, *cap, count);
    if (st == CT_ERROR_BUFFER_TOO_SMALL) {
        void *grown = realloc(*buf, *count * 2 * elem);
        if (!grown) {
            fprintf(stderr, "ct-track: out of memory\n");
            return -1;
        }
        *buf = grown;
        *cap = *count * 2;
        st = get(r->tracker, *buf, *cap, count);
    }
    if (st != CT_OK) {
        fprintf(stderr, "ct-track: frame %lld: %s: %s\n", k, ct_status_str(st),
                ct_tracker_last_error(r->tracker));
        return -1;
    }
    return 0;
}

/* Frame k's detections (none without -d): from the file, or waited for on
 * the stream. Returns 1, 0 when a stream of detections alone has ended (no
 * frame k), -1 on an error (printed). */
static int detections_of(run *r, long long k, const ct_detection **dets, size_t *n)
{
    *dets = NULL;
    *n = 0;
    if (!r->o->det_path)
        return 1;
    if (!r->ds) {
        *dets = detfile_frame(&r->df, (int)k, n);
        return 1;
    }
    char msg[512];
    const int got = detstream_frame(r->ds, k, dets, n, msg, sizeof msg);
    if (got < 0)
        fprintf(stderr, "ct-track: %s\n", msg);
    /* With a video, a stream that ended leaves the frames after it without
     * detections. */
    return got == 0 && r->in ? 1 : got;
}

/* Frame k's counting: its events (written to --events) and the counts
 * (drawn on the overlay). */
static int count_frame(run *r, long long k, int64_t us)
{
    if (get_all(r, k, get_events, sizeof(ct_event), (void **)&r->events, &r->events_cap,
                &r->n_events) < 0)
        return -1;
    if (ct_tracker_get_line_counts(r->tracker, r->lines, CT_COUNT_MAX_LINES,
                                   sizeof(ct_line_count), &r->n_lines) != CT_OK ||
        ct_tracker_get_zone_counts(r->tracker, r->zones, CT_COUNT_MAX_ZONES,
                                   sizeof(ct_zone_count), &r->n_zones) != CT_OK) {
        fprintf(stderr, "ct-track: frame %lld: %s\n", k, ct_tracker_last_error(r->tracker));
        return -1;
    }
    if (r->events_out)
        events_write(r->events_out, k, us * 1e-6, r->events, r->n_events, r->lines, r->zones);
    return 0;
}

/* One frame through the tracker and into every output. */
static int track_frame(run *r, long long k, const ct_frame *frame, const ct_frame *picture,
                       const ct_detection *dets, size_t n)
{
    const options *o = r->o;
    const int st = ct_tracker_feed(r->tracker, frame, dets, n);
    if (st != CT_OK) {
        fprintf(stderr, "ct-track: frame %lld: %s: %s\n", k, ct_status_str(st),
                ct_tracker_last_error(r->tracker));
        return -1;
    }
    if (get_all(r, k, get_tracks, sizeof(ct_track), (void **)&r->tracks, &r->tracks_cap,
                &r->n_tracks) < 0)
        return -1;
    r->n_cands = 0;
    if ((r->cand_out || o->overlay_candidates) &&
        get_all(r, k, get_candidates, sizeof(ct_candidate), (void **)&r->cands,
                &r->cands_cap, &r->n_cands) < 0)
        return -1;
    if (r->cand_out)
        mot_write_candidates(r->cand_out, k, r->cands, r->n_cands);
    if (r->counting && count_frame(r, k, frame->timestamp_us) < 0)
        return -1;
    mot_write_tracks(r->out, k, r->tracks, r->n_tracks);
    if (r->overlay && o->overlay_size) {
        ct_person_size size = {.size = sizeof size};
        if (ct_tracker_get_person_size(r->tracker, &size) != CT_OK) {
            fprintf(stderr, "ct-track: frame %lld: %s\n", k, ct_tracker_last_error(r->tracker));
            return -1;
        }
        overlay_set_person_size(r->overlay, &size);
    }
    char msg[512];
    if (r->overlay && overlay_write(r->overlay, picture, r->tracks, r->n_tracks, r->cands,
                                    o->overlay_candidates ? r->n_cands : 0, msg,
                                    sizeof msg) < 0) {
        fprintf(stderr, "ct-track: %s\n", msg);
        return -1;
    }
    if (r->flush && (fflush(r->out) != 0 || (r->cand_out && fflush(r->cand_out) != 0) ||
                     (r->events_out && fflush(r->events_out) != 0))) {
        fprintf(stderr, "ct-track: error writing the tracks: %s\n", strerror(errno));
        return -1;
    }
    return 0;
}

/* Flushes and closes the outputs; returns the exit status, rc unless a
 * write failed. */
static int close_run(run *r, int rc)
{
    char msg[512];
    if (r->overlay && overlay_close(r->overlay, msg, sizeof msg) < 0 && rc == 0) {
        fprintf(stderr, "ct-track: %s\n", msg);
        rc = EXIT_RUNTIME;
    }
    if (r->out && r->out != stdout && fclose(r->out) != 0 && rc == 0) {
        fprintf(stderr, "ct-track: error writing '%s': %s\n", r->o->out_path, strerror(errno));
        rc = EXIT_RUNTIME;
    }
    if (r->cand_out && fclose(r->cand_out) != 0 && rc == 0) {
        fprintf(stderr, "ct-track: error writing '%s': %s\n", r->o->candidates_path,
                strerror(errno));
        rc = EXIT_RUNTIME;
    }
    if (r->events_out &&
        (r->events_out == stdout ? fflush(stdout) : fclose(r->events_out)) != 0 && rc == 0) {
        fprintf(stderr, "ct-track: error writing '%s': %s\n", r->o->events_path,
                strerror(errno));
        rc = EXIT_RUNTIME;
    }
    free(r->events);
    free(r->cands);
    free(r->tracks);
    ct_tracker_destroy(r->tracker);
    video_close(r->in);
    detfile_free(&r->df);
    detstream_close(r->ds);
    return rc;
}

/* Frames kept in memory for --prime at most: a shorter start beyond. */
#define PRIME_MAX_BYTES ((size_t)512 << 20)

/* --prime: the tracker learns the scene's background from the video's first
 * seconds (ct_tracker_prime()), then tracks from the first frame, which the
 * reader replays from memory. Only where the tracker uses a background: from
 * the pixels, or verifying detections. */
static int prime(run *r)
{
    const options *o = r->o;
    if (!r->in || o->no_pixels || !(o->prime > 0) ||
        (o->cfg.source != CT_SOURCE_PIXELS && !o->cfg.verify_detections))
        return 0;
    long long n = (long long)ceil(o->prime * r->rate_num / r->rate_den);
    if (r->frames > 0 && n > r->frames)
        n = r->frames;
    if (n > CT_PRIME_MAX_FRAMES)
        n = CT_PRIME_MAX_FRAMES;
    const size_t bytes = frame_bytes(r->format, r->width, r->height);
    char msg[512];
    if (bytes > 0 && (size_t)n > PRIME_MAX_BYTES / bytes) {
        n = (long long)(PRIME_MAX_BYTES / bytes);
        if (n < 1)
            return 0;
        fprintf(stderr, "ct-track: --prime: %lld frames fit in %zu MiB, %.2f s\n", n,
                PRIME_MAX_BYTES >> 20, (double)n * r->rate_den / r->rate_num);
    }
    /* Priming is worth a try, not a failed run: without the memory for it,
     * the video is tracked live. */
    ct_frame *frames = malloc((size_t)n * sizeof *frames);
    const ct_frame **ptrs = malloc((size_t)n * sizeof *ptrs);
    if (!frames || !ptrs || video_keep(r->in, n, msg, sizeof msg) < 0) {
        fprintf(stderr, "ct-track: --prime: %s: tracked live\n",
                frames && ptrs ? msg : "out of memory");
        free(frames);
        free(ptrs);
        return 0;
    }
    /* A read that fails stops the start here: the frames before it are
     * primed on and tracked, and the tracking meets the error where a run
     * without --prime meets it (the reader repeats it). */
    long long got = 0;
    while (got < n) {
        ct_frame frame;
        if (video_read(r->in, &frame, msg, sizeof msg) != 1)
            break;
        got++;
    }
    for (long long i = 0; i < got; i++) {
        video_kept(r->in, i, &frames[i]);
        frames[i].timestamp_us = (int64_t)llround((double)i * 1e6 * r->rate_den / r->rate_num);
        ptrs[i] = &frames[i];
    }
    const int st = got > 0 ? ct_tracker_prime(r->tracker, ptrs, (size_t)got) : CT_OK;
    free(ptrs);
    free(frames);
    if (st != CT_OK) {
        fprintf(stderr, "ct-track: --prime: %s: %s\n", ct_status_str(st),
                ct_tracker_last_error(r->tracker));
        return -1;
    }
    video_replay(r->in);
    return 0;
}

static int track_all(run *r)
{
    const options *o = r->o;
    if (prime(r) < 0)
        return EXIT_RUNTIME;
    progress pr;
    progress_start(&pr, o->progress, r->frames);
    long long k = 0;
    for (;;) {
        ct_frame frame, picture;
        const int got = next_frame(r, k + 1, &frame, &picture);
        if (got < 0)
            return EXIT_RUNTIME;
        if (got == 0)
            break;
        const ct_detection *dets;
        size_t n;
        const int have = detections_of(r, k + 1, &dets, &n);
        if (have < 0)
            return EXIT_RUNTIME;
        if (have == 0)
            break;
        k++;
        if (track_frame(r, k, &frame, &picture, dets, n) < 0)
            return EXIT_RUNTIME;
        progress_update(&pr, k);
    }
    progress_end(&pr, k);
    if (o->stats)
        print_stats(r->tracker);
    if (r->counting)
        counts_print(stderr, "ct-track: ", r->lines, r->n_lines, r->zones, r->n_zones);
    const long long last = r->ds ? detstream_last_frame(r->ds) : r->df.max_frame;
    if (o->det_path && last > k)
        fprintf(stderr, "ct-track: warning: detections go to frame %lld, the video has %lld\n",
                last, k);
    if (fflush(r->out) != 0 || ferror(r->out)) {
        fprintf(stderr, "ct-track: error writing the tracks: %s\n", strerror(errno));
        return EXIT_RUNTIME;
    }
    return 0;
}

int main(int argc, char **argv)
{
    options o;
    const int stop = options_parse(argc, argv, &o);
    if (stop >= 0)
        return stop;
    run r;
    memset(&r, 0, sizeof r);
    r.o = &o;
    const int rc = open_run(&r) < 0 ? EXIT_RUNTIME : track_all(&r);
    return close_run(&r, rc);
}
