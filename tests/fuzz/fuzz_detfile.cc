// libFuzzer target: ct-track's detection-file parser (tools/input/detfile.c).
// Beyond the sanitizers: a file is either refused with a "LINE: what"
// message or loaded, and then every detection is what the tracker takes
// (finite box, positive size, finite score), frames are in [1, max_frame]
// and sorted, and reading frame after frame gives back every detection.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "detfile.h"
#include "fuzz.h"


extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    MemFile file(data, size);
    det_file df;
    char err[256];
    std::memset(err, 'x', sizeof err);
    if (detfile_load(file.path(), &df, err, sizeof err) != 0) {
        CHECK(std::memchr(err, 0, sizeof err) && err[0] != '\0' && err[0] != 'x');
        return 0;
    }
    CHECK(df.count == 0 ? df.max_frame == 0 : df.max_frame >= 1);
    CHECK(df.max_frame <= DETFILE_MAX_FRAME);
    for (size_t k = 0; k < df.count; k++) {
        const ct_detection &d = df.dets[k];
        CHECK(std::isfinite(d.left) && std::isfinite(d.top));
        CHECK(std::isfinite(d.width) && d.width > 0 && std::isfinite(d.height) && d.height > 0);
        CHECK(std::isfinite(d.score));
        CHECK(df.frames[k] >= 1 && df.frames[k] <= df.max_frame);
        CHECK(k == 0 || df.frames[k - 1] <= df.frames[k]);
    }
    // Frame by frame (only the frames that hold detections: max_frame may be
    // ten million), every detection comes back once, in order.
    size_t seen = 0;
    for (size_t k = 0; k < df.count; k = seen) {
        size_t n = 0;
        const ct_detection *got = detfile_frame(&df, df.frames[k], &n);
        CHECK(n >= 1 && got == df.dets + k);
        seen = k + n;
        CHECK(seen <= df.count);
    }
    CHECK(seen == df.count);
    size_t n = 1;
    detfile_frame(&df, df.max_frame + 1, &n);
    CHECK(n == 0);
    detfile_free(&df);
    return 0;
}
