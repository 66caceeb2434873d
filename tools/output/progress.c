#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

void progress_start(progress *p, int on, long long total)
{
    p->on = on;
    p->total = total;
    p->start = now_seconds();
    p->next = p->start + 0.5;
    const int tty = isatty(STDERR_FILENO);
    p->lead = tty ? "\r" : "";
    p->tail = tty ? "" : "\n";
}

void progress_update(progress *p, long long frame)
{
    if (!p->on)
        return;
    const double now = now_seconds();
    if (now < p->next)
        return;
    p->next = now + 0.5;
    if (p->total > 0)
        fprintf(stderr, "%sct-track: frame %lld of %lld, %.0f frames/s%s", p->lead, frame,
                p->total, frame / (now - p->start), p->tail);
    else
        fprintf(stderr, "%sct-track: frame %lld, %.0f frames/s%s", p->lead, frame,
                frame / (now - p->start), p->tail);
}

void progress_end(progress *p, long long frames)
{
    if (!p->on)
        return;
    const double el = now_seconds() - p->start;
    const long rss = peak_rss_kib();
    fprintf(stderr, "%sct-track: %lld frames in %.3f s, %.0f frames/s", p->lead, frames, el,
            el > 0 ? frames / el : 0.0);
    if (rss >= 0)
        fprintf(stderr, ", peak memory %.1f MiB", rss / 1024.0);
    fputc('\n', stderr);
}

long peak_rss_kib(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f)
        return -1;
    char line[256];
    long kib = -1;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "VmHWM: %ld kB", &kib) == 1)
            break;
    fclose(f);
    return kib;
}
