// Packed colour frames (CT_FORMAT_BGR24, CT_FORMAT_RGB24) converted to the
// I420 planes the rest of the library reads.
#ifndef CTRACK_CONVERT_H
#define CTRACK_CONVERT_H

#include <cstdint>
#include <vector>

#include "base/memory.h"

#include "ctrack/ctrack.h"
#include "dsp/dsp.h"
#include "base/planes.h"

namespace ctrack {

// A loaded BGR24 or RGB24 frame converted to I420 planes in buf (resized to
// fit, and working rows after them; the planes point into it), its rows by
// dsp's kernels.
Planes packed_to_i420(const ct_frame &f, const Dsp &dsp, Vec<int16_t> *buf);

} // namespace ctrack

#endif
