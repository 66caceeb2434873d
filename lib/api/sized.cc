#include "api/sized.h"

#include "api/error.h"
#include "ctrack/ctrack.h"

namespace ctrack {

int explain_sized(SizedResult r, size_t caller_size, size_t oldest, size_t now,
                  const char *name, const char *type, char *msg, size_t msg_len)
{
    switch (r) {
    case SizedResult::too_small:
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "%s.size: %zu is smaller than any %s (%zu); fill it with %s_default()",
                    name, caller_size, type, oldest, type);
    case SizedResult::too_large:
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "%s.size: %zu is larger than any %s can be (%zu): not set, or "
                    "overwritten?",
                    name, caller_size, type, kMaxStructSize);
    case SizedResult::unknown_fields:
        return fail(msg, msg_len, CT_ERROR_UNSUPPORTED,
                    "%s.size: %zu bytes, of which this library (ctrack %s) knows %zu; the "
                    "newer fields are set",
                    name, caller_size, ct_version_string(), now);
    case SizedResult::ok:
        break;
    }
    return CT_OK;
}

} // namespace ctrack
