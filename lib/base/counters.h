// The counts of ct_stats that a tracker's parts add to as they run: time
// per stage and the work done. They are part of the engine's state: a
// failed step counts nothing.
#ifndef CTRACK_COUNTERS_H
#define CTRACK_COUNTERS_H

#include <cstdint>

#include "ctrack/ctrack.h"

namespace ctrack {

struct Counters {
    uint64_t stage_ns[CT_STATS_MAX_STAGES] = {}; // nanoseconds, by ct_stage
    uint64_t mean_shift_runs = 0;
    uint64_t ddis_runs = 0, template_builds = 0;
    uint64_t blobs_dropped = 0, masks_flooded = 0;
};

} // namespace ctrack

#endif
