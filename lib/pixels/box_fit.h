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

// The box b (frame pixels) fitted to the silhouette in the w x h mask
// (non-zero: foreground; a working pixel is `scale` frame pixels across),
// into *out, its centre moved `follow` of the way to the silhouette's (1:
// all the way); false, *out untouched, where the mask does not show one
// person in it clearly (too little or too much foreground, no head or feet
// on the body's axis). Its size is kept, but with the people's size known
// (`size`, or null) a box cut short of a person's height (below the head
// it has at its top) grows to the feet below, or to that height; and when
// `narrow`, a box much wider than the silhouette is narrowed to it.
bool fit_box(const uint8_t *mask, int w, int h, int scale, const Box &b, double follow,
             const PersonSize *size, bool narrow, Box *out);

} // namespace ctrack

#endif
