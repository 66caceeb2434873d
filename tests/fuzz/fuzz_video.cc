// libFuzzer target: ct-track's video readers (tools/input/video.c), Y4M and
// raw I420, NV12 and GRAY8. The first four bytes choose the raw size and
// format (Y4M files carry their own; the fourth is spare); the rest is the
// file. Beyond the
// sanitizers: a file is refused with a message or opened, every frame read
// has the size and format the header gave and strides that hold a row, its
// planes are readable to their last byte (AddressSanitizer checks the read
// below), the frame count of a regular file is what is read, and a
// truncated frame is an error, never a frame.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "fuzz.h"
#include "video.h"


extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 4)
        return 0;
    static const uint32_t formats[] = {CT_FORMAT_I420, CT_FORMAT_NV12, CT_FORMAT_GRAY8,
                                       CT_FORMAT_BGR24};
    video_params params;
    params.width = data[0] % 64 - 2;  // a few sizes the reader must refuse
    params.height = data[1] % 64 - 2;
    params.format = formats[data[2] % 4];
    MemFile file(data + 4, size - 4);
    video_input *in = nullptr;
    video_info info;
    char err[256];
    std::memset(err, 'x', sizeof err);
    if (video_open(file.path(), &params, &in, &info, err, sizeof err) != 0) {
        CHECK(in == nullptr);
        CHECK(std::memchr(err, 0, sizeof err) && err[0] != '\0' && err[0] != 'x');
        return 0;
    }
    CHECK(in && info.width >= 1 && info.height >= 1);
    const size_t bytes = frame_bytes(info.format, info.width, info.height);
    CHECK(bytes > 0);
    long long frames = 0;
    unsigned sum = 0;
    for (;;) {
        ct_frame f;
        std::memset(&f, 0, sizeof f);
        const int r = video_read(in, &f, err, sizeof err);
        CHECK(r == 1 || r == 0 || r == -1);
        if (r != 1) {
            if (r == -1)
                CHECK(err[0] != '\0');
            else if (info.frames >= 0)
                CHECK(frames == info.frames);
            break;
        }
        frames++;
        CHECK(f.width == info.width && f.height == info.height && f.format == info.format);
        const int cw = (f.width + 1) / 2, ch = (f.height + 1) / 2;
        int planes = 1, row[3] = {f.width, 0, 0}, rows[3] = {f.height, 0, 0};
        if (f.format == CT_FORMAT_I420) {
            planes = 3; row[1] = row[2] = cw; rows[1] = rows[2] = ch;
        } else if (f.format == CT_FORMAT_NV12) {
            planes = 2; row[1] = 2 * cw; rows[1] = ch;
        }
        for (int p = 0; p < planes; p++) {
            CHECK(f.planes[p] && f.strides[p] >= row[p]);
            for (int y = 0; y < rows[p]; y++)
                for (int x = 0; x < row[p]; x++)
                    sum += f.planes[p][(size_t)y * f.strides[p] + x];
        }
    }
    video_close(in);
    return (int)(sum & 0); // the reads are the check
}
