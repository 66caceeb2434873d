#include "pixels/box_fit.h"

#include <algorithm>
#include <cmath>

#include "base/tunable.h"
#include "pixels/mask.h"

namespace ctrack {

namespace {

// Constants of the fit, chosen on both sequences with frames
// (docs/tuning.md, "Boxes fitted to the silhouette").
// The search reaches this share of the box's width and height beyond it.
constexpr double kReach = 0.1;
// The body's axis: the median column of the foreground in the rows from
// kAxisTop to kAxisBottom of the box (the torso, not the swinging legs);
// the head is sought within kHeadBand box heights of it (a head is about
// a tenth of a person's height across), the feet within kFeetBand: a
// walker's feet are up to a third of their height apart in a stride, and
// a narrower band sees the front foot only, the box's bottom too high.
constexpr double kAxisTop = 0.1, kAxisBottom = 0.6, kHeadBand = 0.05, kFeetBand = 0.15;
// The head's top: the first row whose share of foreground on the axis
// reaches kHeadFill; the feet: the last that reaches kFeetFill (over the
// band's 0.3 box heights, a foot's width).
constexpr double kHeadFill = 0.3, kFeetFill = 0.1;
// The box holds one person's silhouette clearly when its foreground share
// is in [kMinFill, kMaxFill]; the head-to-feet extent is taken when it is
// kMinHeight to kMaxHeight of the box's height.
constexpr double kMinFill = 0.3, kMaxFill = 0.85;
constexpr double kMinHeight = 0.8, kMaxHeight = 1.25;
// A head found farther than kHeadSlack box heights from the box's top is
// not this person's top (a group's, a blob in pieces): no move up or down.
// Unless, for a detector's box, the people's size vouches for it: the
// extent from that head to the feet is at least kSizedExtent of a person's
// height at those feet (and no more than kOnePerson), so it is one whole
// person and the detector's box sits above or below them (docs/tuning.md,
// "A head far from a detector's box's top").
constexpr double kHeadSlack = 0.15;
CT_TUNABLE(kSizedExtent, "CTRACK_SIZED_EXTENT", 0.8);
// Where the people's size speaks, a head-to-feet extent taller than
// kOnePerson times a person's height at its feet's row holds another
// person's head above or feet below (one behind, one in front, their
// silhouettes joined): no move up or down.
CT_TUNABLE(kOnePerson, "CTRACK_FIT_ONE_PERSON", 1.1);
// With the people's size known: a box under kCut of the height a person
// whose head is at its top has is cut (a coat the colour of the ground, an
// occluder), and grows to the feet found below within kFeetReach of that
// height, or to that height.
constexpr double kCut = 0.75, kFeetReach = 1.2;
// An extent taller than kOnePerson people whose feet lie within kFeetSlack
// box heights of a detector's box's bottom holds this person's feet and
// the head of someone behind: the box moves toward the height of a person
// standing at those feet (docs/tuning.md, "The feet of a joined extent").
CT_TUNABLE(kFeetSlack, "CTRACK_FEET_SLACK", 0.1);
// A box too faint to fit (fit_faint()): its person's head is sought from
// the reach above its top down to kFaintHeadSlack of its height below it.
CT_TUNABLE(kFaintHeadSlack, "CTRACK_FAINT_HEAD_SLACK", 0.25);
// The silhouette's width: the columns around the axis in which at least
// kColumnFill of the box's rows are foreground (its arms and legs in
// stride included). A box wider than kWidthMargin times that is narrowed
// to it: a detector's boxes are often looser than a person.
constexpr double kColumnFill = 0.1, kWidthMargin = 1.2;
// A box whose top another covers is its person's in front where its bottom
// is kFrontRows of its height below the other's, and the rows there are
// read where kFrontFill of them is foreground (docs/tuning.md, "The person
// in front").
constexpr double kFrontRows = 0.05, kFrontFill = 0.1;
constexpr int kMaxColumns = 1024;
// FitBias: boxes learnt before the mean is used, and the number of boxes
// the mean is over once it runs.
CT_TUNABLE(kBiasMinSamples, "CTRACK_BIAS_MIN", 20);
CT_TUNABLE(kBiasSamples, "CTRACK_BIAS_SAMPLES", 50);

// The first column at which the running sum of counts[0..n-1] reaches
// `share` of `total` (n > 0, a positive total).
int share_column(const int *counts, int n, long total, double share)
{
    long sum = 0;
    for (int x = 0; x < n; x++) {
        sum += counts[x];
        if (sum >= share * total)
            return x;
    }
    return n - 1;
}

// The height of a person whose feet are at row `feet` (frame pixels),
// where the people's size speaks there and its line is its own, not held
// at its bounds (PersonSize::line_holds_at()); 0 elsewhere.
double person_at_feet(const PersonSize &size, double feet)
{
    return size.speaks_at(feet) && size.line_holds_at(feet) ? size.height_at(feet) : 0;
}

// Columns [c0, c1) of the mask.
struct Band {
    int c0, c1;
};

// The mask's rows and columns as the fit reads them.
struct View {
    const uint8_t *mask;
    int w, h;
    double s;
    // The share of foreground in row y between columns c0 and c1.
    double share(int y, int c0, int c1) const
    {
        return (double)count_nonzero(mask + (size_t)y * w + c0, c1 - c0) / (c1 - c0);
    }
    int col(double v) const { return std::min(w, std::max(0, (int)v)); }
    int row(double v) const { return std::min(h, std::max(0, (int)v)); }
    // The columns within `reach` frame pixels of column `axis` (at least
    // one each side), clipped to [x0, x1).
    Band around(int axis, double reach, int x0, int x1) const
    {
        const int n = std::max(1, (int)(reach / s));
        return {std::max(x0, axis - n), std::min(x1, axis + n + 1)};
    }
};

// A box and the reach around it, in working pixels, clipped to the mask:
// the reach's columns [x0, x1) and rows [y0, y1), the box's [bx0, bx1)
// and [by0, by1).
struct Reach {
    int x0, x1, y0, y1, bx0, bx1, by0, by1;
    Reach(const View &v, const Box &b)
        : x0(v.col(std::floor((b.left - kReach * b.width) / v.s))),
          x1(v.col(std::ceil((b.left + (1 + kReach) * b.width) / v.s))),
          y0(v.row(std::floor((b.top - kReach * b.height) / v.s))),
          y1(v.row(std::ceil((b.top + (1 + kReach) * b.height) / v.s))),
          bx0(v.col(std::floor(b.left / v.s))), bx1(v.col(std::ceil((b.left + b.width) / v.s))),
          by0(v.row(std::floor(b.top / v.s))), by1(v.row(std::ceil((b.top + b.height) / v.s)))
    {
    }
    // Whether there is enough of it to read, and not too much to count.
    bool readable() const
    {
        return x1 - x0 >= 4 && y1 - y0 >= 6 && bx1 > bx0 && by1 > by0 && x1 - x0 <= kMaxColumns;
    }
    // The share of foreground in the box.
    double fill(const View &v) const
    {
        const long inside = count_nonzero(v.mask, (size_t)v.w, bx0, by0, bx1, by1);
        return (double)inside / ((double)(bx1 - bx0) * (by1 - by0));
    }
};

// The foreground in each column of [x0, x1) over rows [y0, y1), into
// counts[0 .. x1 - x0 - 1] (x1 - x0 <= kMaxColumns); returns their sum.
long column_counts(const View &v, int x0, int x1, int y0, int y1, int *counts)
{
    std::fill(counts, counts + (x1 - x0), 0);
    long total = 0;
    for (int y = y0; y < y1; y++) {
        const uint8_t *r = v.mask + (size_t)y * v.w;
        for (int x = x0; x < x1; x++)
            if (r[x]) {
                counts[x - x0]++;
                total++;
            }
    }
    return total;
}

// The last row in [y0, y1) whose share on the axis reaches kFeetFill, or -1.
int feet_row(const View &v, int y0, int y1, int c0, int c1)
{
    int last = -1;
    for (int y = y0; y < y1; y++)
        if (v.share(y, c0, c1) >= kFeetFill)
            last = y;
    return last;
}

// The body's axis: the median column of the foreground in the torso's rows
// of box rows [by0, by1), over columns [x0, x1); -1 where they hold too
// little to say.
int torso_axis(const View &v, int x0, int x1, int by0, int by1)
{
    int counts[kMaxColumns];
    const int ay0 = by0 + (int)(kAxisTop * (by1 - by0));
    const int ay1 = std::max(ay0 + 1, by0 + (int)(kAxisBottom * (by1 - by0)));
    const long total = column_counts(v, x0, x1, ay0, ay1, counts);
    return total < 5 ? -1 : x0 + share_column(counts, x1 - x0, total, 0.5);
}

// The head's top: the first row in [y0, y1) whose share of the head's
// band reaches kHeadFill, or -1.
int head_row(const View &v, const Band &head, int y0, int y1)
{
    for (int y = y0; y < y1; y++)
        if (v.share(y, head.c0, head.c1) >= kHeadFill)
            return y;
    return -1;
}

// With the people's size: a cut box grown to the feet, or to the height a
// person whose head is at its top has.
void grow_cut(const View &v, const PersonSize &size, int c0, int c1, Box *b)
{
    if (!size.known() || size.slope() >= 1)
        return;
    const double head = b->top;
    const double tall = size.height_under_head(head);
    // The line holds its heights at the feet only up to the tallest person
    // it may give: with a slope near 1 the height under a head grows
    // without bound (TUD-Campus with sensor noise: 1,700 pixels under a
    // head at row 200 of 480).
    if (tall > 0 && b->height < kCut * tall && size.line_holds_at(head + tall)) {
        const int feet = feet_row(v, v.row((head + kCut * tall) / v.s),
                                  v.row((head + kFeetReach * tall) / v.s), c0, c1);
        b->top = head;
        b->height = feet >= 0 ? (feet + 1) * v.s - head : tall;
    }
}

// The width of the silhouette around column `axis`: its columns in [x0,
// x1) holding foreground in at least kColumnFill of rows [y0, y1),
// contiguous with the axis (frame pixels; 0 when the axis holds none).
double silhouette_width(const View &v, int x0, int x1, int y0, int y1, int axis)
{
    auto solid = [&](int x) {
        int n = 0;
        for (int y = y0; y < y1; y++)
            n += v.mask[(size_t)y * v.w + x] != 0;
        return n >= kColumnFill * (y1 - y0);
    };
    if (!solid(axis))
        return 0;
    int lo = axis, hi = axis;
    while (lo > x0 && solid(lo - 1))
        lo--;
    while (hi + 1 < x1 && solid(hi + 1))
        hi++;
    return (hi - lo + 1) * v.s;
}

} // namespace

bool fit_box(const uint8_t *mask, int w, int h, int scale, const Box &b, double follow,
             const PersonSize *size, bool detector, Box *out, Stature *stature)
{
    if (stature)
        stature->seen = 0;
    if (!(b.width > 0 && b.height > 0) || scale < 1)
        return false;
    const View v{mask, w, h, (double)scale};
    const Reach r(v, b);
    if (!r.readable())
        return false;
    const int x0 = r.x0, x1 = r.x1, y0 = r.y0, y1 = r.y1, by0 = r.by0, by1 = r.by1;
    // One person, clearly: neither a fragment nor a filled block.
    const double fill = r.fill(v);
    if (fill < kMinFill || fill > kMaxFill)
        return false;
    // The body's axis and width, from the torso's rows.
    const int axis = torso_axis(v, x0, x1, by0, by1);
    if (axis < 0)
        return false;
    // The head's top and the feet on the axis.
    const Band head = v.around(axis, kHeadBand * b.height, x0, x1);
    const Band feet = v.around(axis, kFeetBand * b.height, x0, x1);
    const int top = head_row(v, head, y0, y1);
    const int bottom = top < 0 ? -1 : feet_row(v, top, y1, feet.c0, feet.c1);
    if (top < 0 || bottom < top)
        return false;
    Box sized = b;
    if (size)
        grow_cut(v, *size, feet.c0, feet.c1, &sized);
    const double sil_w = detector ? silhouette_width(v, x0, x1, by0, by1, axis) : 0;
    if (sil_w > 0 && sized.width > kWidthMargin * sil_w) {
        sized.left += (sized.width - kWidthMargin * sil_w) / 2;
        sized.width = kWidthMargin * sil_w;
    }
    // A person the image's edge cuts has no silhouette's centre across it:
    // the box stays where it is in that direction.
    const bool cut_side = b.left < 0 || b.left + b.width > w * v.s;
    const bool at_edge = bottom >= h - 1, past_edge = b.top + b.height > h * v.s;
    const bool cut_foot = at_edge || past_edge;
    const double axis_x = (axis + 0.5) * v.s, head_y = top * v.s;
    const double cx = cut_side ? b.left + b.width / 2 : axis_x;
    const double tall = (bottom + 1 - top) * v.s;
    const bool head_near = std::fabs(head_y - b.top) <= kHeadSlack * b.height;
    *out = sized;
    out->left += follow * (cx - (sized.left + sized.width / 2));
    if (sized.height != b.height)
        return true; // grown to the feet: its top is the head's already
    // The silhouette's head-to-feet extent, where it is the whole person's:
    // not more than kOnePerson times as tall as this person, their own
    // stature once it is known (docs/tuning.md, "One person by their own
    // stature"). The stature itself is read against the people's size, so
    // that one read low does not refuse the person's whole extent after.
    const double feet_y = (bottom + 1) * v.s;
    const double line = size && size->speaks_at(feet_y) ? size->height_at(feet_y) : 0;
    const double own = stature && stature->known > 0 ? stature->known : 1;
    const bool one_person = !(line > 0) || tall <= kOnePerson * own * line;
    const bool one_of_the_people = !(line > 0) || tall <= kOnePerson * line;
    const double at_feet = detector && size ? person_at_feet(*size, feet_y) : 0;
    const bool whole = at_feet > 0 && tall >= kSizedExtent * at_feet;
    // A silhouette on the image's last row reaches at least that far, cut
    // there or standing on it: a detector's box that ends above the edge
    // takes the extent to it (docs/tuning.md, "Feet on the image's edge").
    const bool to_edge = detector && at_edge && !past_edge;
    const bool readable = (!cut_foot || to_edge) && (head_near || whole) &&
                          tall >= kMinHeight * b.height && tall <= kMaxHeight * b.height;
    const bool extent = readable && one_person;
    const double mid = b.top + b.height / 2;
    double cy = mid;
    if (readable && one_of_the_people && stature && head_near && !cut_foot && at_feet > 0)
        stature->seen = tall / at_feet;
    if (extent) {
        cy += follow * ((top + bottom + 1) * v.s / 2 - mid);
        // A detector's box often runs past the feet or above the head;
        // the pixels' own boxes are the blob's extent already.
        if (detector)
            out->height = b.height + follow * (tall - b.height);
    } else if (at_feet > 0 && !one_person && !cut_foot &&
               std::fabs(feet_y - (b.top + b.height)) <= kFeetSlack * b.height) {
        // Not one person's extent, but its feet are where the detector
        // put this person's: toward their own height where it is known
        // (docs/tuning.md, "A person's own stature").
        const double theirs = own * at_feet;
        cy += follow * (feet_y - theirs / 2 - mid);
        out->height = b.height + follow * (theirs - b.height);
    }
    out->top = cy - out->height / 2;
    return true;
}

namespace {

// Box b placed from its person's head: the first row in [y0, y1) whose
// share of the head's band around column `axis` reaches kHeadFill, and the
// person of `stature` the people's size puts under it, where its line
// holds at their feet; *out moves `follow` of the way to them (its top to
// the head, its height to theirs) and, `across`, to the axis. False, *out
// untouched, where there is no head or no such person.
bool place_from_head(const View &v, const Box &b, int axis, int x0, int x1, int y0, int y1,
                     double follow, const PersonSize &size, double stature, bool across,
                     Box *out)
{
    const Band band = v.around(axis, kHeadBand * b.height, x0, x1);
    const int top = head_row(v, band, y0, y1);
    if (top < 0)
        return false;
    const double head = top * v.s;
    const double tall = size.height_under_head(head, stature);
    if (!(tall > 0) || !size.speaks_at(head + tall) || !size.line_holds_at(head + tall))
        return false;
    *out = b;
    if (across)
        out->left += follow * ((axis + 0.5) * v.s - (b.left + b.width / 2));
    out->top = b.top + follow * (head - b.top);
    out->height = b.height + follow * (tall - b.height);
    return true;
}

// With a line as steep as the rows (a camera at head height), a nearer
// person's head is no lower in the image: a head's row says little of the
// height under it.
bool head_says_height(const PersonSize &size, double stature)
{
    return size.known() && stature > 0 && stature * size.slope() < 1;
}

} // namespace

bool fit_faint(const uint8_t *mask, int w, int h, int scale, const Box &b, double follow,
               const PersonSize &size, double stature, Box *out)
{
    if (!(b.width > 0 && b.height > 0) || scale < 1 || !head_says_height(size, stature))
        return false;
    const View v{mask, w, h, (double)scale};
    const Reach r(v, b);
    if (!r.readable() || r.fill(v) >= kMinFill)
        return false;
    const int axis = torso_axis(v, r.x0, r.x1, r.by0, r.by1);
    // A person the image's edge cuts has no silhouette's centre across it.
    const bool across = b.left >= 0 && b.left + b.width <= w * v.s;
    return axis >= 0 &&
           place_from_head(v, b, axis, r.x0, r.x1, r.y0,
                           v.row((b.top + kFaintHeadSlack * b.height) / v.s), follow, size,
                           stature, across, out);
}

bool fit_behind(const uint8_t *mask, int w, int h, int scale, const Box &b, double cover_top,
                double cover_bottom, double follow, const PersonSize &size, double stature,
                Box *out)
{
    if (!(b.width > 0 && b.height > 0) || scale < 1 || !head_says_height(size, stature) ||
        !(b.top < cover_top) || !(b.top + b.height < cover_bottom))
        return false;
    const View v{mask, w, h, (double)scale};
    const Reach r(v, b);
    if (!r.readable())
        return false;
    // The head is sought above the other box, on the axis of the box's
    // torso's rows, as the fit reads it.
    const int axis = torso_axis(v, r.x0, r.x1, r.by0, r.by1);
    return axis >= 0 && place_from_head(v, b, axis, r.x0, r.x1, r.y0,
                                        v.row(std::ceil(cover_top / v.s)), follow, size, stature,
                                        false, out);
}

bool fit_in_front(const uint8_t *mask, int w, int h, int scale, const Box &b,
                  double cover_bottom, double follow, const PersonSize *size, Box *out)
{
    const double bottom = b.top + b.height;
    if (!(b.width > 0 && b.height > 0) || scale < 1 ||
        !(bottom - cover_bottom >= kFrontRows * b.height))
        return false;
    *out = b;
    // The rows of the person alone, to the reach below the box.
    const View v{mask, w, h, (double)scale};
    const int x0 = v.col(std::floor(b.left / v.s));
    const int x1 = v.col(std::ceil((b.left + b.width) / v.s));
    const int y0 = v.row(std::ceil(cover_bottom / v.s));
    const int y1 = v.row(std::ceil((bottom + kReach * b.height) / v.s));
    int counts[kMaxColumns];
    const long total = x1 - x0 >= 4 && x1 - x0 <= kMaxColumns && y1 - y0 >= 3
                           ? column_counts(v, x0, x1, y0, y1, counts)
                           : 0;
    if (total >= 5 && total >= kFrontFill * (x1 - x0) * (y1 - y0)) {
        const int axis = x0 + share_column(counts, x1 - x0, total, 0.5);
        out->left += follow * ((axis + 0.5) * v.s - (b.left + b.width / 2));
        const Band band = v.around(axis, kFeetBand * b.height, x0, x1);
        const int feet = feet_row(v, y0, y1, band.c0, band.c1);
        // Feet on the image's last row may be cut by its edge.
        if (feet >= 0 && feet < h - 1)
            out->top += follow * ((feet + 1) * v.s - bottom);
    }
    const double feet_y = out->top + out->height;
    const double person = size ? person_at_feet(*size, feet_y) : 0;
    if (person > 0) {
        out->height = person;
        out->top = feet_y - person;
    }
    return true;
}

bool cut_to_one_person(const PersonSize &size, Box *b)
{
    // Where the line is held at its bounds (PersonSize::max_height()), that
    // height is no measure of anyone: everyone taller would be cut to it.
    const double feet = b->top + b->height;
    const double tall = person_at_feet(size, feet);
    if (!(tall > 0) || !(b->height > kOnePerson * tall))
        return false;
    b->top = feet - tall;
    b->height = tall;
    return true;
}

void FitBias::learn(const Box &detector, const Box &fitted)
{
    if (!(detector.width > 0 && detector.height > 0))
        return;
    const double width = fitted.width / detector.width;
    const double down = (fitted.top + fitted.height / 2 - detector.top - detector.height / 2) /
                        detector.height;
    if (!std::isfinite(width) || !std::isfinite(down))
        return;
    n_++;
    const double rate = 1 / std::min(n_, kBiasSamples);
    width_ += rate * (width - width_);
    down_ += rate * (down - down_);
}

bool FitBias::known() const { return n_ >= kBiasMinSamples; }

Box FitBias::apply(const Box &b) const
{
    if (!known())
        return b;
    Box out = b;
    out.width = b.width * width_;
    out.left = b.left + (b.width - out.width) / 2;
    out.top = b.top + down_ * b.height;
    return out;
}

} // namespace ctrack
