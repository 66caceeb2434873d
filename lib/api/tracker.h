// The tracker behind the C ABI's handle, and what every public function
// that takes one shares: errors caught into statuses, and results copied
// out into the caller's arrays.
#ifndef CTRACK_TRACKER_H
#define CTRACK_TRACKER_H

#include <cstddef>
#include <cstdint>
#include <exception>
#include <new>
#include <type_traits>

#include "api/error.h"
#include "api/sized.h"
#include "base/memory.h"
#include "ctrack/ctrack.h"
#include "dsp/cpu.h"
#include "dsp/dsp.h"
#include "track/engine.h"

struct ct_tracker {
    ct_tracker(const ct_config &cfg, const ctrack::Memory &m)
        : memory(m), construction(&memory), engine(cfg), source(cfg.source)
    {
        ctrack::dsp_init(&dsp, ctrack::cpu_flags());
        construction.end();
    }
    // The host's allocator (or none): first, so that it outlives every
    // container that allocates from it.
    const ctrack::Memory memory;
    // The members below are made with it.
    ctrack::MemoryScope construction;
    ctrack::Engine engine;
    int source;
    // The pixel kernels for this CPU, chosen when the tracker is made.
    ctrack::Dsp dsp;
    uint64_t steps = 0, feed_ns = 0, validate_ns = 0, convert_ns = 0;
    // A packed colour frame's planes, made by the library (CT_FORMAT_BGR24,
    // CT_FORMAT_RGB24): kept from one feed to the next, so that a steady
    // stream of frames allocates nothing.
    ctrack::Vec<int16_t> converted;
    // The message of the last failed call. A fixed buffer: reporting an
    // error never allocates.
    mutable char error[512] = {0};
};

namespace ctrack {

// Runs f, turning any exception into a status and a message.
template <typename F>
int guarded(const ct_tracker *t, F &&f)
{
    char *msg = t ? t->error : nullptr;
    size_t len = t ? sizeof t->error : 0;
    try {
        return f();
    } catch (const std::bad_alloc &) {
        return ctrack::fail(msg, len, CT_ERROR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception &e) {
        return ctrack::fail(msg, len, CT_ERROR_INTERNAL, "internal error: %s", e.what());
    } catch (...) {
        return ctrack::fail(msg, len, CT_ERROR_INTERNAL, "internal error: unknown exception");
    }
}

inline void clear_error(const ct_tracker *t)
{
    t->error[0] = '\0';
}

// Copies items_of(*tracker), a Vec<T>, into the caller's array of elements
// of elem_size bytes (at least min_size, the first published sizeof(T): an
// older header's element gets the fields it has, a larger element's tail is
// zeroed), or reports the count needed. A NULL tracker is an error.
template <typename Items>
int copy_out(const ct_tracker *tracker, Items &&items_of, const char *what, size_t min_size,
             void *out, size_t capacity, size_t elem_size, size_t *count)
{
    if (!tracker)
        return CT_ERROR_INVALID_ARGUMENT;
    clear_error(tracker);
    const auto &items = items_of(*tracker);
    using T = typename std::decay_t<decltype(items)>::value_type;
    char *msg = tracker->error;
    const size_t len = sizeof tracker->error;
    if (!count)
        return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT, "count: NULL pointer");
    *count = 0;
    if (elem_size < min_size || elem_size > ctrack::kMaxStructSize) {
        if (min_size == sizeof(T)) // never grown
            return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                                "elem_size: %zu is not sizeof(ct_%s) (%zu, or more from a "
                                "newer header)",
                                elem_size, what, sizeof(T));
        return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                            "elem_size: %zu is not sizeof(ct_%s) (%zu, or %zu from an older "
                            "header, or more from a newer one)",
                            elem_size, what, sizeof(T), min_size);
    }
    if (capacity > 0 && !out)
        return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                            "out: NULL with capacity %zu", capacity);
    *count = items.size();
    if (capacity < items.size())
        return ctrack::fail(msg, len, CT_ERROR_BUFFER_TOO_SMALL,
                            "capacity: %zu %ss, %zu needed", capacity, what, items.size());
    unsigned char *dst = static_cast<unsigned char *>(out);
    for (size_t i = 0; i < items.size(); i++, dst += elem_size)
        ctrack::write_sized(dst, elem_size, items[i]);
    return CT_OK;
}

} // namespace ctrack

#endif
