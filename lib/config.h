// Configuration defaults and validation.
#ifndef CTRACK_CONFIG_H
#define CTRACK_CONFIG_H

#include <cstddef>

#include "ctrack/ctrack.h"

namespace ctrack {

// The first published sizeof(ct_config): callers' structs are at least this.
constexpr size_t kConfigSizeV1 = sizeof(ct_config);

ct_config default_config();

// Reads the caller's config over the defaults and checks every field. On
// failure writes a message naming the field into msg and returns a status.
int load_config(const ct_config *in, ct_config *out, char *msg, size_t msg_len);

} // namespace ctrack

#endif
