#include "appearance/appearance.h"

#include "dsp/cpu.h"

#include <algorithm>
#include <cmath>

namespace ctrack {

namespace {

// Chroma counts for more than one luma sample: a shirt's colour tells
// people apart better than its shading.
constexpr float kChromaWeight = 2.0f;

inline int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

} // namespace

namespace {

// The pixels [a, b] of a plane (subsampling shift, w samples across) that
// the interval [x0, x1) of luma coordinates reads, clamped to the plane;
// at least one.
struct Span {
    int a, b;
};
inline Span span_of(double x0, double x1, int shift, int w)
{
    const int a = clampi((int)std::floor(x0) >> shift, 0, w - 1);
    return Span{a, clampi(((int)std::ceil(x1) - 1) >> shift, a, w - 1)};
}

} // namespace

// The box's cells and the 3 x 3 sub-blocks of each as spans of columns
// and of rows (those of a column of cells are the same in every row of
// cells); each block's sum is then a sum of the columns' sums over its
// rows, taken once for each band of rows: every pixel is read once a band,
// with no per-block setup. Exact integer sums, so the same means as block
// by block (check_appearance compares with that).
void Describer::describe(const Planes &img, double left, double top, double width,
                         double height, float *out)
{
    // A row of sums as wide as the frame (no span is wider) from the
    // first box on: later boxes, however wide, need no more.
    cols_.reserve((size_t)img.width);
    const double cw = width / kGridX, ch = height / kGridY;
    // Luma: 3 sub-blocks a cell each way; chroma: the cell.
    Span lx[3 * kGridX], ly[3 * kGridY], cx[kGridX], cy[kGridY];
    // Along one axis: `cells` cells of `cell` from `start`, over `size`
    // luma samples.
    auto axis = [](double start, double cell, int cells, int size, Span *luma, Span *chroma) {
        for (int g = 0; g < cells; g++) {
            const double a = start + g * cell;
            for (int k = 0; k < 3; k++)
                luma[3 * g + k] = span_of(a + k * cell / 3, a + (k + 1) * cell / 3, 0, size);
            chroma[g] = span_of(a, a + cell, 1, (size + 1) >> 1);
        }
    };
    axis(left, cw, kGridX, img.width, lx, cx);
    axis(top, ch, kGridY, img.height, ly, cy);
    // out[(cell) * kDescDim + k] for k in [0, 9) luma, 9 and 10 chroma.
    auto sums = [&](const uint8_t *p, int stride, int step, const Span *xs, int nx,
                    const Span *ys, int ny, int k0, int dk, float scale) {
        int lo = xs[0].a, hi = xs[0].b;
        for (int i = 1; i < nx; i++) {
            lo = std::min(lo, xs[i].a);
            hi = std::max(hi, xs[i].b);
        }
        cols_.resize((size_t)(hi - lo + 1));
        uint32_t *col = cols_.data();
        for (int j = 0; j < ny; j++) {
            const Span &r = ys[j];
            std::fill(col, col + (hi - lo + 1), 0u);
            for (int y = r.a; y <= r.b; y++) {
                const uint8_t *row = p + (size_t)y * stride;
                if (step == 1) {
                    const uint8_t *__restrict src = row + lo;
                    uint32_t *__restrict dst = col;
                    for (int x = 0; x <= hi - lo; x++)
                        dst[x] += src[x];
                } else {
                    for (int x = lo; x <= hi; x++)
                        col[x - lo] += row[(size_t)x * step];
                }
            }
            const unsigned rows = (unsigned)(r.b - r.a + 1);
            for (int i = 0; i < nx; i++) {
                unsigned sum = 0;
                for (int x = xs[i].a; x <= xs[i].b; x++)
                    sum += col[x - lo];
                const unsigned n = rows * (unsigned)(xs[i].b - xs[i].a + 1);
                // Block (i, j) of the grid: cell (i / dk, j / dk), entry
                // (j % dk) * dk + i % dk (luma), or k0 (chroma).
                const int cell = (j / dk) * kGridX + i / dk;
                const int k = k0 + (dk == 3 ? (j % 3) * 3 + i % 3 : 0);
                out[(size_t)cell * kDescDim + k] = scale * ((float)sum / (float)n);
            }
        }
    };
    sums(img.y, img.y_stride, 1, lx, 3 * kGridX, ly, 3 * kGridY, 0, 3, 1.0f);
    if (img.color) {
        sums(img.u, img.u_stride, img.c_step, cx, kGridX, cy, kGridY, 9, 1, kChromaWeight);
        sums(img.v, img.v_stride, img.c_step, cx, kGridX, cy, kGridY, 10, 1, kChromaWeight);
    } else {
        for (int c = 0; c < kPoints; c++)
            out[(size_t)c * kDescDim + 9] = out[(size_t)c * kDescDim + 10] = 0;
    }
}

void describe(const Planes &img, double left, double top, double width, double height,
              float *out)
{
    Describer().describe(img, left, top, width, height, out);
}

void Template::build(const float *descriptors, bool tree)
{
    desc.assign(descriptors, descriptors + (size_t)kPoints * kDescDim);
    index.build(desc.data(), kPoints, kDescDim, tree);
}

void Ddis::neighbours(const Template &p, const float *q, float eps)
{
    p.index.search(q, kPoints, index_, dist2_, eps, &dsp_);
    std::fill(kappa_, kappa_ + kPoints, 0);
    for (int j = 0; j < kPoints; j++)
        kappa_[index_[j]]++;
}

Ddis::Ddis()
{
    dsp_init(&dsp_, cpu_flags());
    for (int k = 0; k <= kPoints; k++)
        exp_[k] = std::exp(1.0 - k);
}

double Ddis::ddis(const Template &p, const float *q, float eps)
{
    neighbours(p, q, eps);
    double sum = 0;
    for (int j = 0; j < kPoints; j++) {
        const int i = index_[j];
        const int dx = (i % kGridX) - (j % kGridX), dy = (i / kGridX) - (j / kGridX);
        const double r = std::sqrt((double)(dx * dx + dy * dy)); // in grid cells
        sum += exp_[kappa_[i]] / (1 + r);
    }
    return sum / kPoints; // m = n = kPoints
}

double Ddis::dis(const Template &p, const float *q, float eps)
{
    neighbours(p, q, eps);
    int distinct = 0;
    for (int i = 0; i < kPoints; i++)
        distinct += kappa_[i] > 0;
    return (double)distinct / kPoints;
}

} // namespace ctrack
