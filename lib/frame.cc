#include "frame.h"

#include <cmath>
#include <cstdio>

#include "error.h"
#include "sized.h"

namespace ctrack {

namespace {

constexpr size_t kMaxDetections = 1 << 16;
constexpr double kMaxCoordinate = 1e6;

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

} // namespace

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
    switch (read_sized(in, in->size, kFrameSizeV1, &f)) {
    case SizedResult::too_small:
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "frame.size: %zu is smaller than any ct_frame (%zu); "
                    "fill it with ct_frame_default()",
                    in->size, kFrameSizeV1);
    case SizedResult::unknown_fields:
        return fail(msg, msg_len, CT_ERROR_UNSUPPORTED,
                    "frame.size: %zu bytes, of which this library knows %zu; "
                    "the newer fields are set",
                    in->size, sizeof(ct_frame));
    case SizedResult::ok:
        break;
    }

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

namespace {

#if defined(__GNUC__)
#define CT_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define CT_ALWAYS_INLINE inline
#endif

// One row of packed pixels (R at byte ri, B at byte bi): its luma, and each
// pixel's chroma before the 2x2 means. BT.601, limited range, in integers:
// OpenCV's COLOR_BGR2YUV_I420 up to rounding, and exactly the Python
// binding's bgr_to_i420(). Adding 128 << 8 before the shift keeps the chroma
// sums positive, so that the shift is a floor in C as in numpy. Unit-stride
// outputs and no branches, so that the loop vectorises wherever the target
// can read every third byte (below).
template <int ri, int bi>
CT_ALWAYS_INLINE void
convert_row(const uint8_t *__restrict src, int w, uint8_t *__restrict y, int16_t *__restrict u,
            int16_t *__restrict v)
{
    for (int x = 0; x < w; x++) {
        const int r = src[3 * x + ri], g = src[3 * x + 1], b = src[3 * x + bi];
        y[x] = (uint8_t)(((66 * r + 129 * g + 25 * b + 128) >> 8) + 16);
        u[x] = (int16_t)((-38 * r - 74 * g + 112 * b + 128 + (128 << 8)) >> 8);
        v[x] = (int16_t)((112 * r - 94 * g - 18 * b + 128 + (128 << 8)) >> 8);
    }
}

// Reading every third byte vectorises only with byte shuffles, which x86-64's
// baseline (SSE2) lacks: there the rows are converted by the best of three
// builds, chosen once when the library loads (with AVX2, 5 times faster
// than the baseline's here). Other targets (NEON) have the loads the loop
// needs.
#if defined(__x86_64__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define CT_ROW_CLONES __attribute__((target_clones("avx2", "ssse3", "default")))
#endif
#endif
#ifndef CT_ROW_CLONES
#define CT_ROW_CLONES
#endif

CT_ROW_CLONES void bgr_row(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v)
{
    convert_row<2, 0>(src, w, y, u, v);
}

CT_ROW_CLONES void rgb_row(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v)
{
    convert_row<0, 2>(src, w, y, u, v);
}

// The mean of each 2x2 block of two rows' chroma (an odd last column
// counts twice).
void block_means(const int16_t *__restrict a, const int16_t *__restrict b, int w,
                 uint8_t *__restrict out)
{
    const int pairs = w / 2;
    for (int c = 0; c < pairs; c++)
        out[c] = (uint8_t)((a[2 * c] + a[2 * c + 1] + b[2 * c] + b[2 * c + 1] + 2) >> 2);
    if (w % 2)
        out[pairs] = (uint8_t)((2 * a[w - 1] + 2 * b[w - 1] + 2) >> 2);
}

} // namespace

Planes packed_to_i420(const ct_frame &f, std::vector<int16_t> *buf)
{
    const int w = f.width, h = f.height, cw = (w + 1) / 2, ch = (h + 1) / 2;
    // The planes' bytes, then two rows of each pixel's chroma (U and V for
    // the block's top row, then for its bottom row).
    const size_t planes = ((size_t)w * h + 2 * (size_t)cw * ch + 1) / 2;
    buf->resize(planes + 4 * (size_t)w);
    uint8_t *const Y = reinterpret_cast<uint8_t *>(buf->data());
    uint8_t *const U = Y + (size_t)w * h;
    uint8_t *const V = U + (size_t)cw * ch;
    int16_t *const rows = buf->data() + planes;
    int16_t *const u0 = rows, *const v0 = rows + w, *const u1 = rows + 2 * w,
                   *const v1 = rows + 3 * w;
    const bool rgb = f.format == CT_FORMAT_RGB24;
    auto row = [&](int y, int16_t *u, int16_t *v) {
        const uint8_t *src = f.planes[0] + (size_t)y * f.strides[0];
        (rgb ? rgb_row : bgr_row)(src, w, Y + (size_t)y * w, u, v);
    };
    for (int cy = 0; cy < ch; cy++) {
        row(2 * cy, u0, v0);
        // An odd last row counts twice (the image's edge repeated).
        const bool pair = 2 * cy + 1 < h;
        if (pair)
            row(2 * cy + 1, u1, v1);
        block_means(u0, pair ? u1 : u0, w, U + (size_t)cy * cw);
        block_means(v0, pair ? v1 : v0, w, V + (size_t)cy * cw);
    }
    Planes p;
    p.width = w;
    p.height = h;
    p.y = Y;
    p.u = U;
    p.v = V;
    p.y_stride = w;
    p.u_stride = p.v_stride = cw;
    p.color = true;
    return p;
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
