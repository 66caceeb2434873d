// Frame validation: a frame is checked whole before the tracker uses it.
#ifndef CTRACK_FRAME_H
#define CTRACK_FRAME_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ctrack/ctrack.h"
#include "base/planes.h"

namespace ctrack {

constexpr size_t kFrameSizeV1 = sizeof(ct_frame);
// Largest accepted image side: beyond it a size is taken for garbage.
constexpr int kMaxSide = 16384;

ct_frame default_frame();

// A format's name as the header spells it ("I420"; "NONE" for any other
// value).
const char *format_name(uint32_t format);

// Reads the caller's frame and checks its format, size, planes and strides.
// The timestamp's order is the tracker's business. On failure writes a
// message into msg and returns a status.
int load_frame(const ct_frame *in, ct_frame *out, char *msg, size_t msg_len);

// Whether a format is packed colour, which the library converts to planes.
inline bool packed_rgb(uint32_t format)
{
    return format == CT_FORMAT_BGR24 || format == CT_FORMAT_RGB24;
}

// Checks n detections: finite boxes of positive size, finite scores.
int check_detections(const ct_detection *dets, size_t n, char *msg, size_t msg_len);

} // namespace ctrack

#endif
