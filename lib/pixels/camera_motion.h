// Whether the camera moved between two frames, from their luma's column
// and row sums (projections): a still camera's profiles match where they
// are, a panning or shaking one's match better shifted. Cheap (one pass
// over the pixels, already read for the background model) and blind to
// people moving, who change the sums only locally.
#ifndef CTRACK_CAMERA_MOTION_H
#define CTRACK_CAMERA_MOTION_H

#include <cstdint>

namespace ctrack {

// Whether profile `now` (n sums) matches `before` shifted by a whole
// number of samples in [-reach, reach], not 0, clearly better than
// unshifted.
bool profile_shifted(const int32_t *now, const int32_t *before, int n, int reach);

} // namespace ctrack

#endif
