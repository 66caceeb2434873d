// Kernel-based mean shift on colour histograms, in integer arithmetic
// (docs/algorithm.md, "Mean shift"; Comaniciu, Ramesh and Meer 2003, with the
// corrected background-weighted histogram of Ning et al. 2012).
#ifndef CTRACK_MEANSHIFT_H
#define CTRACK_MEANSHIFT_H

#include <algorithm>
#include <cstdint>
#include <vector>

#include "base/memory.h"

#include "base/planes.h"

namespace ctrack {

// 8 x 8 x 8 bins of quantised Y, U, V (grey frames use the first 32, of Y).
constexpr int kHistBins = 512;
// Histograms are normalised to sum to kQ16 (1.0 in Q16).
constexpr uint32_t kQ16 = 65536;
// About this many samples a window, at least: the sampling step is
// floor(sqrt(ellipse area / kTargetSamples)), so a window of fewer than four
// times this many pixels reads them all, and every window reads at most
// four times this many. It sets the cost: see docs/notes/meanshift.md.
constexpr double kTargetSamples = 300;
// The rings around a window (background weighting, scale) likewise.
constexpr double kTargetRingSamples = 300;

// A track's colour model: histograms in Q16.
struct ColorModel {
    uint16_t q[kHistBins] = {};  // the target as observed (eq. 9 blends this one)
    uint16_t qw[kHistBins] = {}; // q weighted against the surrounding background (CBWH)
    bool valid = false;
    bool color = false;     // built from a colour frame (else grey)
};

struct MeanShiftParams {
    int max_iterations = 10;  // step 8: at most this many moves
    int max_halvings = 4;     // step 7: at most this many halvings a move
    double epsilon = 0.5;     // step 8: stop when a move is shorter (pixels)
    double scale_step = 0.05; // scales {1 - d, 1, 1 + d}; 0: no scale change
    // A scale other than 1 must beat scale 1 by this much (Q16) of the scale
    // criterion: the size regulariser.
    int scale_margin = 200;
    // Coarse to fine: when the similarity at the start is below
    // coarse_below (Q16; 0: never), search first with a window coarse_scale
    // times larger.
    double coarse_scale = 1.5;
    int coarse_below = 0;
};

struct MeanShiftResult {
    MeanShiftResult() = default;
    MeanShiftResult(double x, double y, double w, double h) : cx(x), cy(y), width(w), height(h) {}
    double cx = 0, cy = 0, width = 0, height = 0;
    int rho = 0;          // Bhattacharyya coefficient at the result, Q16
    int iterations = 0;
};

// The Epanechnikov kernel's profile in Q12: kKernelOne at the ellipse's
// edge.
constexpr int kKernelOne = 4096;

// d^2 / h2 in Q12, at most kKernelOne (a sample's offset d from the
// window's centre and the squared half-side h2, both in Q8): exact in 64-bit
// integers while |d| < 2^25 (windows under 131,072 pixels), past which
// d^2 * kKernelOne could overflow and the ratio is taken in floating point.
inline int32_t kernel_term(int64_t d, int64_t h2)
{
    constexpr int64_t kExact = int64_t(1) << 25;
    if (d > -kExact && d < kExact)
        return (int32_t)std::min<int64_t>(kKernelOne, d * d * kKernelOne / h2);
    return (int32_t)std::min<double>(kKernelOne, (double)d * (double)d * kKernelOne / (double)h2);
}

// kernel_term(d, h2) for the many d of one window, without a division each:
// the quotient from a multiplication by 1 / h2 in floating point is within
// one of the exact one, and two integer comparisons settle it. Windows so
// large that those products could overflow (h2 >= 2^50: half-sides over
// 2^17 pixels) divide (check_meanshift compares the two).
class KernelTerm {
public:
    explicit KernelTerm(int64_t h2) : h2_(h2), inv_(1.0 / (double)h2), divide_(h2 >= kHuge) {}
    int32_t operator()(int64_t d) const
    {
        constexpr int64_t kExact = int64_t(1) << 25;
        if (divide_ || d <= -kExact || d >= kExact)
            return kernel_term(d, h2_);
        const int64_t d2 = d * d;
        if (d2 >= h2_)
            return kKernelOne; // the quotient is kKernelOne or more
        const int64_t n = d2 * kKernelOne;
        int64_t q = (int64_t)((double)n * inv_); // at most kKernelOne: q * h2_ < 2^63
        if (q * h2_ > n)
            q--;
        else if ((q + 1) * h2_ <= n)
            q++;
        return (int32_t)q;
    }

private:
    static constexpr int64_t kHuge = int64_t(1) << 50;
    int64_t h2_;
    double inv_;
    bool divide_;
};

// sqrt(i / 65536) in Q16 for i in [0, 65535], from a table made at compile time.
uint32_t sqrt_q16(uint32_t i);

// The histogram bin of a colour (8 levels of each) and of a grey level (32).
inline int colour_bin(int Y, int U, int V)
{
    return ((Y >> 5) << 6) | ((U >> 5) << 3) | (V >> 5);
}
inline int grey_bin(int Y)
{
    return Y >> 3;
}

// The histogram bin of pixel (x, y).
inline int bin_of(const Planes &img, int x, int y)
{
    int Y = img.y[(size_t)y * img.y_stride + x];
    if (!img.color)
        return grey_bin(Y);
    int cx = (x >> 1) * img.c_step, cy = y >> 1;
    return colour_bin(Y, img.u[(size_t)cy * img.u_stride + cx],
                      img.v[(size_t)cy * img.v_stride + cx]);
}

// The work of one tracker's mean shift; holds only scratch buffers, which
// keep their capacity, so tracking does not allocate in steady state.
class MeanShift {
public:
    // Builds the model of the box (centre cx, cy; size w x h) in the frame.
    void build(const Planes &img, double cx, double cy, double w, double h, ColorModel *m);
    // Eq. (9): q <- mu q_observed + (1 - mu) q, mu in Q8 (0..256), and the
    // background weighting recomputed around the box; only when the box
    // still looks like the model (rho >= min_rho, Q16). Returns whether it
    // learnt.
    bool learn(const Planes &img, double cx, double cy, double w, double h, int mu_q8,
               int min_rho, ColorModel *m);
    // Bhattacharyya coefficient (Q16) between the model and the box.
    int similarity(const Planes &img, double cx, double cy, double w, double h,
                   const ColorModel &m);
    // One mean shift step (eq. 12 and 13) of the window centred at (cx, cy)
    // with half sizes hw, hh: the weighted centroid of its samples, each
    // weighted by sqrt(q_u / p_u) of its bin. Returns false when the window
    // holds nothing. `weights` (kHistBins, Q16), when given, receives the
    // weight of every bin present in the window (others untouched).
    bool step(const Planes &img, double cx, double cy, double hw, double hh,
              const ColorModel &m, double *nx, double *ny, uint32_t *weights = nullptr);
    // Moves the window from (cx, cy) to the local maximum of similarity
    // (steps 7 and 8 of the paper's algorithm), coarse to fine when the start
    // is far off; the size stays.
    MeanShiftResult track(const Planes &img, double cx, double cy, double w, double h,
                          const ColorModel &m, const MeanShiftParams &p);
    // Steps 7 and 8 from (cx, cy) at this window size (track() without its
    // coarse search).
    MeanShiftResult converge(const Planes &img, double cx, double cy, double w, double h,
                             const ColorModel &m, const MeanShiftParams &p);
    // Multiscale: replaces r's size by the best of {1 - d, 1, 1 + d} times it
    // at r's centre (and r->rho by that window's), judged by contrast():
    // similarity alone cannot see a person grow, since every window inside
    // them looks the same.
    void scale(const Planes &img, const ColorModel &m, const MeanShiftParams &p,
               MeanShiftResult *r);

    size_t memory_bytes() const
    {
        return bins_.capacity() * sizeof(uint16_t) + runs_.capacity() * sizeof(Run) +
               (columns_.capacity() + chroma_.capacity()) * sizeof(int32_t);
    }

private:
    // The samples of one row: at x, x + step, ... (count of them), row y;
    // their bins are the next `count` of bins_.
    struct Run {
        int32_t x, y, count;
    };
    // Samples the ellipse inscribed in the box: fills runs_, bins_ and the
    // raw kernel-weighted histogram hist_; returns its total.
    uint64_t sample(const Planes &img, double cx, double cy, double hw, double hh);
    // The raw histogram as Q16 probabilities into out (all bins).
    void normalise(uint64_t total, uint16_t *out) const;
    bool centroid(uint64_t total, const ColorModel &m, double *nx, double *ny,
                  uint32_t *weights);
    // rho of the raw histogram (total) against a Q16 model.
    int rho(uint64_t total, const uint16_t *model) const;
    // Scale criterion (Q16, may be negative): how much more the window is
    // like the model than the ring just around it, whose area equals the
    // window's. A window smaller than the person has the person in its ring;
    // a larger one has background inside.
    int contrast(const Planes &img, double cx, double cy, double hw, double hh,
                 const ColorModel &m);
    // Histogram of the ring around the box, Q16 (uniform weights).
    void background(const Planes &img, double cx, double cy, double w, double h,
                    double grow, uint16_t *out);
    void weight_against_background(const Planes &img, double cx, double cy, double w,
                                   double h, ColorModel *m);
    void list_touched();
    // chroma_: the offsets in a chroma row of columns x0, x0 + step, ...
    // (ncols of them).
    void chroma_columns(const Planes &img, int x0, int step, int ncols);
    void clear_hist();

    // This window's samples, row by row: n_runs_ runs, their bins in order.
    Vec<Run> runs_;
    Vec<uint16_t> bins_;
    size_t n_runs_ = 0;
    int step_ = 1;
    Vec<int32_t> columns_; // each sampled column's kernel term
    Vec<int32_t> chroma_;  // and its offset in a chroma row
    uint32_t hist_[kHistBins] = {};
    uint16_t touched_[kHistBins]; // the bins of hist_ that are not 0
    int n_touched_ = 0;
};

} // namespace ctrack

#endif
