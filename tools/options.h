/* ct-track's command line: the options, their checks and --help. */
#ifndef CT_TOOLS_OPTIONS_H
#define CT_TOOLS_OPTIONS_H

#include <stdint.h>

#include "counting.h"
#include "ctrack/ctrack.h"

enum { EXIT_RUNTIME = 1, EXIT_USAGE = 2 };

typedef struct options {
    ct_config cfg;           /* defaults, then --param; source set from the inputs */
    const char *input_path;  /* NULL: detections only */
    const char *det_path;    /* NULL: the tracker finds people in the pixels */
    const char *out_path;    /* NULL: standard output */
    const char *overlay_path, *candidates_path;
    const char *events_path;  /* --events: counting events as JSON lines */
    counting_spec counting;   /* --line, --zone */
    int width, height;       /* --size (raw video, or detections only) */
    uint32_t format;         /* --format of a raw video */
    double fps;              /* --fps, 0 when not given */
    double prime;            /* --prime, seconds */
    int no_pixels, progress, stats, overlay_candidates, overlay_size;
    int flush;               /* --flush: each frame's lines out as it is tracked */
} options;

/* Reads the command line into *o. Returns -1 when ct-track should run, or
 * the exit status when it should stop here (0 after --help or --version,
 * EXIT_USAGE after a message on standard error). */
int options_parse(int argc, char **argv, options *o);

#endif
