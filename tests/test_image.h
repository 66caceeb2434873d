// Real frames for the C++ suites: an I420 image in memory and the clips of
// tests/data/pets09-crops read with ct-track's own Y4M reader.
#ifndef CT_TESTS_TEST_IMAGE_H
#define CT_TESTS_TEST_IMAGE_H

#include <check.h>

#include <string>
#include <vector>

#include "video.h"
#include "base/planes.h"

struct Image {
    int w = 0, h = 0;
    std::vector<uint8_t> buf;
    ctrack::Planes planes() const
    {
        ctrack::Planes p;
        p.width = w;
        p.height = h;
        p.y = buf.data();
        p.u = buf.data() + (size_t)w * h;
        p.v = p.u + (size_t)((w + 1) / 2) * ((h + 1) / 2);
        p.y_stride = w;
        p.u_stride = p.v_stride = (w + 1) / 2;
        p.color = true;
        return p;
    }
    // Pixel access for drawing synthetic scenes.
    uint8_t &Y(int x, int y) { return buf[(size_t)y * w + x]; }
    uint8_t &U(int x, int y) { return buf[(size_t)w * h + (size_t)(y / 2) * ((w + 1) / 2) + x / 2]; }
    uint8_t &V(int x, int y)
    {
        size_t c = (size_t)((w + 1) / 2) * ((h + 1) / 2);
        return buf[(size_t)w * h + c + (size_t)(y / 2) * ((w + 1) / 2) + x / 2];
    }
};

// Reads the first n frames of a 4:2:0 Y4M file.
inline void read_clip(const std::string &path, Image *frames, int n)
{
    video_params ip = {0, 0, CT_FORMAT_I420};
    video_input *in = nullptr;
    video_info info;
    char err[256];
    ck_assert_msg(video_open(path.c_str(), &ip, &in, &info, err, sizeof err) == 0, "%s", err);
    for (int k = 0; k < n; k++) {
        ct_frame fr;
        ck_assert_int_eq(video_read(in, &fr, err, sizeof err), 1);
        frames[k].w = fr.width;
        frames[k].h = fr.height;
        frames[k].buf.assign(fr.planes[0],
                             fr.planes[0] + frame_bytes(CT_FORMAT_I420, fr.width, fr.height));
    }
    video_close(in);
}

#endif
