#include "api/error.h"

#include <cstdarg>
#include <cstdio>

namespace ctrack {

int fail(char *msg, size_t msg_len, int status, const char *fmt, ...)
{
    if (msg && msg_len > 0) {
        va_list ap;
        va_start(ap, fmt);
        std::vsnprintf(msg, msg_len, fmt, ap);
        va_end(ap);
    }
    return status;
}

} // namespace ctrack
