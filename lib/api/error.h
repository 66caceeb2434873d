// Writing an error message into a caller's buffer.
#ifndef CTRACK_ERROR_H
#define CTRACK_ERROR_H

#include <cstddef>

namespace ctrack {

// Formats a message into msg (when msg_len > 0; always NUL-terminated,
// truncated if need be) and returns status, so checks read
// `return fail(msg, len, CT_ERROR_..., "field: ...", ...);`.
int fail(char *msg, size_t msg_len, int status, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

} // namespace ctrack

#endif
