#include "pixels/regions.h"

#include <algorithm>
#include <cstring>

#include "dsp/cpu.h"
#include "dsp/dsp.h"

namespace ctrack {

namespace {

// The closing's max and min, for the rows' ends (the rows themselves are
// the kernels', dsp/closing_rows.cc).
template <bool Max> CT_ALWAYS_INLINE uint8_t op(uint8_t a, uint8_t b)
{
    return Max ? std::max(a, b) : std::min(a, b);
}

// dst[x] = max (or min) of src[x - 1], src[x], src[x + 1] for x in [0, n),
// where src[-1] and src[n] exist when has_left and has_right, else count as
// neither (outside_left, outside_right).
template <bool Max>
void across3(const Dsp &dsp, const uint8_t *src, uint8_t *dst, int n, bool has_left,
             bool has_right, uint8_t outside_left, uint8_t outside_right)
{
    const uint8_t left = has_left ? src[-1] : outside_left;
    const uint8_t right = has_right ? src[n] : outside_right;
    if (n == 1) {
        dst[0] = op<Max>(op<Max>(left, src[0]), right);
        return;
    }
    dst[0] = op<Max>(op<Max>(left, src[0]), src[1]);
    dsp.close_row3(src, dst, n, Max);
    dst[n - 1] = op<Max>(op<Max>(src[n - 2], src[n - 1]), right);
}

// dst = max (or min) of rows y - half to y + half of the h rows of n bytes
// at src, those that exist.
template <bool Max>
void down(const Dsp &dsp, const uint8_t *src, int n, int h, int y, int half, uint8_t *dst)
{
    const int lo = std::max(0, y - half), hi = std::min(h - 1, y + half);
    dsp.close_rows(src + (size_t)lo * n, (size_t)n, hi - lo + 1, dst, n, Max);
}

} // namespace

Closing::Closing() { dsp_init(&dsp_, cpu_flags()); }

void Closing::run(const uint8_t *in, uint8_t *out, int w, int h, const Rect &area)
{
    static_assert(kCloseWidth == 3, "across3 is the horizontal pass");
    static_assert(kCloseHeight <= 5, "close_rows takes up to 5 rows");
    constexpr int kHalf = kCloseHeight / 2;
    const int x0 = area.x0, y0 = area.y0, aw = area.x1 - area.x0, ah = area.y1 - area.y0;
    if (aw <= 0 || ah <= 0)
        return;
    a_.resize((size_t)aw * ah);
    b_.resize((size_t)aw * ah);
    // Dilation across: a pixel beyond the image's edge counts as neither,
    // one beyond the area's is the input's.
    for (int y = 0; y < ah; y++)
        across3<true>(dsp_, in + (size_t)(y0 + y) * w + x0, &a_[(size_t)y * aw], aw, x0 > 0,
                      area.x1 < w, 0, 0);
    // Dilation down: rows outside the area are 0 after the dilation across
    // (the input's margin), so the area's rows are all there is.
    for (int y = 0; y < ah; y++)
        down<true>(dsp_, a_.data(), aw, ah, y, kHalf, &b_[(size_t)y * aw]);
    // Erosion across: beyond the image's edge counts as neither (255),
    // beyond the area's the dilation is 0.
    for (int y = 0; y < ah; y++)
        across3<false>(dsp_, &b_[(size_t)y * aw], &a_[(size_t)y * aw], aw, false, false,
                       x0 > 0 ? 0 : 255, area.x1 < w ? 0 : 255);
    // Erosion down: likewise, a row beyond the image's edge counts as
    // neither, one beyond the area's is 0.
    for (int y = 0; y < ah; y++) {
        uint8_t *d = out + (size_t)(y0 + y) * w + x0;
        if (std::max(0, y0 + y - kHalf) < y0 || std::min(h - 1, y0 + y + kHalf) >= y0 + ah) {
            std::fill(d, d + aw, 0);
            continue;
        }
        down<false>(dsp_, a_.data(), aw, ah, y, kHalf, d);
    }
}

namespace {

// The first x in [x, end) whose byte is zero (Zero) or non-zero (!Zero), or
// end; eight bytes at a time across long runs.
template <bool Zero> int run_end(const uint8_t *row, int x, int end)
{
    constexpr uint64_t kOnes = 0x0101010101010101ull, kHigh = 0x8080808080808080ull;
    while (x + 8 <= end) {
        uint64_t v;
        std::memcpy(&v, row + x, 8);
        // Zero: stop at a run of non-zero bytes, so the word must be all
        // non-zero (no zero byte) to skip; !Zero: all zero.
        const bool skip = Zero ? ((v - kOnes) & ~v & kHigh) == 0 : v == 0;
        if (!skip)
            break;
        x += 8;
    }
    while (x < end && (row[x] != 0) == Zero)
        x++;
    return x;
}

} // namespace

int first_nonzero(const uint8_t *row, int x, int end)
{
    return run_end<false>(row, x, end);
}

void BoxRuns::join(Vec<int> &up, int a, int b)
{
    a = find_root(up, a);
    b = find_root(up, b);
    if (a < b)
        up[b] = a;
    else if (b < a)
        up[a] = b;
}

void BoxRuns::label(const uint8_t *mask, int stride, const Rect &box, bool join_foreground)
{
    fg_.clear();
    bg_.clear();
    fg_up_.clear();
    bg_up_.clear();
    fg_row_.clear();
    bg_row_.clear();
    // Background run 0 stands for everything around the box.
    bg_.push_back(Run{0, 0, -1, -1});
    bg_up_.push_back(0);
    if (box.x1 <= box.x0 || box.y1 <= box.y0) {
        fg_row_.push_back(0);
        bg_row_.push_back(1);
        return;
    }
    for (int y = box.y0; y < box.y1; y++) {
        const uint8_t *row = mask + (size_t)y * stride;
        const int fg_first = (int)fg_.size(), bg_first = (int)bg_.size();
        fg_row_.push_back(fg_first);
        bg_row_.push_back(bg_first);
        const bool edge_row = y == box.y0 || y == box.y1 - 1;
        int x = box.x0;
        while (x < box.x1) {
            if (row[x]) {
                const int e = run_end<true>(row, x + 1, box.x1);
                const int left = x == box.x0 ? -1 : (int)bg_.size() - 1;
                fg_up_.push_back((int)fg_.size());
                fg_.push_back(Run{x, e, y, left});
                x = e;
            } else {
                const int e = first_nonzero(row, x + 1, box.x1);
                const int i = (int)bg_.size();
                bg_.push_back(Run{x, e, y, -1});
                bg_up_.push_back(i);
                if (edge_row || x == box.x0 || e == box.x1)
                    join(bg_up_, 0, i);
                x = e;
            }
        }
        if (y == box.y0)
            continue;
        // Joined to the previous row's runs: foreground through the 8
        // neighbours (runs that touch at a corner), background through the
        // 4 (runs that share a column).
        const int pf = fg_row_[fg_row_.size() - 2], pb = bg_row_[bg_row_.size() - 2];
        if (join_foreground)
            for (int i = fg_first, j = pf; i < (int)fg_.size() && j < fg_first;) {
                if (fg_[i].x0 <= fg_[j].x1 && fg_[j].x0 <= fg_[i].x1)
                    join(fg_up_, i, j);
                if (fg_[i].x1 < fg_[j].x1)
                    i++;
                else
                    j++;
            }
        for (int i = bg_first, j = pb; i < (int)bg_.size() && j < bg_first;) {
            if (bg_[i].x0 < bg_[j].x1 && bg_[j].x0 < bg_[i].x1)
                join(bg_up_, i, j);
            if (bg_[i].x1 < bg_[j].x1)
                i++;
            else
                j++;
        }
    }
    fg_row_.push_back((int)fg_.size());
    bg_row_.push_back((int)bg_.size());
}

void OuterRegions::find(const uint8_t *mask, int stride, const Rect &area, Vec<Rect> &out)
{
    out.clear();
    runs_.label(mask, stride, area);
    const Vec<BoxRuns::Run> &fg = runs_.fg();
    // Each region's box; its root is its first run, whose left neighbour
    // lies in the background around it (no hole of the region itself is on
    // the region's first row): a region is outer when that background is
    // the area's surroundings.
    box_of_.assign(fg.size(), -1);
    boxes_.clear();
    for (int i = 0; i < (int)fg.size(); i++) {
        const int r = runs_.fg_root(i);
        const BoxRuns::Run &run = fg[i];
        if (r == i) {
            box_of_[i] = (int)boxes_.size();
            boxes_.push_back(Rect{run.x0, run.y, run.x1, run.y + 1});
            continue;
        }
        Rect &b = boxes_[(size_t)box_of_[r]];
        b.x0 = std::min(b.x0, run.x0);
        b.x1 = std::max(b.x1, run.x1);
        b.y1 = std::max(b.y1, run.y + 1);
    }
    for (int i = (int)fg.size() - 1; i >= 0; i--)
        if (box_of_[i] >= 0 && (fg[i].left < 0 || runs_.outside(fg[i].left)))
            out.push_back(boxes_[(size_t)box_of_[i]]);
}

} // namespace ctrack
