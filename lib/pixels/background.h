// The background model for tracking from the pixels alone: Sigma-Delta
// estimation (Manzanera and Richefeu 2004) in integers on the frame at a
// working scale (half resolution, or full or a quarter for small or large
// people), with selective update, chroma shadow suppression and, from the
// pixels alone, a walker's trail left out (trail.h).
#ifndef CTRACK_BACKGROUND_H
#define CTRACK_BACKGROUND_H

#include <algorithm>
#include <cstdint>
#include <vector>

#include "base/memory.h"

#include "dsp/dsp.h"
#include "pixels/mask.h"
#include "pixels/noise.h"
#include "pixels/trail.h"
#include "base/planes.h"

namespace ctrack {

// n / d for d in [1, 255] and n < 2^16, by a multiplication.
uint32_t divide_small(uint32_t n, uint32_t d);

class Background {
public:
    Background() : dsp_(make_dsp()) { set_gain(1.0); }
    // The working scale: one working pixel for scale x scale frame pixels,
    // 1, 2 or 4. The model starts at kStartScale (the chroma grid of 4:2:0);
    // the host of the model chooses another from the people's size.
    static constexpr int kStartScale = 2;
    static constexpr int kMinScale = 1, kMaxScale = 4;
    int scale() const { return scale_; }
    // The finest scale the model may take: kMinScale, or the scale it had
    // when a step that took it finer was rolled back (out of memory: a
    // fixed heap keeps the scale it holds rather than fail every frame).
    int finest_scale() const { return finest_; }

    // Updates the model with the frame and computes the foreground mask
    // (255 foreground, 0 background, working size). Pixels inside `frozen`
    // (working coordinates at `scale`: the boxes of confirmed tracks) are
    // not learnt, so a person who stops stays foreground. A frame of another
    // size restarts the model, at `scale`. Another scale than the model's
    // resamples it: each new working pixel takes M and V of the old pixel
    // around it (of up to four) whose M is closest to the frame there, and
    // the chroma of the one closest in chroma, so that the background's
    // edges stay sharp and a person on them stays foreground; `scale` is
    // taken no finer than finest_scale().
    void apply(int64_t t_us, const Planes &img, int scale, const Rect *frozen, int n_frozen);
    // The model starts again with the next frame, at kStartScale.
    void reset()
    {
        frames_ = 0;
        scale_ = std::max(kStartScale, finest_);
    }
    // Whether a frame was learnt since the start or the last reset.
    bool started() const { return frames_ > 0; }
    // How long the model has learnt at t_us (0 before it started).
    double age_s(int64_t t_us) const;
    // Whether the camera moved between the last two frames learnt
    // (camera_motion.h): their luma's projections match better shifted.
    bool camera_moved() const { return camera_moved_; }
    // Seconds from the last frame in which the camera moved to t_us (a
    // large number if it never did since the model started).
    double since_camera_moved_s(int64_t t_us) const;
    // The model as it was before the last apply() (and absorb()) is kept
    // until commit(): rollback() returns to it, so that a step that fails
    // after the update leaves the model untouched. rollback() is O(1) and
    // never throws. commit() also keeps a copy of the last frame's luma for
    // live() once the one it keeps is kLiveSpanS old: the copy's first
    // allocation may throw std::bad_alloc, which leaves the kept frame as it
    // was (Engine::step() calls it before the step, whose feed then fails
    // and changes nothing).
    void commit();
    void rollback();

    const uint8_t *mask() const { return mask_.data(); }
    // While the model still holds the people of its first frames (its
    // first seconds, the camera still and the frame before at this scale
    // kept for live()): the pixels (255) where the frame changed from the
    // frame before by more than the sensor's noise. Null otherwise.
    const uint8_t *motion() const { return motion_ready_ ? motion_.data() : nullptr; }

    // Edge strength along the outline of the blob `blob` (a working-size
    // mask, non-zero inside) within r: in the frame (`frame`) and in the
    // model (`model`), sums of |dx| + |dy| of luma over the blob's outline
    // pixels. A ghost (the model still holds what has left) has its edges
    // in the model, a real object in the frame.
    void outline_edges(const Planes &img, const uint8_t *blob, const Rect &r, long *frame,
                       long *model) const;
    // Re-learns the pixels of the blob within r at once: the model takes the
    // frame's values there.
    void absorb(const Planes &img, const uint8_t *blob, const Rect &r);
    // Whether the blob `blob` within r moved inside since the frame before,
    // or since the frame kept by commit() (kLiveSpanS old at most): at
    // least kLiveFraction of its pixels changed by more than V's floor (the
    // scene's noise). A person standing still sways and breathes; a board
    // or a bag put down does not. False when the frame before was at
    // another size or scale. A null blob asks it of every pixel of r.
    bool live(const uint8_t *blob, const Rect &r) const;
    // Whether the frames' luma is kept for live() (from the next apply();
    // off, its buffers are freed).
    void keep_luma(bool on);
    // The weight of the frame before in this one, where the frames show
    // a walker's trail (a camera's temporal noise filter: trail.h); 0
    // where they show none. While it is known, a pixel whose luma's
    // difference from the background fell to about that share of the
    // frame before's, on the same side, is background in the mask. Read
    // from the frames while keep_luma() is on.
    double trail_weight() const { return trail_.weight(); }
    // Whether the last frame's working pixels were 2 x 2 means of the
    // frame's (under sensor noise), not one pixel of their block.
    bool averages() const { return mean_2x2_; }
    int width() const { return w_; }
    int height() const { return h_; }
    size_t memory_bytes() const;

private:
    // How this frame's update begins: the model started from the frame
    // (the first frame, or another size or format), or at another scale.
    struct Update {
        bool restart = false, rescale = false;
    };
    // The model before the frame kept for rollback(), sized, resampled or
    // started for it, and the frame's exposure read.
    Update prepare(const Planes &img, int scale, const Rect *frozen, int n_frozen);
    // This frame's rates and decision levels, t_us after the last.
    BgRow rates(int64_t t_us);
    // Row y's gathering (into line_y_, and line_u_ and line_v_ unless
    // *iu and *iv point at the frame's own chroma row).
    BgGather gather(const Planes &img, int y, const uint8_t **iu, const uint8_t **iv);
    // Every row's update and foreground; the noise sampled when asked.
    void update_rows(const Planes &img, const Rect *frozen, int n_frozen, const BgRow &rates,
                     Update u, bool sample);
    void start(const Planes &img);
    // Sizes the buffers for the image at scale_.
    void size_for(const Planes &img);
    // The model before this frame at scale_, from the old buffers at the old
    // dimensions (old_dims_), into rs_*.
    void resample(const Planes &img);
    void release_resampled();
    // The frame's exposure against the model's: the median ratio of image to
    // model luma over a grid of pixels no track stands on (1 within a
    // deadband). A global step of light (auto-exposure, a cloud, a lamp)
    // changes it, people moving do not.
    double exposure_ratio(const Planes &img, const Rect *frozen, int n_frozen);
    // Row y of the frozen mask (1 inside the boxes, working pixels): a row
    // no box reaches is a row of zeros kept for it, else one row of
    // frozen_line_ is filled.
    const uint8_t *frozen_row(const Rect *frozen, int n_frozen, int y);
    // Reads the frame's luma divided by gain from now on (gain_lut_).
    void set_gain(double gain);
    void swap_models();
    // Row r's trail (trail.h), sampled when `sample` and, where the weight
    // is known, left out of its mask (row: its first pixel's index).
    void leave_trail(const BgRow &r, size_t row, bool sample);
    // motion() for this frame, or its buffer freed once the time is past.
    void find_motion(int64_t t_us);
    // The noise within the frame (NoiseLevel::fine): the median absolute
    // difference between horizontal neighbours over a grid of the working
    // pixels, as a standard deviation.
    double fine_noise(const Planes &img) const;

    static Dsp make_dsp();
    Dsp dsp_; // the row kernels for this CPU, chosen when the tracker is made
    int w_ = 0, h_ = 0, fw_ = 0, fh_ = 0, scale_ = kStartScale, finest_ = kMinScale;
    bool color_ = false;
    int frames_ = 0;
    NoiseLevel noise_;
    TrailWeight trail_;
    NoiseSamples noise_samples_;
    // Whether this frame's working pixels are 2 x 2 means (kMeanNoise).
    bool mean_2x2_ = false;
    // The exposure, and the table through which the frame's luma is read:
    // the model stays in its own exposure while the frames' changes, and a
    // global step of light is no foreground.
    double gain_ = 1.0;
    uint8_t gain_lut_[256];
    int64_t start_us_ = 0, last_us_ = 0;
    // Means and variances (Sigma-Delta: M moves one level a frame toward
    // the image, V toward N times |I - M|).
    Vec<uint8_t> my_, vy_, mu_, mv_;
    // The model before the last apply(), while kept_: apply() reads it and
    // writes the new one into the buffers above (double buffering: no copy).
    struct Dims {
        int w, h, fw, fh, scale;
        bool color;
        int frames;
        int64_t start_us, last_us;
        NoiseLevel noise;
        double gain;
        bool camera_moved;
        int64_t moved_us;
        bool mean_2x2;
        TrailWeight trail;
    } old_dims_{};
    Vec<uint8_t> old_my_, old_vy_, old_mu_, old_mv_;
    // This frame's luma and the last one's, at the working scale (swapped
    // with the model), for live(); whether the last one is comparable, and
    // this frame's V floor.
    Vec<uint8_t> luma_, old_luma_;
    bool keep_luma_ = false, have_last_ = false;
    // The frame live() compares with (commit()), its time, and the scale
    // and start of the model it was read at; whether this frame may be
    // compared with it.
    Vec<uint8_t> ref_luma_;
    int64_t ref_us_ = 0, ref_start_us_ = 0;
    int ref_scale_ = 0;
    bool have_ref_ = false;
    // Whether the kept frame was read at this frame's size and scale, since
    // the model's last start.
    bool ref_matches() const;
    bool motion_ready_ = false;
    Vec<uint8_t> motion_;
    int live_level_ = 0;
    // The luma's column and row sums of this frame and the one before
    // (swapped with the model), and what they say of the camera.
    Vec<int32_t> columns_, rows_, old_columns_, old_rows_;
    bool camera_moved_ = false;
    int64_t moved_us_ = kNever; // the last frame in which it moved
    static constexpr int64_t kNever = INT64_MIN;
    // The old model resampled to a new scale, for the one update that
    // changes it (released after).
    Vec<uint8_t> rs_my_, rs_vy_, rs_mu_, rs_mv_;
    bool kept_ = false;
    Vec<uint8_t> mask_;
    Vec<uint8_t> frozen_line_; // a row of zeros, then a row for frozen_row()
    Vec<uint8_t> line_y_, line_u_, line_v_; // one row's samples
    Vec<uint8_t> line_vmax_;                // kVMax, a row of it
    Vec<uint8_t> line_dy_, line_dc_;        // a noise row's differences (BgRow)
};

} // namespace ctrack

#endif
