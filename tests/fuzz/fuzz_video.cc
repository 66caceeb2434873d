// libFuzzer target: ct-track's video readers (tools/input/video.c), Y4M and
// raw I420, NV12 and GRAY8. The first four bytes choose the raw size and
// format (Y4M files carry their own; the fourth is spare); the rest is the
// file. Beyond the
// sanitizers: a file is refused with a message or opened, every frame read
// has the size and format the header gave and strides that hold a row, its
// planes are readable to their last byte (AddressSanitizer checks the read
// below), the frame count of a regular file is what is read, and a
// truncated frame is an error, never a frame. The spare byte keeps up to 4
// of the first frames (ct-track --prime): at the end they are replayed,
// equal to what was read, and the end (or the error) comes again.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

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
    const long long keep = bytes <= (1u << 22) ? data[3] % 5 : 0; // within the fuzzer's memory
    if (keep > 0)
        CHECK(video_keep(in, keep, err, sizeof err) == 0);
    std::vector<unsigned> sums; // of each frame read, up to keep
    long long frames = 0, replayed = -1;
    int end = 2;
    unsigned sum = 0;
    for (;;) {
        ct_frame f;
        std::memset(&f, 0, sizeof f);
        const int r = video_read(in, &f, err, sizeof err);
        CHECK(r == 1 || r == 0 || r == -1);
        if (r != 1) {
            if (r == -1)
                CHECK(err[0] != '\0');
            else if (info.frames >= 0 && replayed < 0)
                CHECK(frames == info.frames);
            if (replayed < 0 && keep > 0) {
                CHECK(video_replay(in) == (long long)sums.size());
                replayed = 0;
                end = r;
                continue;
            }
            if (replayed >= 0)
                CHECK(r == end && replayed == (long long)sums.size());
            break;
        }
        if (replayed >= 0)
            CHECK(replayed < (long long)sums.size());
        else
            frames++;
        CHECK(f.width == info.width && f.height == info.height && f.format == info.format);
        const int cw = (f.width + 1) / 2, ch = (f.height + 1) / 2;
        int planes = 1, row[3] = {f.width, 0, 0}, rows[3] = {f.height, 0, 0};
        if (f.format == CT_FORMAT_I420) {
            planes = 3; row[1] = row[2] = cw; rows[1] = rows[2] = ch;
        } else if (f.format == CT_FORMAT_NV12) {
            planes = 2; row[1] = 2 * cw; rows[1] = ch;
        }
        unsigned this_sum = 0;
        for (int p = 0; p < planes; p++) {
            CHECK(f.planes[p] && f.strides[p] >= row[p]);
            for (int y = 0; y < rows[p]; y++)
                for (int x = 0; x < row[p]; x++)
                    this_sum = this_sum * 31 + f.planes[p][(size_t)y * f.strides[p] + x];
        }
        sum += this_sum;
        if (replayed >= 0)
            CHECK(sums[(size_t)replayed++] == this_sum);
        else if ((long long)sums.size() < keep)
            sums.push_back(this_sum);
    }
    video_close(in);
    return (int)(sum & 0); // the reads are the check
}
