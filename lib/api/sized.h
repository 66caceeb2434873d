// Reading a caller's size-prefixed struct that may be older or newer than
// the library's.
#ifndef CTRACK_SIZED_H
#define CTRACK_SIZED_H

#include <cstddef>
#include <cstring>

namespace ctrack {

enum class SizedResult { ok, too_small, too_large, unknown_fields };

// The largest size a caller's struct may claim: no ctrack struct will grow
// past it, so a larger size is garbage (reading that far would run past
// the caller's memory). copy_out() caps element sizes the same way.
constexpr size_t kMaxStructSize = 1u << 16;

// Copies the `caller_size` bytes the caller's struct has over `out` (which
// holds the defaults). A caller's struct smaller than `min_size` (the first
// published version), or larger than kMaxStructSize, is refused; one larger
// than this library's, from a newer header, is accepted only if the fields
// this library does not know are all zero, that is, left at their defaults.
template <typename T>
SizedResult read_sized(const T *in, size_t caller_size, size_t min_size, T *out)
{
    if (caller_size < min_size)
        return SizedResult::too_small;
    if (caller_size > kMaxStructSize)
        return SizedResult::too_large;
    if (caller_size > sizeof(T)) {
        const unsigned char *extra = reinterpret_cast<const unsigned char *>(in) + sizeof(T);
        for (size_t i = 0; i < caller_size - sizeof(T); i++)
            if (extra[i] != 0)
                return SizedResult::unknown_fields;
        caller_size = sizeof(T);
    }
    std::memcpy(static_cast<void *>(out), in, caller_size);
    out->size = sizeof(T);
    return SizedResult::ok;
}

// Writes value into the caller's struct of `size` bytes: what both know is
// copied, a smaller caller's struct gets only its part, a larger one's
// unknown tail is zeroed.
template <typename T>
void write_sized(void *out, size_t size, const T &value)
{
    std::memset(out, 0, size);
    std::memcpy(out, &value, size < sizeof(T) ? size : sizeof(T));
}

// CT_OK for SizedResult::ok, else the error a caller's `name` (a `type`)
// gets, with its message: `oldest` is the first published size of the
// struct, `now` this library's.
int explain_sized(SizedResult r, size_t caller_size, size_t oldest, size_t now,
                  const char *name, const char *type, char *msg, size_t msg_len);

} // namespace ctrack

#endif
