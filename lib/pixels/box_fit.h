// A reported box fitted to the person's silhouette in the foreground mask:
// its centre moved toward the body's axis and toward the middle between
// the head's top and the feet, where the silhouette is clear enough to say.
#ifndef CTRACK_BOX_FIT_H
#define CTRACK_BOX_FIT_H

#include <cstdint>

#include "track/person_size.h"
#include "track/track.h"

namespace ctrack {

// How far a reported box moves toward its silhouette's centre
// (docs/tuning.md, "Boxes fitted to the silhouette").
constexpr double kFitFollow = 0.7;

// One person's stature (the ratio of their silhouette's head-to-feet
// extent to the people's size at its feet): `known`, or 0 where it is not
// yet, stands for the people's size where a detector's box moves toward the
// height of a person at its feet with no head of its own to read; `seen`
// is set to the ratio this fit measured where it read the whole extent (0
// where it did not).
struct Stature {
    double known = 0;
    double seen = 0;
};

// The box b (frame pixels) fitted to the silhouette in the w x h mask
// (non-zero: foreground; a working pixel is `scale` frame pixels across),
// into *out, its centre moved `follow` of the way to the silhouette's (1:
// all the way); false, *out untouched, where the mask does not show one
// person in it clearly (too little or too much foreground, no head or feet
// on the body's axis). With the people's size known (`size`, or null) a
// box cut short of a person's height (below the head it has at its top)
// grows to the feet below, or to that height; and a head-to-feet extent
// more than a tenth taller than a person whose feet are at its bottom
// (than this person, where `stature` knows their share of the people's
// size) is not one person's (a head behind or feet in front joined to it): the
// box is not moved up or down by it, but for a detector's box whose bottom
// is at those feet, which moves `follow` of the way to the height of a
// person standing there (someone's head behind joined the extent): this
// person's own where `stature` knows it. A `detector`'s box (not the
// pixels' own, which is its blob's extent) much wider than the silhouette
// is narrowed to it, and its height moves `follow` of the way to the
// silhouette's head-to-feet extent where that is the whole person's (its
// head near the box's top, or, with the size, the extent one person tall
// at its feet; feet on the image's last row are the edge's, taken only for
// a box that ends above it); other boxes keep their size.
bool fit_box(const uint8_t *mask, int w, int h, int scale, const Box &b, double follow,
             const PersonSize *size, bool detector, Box *out, Stature *stature = nullptr);

// A detector's box b too faint for fit_box() (under 0.3 of it foreground: a
// person behind a sign or a post, their legs hidden, or dressed like the
// ground) whose person's `stature` is known (Stature::known): the first
// row of foreground on the body's axis from the reach above its top to a
// quarter of its height below it is their head, and the box moves
// `follow` of the way to the person of that stature the people's size
// puts under it (its top to the head, its height to theirs) and across to
// the axis (docs/tuning.md, "A box too faint to fit"). False, *out
// untouched, where no head is found or the size gives no one under it (a
// line as steep as the rows: a camera at head height).
bool fit_faint(const uint8_t *mask, int w, int h, int scale, const Box &b, double follow,
               const PersonSize &size, double stature, Box *out);

// A detector's box whose bottom another box covers, its person behind
// (their box starting above the other's top, `cover_top`, and ending above
// its bottom, `cover_bottom`), whose `stature` is known: the rows above the
// other box are its person's alone, and the first row of foreground on the
// body's axis there is their head. The box moves `follow` of the way to
// the person of that stature the people's size puts under it, its top to
// the head and its height to theirs; across it stays, the axis of two
// people's silhouette being no nearer its person's centre than the
// detector's box (docs/tuning.md, "The person behind"). False, *out
// untouched, where the person is not behind, no head is found or the size
// gives no one under it (a line as steep as the rows).
bool fit_behind(const uint8_t *mask, int w, int h, int scale, const Box &b, double cover_top,
                double cover_bottom, double follow, const PersonSize &size, double stature,
                Box *out);

// A detector's box whose top another box covers, its person in front
// (their feet below the other box's bottom, `cover_bottom`, by kFrontRows
// of its height or more): the rows below the other box are its person's
// alone. Its centre moves `follow` of the way across to the axis of the
// foreground in those rows (between the legs) and down or up to the feet
// found there; it then takes the height of a person whose feet are at its
// bottom, where the people's size (`size`, or null) speaks there. False,
// *out untouched, where the person is not in front.
bool fit_in_front(const uint8_t *mask, int w, int h, int scale, const Box &b,
                  double cover_bottom, double follow, const PersonSize *size, Box *out);

// A detector's box more than a tenth taller than a person whose feet are
// at its bottom row (where the people's size speaks, and its line is its
// own, not held at its bounds: PersonSize::line_holds_at()) is not one
// person's: the head of someone behind, or a top left loose. It becomes
// that one person, from its bottom row up, as the fit takes a
// silhouette's extent (docs/tuning.md, "A detector's box over more than
// one person"). True when *b was cut.
bool cut_to_one_person(const PersonSize &size, Box *b);

// What the fit does to a detector's boxes, learnt online from the boxes it
// fits: their mean width over the detector's, and how far their centre
// lies below the detector's, in box heights (a detector's boxes are often
// wider than a person, or start above the head). A box of that detector
// whose silhouette the fit cannot read (too little foreground in it: a
// person the colour of the ground, a box far too loose) takes that mean
// instead of passing the detector's bias through. Its horizontal shift is
// not learnt: people walk both ways, and a detector's error across is not
// one-sided.
class FitBias {
public:
    // A box the detector gave and the fit it got.
    void learn(const Box &detector, const Box &fitted);
    // Whether enough boxes were learnt for the mean to be used.
    bool known() const;
    // b with the learnt width and centre (b itself while not known()).
    Box apply(const Box &b) const;

private:
    double n_ = 0, width_ = 1, down_ = 0;
};

} // namespace ctrack

#endif
