#include "pixels/prime.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace ctrack {

namespace {

// The planes of a frame's format: rows, and bytes a row.
struct PlaneShape {
    int rows;
    size_t row_bytes;
};

int plane_shapes(const ct_frame &f, PlaneShape out[3])
{
    const size_t w = (size_t)f.width;
    const int h = f.height;
    const size_t cw = (w + 1) / 2;
    const int ch = (h + 1) / 2;
    switch (f.format) {
    case CT_FORMAT_I420:
        out[0] = {h, w};
        out[1] = out[2] = {ch, cw};
        return 3;
    case CT_FORMAT_NV12:
        out[0] = {h, w};
        out[1] = {ch, 2 * cw};
        return 2;
    case CT_FORMAT_BGR24:
    case CT_FORMAT_RGB24: out[0] = {h, 3 * w}; return 1;
    default: out[0] = {h, w}; return 1; // CT_FORMAT_GRAY8
    }
}

const uint8_t *row(const ct_frame &f, int plane, int y)
{
    return f.planes[plane] + (ptrdiff_t)y * f.strides[plane];
}

} // namespace

void PackedFrame::shape(const ct_frame &like)
{
    PlaneShape ps[3];
    const int n = plane_shapes(like, ps);
    size_t total = 0;
    for (int p = 0; p < n; p++)
        total += ps[p].row_bytes * (size_t)ps[p].rows;
    bytes_.resize(total);
    frame_ = like;
    size_t offset = 0;
    for (int p = 0; p < 3; p++) {
        frame_.planes[p] = p < n ? bytes_.data() + offset : nullptr;
        frame_.strides[p] = p < n ? (int32_t)ps[p].row_bytes : 0;
        if (p < n)
            offset += ps[p].row_bytes * (size_t)ps[p].rows;
    }
}

void median_frame(const ct_frame *frames, size_t n, PackedFrame *median)
{
    const size_t k = std::min(n, kPrimeMedianFrames);
    const ct_frame *picked[kPrimeMedianFrames];
    for (size_t j = 0; j < k; j++)
        picked[j] = &frames[(2 * j + 1) * n / (2 * k)];
    median->shape(frames[0]);
    const ct_frame &m = median->frame();
    PlaneShape ps[3];
    const int planes = plane_shapes(m, ps);
    size_t widest = 0;
    for (int p = 0; p < planes; p++)
        widest = std::max(widest, ps[p].row_bytes);
    // The k rows of a row, copied, then ordered in place byte by byte: a
    // bubble pass takes each byte's largest of the rows below the ones
    // already passed to the top, so k - k / 2 passes leave rows k / 2 and
    // up in order, and row k / 2 the median (the upper one of an even k).
    // Each comparison runs along the row, where the compiler vectorises it.
    Vec<uint8_t> rows(k * widest);
    for (int p = 0; p < planes; p++) {
        const size_t len = ps[p].row_bytes;
        for (int y = 0; y < ps[p].rows; y++) {
            for (size_t j = 0; j < k; j++)
                std::copy(row(*picked[j], p, y), row(*picked[j], p, y) + len,
                          rows.data() + j * len);
            for (size_t pass = 0; pass < k - k / 2; pass++)
                for (size_t j = 0; j + 1 < k - pass; j++) {
                    uint8_t *a = rows.data() + j * len, *b = a + len;
                    for (size_t x = 0; x < len; x++) {
                        const uint8_t lo = std::min(a[x], b[x]), hi = std::max(a[x], b[x]);
                        a[x] = lo;
                        b[x] = hi;
                    }
                }
            std::copy(rows.data() + k / 2 * len, rows.data() + (k / 2 + 1) * len,
                      const_cast<uint8_t *>(row(m, p, y)));
        }
    }
}

void clean_frame(const ct_frame &frame, const PackedFrame &median, double k, PackedFrame *out)
{
    out->shape(frame);
    const ct_frame &m = median.frame();
    const ct_frame &o = out->frame();
    PlaneShape ps[3];
    const int planes = plane_shapes(frame, ps);
    for (int p = 0; p < planes; p++) {
        // The plane's noise: the median absolute difference from the
        // median frame, on every 7th byte of every 4th row (the people are
        // a minority of the bytes).
        uint64_t hist[256] = {};
        uint64_t count = 0;
        for (int y = 0; y < ps[p].rows; y += 4) {
            const uint8_t *a = row(frame, p, y), *b = row(m, p, y);
            for (size_t x = 0; x < ps[p].row_bytes; x += 7) {
                hist[std::abs(a[x] - b[x])]++;
                count++;
            }
        }
        int mad = 0;
        for (uint64_t c = hist[0]; 2 * c < count && mad < 255; c += hist[mad])
            mad++;
        const int limit = (int)std::lround(k * 1.4826 * std::max(mad, 1));
        for (int y = 0; y < ps[p].rows; y++) {
            const uint8_t *a = row(frame, p, y), *b = row(m, p, y);
            uint8_t *c = const_cast<uint8_t *>(row(o, p, y));
            for (size_t x = 0; x < ps[p].row_bytes; x++)
                c[x] = std::abs(a[x] - b[x]) > limit ? b[x] : a[x];
        }
    }
}

} // namespace ctrack
