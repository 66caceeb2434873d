// The background model for tracking from the pixels alone: Sigma-Delta
// estimation (Manzanera and Richefeu 2004) in integers on the frame at half
// resolution, with selective update and chroma shadow suppression.
#ifndef CTRACK_BACKGROUND_H
#define CTRACK_BACKGROUND_H

#include <cstdint>
#include <vector>

#include "planes.h"

namespace ctrack {

struct Rect {
    int x0, y0, x1, y1; // [x0, x1) x [y0, y1), working pixels
};

class Background {
public:
    // One working pixel for 2 x 2 frame pixels (the chroma grid of 4:2:0).
    static constexpr int kScale = 2;

    // Updates the model with the frame and computes the foreground mask
    // (255 foreground, 0 background, working size). Pixels inside `frozen`
    // (working coordinates: the boxes of confirmed tracks) are not learnt,
    // so a person who stops stays foreground. A frame of another size
    // restarts the model.
    void apply(const Planes &img, const Rect *frozen, int n_frozen);
    void reset() { frames_ = 0; }

    const uint8_t *mask() const { return mask_.data(); }

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
    int width() const { return w_; }
    int height() const { return h_; }
    size_t memory_bytes() const;

private:
    void start(const Planes &img);

    int w_ = 0, h_ = 0, fw_ = 0, fh_ = 0;
    bool color_ = false;
    int frames_ = 0;
    // Means and variances (Sigma-Delta: M moves one level a frame toward
    // the image, V toward N times |I - M|).
    std::vector<uint8_t> my_, vy_, mu_, mv_;
    std::vector<uint8_t> mask_, frozen_;
    std::vector<uint8_t> line_y_, line_u_, line_v_; // one row's samples
};

} // namespace ctrack

#endif
