// The internal eval tools' common loop: a video through the pixels-alone
// engine, online, frame by frame, with a look at the engine after each
// step (its foreground, candidates, people's size).
#ifndef CT_EVAL_PIXELS_RUN_H
#define CT_EVAL_PIXELS_RUN_H

#include <cstdio>

#include "track/engine.h"
#include "video.h"

// Runs the video at `path` through a pixels-alone engine with the default
// configuration, calling after(k, engine, frame) after frame k's step (k
// from 1; timestamps from the video's rate, 25 frames/s when it has none).
// Returns 0, or 1 after printing why (`tool`: the name in the message).
template <typename After> int run_pixels(const char *tool, const char *path, After &&after)
{
    char err[256];
    video_input *in = nullptr;
    video_info info;
    video_params params = {};
    if (video_open(path, &params, &in, &info, err, sizeof err) != 0) {
        std::fprintf(stderr, "%s: %s\n", tool, err);
        return 1;
    }
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    cfg.source = CT_SOURCE_PIXELS;
    ctrack::Engine engine(cfg);
    const double rate =
        info.rate_num > 0 && info.rate_den > 0 ? (double)info.rate_num / info.rate_den : 25.0;
    ct_frame f;
    int status = 0;
    for (int k = 1;; k++) {
        const int r = video_read(in, &f, err, sizeof err);
        if (r <= 0) {
            if (r < 0) {
                std::fprintf(stderr, "%s: %s\n", tool, err);
                status = 1;
            }
            break;
        }
        f.timestamp_us = (int64_t)((k - 1) * 1e6 / rate);
        engine.step(f.timestamp_us, ctrack::Planes::of(f), ctrack::ImageSize{f.width, f.height},
                    nullptr, 0);
        after(k, engine, f);
    }
    video_close(in);
    return status;
}

#endif
