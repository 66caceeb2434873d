#include "pixels/background.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "base/clock.h"
#include "base/tunable.h"
#include "dsp/cpu.h"
#include "pixels/camera_motion.h"
#include "pixels/mask.h"
#include "pixels/regions.h"

namespace ctrack {

namespace {

// V's lower bound (its upper one is kBgVMax, dsp.h): below it,
// compression and flicker would show (at the scene's usual contrast,
// below).
constexpr int kVMin = 25;
// While the model starts (its first kWarmupUs microseconds), M and V move
// up to kWarmupRate levels a second (at least one a frame), so that people
// present in the first frame leave no lasting ghost when they walk away. In
// time, not in frames: a 7 frames/s camera starts as a 25 frames/s one does.
// At 25 frames/s it is 12 frames of 8 levels (the bound falls between two
// frames, so that a timestamp's jitter does not add one). Counted in
// frames, a slow camera would keep its model fast for seconds and learn
// people who had just come in (docs/notes/pixels.md).
constexpr int64_t kWarmupUs = 460000;
constexpr int kWarmupRate = 200;
// The first frame has no interval behind it: it counts as one of 25
// frames/s.
constexpr int64_t kFirstFrameUs = 40000;

// The start's step for a frame interval_us after the last one (up to 2^64
// - 1: past 1.3 s the step is 255 anyway).
int warmup_step(uint64_t interval_us)
{
    const uint64_t levels =
        (kWarmupRate * std::min<uint64_t>(interval_us, 10000000) + 500000) / 1000000;
    return (int)std::min<uint64_t>(255, std::max<uint64_t>(1, levels));
}

// A pixel darker than the background by a ratio in [kBgShadowLow,
// kBgShadowHigh] (dsp.h) with chroma within kShadowChroma levels is a
// shadow.
constexpr int kShadowChroma = 8;
// A pixel whose chroma differs from the background's by more than this is
// foreground whatever its brightness (a red shirt on grey stone).
constexpr int kChromaForeground = 24;

// Sensor noise, learnt from the frames (NoiseLevel): the decisions never
// fall under these many standard deviations of the scene's noise, in luma
// (V's floor) and in chroma (the colour test and the shadows' tolerance).
// Chosen over three strengths of noise and two seeds each
// (docs/tuning.md, "The scene's noise, contrast and black level").
CT_TUNABLE(kLumaNoise, "CTRACK_LUMA_NOISE", 3.5);
constexpr double kChromaNoise = 4.0, kShadowNoise = 1.0;
// Where the frame's fine noise (NoiseLevel::fine) reaches kMeanNoise grey
// levels, each working pixel is the mean of the 2 x 2 frame pixels at its
// block's top left rather than the top-left one alone: the noise's
// deviation halves, and a person at the working scale keeps the shape one
// pixel of the block gives. Clean frames read 0.5 to 2.4 levels, ffmpeg's
// noise=alls=6 3.5 to 3.8; off again under kMeanNoiseOff times the level
// (docs/tuning.md, "Sensor noise: 2 x 2 means"). At scale 1 there is no
// block to average.
CT_TUNABLE(kMeanNoise, "CTRACK_MEAN_NOISE", 3.0);
constexpr double kMeanNoiseOff = 2.0 / 3.0;
// The median absolute difference of two pixels of Gaussian noise, in the
// noise's standard deviations (sqrt(2) times 0.6745).
constexpr double kMadOfDifference = 0.954;
// For the first kMotionS seconds the model holds the people of its first
// frames, and the frame's change from the frame before shows where people
// are (motion()): a change above kMotionFloor grey levels, and above
// kMotionOverMedian times the median change (the sensor's noise: most
// pixels are still background); docs/tuning.md, "The first second".
CT_TUNABLE(kMotionS, "CTRACK_MOTION_TIME", 1.2);
CT_TUNABLE(kMotionFloor, "CTRACK_MOTION_FLOOR", 15);
CT_TUNABLE(kMotionOverMedian, "CTRACK_MOTION_OVER_MEDIAN", 6);
// The median is taken over every kMotionGrid-th pixel.
constexpr size_t kMotionGrid = 7;

// The scene's contrast and black level (NoiseLevel). V's floor is kVMin at
// a contrast of kContrastRef grey levels (the model's median absolute
// deviation of luma) or more, and falls with it below, to kVMinLowest: a
// person's differences from the scene fall with its contrast. A shadow's
// ratio to the model is taken above the black level: the model's first
// percentile of luma less kBlackBelow, a little above video black (16),
// where a lifted black (haze, a washed-out picture) would make a dark
// coat's ratio to the ground a shadow's. Same docs/tuning.md section.
CT_TUNABLE(kContrastRef, "CTRACK_CONTRAST_REF", 41);
CT_TUNABLE(kBlackBelow, "CTRACK_BLACK_BELOW", 16);
constexpr int kVMinLowest = 10;

// The share of a blob's pixels that change by more than V's floor from a
// frame to the next in a blob that is alive (Background::live()). Noise
// alone changes about 1.3% of them (the difference of two frames has
// sqrt(2) times the noise, and the floor is 3.5 times it): the share asked
// is some four times that (docs/tuning.md, "An object put down").
CT_TUNABLE(kLiveFraction, "CTRACK_LIVE_FRACTION", 0.05);
// live() reads change from the frame before and from a frame kept until it
// is kLiveSpanS old. A pixel's sway at 0.5 Hz moves 0.3 pixels a frame at
// 10 frames/s and 0.13 at 25, which stirs too few pixels; over 0.3 s it
// moves up to 0.9 (docs/tuning.md, "A person standing from the first
// frame"). Counted in frames, the same sway would be alive at 10 frames/s
// and not at 25.
CT_TUNABLE(kLiveSpanS, "CTRACK_LIVE_SPAN", 0.3);
// A walker's trail (trail.h) is read and left out (0: neither; for the
// sweeps of docs/tuning.md, "A walker's trail").
CT_TUNABLE(kTrailOn, "CTRACK_TRAIL_ON", 1);

} // namespace

double Background::age_s(int64_t t_us) const
{
    return frames_ > 0 ? elapsed_s(t_us, start_us_) : 0.0;
}

Dsp Background::make_dsp()
{
    Dsp d;
    dsp_init(&d, cpu_flags());
    return d;
}

namespace {

// The exposure's deadband: a ratio within 1/32 of 1 is 1 (compression and
// people moving shift the median by less), so that a steady camera's frames
// are read as they are.
constexpr int kRatioOne = 64;
constexpr int kRatioDeadband = 2;
// Fewer usable samples than this, and the exposure is taken as the model's.
constexpr uint32_t kMinRatioSamples = 64;
// Model luma under this is too dark for a ratio.
constexpr int kMinRatioLuma = 16;

} // namespace

namespace {

// ceil(2^32 / d) for d in [1, 255]: n / d is (n * it) >> 32 for every n up
// to 2^16 (the error, under n / 2^32, never reaches the next integer,
// which is at least 1/255 away); check_background tries every n and d.
struct Reciprocals {
    uint64_t r[256];
    constexpr Reciprocals() : r()
    {
        for (int d = 1; d < 256; d++)
            r[d] = (((uint64_t)1 << 32) + (uint64_t)d - 1) / (uint64_t)d;
    }
};
constexpr Reciprocals kReciprocal;

} // namespace

uint32_t divide_small(uint32_t n, uint32_t d)
{
    return (uint32_t)(((uint64_t)n * kReciprocal.r[d]) >> 32);
}

const uint8_t *Background::frozen_row(const Rect *frozen, int n_frozen, int y)
{
    uint8_t *zeros = frozen_line_.data(), *line = zeros + w_;
    bool any = false;
    for (int k = 0; k < n_frozen; k++) {
        const Rect &r = frozen[k];
        const int x0 = std::max(0, r.x0), x1 = std::min(w_, r.x1);
        if (y < r.y0 || y >= r.y1 || x0 >= x1)
            continue;
        if (!any)
            std::memset(line, 0, (size_t)w_);
        any = true;
        std::memset(line + x0, 1, (size_t)(x1 - x0));
    }
    return any ? line : zeros;
}

double Background::exposure_ratio(const Planes &img, const Rect *frozen, int n_frozen)
{
    // Four histograms in turn (summed at the end): a sample never waits on
    // the one before it to count the same level, as neighbours mostly do.
    // Every sample is counted, by 1 when usable and else by 0 (no branch;
    // divide_small(n, 0) is 0).
    uint32_t hists[4][256] = {}, n = 0;
    for (int y = 0; y < h_; y += 4) {
        const uint8_t *src = img.y + (size_t)(y * scale_) * img.y_stride;
        const uint8_t *m = old_my_.data() + (size_t)y * w_;
        const uint8_t *f = frozen_row(frozen, n_frozen, y);
        for (int x = 0, k = 0; x < w_; x += 4, k++) {
            const uint32_t mx = m[x];
            const uint32_t use = (f[x] == 0) & (mx >= (uint32_t)kMinRatioLuma);
            const uint32_t q = divide_small(kRatioOne * src[x * scale_] + mx / 2, mx);
            hists[k & 3][std::min<uint32_t>(255, q)] += use;
            n += use;
        }
    }
    uint32_t hist[256];
    sum_of_four(hists[0], hists[1], hists[2], hists[3], hist);
    if (n < kMinRatioSamples)
        return 1.0;
    const int median = (int)median_of(hist, n);
    return std::abs(median - kRatioOne) <= kRatioDeadband ? 1.0 : (double)median / kRatioOne;
}

void Background::set_gain(double gain)
{
    gain_ = gain;
    for (int i = 0; i < 256; i++)
        gain_lut_[i] = (uint8_t)std::min(255L, std::lround(i / gain));
}

size_t Background::memory_bytes() const
{
    return my_.capacity() + vy_.capacity() + mu_.capacity() + mv_.capacity() +
           old_my_.capacity() + old_vy_.capacity() + old_mu_.capacity() + old_mv_.capacity() +
           luma_.capacity() + old_luma_.capacity() + ref_luma_.capacity() + motion_.capacity() +
           mask_.capacity() + frozen_line_.capacity() + line_y_.capacity() + line_u_.capacity() +
           line_v_.capacity() + line_vmax_.capacity() + line_dy_.capacity() +
           line_dc_.capacity() + noise_samples_.memory_bytes() +
           (columns_.capacity() + rows_.capacity() + old_columns_.capacity() +
            old_rows_.capacity()) *
               sizeof(int32_t);
}

void Background::swap_models()
{
    my_.swap(old_my_);
    vy_.swap(old_vy_);
    mu_.swap(old_mu_);
    mv_.swap(old_mv_);
    columns_.swap(old_columns_);
    rows_.swap(old_rows_);
    luma_.swap(old_luma_);
}

double Background::since_camera_moved_s(int64_t t_us) const
{
    return moved_us_ == kNever ? 1e9 : elapsed_s(t_us, moved_us_);
}

void Background::rollback()
{
    if (!kept_)
        return;
    swap_models();
    w_ = old_dims_.w;
    h_ = old_dims_.h;
    // A step that took the model finer failed (its buffers did not fit the
    // host's heap): the model stays at the scale it had from now on.
    if (old_dims_.frames > 0 && old_dims_.fw == fw_ && old_dims_.fh == fh_ &&
        old_dims_.scale > scale_)
        finest_ = old_dims_.scale;
    scale_ = old_dims_.scale;
    release_resampled();
    fw_ = old_dims_.fw;
    fh_ = old_dims_.fh;
    color_ = old_dims_.color;
    frames_ = old_dims_.frames;
    start_us_ = old_dims_.start_us;
    last_us_ = old_dims_.last_us;
    noise_ = old_dims_.noise;
    trail_ = old_dims_.trail;
    mean_2x2_ = old_dims_.mean_2x2;
    set_gain(old_dims_.gain);
    camera_moved_ = old_dims_.camera_moved;
    moved_us_ = old_dims_.moved_us;
    kept_ = false;
}

void Background::release_resampled()
{
    for (Vec<uint8_t> *v : {&rs_my_, &rs_vy_, &rs_mu_, &rs_mv_})
        Vec<uint8_t>(v->get_allocator()).swap(*v);
}

void Background::size_for(const Planes &img)
{
    fw_ = img.width;
    fh_ = img.height;
    color_ = img.color;
    w_ = (img.width + scale_ - 1) / scale_;
    h_ = (img.height + scale_ - 1) / scale_;
    const size_t n = (size_t)w_ * h_;
    my_.resize(n);
    vy_.resize(n);
    mu_.resize(n);
    mv_.resize(n); // grey frames leave the chroma alone: nothing reads it
    mask_.assign(n, 0);
    frozen_line_.assign(2 * (size_t)w_, 0);
    line_vmax_.assign(w_, kBgVMax);
}

// Sizes the model for the image. The update that follows starts it from
// the image itself: M and the chroma take its samples, V starts at kBgVMax.
void Background::start(const Planes &img)
{
    size_for(img);
    mu_.assign(mu_.size(), 128); // grey frames: no colour, and the loop leaves them
    mv_.assign(mv_.size(), 128);
    frames_ = 0;
    noise_ = NoiseLevel();
    trail_.reset();
}

void Background::resample(const Planes &img)
{
    const int so = old_dims_.scale, wo = old_dims_.w, ho = old_dims_.h;
    const size_t n = (size_t)w_ * h_;
    rs_my_.resize(n);
    rs_vy_.resize(n);
    rs_mu_.resize(n);
    rs_mv_.resize(n);
    const uint8_t *lut = gain_lut_;
    for (int y = 0; y < h_; y++) {
        const int fy = y * scale_;
        const int oy0 = std::min(fy / so, ho - 1), oy1 = std::min((fy + so - 1) / so, ho - 1);
        for (int x = 0; x < w_; x++) {
            const int fx = x * scale_;
            const int ox0 = std::min(fx / so, wo - 1), ox1 = std::min((fx + so - 1) / so, wo - 1);
            const size_t i = (size_t)y * w_ + x;
            const int I = lut[img.y[(size_t)fy * img.y_stride + fx]];
            int U = 128, V = 128;
            if (color_) {
                const size_t cy = (size_t)(fy >> 1), cx = (size_t)(fx >> 1);
                U = img.u[cy * img.u_stride + cx * img.c_step];
                V = img.v[cy * img.v_stride + cx * img.c_step];
            }
            if (fx > (wo - 1) * so || fy > (ho - 1) * so) {
                // Past the old model's last row or column (the image's last
                // few pixels, which it never sampled): started from the
                // frame, as the model starts.
                rs_my_[i] = (uint8_t)I;
                rs_vy_[i] = kBgVMax;
                rs_mu_[i] = (uint8_t)U;
                rs_mv_[i] = (uint8_t)V;
                continue;
            }
            // Of the old pixels around (up to four), the one whose model is
            // closest to the frame here: in luma for M and V, and apart in
            // chroma (4:2:0's chroma lies across the luma's edges).
            size_t best = (size_t)oy0 * wo + ox0, best_c = best;
            int best_d = 256, best_dc = 512;
            for (int oy = oy0; oy <= oy1; oy++)
                for (int ox = ox0; ox <= ox1; ox++) {
                    const size_t o = (size_t)oy * wo + ox;
                    const int d = std::abs(I - (int)old_my_[o]);
                    if (d < best_d) {
                        best_d = d;
                        best = o;
                    }
                    const int dc = std::abs(U - (int)old_mu_[o]) + std::abs(V - (int)old_mv_[o]);
                    if (dc < best_dc) {
                        best_dc = dc;
                        best_c = o;
                    }
                }
            rs_my_[i] = old_my_[best];
            rs_vy_[i] = old_vy_[best];
            rs_mu_[i] = old_mu_[best_c];
            rs_mv_[i] = old_mv_[best_c];
        }
    }
}

Background::Update Background::prepare(const Planes &img, int scale, const Rect *frozen,
                                       int n_frozen)
{
    // The model so far moves to the old buffers, kept for rollback(); the
    // update reads it there and writes the new one in place of the current.
    old_dims_ = Dims{w_,        h_,       fw_,    fh_,   scale_,         color_,   frames_,
                     start_us_, last_us_, noise_, gain_, camera_moved_, moved_us_, mean_2x2_,
                     trail_};
    swap_models();
    kept_ = true;
    scale = std::min(std::max(scale, finest_), kMaxScale);
    Update u;
    u.restart = frames_ == 0 || img.width != fw_ || img.height != fh_ || img.color != color_;
    u.rescale = !u.restart && scale != scale_;
    if (!u.restart) {
        const size_t n = (size_t)w_ * h_;
        my_.resize(n);
        vy_.resize(n);
        mu_.resize(n);
        mv_.resize(n); // grey frames leave the chroma alone: nothing reads it
        // A restart at another size (or scale) that failed and was rolled
        // back left these at that size.
        mask_.resize(n);
        if (frozen_line_.size() != 2 * (size_t)w_)
            frozen_line_.assign(2 * (size_t)w_, 0);
    }
    // The exposure against the model as it is (at its old scale, where the
    // frozen boxes, at the new one, do not apply).
    set_gain(u.restart ? 1.0
                       : exposure_ratio(img, u.rescale ? nullptr : frozen,
                                        u.rescale ? 0 : n_frozen));
    if (u.restart) {
        scale_ = scale;
        start(img);
    } else if (u.rescale) {
        scale_ = scale;
        size_for(img);
        resample(img);
    }
    return u;
}

BgRow Background::rates(int64_t t_us)
{
    const bool warm = elapsed_us(t_us, start_us_) < (uint64_t)kWarmupUs;
    const int step =
        warm ? warmup_step(frames_ == 0 ? kFirstFrameUs : elapsed_us(t_us, last_us_)) : 1;
    last_us_ = t_us;
    // While warming up, V moves as fast as M, and also where M has reached
    // the image: else V stays near kBgVMax, where it starts, for some 50
    // frames, and hides people with the background's contrast
    // (docs/notes/pixels.md).
    const int vmin_contrast =
        noise_.known()
            ? std::max(kVMinLowest,
                       (int)std::lround(kVMin * std::min(1.0, noise_.contrast / kContrastRef)))
            : kVMin;
    BgRow rates{};
    rates.step = step;
    rates.warm = warm;
    rates.vmin = std::max(vmin_contrast, (int)std::lround(kLumaNoise * noise_.luma));
    rates.chroma_fg =
        std::max(kChromaForeground, (int)std::lround(kChromaNoise * noise_.chroma));
    rates.shadow_chroma =
        std::max(kShadowChroma, (int)std::lround(kShadowNoise * noise_.chroma));
    rates.black = std::max(0, (int)std::lround(noise_.dark - kBlackBelow));
    return rates;
}

BgGather Background::gather(const Planes &img, int y, const uint8_t **iu,
                            const uint8_t **iv)
{
    const int sc = scale_;
    BgGather g;
    g.src_y = img.y + (size_t)(y * sc) * img.y_stride;
    if (mean_2x2_) {
        // The last row and column of an odd-sized frame pair with themselves.
        g.src_y2 = y * sc + 1 < img.height ? g.src_y + img.y_stride : g.src_y;
        g.pairs = std::min(w_, (img.width - 1 + sc - 1) / sc);
    }
    g.lut = gain_ == 1.0 ? nullptr : gain_lut_;
    g.w = w_;
    g.scale = sc;
    g.iy = line_y_.data();
    g.iu = line_u_.data();
    g.iv = line_v_.data();
    g.su = g.sv = nullptr;
    // The 4:2:0 chroma sample under working pixel x: x * scale / 2.
    g.c_half = sc == 1;
    g.c_step = (int)img.c_step * (sc == 1 ? 1 : sc / 2);
    *iu = g.iu;
    *iv = g.iv;
    if (color_) {
        g.su = img.u + (size_t)((y * sc) >> 1) * img.u_stride;
        g.sv = img.v + (size_t)((y * sc) >> 1) * img.v_stride;
        if (g.c_step == 1 && !g.c_half) { // I420 at scale 2: read in place
            *iu = g.su;
            *iv = g.sv;
        }
    }
    return g;
}

void Background::update_rows(const Planes &img, const Rect *frozen, int n_frozen,
                             const BgRow &rates, Update u, bool sample)
{
    const bool color = color_;
    const int w = w_, h = h_;
    // Each row's samples are gathered first into contiguous buffers (I420's
    // chroma is read in place), so that the update reads unit-stride arrays.
    line_y_.resize(w);
    line_u_.resize(w);
    line_v_.resize(w);
    line_dy_.resize(w);
    line_dc_.resize(w);
    columns_.assign(w, 0);
    rows_.assign(h, 0);
    if (keep_luma_)
        luma_.resize((size_t)w * h);
    // A trail is read against the frame before, at the same size and scale.
    const bool trail = kTrailOn > 0 && keep_luma_ && !u.restart && !u.rescale &&
                       old_luma_.size() == (size_t)w * h;
    for (int y = 0; y < h; y++) {
        const uint8_t *iu, *iv;
        dsp_.bg_gather_row(gather(img, y, &iu, &iv));
        const size_t row = (size_t)y * w;
        const uint8_t *iy = line_y_.data();
        int32_t sum = 0;
        for (int x = 0; x < w; x++) {
            columns_[x] += iy[x];
            sum += iy[x];
        }
        rows_[y] = sum;
        if (keep_luma_)
            std::memcpy(luma_.data() + (size_t)y * w, iy, (size_t)w);
        const uint8_t *frozen_y = frozen_row(frozen, n_frozen, y);
        // The model before this frame: the old buffers, or on a (re)start
        // the image's own samples (and V at kBgVMax), or at a new scale the
        // old model resampled. Never the buffers written.
        BgRow r = rates;
        r.om = u.restart ? iy : (u.rescale ? rs_my_ : old_my_).data() + row;
        r.ov = u.restart ? line_vmax_.data() : (u.rescale ? rs_vy_ : old_vy_).data() + row;
        r.ou = u.restart ? iu : (u.rescale ? rs_mu_ : old_mu_).data() + row;
        r.ow = u.restart ? iv : (u.rescale ? rs_mv_ : old_mv_).data() + row;
        // The noise's rows: the update leaves the image's differences from
        // the model before it in line_dy_ and line_dc_.
        const bool noise_row = sample && y % 4 == 0;
        r.noise_y = noise_row ? line_dy_.data() : nullptr;
        r.noise_c = line_dc_.data();
        r.iy = iy;
        r.iu = iu;
        r.iv = iv;
        r.frozen = frozen_y;
        r.my = my_.data() + row;
        r.vy = vy_.data() + row;
        r.mu = mu_.data() + row;
        r.mv = mv_.data() + row;
        r.mask = mask_.data() + row;
        r.w = w;
        r.color = color;
        dsp_.bg_update_row(r);
        // The trail's weight is read on every 4th row (as the noise is),
        // and left out of every row once it is known.
        const bool trail_row = y % 4 == 0;
        if (trail && (trail_row || trail_.known()))
            leave_trail(r, row, trail_row);
        if (noise_row) {
            noise_samples_.sample(line_dy_.data(), color ? line_dc_.data() : nullptr, frozen_y,
                                  w);
            noise_samples_.levels(r.my, w);
        }
    }
}

void Background::leave_trail(const BgRow &r, size_t row, bool sample)
{
    // Where the frame before's luma differed from the background by more
    // than V and this frame's differs on the same side, by less, the ratio
    // of the two differences is sampled, and a trail's is background.
    const uint8_t *last = old_luma_.data() + row;
    const uint8_t *iy = r.iy, *my = r.my, *vy = r.vy;
    uint8_t *mask = r.mask;
    const int w = r.w;
    // Most of a mask is background, skipped eight bytes at a time.
    for (int x = first_nonzero(mask, 0, w); x < w; x = first_nonzero(mask, x + 1, w)) {
        const int d = iy[x] - my[x], before = last[x] - my[x];
        const int now = std::abs(d), then = std::abs(before);
        if (d * before <= 0 || then <= vy[x] || now >= then)
            continue;
        if (sample)
            trail_.sample(now, then);
        if (trail_.trail(now, then))
            mask[x] = 0;
    }
}

void Background::apply(int64_t t_us, const Planes &img, int scale, const Rect *frozen,
                       int n_frozen)
{
    const Update u = prepare(img, scale, frozen, n_frozen);
    if (u.restart)
        start_us_ = last_us_ = t_us;
    // Under sensor noise, 2 x 2 means (kMeanNoise), decided as the levels
    // are, on the frames before this one (the first frame starts the model
    // from its pixels as they are), and on the noise within the frames:
    // the means halve the noise the model sees, not that one.
    const double mean_level = mean_2x2_ ? kMeanNoiseOff * kMeanNoise : kMeanNoise;
    mean_2x2_ = !u.restart && scale_ >= 2 && kMeanNoise > 0 && noise_.fine >= mean_level;
    // This frame's rates and decision levels, the same for every row.
    const BgRow r = rates(t_us);
    // The noise is sampled on a grid of every 4th working pixel, from the
    // model before this frame (not while it starts: it is the image then).
    const bool sample = !u.restart;
    if (sample)
        noise_samples_.begin();
    trail_.begin();
    update_rows(img, frozen, n_frozen, r, u, sample);
    trail_.end(u.restart ? 0 : elapsed_s(t_us, old_dims_.last_us));
    have_last_ = keep_luma_ && !u.restart && !u.rescale && old_luma_.size() == luma_.size();
    have_ref_ = have_last_ && ref_matches();
    live_level_ = r.vmin;
    // The camera, against the frame before at the same scale and size.
    constexpr int kReach = 8;
    camera_moved_ = !u.restart && !u.rescale && old_columns_.size() == columns_.size() &&
                    old_rows_.size() == rows_.size() &&
                    (profile_shifted(columns_.data(), old_columns_.data(), w_, kReach) ||
                     profile_shifted(rows_.data(), old_rows_.data(), h_, kReach));
    if (camera_moved_)
        moved_us_ = t_us;
    find_motion(t_us);
    if (sample)
        noise_.end(noise_samples_, u.restart ? 0 : elapsed_s(t_us, old_dims_.last_us));
    noise_.end_fine(fine_noise(img), u.restart ? 0 : elapsed_s(t_us, old_dims_.last_us));
    frames_++;
    if (u.rescale)
        release_resampled();
}

double Background::fine_noise(const Planes &img) const
{
    // Over a grid of every 4th working pixel: the frame's pixel there
    // against its right neighbour. Texture finer than a pixel counts too,
    // but on most of a scene's pixels there is none.
    uint32_t hist[256] = {};
    uint32_t n = 0;
    const int s = scale_;
    for (int y = 0; y < h_; y += 4) {
        const uint8_t *row = img.y + (size_t)(y * s) * img.y_stride;
        for (int x = 0; x < w_ && x * s + 1 < img.width; x += 4, n++)
            hist[std::abs((int)row[x * s] - (int)row[x * s + 1])]++;
    }
    if (n == 0)
        return 0.0;
    // The median between levels (the counts spread evenly over each
    // level's unit): the levels near it are one or two grey levels apart.
    const int v = (int)median_of(hist, n);
    uint32_t below = 0;
    for (int i = 0; i < v; i++)
        below += hist[i];
    const double median = v - 0.5 + (0.5 * n - below) / std::max<uint32_t>(hist[v], 1);
    return std::max(0.0, median) / kMadOfDifference;
}

void Background::find_motion(int64_t t_us)
{
    motion_ready_ = have_last_ && !camera_moved_ && age_s(t_us) < kMotionS;
    if (!motion_ready_) {
        if (!motion_.empty())
            Vec<uint8_t>(motion_.get_allocator()).swap(motion_);
        return;
    }
    const size_t n = (size_t)w_ * h_;
    uint32_t hist[256] = {};
    uint32_t total = 0;
    for (size_t i = 0; i < n; i += kMotionGrid, total++)
        hist[std::abs((int)luma_[i] - (int)old_luma_[i])]++;
    const double median = median_of(hist, total);
    const int level = (int)std::lround(std::max((double)kMotionFloor, kMotionOverMedian * median));
    motion_.resize(n);
    for (size_t i = 0; i < n; i++)
        motion_[i] = std::abs((int)luma_[i] - (int)old_luma_[i]) > level ? 255 : 0;
}

namespace {

// Calls f(x, y, i) for each pixel of the blob `blob` (a w x h mask,
// non-zero inside; null: every pixel) within r clipped to the mask, i its
// index.
template <typename F>
void for_each_blob_pixel(const uint8_t *blob, int w, int h, const Rect &r, F &&f)
{
    for (int y = std::max(r.y0, 0); y < std::min(r.y1, h); y++)
        for (int x = std::max(r.x0, 0); x < std::min(r.x1, w); x++) {
            const size_t i = (size_t)y * w + x;
            if (!blob || blob[i])
                f(x, y, i);
        }
}

// Luma at working pixel (x, y) of a model at scale s, clamped to the
// image, through the exposure table lut.
inline int luma_at(const Planes &img, const uint8_t *lut, int s, int w, int h, int x, int y,
                   bool mean_2x2)
{
    x = std::min(std::max(x, 0), w - 1);
    y = std::min(std::max(y, 0), h - 1);
    const uint8_t *p = img.y + (size_t)(y * s) * img.y_stride + (size_t)x * s;
    if (!mean_2x2)
        return lut[p[0]];
    const size_t right = x * s + 1 < img.width ? 1 : 0;
    const size_t below = y * s + 1 < img.height ? img.y_stride : 0;
    return lut[(p[0] + p[right] + p[below] + p[below + right] + 2) >> 2];
}

} // namespace

void Background::outline_edges(const Planes &img, const uint8_t *blob, const Rect &r,
                               long *frame, long *model) const
{
    *frame = *model = 0;
    const int w = w_, h = h_, s = scale_;
    const int x0 = std::max(r.x0, 0), y0 = std::max(r.y0, 0);
    const int x1 = std::min(r.x1, w), y1 = std::min(r.y1, h);
    auto m = [&](int x, int y) {
        x = std::min(std::max(x, 0), w - 1);
        y = std::min(std::max(y, 0), h - 1);
        return (int)my_[(size_t)y * w + x];
    };
    auto f = [&](int x, int y) { return luma_at(img, gain_lut_, s, w, h, x, y, mean_2x2_); };
    for_each_outline(blob, (size_t)w, x0, y0, x1, y1, [&](int x, int y) {
        *frame += std::abs(f(x + 1, y) - f(x - 1, y)) + std::abs(f(x, y + 1) - f(x, y - 1));
        *model += std::abs(m(x + 1, y) - m(x - 1, y)) + std::abs(m(x, y + 1) - m(x, y - 1));
    });
}

void Background::keep_luma(bool on)
{
    keep_luma_ = on;
    if (!on && !kept_) // a step that may still be rolled back keeps the last frame's
        for (Vec<uint8_t> *v : {&luma_, &old_luma_, &ref_luma_})
            Vec<uint8_t>(v->get_allocator()).swap(*v);
}

bool Background::ref_matches() const
{
    return ref_luma_.size() == luma_.size() && ref_scale_ == scale_ &&
           ref_start_us_ == start_us_;
}

void Background::commit()
{
    kept_ = false;
    // The last frame stands: it becomes the one live() compares with once
    // the one kept is kLiveSpanS old.
    if (!keep_luma_ || frames_ == 0 || luma_.size() != (size_t)w_ * h_)
        return;
    const bool same = ref_matches();
    if (same && last_us_ >= ref_us_ && last_us_ - ref_us_ < std::llround(kLiveSpanS * 1e6))
        return;
    ref_luma_.assign(luma_.begin(), luma_.end());
    ref_us_ = last_us_;
    ref_scale_ = scale_;
    ref_start_us_ = start_us_;
}

bool Background::live(const uint8_t *blob, const Rect &r) const
{
    if (!have_last_)
        return false;
    // A sway to and fro from frame to frame shows against the frame before,
    // a slow one against the kept frame.
    const bool ref = have_ref_ && ref_us_ < old_dims_.last_us;
    long area = 0, changed = 0, changed_ref = 0;
    for_each_blob_pixel(blob, w_, h_, r, [&](int, int, size_t i) {
        area++;
        changed += std::abs((int)luma_[i] - (int)old_luma_[i]) > live_level_;
        if (ref)
            changed_ref += std::abs((int)luma_[i] - (int)ref_luma_[i]) > live_level_;
    });
    return area > 0 && std::max(changed, changed_ref) >= kLiveFraction * area;
}

void Background::absorb(const Planes &img, const uint8_t *blob, const Rect &r)
{
    const int s = scale_;
    for_each_blob_pixel(blob, w_, h_, r, [&](int x, int y, size_t i) {
        my_[i] = (uint8_t)luma_at(img, gain_lut_, s, w_, h_, x, y, mean_2x2_);
        if (color_) {
            const size_t cy = (size_t)((y * s) >> 1), cx = (size_t)((x * s) >> 1);
            mu_[i] = img.u[cy * img.u_stride + cx * img.c_step];
            mv_[i] = img.v[cy * img.v_stride + cx * img.c_step];
        }
        mask_[i] = 0;
    });
}

} // namespace ctrack
