/* Progress on standard error for long runs, and the process's peak memory
 * (ct-track's summary, ct-bench). */
#ifndef CT_TOOLS_PROGRESS_H
#define CT_TOOLS_PROGRESS_H

typedef struct progress {
    int on;
    long long total;    /* frames in the input when known, else <= 0 */
    double start, next; /* seconds, monotonic */
    const char *lead, *tail;
} progress;

/* Starts the clock. Nothing is printed unless `on`. On a terminal each
 * update overwrites the last; in a log each is a line of its own. */
void progress_start(progress *p, int on, long long total);
/* After `frame` frames: a line at most every half second. */
void progress_update(progress *p, long long frame);
/* The closing line: frames, time, frames per second and peak memory. */
void progress_end(progress *p, long long frames);

/* Peak resident memory in KiB from /proc/self/status (VmHWM, which, unlike
 * getrusage, does not count the parent's image before exec), or -1 where
 * there is no /proc. */
long peak_rss_kib(void);

#endif
