// The C ABI: every public function. Each checks its arguments, then runs the
// engine inside a catch-all, so no C++ exception ever crosses into C.
#include "ctrack/ctrack.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#include "base/clock.h"
#include "api/config.h"
#include "api/convert.h"
#include "dsp/cpu.h"
#include "dsp/dsp.h"
#include "api/error.h"
#include "api/frame.h"
#include "api/sized.h"
#include "api/tracker.h"
#include "track/engine.h"
#include "pixels/prime.h"

#define CT_STR2(x) #x
#define CT_STR(x) CT_STR2(x)

using ctrack::clear_error;
using ctrack::copy_out;
using ctrack::guarded;

namespace {

// One step on a validated frame: packed colour converted, the engine's
// step, and the time it took counted (validate_ns already spent on it).
// Throws as Engine::step() does, leaving the tracker as it was.
void step_frame(ct_tracker *tracker, const ct_frame &f, const ct_detection *dets, size_t n,
                uint64_t validate_ns, ctrack::Stopwatch &sw)
{
    uint64_t convert_ns = 0;
    ctrack::Planes planes;
    if (ctrack::packed_rgb(f.format)) {
        planes = ctrack::packed_to_i420(f, tracker->dsp, &tracker->converted);
        convert_ns = sw.lap();
    } else {
        planes = ctrack::Planes::of(f);
    }
    tracker->engine.step(f.timestamp_us, planes, ctrack::ImageSize{f.width, f.height}, dets,
                         n);
    tracker->steps++;
    tracker->validate_ns += validate_ns;
    tracker->convert_ns += convert_ns;
    tracker->feed_ns += validate_ns + convert_ns + sw.lap();
}

// What the getters copy out.
const ctrack::Vec<ct_track> &tracks_of(const ct_tracker &t)
{
    return t.engine.reported();
}
const ctrack::Vec<ct_candidate> &candidates_of(const ct_tracker &t)
{
    return t.engine.candidates();
}

} // namespace

extern "C" {

const char *ct_status_str(int status)
{
    switch (status) {
    case CT_OK: return "success";
    case CT_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case CT_ERROR_OUT_OF_MEMORY: return "out of memory";
    case CT_ERROR_UNSUPPORTED: return "unsupported";
    case CT_ERROR_BUFFER_TOO_SMALL: return "buffer too small";
    case CT_ERROR_BAD_STATE: return "bad state";
    case CT_ERROR_INTERNAL: return "internal error";
    default: return "unknown status";
    }
}

const char *ct_version_string(void)
{
    return CT_STR(CT_VERSION_MAJOR) "." CT_STR(CT_VERSION_MINOR) "." CT_STR(CT_VERSION_PATCH);
}

uint32_t ct_version_number(void)
{
    return CT_VERSION_NUMBER;
}

uint32_t ct_abi_version(void)
{
    return CT_ABI_VERSION;
}

int ct_config_default(ct_config *cfg, size_t size)
{
    if (!cfg || size < sizeof(size_t))
        return CT_ERROR_INVALID_ARGUMENT;
    ctrack::write_sized(cfg, size, ctrack::default_config());
    cfg->size = size;
    return CT_OK;
}

int ct_config_check(const ct_config *cfg, char *msg, size_t msg_len)
{
    return ctrack::load_config(cfg, nullptr, msg, msg_len);
}

int ct_frame_default(ct_frame *frame, size_t size)
{
    if (!frame || size < sizeof(size_t))
        return CT_ERROR_INVALID_ARGUMENT;
    ctrack::write_sized(frame, size, ctrack::default_frame());
    frame->size = size;
    return CT_OK;
}

// A host's allocator aligns as malloc does (ct_allocator's contract).
static_assert(alignof(ct_tracker) <= alignof(std::max_align_t), "a tracker's alignment");

int ct_tracker_create(const ct_config *cfg, ct_tracker **out)
{
    return ct_tracker_create_with_allocator(cfg, nullptr, out);
}

int ct_tracker_create_with_allocator(const ct_config *cfg, const ct_allocator *allocator,
                                     ct_tracker **out)
{
    if (!out)
        return CT_ERROR_INVALID_ARGUMENT;
    *out = nullptr;
    ctrack::Memory m;
    if (allocator) {
        // The first published ct_allocator (0.9.0) is the whole struct.
        if (allocator->size < sizeof(ct_allocator) || allocator->size > ctrack::kMaxStructSize ||
            !allocator->alloc || !allocator->free)
            return CT_ERROR_INVALID_ARGUMENT;
        m.alloc = allocator->alloc;
        m.free = allocator->free;
        m.opaque = allocator->opaque;
    }
    ct_config c;
    int st = ctrack::load_config(cfg, &c, nullptr, 0);
    if (st != CT_OK)
        return st;
    return guarded(nullptr, [&] {
        void *p = ctrack::allocate(&m, sizeof(ct_tracker));
        try {
            *out = new (p) ct_tracker(c, m);
        } catch (...) {
            ctrack::release(&m, p);
            throw;
        }
        return CT_OK;
    });
}

void ct_tracker_destroy(ct_tracker *tracker)
{
    if (!tracker)
        return;
    const ctrack::Memory m = tracker->memory;
    {
        ctrack::MemoryScope scope(&tracker->memory);
        tracker->~ct_tracker();
    }
    ctrack::release(&m, tracker);
}

int ct_tracker_feed(ct_tracker *tracker, const ct_frame *frame,
                    const ct_detection *dets, size_t n)
{
    if (!tracker)
        return CT_ERROR_INVALID_ARGUMENT;
    ctrack::Stopwatch sw;
    clear_error(tracker);
    char *msg = tracker->error;
    const size_t len = sizeof tracker->error;
    ct_frame f;
    int st = ctrack::load_frame(frame, &f, msg, len);
    if (st != CT_OK)
        return st;
    st = ctrack::check_detections(dets, n, msg, len);
    if (st != CT_OK)
        return st;
    if (n > 0 && tracker->source == CT_SOURCE_PIXELS)
        return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                            "dets: %zu given, but this tracker finds its candidates in the "
                            "pixels (config.source = CT_SOURCE_PIXELS)",
                            n);
    ctrack::Engine &e = tracker->engine;
    if (e.has_time() && f.timestamp_us <= e.last_time())
        return ctrack::fail(msg, len, CT_ERROR_BAD_STATE,
                            "frame.timestamp_us: %lld does not increase (the last was %lld)",
                            (long long)f.timestamp_us, (long long)e.last_time());
    const uint64_t validate_ns = sw.lap();
    // Whatever the step makes allocates from the tracker's Memory.
    ctrack::MemoryScope scope(&tracker->memory);
    return guarded(tracker, [&] {
        step_frame(tracker, f, dets, n, validate_ns, sw);
        return CT_OK;
    });
}

// Checks the frames of a prime call into loaded[0..n-1]: each a frame
// load_frame() takes, with pixels, of frames[0]'s format and size, in
// increasing time. Returns CT_OK, or the error with its message.
static int load_prime_frames(const ct_frame *const *frames, size_t n, ct_frame *loaded,
                             char *msg, size_t len)
{
    for (size_t i = 0; i < n; i++) {
        char why[400];
        if (!frames[i])
            return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT, "frames[%zu]: NULL", i);
        const int st = ctrack::load_frame(frames[i], &loaded[i], why, sizeof why);
        const ct_frame &f = loaded[i], &f0 = loaded[0];
        if (st != CT_OK)
            return ctrack::fail(msg, len, st, "frames[%zu]: %s", i, why);
        if (f.format == CT_FORMAT_NONE)
            return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                                "frames[%zu]: no pixels (CT_FORMAT_NONE); priming learns "
                                "the background from the pixels",
                                i);
        if (i > 0 && (f.format != f0.format || f.width != f0.width || f.height != f0.height))
            return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                                "frames[%zu]: %s %dx%d, where frames[0] is %s %dx%d: one "
                                "priming takes frames of one format and size",
                                i, ctrack::format_name(f.format), f.width, f.height,
                                ctrack::format_name(f0.format), f0.width, f0.height);
        if (i > 0 && f.timestamp_us <= loaded[i - 1].timestamp_us)
            return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                                "frames[%zu].timestamp_us: %lld does not increase (the "
                                "one before is %lld)",
                                i, (long long)f.timestamp_us,
                                (long long)loaded[i - 1].timestamp_us);
    }
    return CT_OK;
}

int ct_tracker_prime(ct_tracker *tracker, const ct_frame *const *frames, size_t n)
{
    if (!tracker)
        return CT_ERROR_INVALID_ARGUMENT;
    clear_error(tracker);
    char *msg = tracker->error;
    const size_t len = sizeof tracker->error;
    if (!frames || n == 0)
        return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                            "frames: %s; priming takes at least one frame",
                            frames ? "n is 0" : "NULL");
    if (n > ctrack::kPrimeMaxFrames)
        return ctrack::fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                            "n: %zu frames; priming takes at most %zu (a recording's first "
                            "seconds)",
                            n, ctrack::kPrimeMaxFrames);
    ctrack::Stopwatch sw;
    ctrack::MemoryScope scope(&tracker->memory);
    return guarded(tracker, [&]() -> int {
        // Every frame is checked, and the median made, before the tracker
        // changes.
        ctrack::Vec<ct_frame> loaded(n);
        if (const int st = load_prime_frames(frames, n, loaded.data(), msg, len))
            return st;
        ctrack::PackedFrame median, clean;
        ctrack::median_frame(loaded.data(), n, &median);
        ctrack::Engine &e = tracker->engine;
        const uint64_t counts[4] = {tracker->steps, tracker->feed_ns, tracker->validate_ns,
                                    tracker->convert_ns};
        e.begin_prime();
        try {
            // The steps count in ct_stats; the checks, the median and the
            // cleaning are no step's validation, and are not counted.
            for (size_t i = 0; i < n; i++) {
                ctrack::clean_frame(loaded[i], median, ctrack::kPrimeClean, &clean);
                sw.lap();
                step_frame(tracker, clean.frame(), nullptr, 0, 0, sw);
            }
        } catch (...) {
            e.abort_prime();
            tracker->steps = counts[0];
            tracker->feed_ns = counts[1];
            tracker->validate_ns = counts[2];
            tracker->convert_ns = counts[3];
            throw;
        }
        e.end_prime();
        return CT_OK;
    });
}

int ct_tracker_get_tracks(const ct_tracker *tracker, ct_track *out, size_t capacity,
                          size_t elem_size, size_t *count)
{
    return copy_out(tracker, tracks_of, "track", sizeof(ct_track), out,
                    capacity, elem_size, count);
}

int ct_tracker_get_candidates(const ct_tracker *tracker, ct_candidate *out, size_t capacity,
                              size_t elem_size, size_t *count)
{
    // The first published ct_candidate (0.4.0) ended with region_distance.
    return copy_out(tracker, candidates_of, "candidate",
                    offsetof(ct_candidate, fill), out, capacity, elem_size, count);
}

const char *ct_stage_name(int stage)
{
    switch (stage) {
    case CT_STAGE_VALIDATE: return "validate";
    case CT_STAGE_PREDICT: return "predict";
    case CT_STAGE_ASSOCIATE: return "associate";
    case CT_STAGE_LIFECYCLE: return "lifecycle";
    case CT_STAGE_REPORT: return "report";
    case CT_STAGE_MEAN_SHIFT: return "mean_shift";
    case CT_STAGE_APPEARANCE: return "appearance";
    case CT_STAGE_BACKGROUND: return "background";
    case CT_STAGE_BLOBS: return "blobs";
    case CT_STAGE_CLASSIFY: return "classify";
    case CT_STAGE_CONVERT: return "convert";
    default: return nullptr;
    }
}

// The checks of a getter that fills a size-prefixed struct: a tracker, a
// struct, and a size from `oldest` (its first published layout) up to
// kMaxStructSize (a newer header's). Returns CT_OK, or the error, set.
static int check_out(const ct_tracker *tracker, const void *out, size_t size, size_t oldest,
                     size_t now, const char *name, const char *type)
{
    if (!tracker)
        return CT_ERROR_INVALID_ARGUMENT;
    clear_error(tracker);
    if (!out)
        return ctrack::fail(tracker->error, sizeof tracker->error, CT_ERROR_INVALID_ARGUMENT,
                            "%s: NULL pointer", name);
    if (size < oldest || size > ctrack::kMaxStructSize)
        return ctrack::fail(tracker->error, sizeof tracker->error, CT_ERROR_INVALID_ARGUMENT,
                            "%s.size: %zu is not sizeof(%s) (%zu, or %zu from an older header, "
                            "or more from a newer one)",
                            name, size, type, now, oldest);
    return CT_OK;
}

int ct_tracker_get_person_size(const ct_tracker *tracker, ct_person_size *out)
{
    const size_t size = out ? out->size : 0;
    // ct_person_size ended with samples before typical_height was added.
    if (const int st = check_out(tracker, out, size, offsetof(ct_person_size, typical_height),
                                 sizeof(ct_person_size), "out", "ct_person_size"))
        return st;
    const ctrack::PersonSize &p = tracker->engine.person_size();
    ct_person_size s = {};
    s.size = size;
    s.known = p.known();
    if (p.known()) {
        s.height_slope = (float)p.slope();
        s.height_intercept = (float)p.intercept();
        s.width_ratio = (float)p.aspect();
        s.typical_height = (float)p.typical_height();
    }
    s.samples = p.samples();
    s.working_scale = tracker->engine.working_scale();
    ctrack::write_sized(out, size, s);
    return CT_OK;
}

int ct_tracker_get_stats(const ct_tracker *tracker, ct_stats *stats)
{
    // The first published ct_stats (0.1.0) ended with memory_bytes.
    const size_t size = stats ? stats->size : 0;
    if (const int st = check_out(tracker, stats, size, offsetof(ct_stats, mean_shift_runs),
                                 sizeof(ct_stats), "stats", "ct_stats"))
        return st;
    ct_stats s = {};
    s.size = size;
    s.steps = tracker->steps;
    s.feed_ns = tracker->feed_ns;
    const ctrack::Engine &e = tracker->engine;
    const ctrack::Counters &c = e.counters();
    for (int i = 0; i < CT_STATS_MAX_STAGES; i++)
        s.stage_ns[i] = c.stage_ns[i];
    s.stage_ns[CT_STAGE_VALIDATE] = tracker->validate_ns;
    s.stage_ns[CT_STAGE_CONVERT] = tracker->convert_ns;
    s.live_tracks = e.live_tracks();
    s.memory_bytes = sizeof(ct_tracker) - sizeof(ctrack::Engine) + e.memory_bytes() +
                     tracker->converted.capacity() * sizeof(int16_t);
    s.mean_shift_runs = c.mean_shift_runs;
    s.ddis_runs = c.ddis_runs;
    s.template_builds = c.template_builds;
    s.blobs_dropped = c.blobs_dropped;
    s.masks_flooded = c.masks_flooded;
    ctrack::write_sized(stats, size, s);
    return CT_OK;
}

int ct_tracker_reset(ct_tracker *tracker)
{
    if (!tracker)
        return CT_ERROR_INVALID_ARGUMENT;
    clear_error(tracker);
    ctrack::MemoryScope scope(&tracker->memory);
    return guarded(tracker, [&] {
        tracker->engine.reset();
        return CT_OK;
    });
}

const char *ct_tracker_last_error(const ct_tracker *tracker)
{
    return tracker ? tracker->error : "";
}

} // extern "C"
