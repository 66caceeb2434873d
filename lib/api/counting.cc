// The C ABI of counting: lines and zones added to a tracker, and the
// events and counts of its steps (lib/count/counter.h does the work).
#include "ctrack/ctrack.h"

#include "api/sized.h"
#include "api/tracker.h"

namespace {

constexpr float kDefaultHysteresis = 0.1f;

ct_line default_line()
{
    ct_line l = {};
    l.size = sizeof l;
    l.hysteresis = kDefaultHysteresis;
    return l;
}

ct_zone default_zone()
{
    ct_zone z = {};
    z.size = sizeof z;
    z.hysteresis = kDefaultHysteresis;
    return z;
}

// Reads a caller's line or zone over the defaults and hands it to add, in
// the tracker's memory; the first published layout is the whole struct.
template <typename T, typename Add>
int add_shape(ct_tracker *tracker, const T *in, T defaults, const char *name,
              const char *type, Add &&add)
{
    if (!tracker)
        return CT_ERROR_INVALID_ARGUMENT;
    ctrack::clear_error(tracker);
    char *msg = tracker->error;
    const size_t len = sizeof tracker->error;
    if (!in)
        return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT, "%s: NULL pointer", name);
    T s = defaults;
    if (const int st = ctrack::explain_sized(ctrack::read_sized(in, in->size, sizeof(T), &s),
                                             in->size, sizeof(T), sizeof(T), name, type, msg,
                                             len))
        return st;
    ctrack::MemoryScope scope(&tracker->memory);
    return ctrack::guarded(tracker, [&] { return add(s, msg, len); });
}

// What the getters copy out.
const ctrack::Vec<ct_event> &events_of(const ct_tracker &t)
{
    return t.engine.counter().events();
}
const ctrack::Vec<ct_line_count> &line_counts_of(const ct_tracker &t)
{
    return t.engine.counter().line_counts();
}
const ctrack::Vec<ct_zone_count> &zone_counts_of(const ct_tracker &t)
{
    return t.engine.counter().zone_counts();
}
const ctrack::Vec<ct_occupant> &occupants_of(const ct_tracker &t)
{
    return t.engine.counter().occupants();
}

// The last step's time, for the tracks already running when a line or a
// zone is added.
int64_t last_step(const ct_tracker *tracker)
{
    const ctrack::Engine &e = tracker->engine;
    return e.has_time() ? e.last_time() : INT64_MIN;
}

} // namespace

extern "C" {

int ct_line_default(ct_line *line, size_t size)
{
    if (!line || size < sizeof(size_t))
        return CT_ERROR_INVALID_ARGUMENT;
    ctrack::write_sized(line, size, default_line());
    line->size = size;
    return CT_OK;
}

int ct_zone_default(ct_zone *zone, size_t size)
{
    if (!zone || size < sizeof(size_t))
        return CT_ERROR_INVALID_ARGUMENT;
    ctrack::write_sized(zone, size, default_zone());
    zone->size = size;
    return CT_OK;
}

int ct_tracker_add_line(ct_tracker *tracker, const ct_line *line, int32_t *index)
{
    return add_shape(tracker, line, default_line(), "line", "ct_line",
                     [&](const ct_line &l, char *msg, size_t len) {
                         return tracker->engine.counter().add_line(l, last_step(tracker), index,
                                                                   msg, len);
                     });
}

int ct_tracker_add_zone(ct_tracker *tracker, const ct_zone *zone, int32_t *index)
{
    return add_shape(tracker, zone, default_zone(), "zone", "ct_zone",
                     [&](const ct_zone &z, char *msg, size_t len) {
                         return tracker->engine.counter().add_zone(z, last_step(tracker), index,
                                                                   msg, len);
                     });
}

int ct_tracker_get_events(const ct_tracker *tracker, ct_event *out, size_t capacity,
                          size_t elem_size, size_t *count)
{
    return ctrack::copy_out(tracker, events_of, "event", sizeof(ct_event), out,
                            capacity, elem_size, count);
}

int ct_tracker_get_line_counts(const ct_tracker *tracker, ct_line_count *out,
                               size_t capacity, size_t elem_size, size_t *count)
{
    return ctrack::copy_out(tracker, line_counts_of, "line_count", sizeof(ct_line_count), out,
                            capacity, elem_size, count);
}

int ct_tracker_get_zone_counts(const ct_tracker *tracker, ct_zone_count *out,
                               size_t capacity, size_t elem_size, size_t *count)
{
    return ctrack::copy_out(tracker, zone_counts_of, "zone_count", sizeof(ct_zone_count), out,
                            capacity, elem_size, count);
}

int ct_tracker_get_occupants(const ct_tracker *tracker, ct_occupant *out, size_t capacity,
                             size_t elem_size, size_t *count)
{
    return ctrack::copy_out(tracker, occupants_of, "occupant", sizeof(ct_occupant), out,
                            capacity, elem_size, count);
}

} // extern "C"
