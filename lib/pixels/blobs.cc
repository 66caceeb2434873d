#include "pixels/blobs.h"

#include "pixels/regions.h"
#include "base/tunable.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ctrack {

namespace {

// A blob is kept when it covers at least this part of the box of a person
// standing where its feet are, and is at least this part of their height
// (the person's size from PersonSize; chosen over both sequences' condition
// families, docs/tuning.md, "The people's size: its constants"; the
// area 0.12 until 0.9.0)...
CT_TUNABLE(kMinAreaFraction, "CTRACK_MIN_AREA", 0.10);
CT_TUNABLE(kMinHeightFraction, "CTRACK_MIN_HEIGHT", 0.4);
// ...and while the model knows nothing, when it covers this many frame
// pixels and rows: a person of about 40 frame pixels, which the prior's
// smallest (30) approaches.
constexpr int kPriorMinArea = 400, kPriorMinRows = 20;
// Fragments merge only while their union is at most this many person
// heights tall (where the size is known): two people one behind the other
// are no person. Chosen over both sequences' condition families
// (docs/tuning.md, "The people's size: its constants"; 1.3 until
// 0.9.0).
CT_TUNABLE(kMaxUnionHeight, "CTRACK_MAX_UNION", 1.2);
// The bounds on a frame's work (BlobFinder::find()).
constexpr int kMaxBlobs = 128;
constexpr double kMaxForeground = 0.5;
constexpr double kMergeOverlap = 0.5; // of the narrower blob's width
constexpr double kMergeGap = 0.25;    // of the taller blob's height
constexpr double kFarMergeGap = 1.0;  // with the contour template's consent
// Two tracks' predicted centres inside one blob split it when at least this
// many blob heights apart: half the width of a person (0.4 of their height
// in the ground truth), side by side.
constexpr double kMinCentreGap = 0.2;
// Between two heads on a blob's top edge, the edge dips at least this many
// blob heights below both (a head is about 0.13 of a person's height;
// docs/tuning.md has the choice).
constexpr double kHeadDip = 0.06;
// The top edge is smoothed by a running median this many blob heights wide
// (a head's width) before heads are sought on it: a speck of noise or a
// raised hand is no head (docs/tuning.md has the choice).
CT_TUNABLE(kHeadWidth, "CTRACK_HEAD_WIDTH", 0.12);
// A blob cut between more heads than its width says: each part must vote
// above this, as sure as a candidate must be to start a track (the default
// candidate_min_score), and above the whole blob.
constexpr double kHeadsVote = 0.8;
constexpr int kMaxHalfWindow = 16;
// Someone behind the person a blob is (BlobFinder::behind()): a second
// head at least this many blob heights from the highest (half the gap
// between two people side by side: one behind the other stand closer in
// the image), under which the people's size puts a person whose feet are
// at least kBehindFeet of their height above the blob's bottom. Chosen
// over both sequences' condition families (docs/tuning.md, "Someone
// behind").
CT_TUNABLE(kBehindGap, "CTRACK_BEHIND_GAP", 0.1);
CT_TUNABLE(kBehindFeet, "CTRACK_BEHIND_FEET", 0.2);
// No box where the size's line is within this of a slope of 1 (behind()).
constexpr double kMinHeadSlope = 0.05;

bool overlaps_x(const Rect &a, const Rect &b, double fraction)
{
    int o = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
    int narrow = std::min(a.x1 - a.x0, b.x1 - b.x0);
    return o >= fraction * narrow;
}

Rect unite(const Rect &a, const Rect &b)
{
    return Rect{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1),
                std::max(a.y1, b.y1)};
}

// One past the last non-zero byte of row[lim, w), or lim.
int end_nonzero(const uint8_t *row, int lim, int w)
{
    int x = w;
    for (; x - 8 >= lim; x -= 8) {
        uint64_t v;
        std::memcpy(&v, row + x - 8, 8);
        if (v)
            break;
    }
    while (x > lim && !row[x - 1])
        x--;
    return x;
}

// The rows and columns of the mask that hold foreground: [x0, x1) x [y0,
// y1), empty (x0 == x1) when it holds none. A row's ends are looked for
// only beyond the columns already known to hold foreground.
Rect foreground_bounds(const uint8_t *mask, int w, int h)
{
    Rect r{w, h, 0, 0};
    for (int y = 0; y < h; y++) {
        const uint8_t *row = mask + (size_t)y * w;
        int x = 0;
        // Eight bytes at a time: most rows are background.
        uint64_t any = 0;
        for (; x + 8 <= w; x += 8) {
            uint64_t v;
            std::memcpy(&v, row + x, 8);
            any |= v;
        }
        for (; x < w; x++)
            any |= row[x];
        if (!any)
            continue;
        r.x0 = first_nonzero(row, 0, r.x0);
        r.x1 = end_nonzero(row, r.x1, w);
        r.y0 = std::min(r.y0, y);
        r.y1 = y + 1;
    }
    if (r.x1 <= r.x0)
        return Rect{0, 0, 0, 0};
    return r;
}

} // namespace

struct BlobFinder::Impl {
    // The cleaned mask, whole (w x h); outside `area` it is 0.
    Vec<uint8_t> clean;
    int w = 0, h = 0;
    Rect area{0, 0, 0, 0};
    Closing closing;
    OuterRegions regions;
    Vec<Rect> blobs, largest; // largest: outer_blobs()' scratch
    Vec<int> columns, centres, tops, smooth, order, heads;
    Vec<float> votes;
    const uint8_t *at(int x, int y) const { return &clean[(size_t)y * w + x]; }
    // Foreground pixels of column x in rows [y0, y1).
    int column_count(int x, int y0, int y1) const
    {
        int c = 0;
        for (int y = y0; y < y1; y++)
            c += *at(x, y) != 0;
        return c;
    }
};

BlobFinder::BlobFinder() : impl_(make_owned<Impl>()) {}
BlobFinder::~BlobFinder() = default;

const uint8_t *BlobFinder::cleaned() const
{
    return impl_->clean.empty() ? nullptr : impl_->clean.data();
}

int BlobFinder::width() const
{
    return impl_->w;
}

int BlobFinder::height() const
{
    return impl_->h;
}

size_t BlobFinder::memory_bytes() const
{
    const Impl &m = *impl_;
    return m.clean.capacity() + m.closing.memory_bytes() + m.regions.memory_bytes() +
           (m.blobs.capacity() + m.largest.capacity()) * sizeof(Rect) +
           m.votes.capacity() * sizeof(float) +
           (m.columns.capacity() + m.centres.capacity() + m.tops.capacity() +
            m.smooth.capacity() + m.order.capacity() + m.heads.capacity()) *
               sizeof(int);
}

float BlobFinder::vote(Classifier &cls, const Rect &r) const
{
    return cls.vote(impl_->clean.data(), impl_->w, r).score;
}

void BlobFinder::clean(const uint8_t *mask, int w, int h)
{
    Impl &m = *impl_;
    if (m.w != w || m.h != h || m.clean.size() != (size_t)w * h) {
        // No size until the new mask stands: after a failed allocation the
        // next call makes it anew, whatever its size (the old mask's
        // foreground is not cleared).
        m.area = Rect{0, 0, 0, 0};
        m.w = m.h = 0;
        m.clean.assign((size_t)w * h, 0);
        m.w = w;
        m.h = h;
    }
    // Work in proportion to what moves: the closing runs over the
    // foreground's rows and columns only, with a margin of twice its
    // kernel's half size (2 columns, 4 rows), past which the whole frame's
    // closing is 0 too: the same mask, to the bit.
    for (int y = m.area.y0; y < m.area.y1; y++)
        std::memset(&m.clean[(size_t)y * w + m.area.x0], 0, (size_t)(m.area.x1 - m.area.x0));
    m.area = Rect{0, 0, 0, 0};
    const Rect fg = foreground_bounds(mask, w, h);
    if (fg.x1 <= fg.x0)
        return;
    static_assert(Closing::kCloseWidth == 3 && Closing::kCloseHeight == 5, "the margin");
    const Rect area{std::max(0, fg.x0 - 2), std::max(0, fg.y0 - 4), std::min(w, fg.x1 + 2),
                    std::min(h, fg.y1 + 4)};
    // Closing only: an opening, even 3 x 3, erases legs a few working
    // pixels wide, and the boxes lose them (docs/notes/pixels.md). Specks
    // are dropped by area in find().
    m.closing.run(mask, m.clean.data(), w, h, area);
    m.area = area;
}

Rect BlobFinder::rows_of(const Rect &r, int x0, int x1) const
{
    const Impl &m = *impl_;
    Rect p{x0, r.y1, x1, r.y0};
    for (int y = r.y0; y < r.y1; y++)
        if (count_nonzero(m.at(x0, y), x1 - x0) > 0) {
            p.y0 = std::min(p.y0, y);
            p.y1 = std::max(p.y1, y + 1);
        }
    return p;
}

Vec<int> &BlobFinder::top_edge(const Rect &r)
{
    Impl &m = *impl_;
    Vec<int> &top = m.tops;
    top.assign(r.x1 - r.x0, r.y1);
    for (int x = r.x0; x < r.x1; x++)
        for (int y = r.y0; y < r.y1; y++)
            if (*m.at(x, y)) {
                top[x - r.x0] = y;
                break;
            }
    return top;
}

int BlobFinder::dip_middle(const Vec<int> &top, int a, int b)
{
    int d = a;
    for (int i = a + 1; i < b; i++)
        if (top[i] > top[d])
            d = i;
    int last = d;
    while (last + 1 < b && top[last + 1] == top[d])
        last++;
    return (d + last + 1) / 2;
}

void BlobFinder::heads(const Rect &r, Vec<int> &out)
{
    Impl &m = *impl_;
    const int bw = r.x1 - r.x0, bh = r.y1 - r.y0;
    const Vec<int> &raw = top_edge(r);
    // The edge smoothed by a running median a head wide.
    Vec<int> &top = m.smooth;
    top.resize(bw);
    const int half = std::min(kMaxHalfWindow, (int)(kHeadWidth * bh / 2));
    int window[2 * kMaxHalfWindow + 1];
    for (int i = 0; i < bw; i++) {
        int n = 0;
        for (int j = std::max(0, i - half); j <= std::min(bw - 1, i + half); j++)
            window[n++] = raw[j];
        std::nth_element(window, window + n / 2, window + n);
        top[i] = window[n / 2];
    }
    // Highest first: a column is a head when it is at least kMinCentreGap
    // heights from each head found (all higher) and the edge between them
    // dips kHeadDip heights below it.
    const int gap = (int)std::ceil(kMinCentreGap * bh);
    Vec<int> &order = m.order;
    order.resize(bw);
    for (int i = 0; i < bw; i++)
        order[i] = i;
    // (std::sort, not stable_sort, which takes a buffer from the heap.)
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return top[a] < top[b] || (top[a] == top[b] && a < b); });
    out.clear();
    for (int i : order) {
        if (top[i] >= r.y1)
            break;
        bool head = true;
        for (size_t k = 0; k < out.size() && head; k++) {
            const int a = std::min(out[k], i), b = std::max(out[k], i);
            head = b - a >= gap &&
                   *std::max_element(&top[a], &top[b]) - top[i] >= kHeadDip * bh;
        }
        if (head)
            out.push_back(i);
    }
    std::sort(out.begin(), out.end());
}

int BlobFinder::head_count(const Rect &r)
{
    Vec<int> &hs = impl_->heads;
    heads(r, hs);
    return (int)hs.size();
}

bool BlobFinder::cut_between_heads(const Rect &r, const Vec<int> &hs, Classifier &cls,
                                   Vec<int> &cuts)
{
    Impl &m = *impl_;
    const float whole = std::max(vote(cls, r), (float)kHeadsVote);
    const size_t first = cuts.size();
    int from = r.x0;
    for (size_t k = 0; k < hs.size(); k++) {
        const int to = k + 1 < hs.size() ? r.x0 + dip_middle(m.tops, hs[k], hs[k + 1]) : r.x1;
        if (!(cls.vote_part(m.clean.data(), m.w, rows_of(r, from, to)).score > whole)) {
            cuts.resize(first);
            return false;
        }
        if (to < r.x1)
            cuts.push_back(to);
        from = to;
    }
    return true;
}

bool BlobFinder::one_head_each(const Rect &r, const Vec<int> &hs, const Vec<int> &cuts)
{
    if (hs.empty() || hs.size() + 1 != cuts.size())
        return false;
    for (size_t k = 0; k < hs.size(); k++)
        if (r.x0 + hs[k] < cuts[k] || r.x0 + hs[k] >= cuts[k + 1])
            return false;
    return true;
}

int BlobFinder::second_head(const Vec<int> &top, int h1, int gap, double dip)
{
    const int bw = (int)top.size();
    int h2 = -1;
    for (int dir : {-1, 1}) {
        // Walking away from h1, d is the deepest column passed (the first
        // of equals, seen from the left).
        int d = h1;
        for (int i = h1 + dir; i >= 0 && i < bw; i += dir) {
            if (top[i] > top[d] || (dir < 0 && top[i] == top[d]))
                d = i;
            if (std::abs(i - h1) < gap || (h2 >= 0 && top[i] >= top[h2]))
                continue;
            if (top[d] - std::max(top[i], top[h1]) >= dip)
                h2 = i;
        }
    }
    return h2;
}

int BlobFinder::between_heads(const Rect &r, const Vec<int> &top, int h1, Classifier &cls)
{
    const int bh = r.y1 - r.y0;
    // The highest column is one head; the other is the highest column at
    // least kMinCentreGap heights away with a dip of kHeadDip heights below
    // both between them.
    const int h2 = second_head(top, h1, (int)std::ceil(kMinCentreGap * bh), kHeadDip * bh);
    if (h2 < 0)
        return -1;
    // The template decides: both parts must be pedestrians by its vote,
    // and look more like one than the whole does.
    const int cut = r.x0 + dip_middle(top, std::min(h1, h2), std::max(h1, h2));
    const float whole = std::max(vote(cls, r), 0.5f);
    if (vote(cls, rows_of(r, r.x0, cut)) > whole && vote(cls, rows_of(r, cut, r.x1)) > whole)
        return cut;
    return -1;
}

void BlobFinder::behind(const Rect &r, const Vec<int> &top, int h1, int s,
                        const PersonSize &size, Vec<Rect> &out)
{
    // Where a person's height grows about as fast as their feet go down
    // the image (the line's slope near 1), every head sits on about one
    // row, and a head's row tells nothing of its person: a row's error
    // moves their height slope / (1 - slope) rows.
    if (!size.known() || std::fabs(1 - size.slope()) < kMinHeadSlope)
        return;
    const int bh = r.y1 - r.y0;
    const int h2 = second_head(top, h1, (int)std::ceil(kBehindGap * bh), kHeadDip * bh);
    if (h2 < 0)
        return;
    // The person the size's line puts under each head; both must have one
    // (a head above the horizon the line guesses is no one's).
    const double tall1 = size.height_under_head((double)top[h1] * s);
    const double tall2 = size.height_under_head((double)top[h2] * s);
    if (!(tall1 > 0 && tall2 > 0))
        return;
    const Impl &m = *impl_;
    for (const int hk : {h1, h2}) {
        // On a camera at street level the one behind has the lower head;
        // looking down, the higher: either may be theirs.
        const double head = (double)top[hk] * s;
        const double tall = hk == h1 ? tall1 : tall2;
        const double feet = head + tall;
        if (feet > r.y1 * s - kBehindFeet * tall)
            continue;
        const double half = size.width_at(feet) / s / 2;
        const int x0 = std::max(0, (int)std::lround(r.x0 + hk - half));
        const int x1 = std::min(m.w, (int)std::lround(r.x0 + hk + half));
        const int y1 = std::min(m.h, (int)std::lround(feet / s));
        if (x1 - x0 < 2 || y1 - top[hk] < 4)
            continue;
        out.push_back(Rect{x0, top[hk], x1, y1});
        whole_.push_back(kBehind);
    }
}

void BlobFinder::find(const uint8_t *mask, int w, int h, int scale, const Rect *predicted,
                      int n_predicted, const PersonSize &size, Classifier &cls, Vec<Rect> &out)
{
    out.clear();
    whole_.clear();
    dropped_ = 0;
    flooded_ = false;
    clean(mask, w, h);
    cls.new_mask(); // the votes remembered were on another mask
    if (!outer_blobs())
        return;
    merge_fragments(scale, size, cls);
    for (const Rect &r : impl_->blobs)
        if (!speck(r, scale, size))
            split(r, scale, predicted, n_predicted, size, cls, out);
}

bool BlobFinder::outer_blobs()
{
    Impl &m = *impl_;
    Vec<Rect> &b = m.blobs;
    b.clear();
    if (m.area.x1 > m.area.x0) {
        // A mask more than kMaxForeground foreground is no picture of
        // people (a light switched, the camera moved, noise the model has
        // not learnt): nothing in it is a candidate.
        const long fg = count_nonzero(m.clean.data(), (size_t)m.w, m.area.x0, m.area.y0,
                                      m.area.x1, m.area.y1);
        if (fg > kMaxForeground * m.w * m.h) {
            flooded_ = true;
            return false;
        }
        // The boxes of the outer regions of the foreground's area (it has a
        // margin of background all round, or ends at the image's edge: the
        // whole mask's regions), in the order findContours gave them.
        m.regions.find(m.clean.data(), m.w, m.area, b);
    }
    // At most kMaxBlobs go on, the largest (then the first found): merging
    // fragments looks at every pair, and a flickering mask could make
    // thousands.
    if (b.size() > (size_t)kMaxBlobs) {
        auto area = [&](int k) { return (long)(b[k].x1 - b[k].x0) * (b[k].y1 - b[k].y0); };
        // (std::sort on the indices, not stable_sort, which takes a buffer
        // from the heap.)
        Vec<int> &order = m.order;
        order.resize(b.size());
        for (size_t k = 0; k < b.size(); k++)
            order[k] = (int)k;
        std::sort(order.begin(), order.end(), [&](int p, int q) {
            return area(p) > area(q) || (area(p) == area(q) && p < q);
        });
        dropped_ = (int)b.size() - kMaxBlobs;
        m.largest.clear();
        for (int k = 0; k < kMaxBlobs; k++)
            m.largest.push_back(b[(size_t)order[(size_t)k]]);
        b.swap(m.largest);
    }
    return true;
}

void BlobFinder::merge_fragments(int s, const PersonSize &size, Classifier &cls)
{
    // Fragments of one person (head, torso, legs split by clothes that match
    // the background) lie one above the other: merge them while the union
    // still has a person's shape.
    Impl &m = *impl_;
    Vec<Rect> &b = m.blobs;
    // Each blob's vote, computed when first needed (NaN: not yet).
    Vec<float> &votes = m.votes;
    votes.assign(b.size(), NAN);
    auto vote_of = [&](size_t k) {
        if (std::isnan(votes[k]))
            votes[k] = vote(cls, b[k]);
        return votes[k];
    };
    for (bool merged = true; merged;) {
        merged = false;
        for (size_t i = 0; i < b.size() && !merged; i++)
            for (size_t j = i + 1; j < b.size() && !merged; j++) {
                const Rect &p = b[i], &q = b[j];
                const int gap = std::max(p.y0, q.y0) - std::min(p.y1, q.y1);
                const int tall = std::max(p.y1 - p.y0, q.y1 - q.y0);
                if (!overlaps_x(p, q, kMergeOverlap) || gap > kFarMergeGap * tall)
                    continue;
                Rect u = unite(p, q);
                if (u.y1 - u.y0 < kPersonAspect * 0.75 * (u.x1 - u.x0))
                    continue;
                if (size.known() &&
                    (u.y1 - u.y0) * s > kMaxUnionHeight * size.height_at(u.y1 * s))
                    continue;
                // Close fragments merge; farther ones only when the union
                // looks more like a person than either part does.
                float vu = NAN;
                if (gap > kMergeGap * tall) {
                    vu = vote(cls, u);
                    if (!(vu > std::max(vote_of(i), vote_of(j))))
                        continue;
                }
                b[i] = u;
                votes[i] = vu;
                b.erase(b.begin() + j);
                votes.erase(votes.begin() + j);
                merged = true;
            }
    }
}

bool BlobFinder::speck(const Rect &r, int s, const PersonSize &size) const
{
    const Impl &m = *impl_;
    const long area = count_nonzero(m.clean.data(), (size_t)m.w, r.x0, r.y0, r.x1, r.y1);
    // A speck or a fragment: under a part of the person who would stand
    // where the blob's feet are (working pixels; while the size model knows
    // nothing there, under the prior's smallest person).
    const int bh = r.y1 - r.y0;
    if (size.speaks_at(r.y1 * s)) {
        const double person_h = size.height_at(r.y1 * s) / s;
        const double person_w = size.width_at(r.y1 * s) / s;
        return area < kMinAreaFraction * person_h * person_w ||
               bh < kMinHeightFraction * person_h;
    }
    return area * s * s < kPriorMinArea || bh * s < kPriorMinRows;
}

int BlobFinder::emptiest(const Rect &r, int lo, int hi, int want) const
{
    const int bh = r.y1 - r.y0;
    int best = want, best_n = bh + 1;
    for (int x = lo; x <= hi; x++) {
        const int n = impl_->column_count(x, r.y0, r.y1);
        if (n < best_n || (n == best_n && std::abs(x - want) < std::abs(best - want))) {
            best_n = n;
            best = x;
        }
    }
    return best;
}

void BlobFinder::split(const Rect &r, int s, const Rect *predicted, int n_predicted,
                       const PersonSize &size, Classifier &cls, Vec<Rect> &out)
{
    Impl &m = *impl_;
    const int bw = r.x1 - r.x0, bh = r.y1 - r.y0;
    // A group: wider than one person of this height (of the size model's
    // width where it speaks: above the feet it has seen, its line's person,
    // a few pixels tall, would cut the blob into slivers).
    const double person_w =
        size.speaks_at(r.y1 * s) ? size.width_at(r.y1 * s) / s : bh / kPersonAspect;
    const int parts = (int)std::lround(bw / person_w);
    // The predicted centres of the tracks inside, those closer than
    // kMinCentreGap heights to the one before counted once.
    Vec<int> &centres = m.centres;
    centres.clear();
    for (int k = 0; k < n_predicted; k++) {
        const Rect &p = predicted[k];
        int c = (p.x0 + p.x1) / 2;
        if (c > r.x0 && c < r.x1 && p.y1 > r.y0 && p.y0 < r.y1)
            centres.push_back(c);
    }
    std::sort(centres.begin(), centres.end());
    size_t kept = 0;
    for (size_t k = 0; k < centres.size(); k++)
        if (kept == 0 || centres[k] - centres[kept - 1] >= kMinCentreGap * bh)
            centres[kept++] = centres[k];
    centres.resize(kept);
    int head_cut = -1;
    if (parts < 2 && centres.size() < 2) {
        // Its top edge and highest column, for both heads' tests.
        const Vec<int> &top = top_edge(r);
        const int h1 = (int)(std::min_element(top.begin(), top.end()) - top.begin());
        head_cut = between_heads(r, top, h1, cls);
        if (head_cut < 0) {
            out.push_back(r);
            whole_.push_back(kWhole);
            behind(r, top, h1, s, size, out);
            return;
        }
    }
    // Two tracks or more inside: cut between each two at the emptiest
    // column of the middle half between their centres, even in a blob no
    // wider than one person (people walking close together merge into one
    // blob, and each track keeps its own part). Else, in a blob wider than
    // one person, at the emptiest column near each equal cut; in a narrower
    // one, between two heads on its top edge when the contour template
    // agrees (people who came in together, whom no track told apart). More
    // heads on the top edge than the width or the tracks say (three
    // abreast, closer than the size model's width) cut it between the
    // heads where the template takes each part for a pedestrian.
    Vec<int> &cuts = m.columns;
    cuts.clear();
    cuts.push_back(r.x0);
    Vec<int> &hs = m.heads;
    hs.clear();
    if (head_cut < 0)
        heads(r, hs);
    if (head_cut >= 0) {
        cuts.push_back(head_cut);
    } else if (hs.size() >= 2 && (int)hs.size() > parts && hs.size() > centres.size() &&
               cut_between_heads(r, hs, cls, cuts)) {
        // cut between the heads
    } else if (centres.size() >= 2) {
        for (size_t k = 0; k + 1 < centres.size(); k++) {
            const int mid = (centres[k] + centres[k + 1]) / 2;
            const int span = (centres[k + 1] - centres[k]) / 4;
            cuts.push_back(emptiest(r, mid - span, mid + span, mid));
        }
    } else {
        for (int k = 1; k < parts; k++) {
            const int want = r.x0 + k * bw / parts;
            cuts.push_back(emptiest(r, std::max(r.x0 + 1, want - (int)(person_w / 3)),
                                    std::min(r.x1 - 2, want + (int)(person_w / 3)), want));
        }
    }
    cuts.push_back(r.x1);
    const char kind = cuts.size() == 2 ? kWhole : one_head_each(r, hs, cuts) ? kHeadedPart : kPart;
    for (size_t k = 0; k + 1 < cuts.size(); k++) {
        // Each part's own vertical extent.
        const Rect part = rows_of(r, cuts[k], cuts[k + 1]);
        if (part.y1 > part.y0 && part.x1 > part.x0) {
            out.push_back(part);
            whole_.push_back(kind);
        }
    }
}

} // namespace ctrack
