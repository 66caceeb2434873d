// Writes the masks of the blobs the pixels-only tracker finds, for
// eval/recognition.py: the labelled set of docs/algorithm.md ("What the paper
// measures") and
// the real blobs of the contour template's unit test. Internal: it links the
// engine itself, to reach its foreground mask. Not installed.
//
//   dump-blobs VIDEO.y4m OUT
//
// OUT is a sequence of records, little-endian int32: frame (from 1), x0, y0,
// width, height of the blob at the mask's scale, and that scale (frame
// pixels across a working pixel), then width * height bytes of the cleaned
// mask inside the box (0 or 255).
#include <cstdio>
#include <cstring>
#include <vector>

#include "pixels_run.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: dump-blobs VIDEO.y4m OUT\n");
        return 2;
    }
    FILE *out = std::fopen(argv[2], "wb");
    if (!out) {
        std::perror(argv[2]);
        return 1;
    }
    std::vector<uint8_t> crop;
    int status = run_pixels("dump-blobs", argv[1], [&](int k, const ctrack::Engine &engine,
                                                        const ct_frame &) {
        int w, h;
        const uint8_t *mask = engine.foreground(&w, &h);
        const int s = engine.working_scale();
        for (const ct_candidate &c : engine.candidates()) {
            const int32_t head[6] = {k, (int32_t)(c.left / s), (int32_t)(c.top / s),
                                     (int32_t)(c.width / s), (int32_t)(c.height / s), s};
            crop.resize((size_t)head[3] * head[4]);
            for (int y = 0; y < head[4]; y++)
                std::memcpy(&crop[(size_t)y * head[3]], mask + (size_t)(head[2] + y) * w + head[1],
                            (size_t)head[3]);
            std::fwrite(head, sizeof head, 1, out);
            std::fwrite(crop.data(), 1, crop.size(), out);
        }
    });
    if (std::fclose(out) != 0) {
        std::perror(argv[2]);
        status = 1;
    }
    return status;
}
