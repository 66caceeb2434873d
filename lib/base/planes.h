// A validated frame's pixels as plane views, for the modules that read them.
#ifndef CTRACK_PLANES_H
#define CTRACK_PLANES_H

#include <cstdint>

#include "ctrack/ctrack.h"

namespace ctrack {

struct Planes {
    int width = 0, height = 0;
    const uint8_t *y = nullptr; // luma
    const uint8_t *u = nullptr; // chroma U (I420), or the UV plane (NV12)
    const uint8_t *v = nullptr; // chroma V (I420), or the UV plane + 1 (NV12)
    int y_stride = 0, u_stride = 0, v_stride = 0;
    int c_step = 1;             // bytes between chroma samples: 1 I420, 2 NV12
    bool color = false;         // false: GRAY8, luma only

    bool empty() const { return y == nullptr; }

    // Views over a planar frame that load_frame() accepted; nothing is
    // copied. (Packed BGR24 and RGB24 are converted first: packed_to_i420().)
    static Planes of(const ct_frame &f)
    {
        Planes p;
        if (f.format == CT_FORMAT_NONE)
            return p;
        p.width = f.width;
        p.height = f.height;
        p.y = f.planes[0];
        p.y_stride = f.strides[0];
        if (f.format == CT_FORMAT_I420) {
            p.u = f.planes[1];
            p.v = f.planes[2];
            p.u_stride = f.strides[1];
            p.v_stride = f.strides[2];
            p.color = true;
        } else if (f.format == CT_FORMAT_NV12) {
            p.u = f.planes[1];
            p.v = f.planes[1] + 1;
            p.u_stride = p.v_stride = f.strides[1];
            p.c_step = 2;
            p.color = true;
        }
        return p;
    }
};

} // namespace ctrack

#endif
