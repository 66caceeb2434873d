// The pixel kernels built for several CPU feature levels, as a table of
// function pointers filled for the CPU at hand (dav1d's way): each tracker
// fills its own when it is created, from cpu_flags(). The portable build
// of each kernel is the reference; tests/check_dsp.cc checks every other
// against it, bit for bit.
#ifndef CTRACK_DSP_H
#define CTRACK_DSP_H

#include <cstddef>
#include <cstdint>

// A kernel's body, written once and inlined into each build of it (each
// target's attributes then apply to the whole of it).
#if defined(__GNUC__)
#define CT_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define CT_ALWAYS_INLINE inline
#endif

namespace ctrack {

// One row of the background model's update (background.cc): the frame's
// samples at the working pixels (iy, iu, iv), the model before the frame
// (om, ov, ou, ow), the model after it and the foreground mask (my, vy, mu,
// mv, mask), w pixels; frozen pixels are not learnt. Unless noise_y is
// null, the image's differences from the model before the frame go there,
// |I - M|, and to noise_c the larger of the chroma's (colour rows). A
// shadow's ratio to the model is taken above the scene's black level.
struct BgRow {
    const uint8_t *iy, *iu, *iv, *om, *ov, *ou, *ow, *frozen;
    uint8_t *my, *vy, *mu, *mv, *mask;
    uint8_t *noise_y, *noise_c;
    int w;
    bool color, warm;
    int step, vmin, chroma_fg, shadow_chroma, black;
};

// Gathering one row's samples: luma every `scale`-th pixel of src_y (1, 2
// or 4), through lut unless it is null, into iy; when su is not null, the
// chroma sample of each working pixel from su and sv into iu and iv: sample
// x * c_step, or (x >> 1) * c_step when c_half (scale 1: two working pixels
// share one 4:2:0 sample). I420 at scale 2 (c_step 1) is read in place and
// never gathered.
// The model's constants its row kernels share: V follows kSigmaDeltaN |I -
// M| (Sigma-Delta's amplification) up to kBgVMax, and a pixel darker than
// the background by a ratio in [kBgShadowLow, kBgShadowHigh] sixteenths
// (with its colour) is a shadow.
constexpr int kSigmaDeltaN = 4;
constexpr int kBgVMax = 80;
constexpr int kBgShadowLow = 8, kBgShadowHigh = 15;

struct BgGather {
    const uint8_t *src_y, *lut, *su, *sv;
    // The frame's row under src_y: each luma sample is then the mean of
    // the 2 x 2 pixels at its block's top left (null: the top-left pixel).
    const uint8_t *src_y2 = nullptr;
    int pairs = 0; // the samples whose pixel has a right neighbour (with src_y2)
    uint8_t *iy, *iu, *iv;
    int w, c_step, scale = 2;
    bool c_half = false;
};

struct Dsp {
    // One row of packed pixels to its luma, and each pixel's chroma before
    // the 2x2 means (convert.cc): BGR24 and RGB24.
    void (*bgr_row)(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v);
    void (*rgb_row)(const uint8_t *src, int w, uint8_t *y, int16_t *u, int16_t *v);
    // The background model (background.cc).
    void (*bg_update_row)(const BgRow &row);
    void (*bg_gather_row)(const BgGather &row);
    // The nearest point to the query q (dim floats), the points stored by
    // dimension (dim rows of `stride` floats, stride a multiple of
    // kNearestLanes and at most kNearestMaxPoints, padded past the last point with infinities): its index (the
    // first of equals) and squared distance, summed as flann::L2 sums it
    // (nnindex.cc).
    int (*nn_nearest)(const float *by_dim, int stride, int dim, const float *q, float *dist2);
    // The closing's rows (regions.cc), max when max is true, else min:
    // dst[x] = op(src[x - 1], src[x], src[x + 1]) for x in [1, n - 1), and
    // dst = op of `rows` rows of n bytes stride apart (1 to 5 rows).
    void (*close_row3)(const uint8_t *src, uint8_t *dst, int n, bool max);
    void (*close_rows)(const uint8_t *src, size_t stride, int rows, uint8_t *dst, int n,
                       bool max);
};

// The nearest-neighbour kernel's rows: a multiple of kNearestLanes points,
// at most kNearestMaxPoints.
constexpr int kNearestLanes = 8, kNearestMaxPoints = 128;

// The portable build of Dsp::nn_nearest, for a search with no table.
int nn_nearest_c(const float *by_dim, int stride, int dim, const float *q, float *dist2);

// Fills every entry with the fastest build the flags (CpuFlag bits) allow.
void dsp_init(Dsp *dsp, unsigned flags);

// Each kernel file's part of dsp_init().
void background_dsp_init(Dsp *dsp, unsigned flags);
void convert_dsp_init(Dsp *dsp, unsigned flags);
void nnindex_dsp_init(Dsp *dsp, unsigned flags);
void regions_dsp_init(Dsp *dsp, unsigned flags);

} // namespace ctrack

#endif
