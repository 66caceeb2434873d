#include "api/frame.h"

#include <cmath>
#include <cstdio>

#include "api/error.h"
#include "api/sized.h"

namespace ctrack {

namespace {

constexpr size_t kMaxDetections = 1 << 16;
constexpr double kMaxCoordinate = 1e6;

} // namespace

const char *format_name(uint32_t f)
{
    switch (f) {
    case CT_FORMAT_I420: return "I420";
    case CT_FORMAT_NV12: return "NV12";
    case CT_FORMAT_GRAY8: return "GRAY8";
    case CT_FORMAT_BGR24: return "BGR24";
    case CT_FORMAT_RGB24: return "RGB24";
    default: return "NONE";
    }
}

ct_frame default_frame()
{
    ct_frame f = {};
    f.size = sizeof(ct_frame);
    f.format = CT_FORMAT_NONE;
    return f;
}

int load_frame(const ct_frame *in, ct_frame *out, char *msg, size_t msg_len)
{
    if (!in)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT, "frame: NULL pointer");
    ct_frame f = default_frame();
    if (const int st = explain_sized(read_sized(in, in->size, kFrameSizeV1, &f), in->size,
                                     kFrameSizeV1, sizeof(ct_frame), "frame", "ct_frame", msg,
                                     msg_len))
        return st;

    int planes;
    switch (f.format) {
    case CT_FORMAT_NONE: planes = 0; break;
    case CT_FORMAT_GRAY8: planes = 1; break;
    case CT_FORMAT_NV12: planes = 2; break;
    case CT_FORMAT_I420: planes = 3; break;
    case CT_FORMAT_BGR24: case CT_FORMAT_RGB24: planes = 1; break;
    default:
        return fail(msg, msg_len, CT_ERROR_UNSUPPORTED,
                    "frame.format: 0x%08x is not I420, NV12, GRAY8, BGR24, RGB24 or NONE",
                    (unsigned)f.format);
    }

    if (planes == 0) {
        bool unknown = f.width == 0 && f.height == 0;
        bool known = f.width > 0 && f.height > 0 && f.width <= kMaxSide && f.height <= kMaxSide;
        if (!unknown && !known)
            return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                        "frame.width x frame.height: %d x %d; with format NONE give "
                        "0 x 0 (unknown) or a size in [1, %d]",
                        (int)f.width, (int)f.height, kMaxSide);
        *out = f;
        return CT_OK;
    }

    if (f.width < 1 || f.height < 1 || f.width > kMaxSide || f.height > kMaxSide)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "frame.width x frame.height: %d x %d is not in [1, %d]",
                    (int)f.width, (int)f.height, kMaxSide);
    const int32_t cw = (f.width + 1) / 2;
    const int32_t min_stride[3] = {
        packed_rgb(f.format) ? 3 * f.width : f.width,
        f.format == CT_FORMAT_NV12 ? 2 * cw : cw, cw};
    for (int p = 0; p < planes; p++) {
        if (!f.planes[p])
            return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                        "frame.planes[%d]: NULL for a %s frame", p, format_name(f.format));
        if (f.strides[p] < min_stride[p])
            return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                        "frame.strides[%d]: %d bytes is less than the plane's width, "
                        "%d bytes, of a %dx%d %s frame",
                        p, (int)f.strides[p], (int)min_stride[p], (int)f.width,
                        (int)f.height, format_name(f.format));
    }
    *out = f;
    return CT_OK;
}

int check_detections(const ct_detection *dets, size_t n, char *msg, size_t msg_len)
{
    if (n == 0)
        return CT_OK;
    if (!dets)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "dets: NULL with n = %zu", n);
    if (n > kMaxDetections)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "n: %zu detections in one step is more than %zu", n, kMaxDetections);
    for (size_t i = 0; i < n; i++) {
        const ct_detection &d = dets[i];
        const struct {
            const char *name;
            float value;
            bool positive;
        } fields[] = {{"left", d.left, false},
                      {"top", d.top, false},
                      {"width", d.width, true},
                      {"height", d.height, true}};
        for (const auto &fl : fields) {
            bool ok = std::isfinite(fl.value) && std::fabs(fl.value) <= kMaxCoordinate &&
                      (!fl.positive || fl.value > 0);
            if (!ok)
                return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                            "dets[%zu].%s: %g is not %s", i, fl.name, (double)fl.value,
                            fl.positive ? "a positive finite size up to 1e6"
                                        : "a finite coordinate within +-1e6");
        }
        if (!std::isfinite(d.score))
            return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                        "dets[%zu].score: %g is not finite", i, (double)d.score);
    }
    return CT_OK;
}

} // namespace ctrack
