// Configuration defaults and validation.
#ifndef CTRACK_CONFIG_H
#define CTRACK_CONFIG_H

#include <cstddef>

#include "ctrack/ctrack.h"

namespace ctrack {

// The first published sizeof(ct_config) (0.1.0, up to max_tracks): callers'
// structs are at least this; fields after it take their defaults.
constexpr size_t kConfigSizeV1 = offsetof(ct_config, mean_shift);

ct_config default_config();

// Reads the caller's config over the defaults and checks every field. On
// failure writes a message naming the field into msg and returns a status.
int load_config(const ct_config *in, ct_config *out, char *msg, size_t msg_len);

} // namespace ctrack

#endif
