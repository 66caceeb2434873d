// libFuzzer target: the tracker's whole C interface. The input is read as
// a fuzzed configuration, then a sequence of calls: feeds of frames in every
// format (each plane in a buffer of exactly the size the frame claims, so
// AddressSanitizer sees any read past it), detections with NaN, infinities,
// huge, negative and thousands of overlapping boxes, timestamps that go
// back or jump, and get_tracks, get_candidates, get_stats, get_person_size,
// reset, priming and counting lines and zones (NaN, huge, degenerate,
// self-crossing, too many corners, long names) in between.
//
// Beyond the sanitizers it checks, after every call:
//   - a twin tracker, created alike and given only the calls that succeeded
//     on the first, reports the same tracks, candidates, step count and
//     person size: a failed feed changed nothing, and the next step's
//     output is what a tracker that never saw it gives;
//   - track ids are positive, increase within a step, and a new id is
//     larger than every id reported before (ids are never reused);
//   - every reported number is finite and in its range (sizes positive,
//     confidence and scores in [0, 1], states, detection indices, votes);
//   - the buffer-size protocol: too small a buffer copies nothing and tells
//     the count needed.
// One input in four is instead a street scene (scene.h): 320x240 frames of
// people walking, in pairs and groups, crossing, stopping, in clothes the
// colour of the ground, fed to trackers from the pixels alone (or
// detections with pixels) for up to 160 frames, under the same checks, so
// that blob merging, group splitting and the people's size are reached.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "ctrack/ctrack.h"
#include "fuzz.h"
#include "scene.h"

namespace {

float fuzz_float(FuzzedDataProvider &in, float lo, float hi)
{
    switch (in.ConsumeIntegralInRange<int>(0, 15)) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    case 2: return -std::numeric_limits<float>::infinity();
    case 3: return -1.0f;
    case 4: return 3e38f;
    case 5: return 0.0f;
    case 6: return std::numeric_limits<float>::denorm_min();
    default: return in.ConsumeFloatingPointInRange<float>(lo, hi);
    }
}

double fuzz_double(FuzzedDataProvider &in, double lo, double hi)
{
    switch (in.ConsumeIntegralInRange<int>(0, 11)) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return -1.0;
    case 3: return 1e300;
    default: return in.ConsumeFloatingPointInRange<double>(lo, hi);
    }
}

void fuzz_config(FuzzedDataProvider &in, ct_config *cfg)
{
    ct_config_default(cfg, sizeof *cfg);
    // Each field is left at its default unless its bit is set: most inputs
    // then run a tracker that works, a few test the checks.
    const uint32_t which = in.ConsumeIntegral<uint32_t>();
    auto f = [&](int bit, float *v, float lo, float hi) {
        if (which & (1u << bit))
            *v = fuzz_float(in, lo, hi);
    };
    auto d = [&](int bit, double *v, double lo, double hi) {
        if (which & (1u << bit))
            *v = fuzz_double(in, lo, hi);
    };
    auto i = [&](int bit, int32_t *v, int32_t lo, int32_t hi) {
        if (which & (1u << bit))
            *v = in.ConsumeIntegralInRange<int32_t>(lo, hi);
    };
    i(0, &cfg->source, -1, 2);
    f(1, &cfg->high_score, -0.5f, 1.5f);
    f(2, &cfg->low_score, -0.5f, 1.5f);
    f(3, &cfg->match_iou, -0.5f, 1.5f);
    f(4, &cfg->low_match_iou, -0.5f, 1.5f);
    f(5, &cfg->tentative_match_iou, -0.5f, 1.5f);
    i(6, &cfg->min_hits, -1, 5);
    d(7, &cfg->lost_lifetime, -1.0, 10.0);
    d(8, &cfg->report_lost_time, -1.0, 10.0);
    f(9, &cfg->motion_noise, -1.0f, 100.0f);
    f(10, &cfg->detection_noise, -1.0f, 10.0f);
    i(11, &cfg->clip_boxes, -1, 2);
    i(12, &cfg->max_tracks, -1, 64);
    i(13, &cfg->mean_shift, -1, 2);
    f(14, &cfg->mean_shift_min_similarity, -0.5f, 1.5f);
    d(15, &cfg->mean_shift_max_time, -1.0, 10.0);
    f(16, &cfg->model_learning_rate, -0.5f, 1.5f);
    f(17, &cfg->mean_shift_coarse_below, -0.5f, 1.5f);
    i(18, &cfg->appearance, -1, 2);
    f(19, &cfg->appearance_weight, -1.0f, 10.0f);
    f(20, &cfg->reid_min_similarity, -0.5f, 1.5f);
    f(21, &cfg->reid_max_speed, -1.0f, 100.0f);
    f(22, &cfg->candidate_min_score, -0.5f, 1.5f);
    i(23, &cfg->verify_detections, -1, 2);
    f(24, &cfg->start_score, -0.5f, 1.5f);
    f(25, &cfg->report_lost_sd, -1.0f, 20.0f);
    i(26, &cfg->pedestrian_test, -1, 2);
    f(27, &cfg->size_gate, -1.0f, 12.0f);
    f(28, &cfg->confirm_score, -0.5f, 1.5f);
}

// The struct as a caller built against another header passes it: its size
// field and a buffer of that size, whose fields unknown here are zero (or,
// rarely, not).
struct Sized {
    std::vector<uint8_t> bytes;
    template <typename T> void wrap(FuzzedDataProvider &in, const T &v)
    {
        size_t size = sizeof v;
        if (in.ConsumeIntegralInRange<int>(0, 31) == 0)
            size = in.ConsumeIntegralInRange<size_t>(0, 2 * sizeof v);
        bytes.assign(size > sizeof v ? size : sizeof v, 0);
        std::memcpy(bytes.data(), &v, sizeof v);
        std::memcpy(bytes.data(), &size, sizeof size); // the size field comes first
        if (size > sizeof v && in.ConsumeBool())
            bytes[size - 1] = 1;
    }
    template <typename T> const T *as() const { return reinterpret_cast<const T *>(bytes.data()); }
};

// A frame whose planes are buffers of exactly the size it claims.
struct Frame {
    ct_frame f;
    Sized header; // f as the call passes it
    std::vector<uint8_t *> owned;
    ~Frame()
    {
        for (uint8_t *p : owned)
            std::free(p);
    }
};

const uint32_t kFormats[] = {CT_FORMAT_NONE,  CT_FORMAT_I420,  CT_FORMAT_NV12, CT_FORMAT_GRAY8,
                             CT_FORMAT_BGR24, CT_FORMAT_RGB24, 0x34424752u /* 'RGB4' */};

void fuzz_frame(FuzzedDataProvider &in, Frame *fr, int64_t *clock, int *shape)
{
    ct_frame &f = fr->f;
    ct_frame_default(&f, sizeof f);
    // The timestamp usually moves on by a frame; sometimes it stands, goes
    // back or jumps to the end of time.
    // (Wrapping round, as the caller's clock might: no overflow here.)
    auto add = [&](int64_t d) { *clock = (int64_t)((uint64_t)*clock + (uint64_t)d); };
    switch (in.ConsumeIntegralInRange<int>(0, 15)) {
    case 0: break;
    case 1: add(-40000); break;
    case 2: *clock = INT64_MAX; break;
    case 3: *clock = INT64_MIN; break;
    case 4: add(in.ConsumeIntegral<int64_t>() / 2); break;
    default: add(in.ConsumeIntegralInRange<int64_t>(1, 400000)); break;
    }
    f.timestamp_us = *clock;
    f.format = kFormats[in.ConsumeIntegralInRange<size_t>(0, 6)];
    // Sizes: mostly the scene's (so the background model learns), else any.
    if (in.ConsumeBool()) {
        f.width = shape[0];
        f.height = shape[1];
    } else if (in.ConsumeIntegralInRange<int>(0, 15) == 0) {
        f.width = in.ConsumeIntegral<int32_t>();
        f.height = in.ConsumeIntegral<int32_t>();
    } else {
        f.width = in.ConsumeIntegralInRange<int32_t>(1, 96);
        f.height = in.ConsumeIntegralInRange<int32_t>(1, 96);
    }
    int planes = 0;
    int64_t row[3] = {0, 0, 0}, rows[3] = {0, 0, 0};
    const int64_t w = f.width, h = f.height, cw = (w + 1) / 2, ch = (h + 1) / 2;
    switch (f.format) {
    case CT_FORMAT_I420: planes = 3; row[0] = w; row[1] = row[2] = cw;
        rows[0] = h; rows[1] = rows[2] = ch; break;
    case CT_FORMAT_NV12: planes = 2; row[0] = w; row[1] = 2 * cw; rows[0] = h; rows[1] = ch; break;
    case CT_FORMAT_GRAY8: planes = 1; row[0] = w; rows[0] = h; break;
    case CT_FORMAT_BGR24:
    case CT_FORMAT_RGB24: planes = 1; row[0] = 3 * w; rows[0] = h; break;
    default: break;
    }
    if (w < 1 || h < 1 || w > 96 || h > 96)
        planes = 0; // claimed sizes the library must refuse before reading
    for (int p = 0; p < planes; p++) {
        // The stride: the row, padded, or (rarely) too short.
        int64_t stride = row[p] + in.ConsumeIntegralInRange<int>(0, 3) * 16;
        if (in.ConsumeIntegralInRange<int>(0, 31) == 0)
            stride = row[p] - in.ConsumeIntegralInRange<int>(1, 8);
        f.strides[p] = (int32_t)stride;
        if (stride < 1)
            continue;
        // The last row need not be padded: exactly what a tight buffer holds.
        const size_t bytes = (size_t)(stride * (rows[p] - 1) + row[p]);
        uint8_t *buf = (uint8_t *)std::malloc(bytes);
        CHECK(buf);
        fr->owned.push_back(buf);
        // A bright figure on a dark ground that moves with time, then noise
        // from the input where it has bytes left.
        const int64_t t = *clock / 40000;
        for (int64_t y = 0; y < rows[p]; y++)
            for (int64_t x = 0; x < row[p] && y * stride + x < (int64_t)bytes; x++) {
                const int64_t px = x * w / row[p], py = y * h / rows[p];
                const bool figure = (px - t % (w + 1)) * (px - t % (w + 1)) < w * w / 64 &&
                                    py > h / 4 && py < 3 * h / 4;
                buf[y * stride + x] = figure ? 200 : 40;
            }
        const std::vector<uint8_t> noise = in.ConsumeBytes<uint8_t>(
            in.ConsumeIntegralInRange<size_t>(0, 64));
        for (size_t k = 0; k < noise.size(); k++)
            buf[(k * 131) % bytes] ^= noise[k];
        f.planes[p] = buf;
    }
    if (planes > 0 && in.ConsumeIntegralInRange<int>(0, 31) == 0)
        f.planes[in.ConsumeIntegralInRange<int>(0, planes - 1)] = nullptr;
    fr->header.wrap(in, f);
}

std::vector<ct_detection> fuzz_detections(FuzzedDataProvider &in, const int *shape)
{
    std::vector<ct_detection> dets;
    // FuzzedDataProvider gives a range's least value once the input runs
    // out: the rare and costly cases are taken at the other end, so that
    // the many inputs that run out do not all end in one.
    const int kind = in.ConsumeIntegralInRange<int>(0, 255);
    if (kind == 255) {
        // A flood: thousands of boxes around one, as a detector without
        // non-maximum suppression gives (rarely: with pixels and appearance
        // one costs as much as thousands of ordinary steps).
        const size_t n = in.ConsumeIntegralInRange<size_t>(1000, 2500);
        const float x = in.ConsumeFloatingPointInRange<float>(0, (float)shape[0]);
        const float y = in.ConsumeFloatingPointInRange<float>(0, (float)shape[1]);
        for (size_t k = 0; k < n; k++)
            dets.push_back({x + (float)(k % 7), y + (float)(k % 5), 20.0f + (float)(k % 3),
                            50.0f, 0.3f + 0.7f * (float)(k % 11) / 10.0f, 0});
        return dets;
    }
    const size_t n = in.ConsumeIntegralInRange<size_t>(0, kind < 64 ? 0 : 12);
    for (size_t k = 0; k < n; k++) {
        ct_detection d;
        if (in.ConsumeIntegralInRange<int>(0, 7) == 0) {
            d.left = fuzz_float(in, -1e6f, 1e6f);
            d.top = fuzz_float(in, -1e6f, 1e6f);
            d.width = fuzz_float(in, -10.0f, 1e6f);
            d.height = fuzz_float(in, -10.0f, 1e6f);
            d.score = fuzz_float(in, -1.0f, 2.0f);
        } else {
            d.left = in.ConsumeFloatingPointInRange<float>(-20.0f, (float)shape[0]);
            d.top = in.ConsumeFloatingPointInRange<float>(-20.0f, (float)shape[1]);
            d.width = in.ConsumeFloatingPointInRange<float>(1.0f, 60.0f);
            d.height = in.ConsumeFloatingPointInRange<float>(1.0f, 120.0f);
            d.score = in.ConsumeFloatingPointInRange<float>(0.0f, 1.0f);
        }
        d.class_id = in.ConsumeIntegral<int32_t>();
        dets.push_back(d);
    }
    return dets;
}

bool finite(float v) { return std::isfinite(v); }

// Everything a getter of `T` has, through the buffer-size protocol.
template <typename T, typename Get> std::vector<T> all_of(const ct_tracker *t, Get get)
{
    size_t count = 0;
    const int st = get(t, nullptr, 0, sizeof(T), &count);
    CHECK(st == (count ? CT_ERROR_BUFFER_TOO_SMALL : CT_OK));
    std::vector<T> v(count + 1);
    size_t got = 0;
    CHECK(get(t, v.data(), v.size(), sizeof(T), &got) == CT_OK);
    CHECK(got == count);
    v.resize(got);
    return v;
}

template <typename T> bool same_bytes(const std::vector<T> &a, const std::vector<T> &b)
{
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

struct Output {
    std::vector<ct_track> tracks;
    std::vector<ct_candidate> candidates;
    std::vector<ct_event> events;
    std::vector<ct_line_count> lines;
    std::vector<ct_zone_count> zones;
    std::vector<ct_occupant> occupants;
    uint64_t steps = 0, live = 0;
    ct_person_size size{};
};

Output output_of(const ct_tracker *t)
{
    Output o;
    size_t count = 0;
    CHECK(ct_tracker_get_tracks(t, nullptr, 0, sizeof(ct_track), &count) ==
          (count ? CT_ERROR_BUFFER_TOO_SMALL : CT_OK));
    // Again with the count asked for: 0 tracks is OK with capacity 0.
    CHECK(ct_tracker_get_tracks(t, nullptr, 0, sizeof(ct_track), &count) ==
          (count ? CT_ERROR_BUFFER_TOO_SMALL : CT_OK));
    o.tracks.resize(count + 1);
    size_t got = 0;
    CHECK(ct_tracker_get_tracks(t, o.tracks.data(), o.tracks.size(), sizeof(ct_track), &got) ==
          CT_OK);
    CHECK(got == count);
    o.tracks.resize(got);
    if (count > 0) { // one short: nothing copied, the count told
        std::vector<ct_track> few(count - 1);
        ct_track guard;
        std::memset(&guard, 0xA5, sizeof guard);
        if (!few.empty())
            few[0] = guard;
        size_t need = 0;
        CHECK(ct_tracker_get_tracks(t, few.empty() ? nullptr : few.data(), few.size(),
                                    sizeof(ct_track), &need) == CT_ERROR_BUFFER_TOO_SMALL);
        CHECK(need == count);
        CHECK(few.empty() || std::memcmp(&few[0], &guard, sizeof guard) == 0);
    }
    count = 0;
    int st = ct_tracker_get_candidates(t, nullptr, 0, sizeof(ct_candidate), &count);
    CHECK(st == (count ? CT_ERROR_BUFFER_TOO_SMALL : CT_OK));
    o.candidates.resize(count + 1);
    CHECK(ct_tracker_get_candidates(t, o.candidates.data(), o.candidates.size(),
                                    sizeof(ct_candidate), &got) == CT_OK);
    CHECK(got == count);
    o.candidates.resize(got);
    ct_stats s;
    std::memset(&s, 0, sizeof s);
    s.size = sizeof s;
    CHECK(ct_tracker_get_stats(t, &s) == CT_OK);
    o.steps = s.steps;
    o.live = s.live_tracks;
    o.size.size = sizeof o.size;
    CHECK(ct_tracker_get_person_size(t, &o.size) == CT_OK);
    o.events = all_of<ct_event>(t, ct_tracker_get_events);
    o.lines = all_of<ct_line_count>(t, ct_tracker_get_line_counts);
    o.zones = all_of<ct_zone_count>(t, ct_tracker_get_zone_counts);
    o.occupants = all_of<ct_occupant>(t, ct_tracker_get_occupants);
    return o;
}

bool same(const Output &a, const Output &b)
{
    return a.tracks.size() == b.tracks.size() && a.candidates.size() == b.candidates.size() &&
           (a.tracks.empty() ||
            std::memcmp(a.tracks.data(), b.tracks.data(), a.tracks.size() * sizeof(ct_track)) ==
                0) &&
           (a.candidates.empty() ||
            std::memcmp(a.candidates.data(), b.candidates.data(),
                        a.candidates.size() * sizeof(ct_candidate)) == 0) &&
           a.steps == b.steps && a.live == b.live &&
           std::memcmp(&a.size, &b.size, sizeof a.size) == 0 && same_bytes(a.events, b.events) &&
           same_bytes(a.lines, b.lines) && same_bytes(a.zones, b.zones) &&
           same_bytes(a.occupants, b.occupants);
}

// The reported numbers are finite and in range; ids never come back.
void check_output(const Output &o, const ct_config &cfg, size_t n_dets, const ct_frame *f,
                  uint64_t *max_id)
{
    uint64_t prev = 0;
    uint64_t new_max = *max_id;
    for (const ct_track &t : o.tracks) {
        CHECK(t.id > prev);
        prev = t.id;
        if (t.id > *max_id && t.id > new_max)
            new_max = t.id;
        CHECK(finite(t.left) && finite(t.top) && finite(t.width) && finite(t.height));
        CHECK(t.width > 0 && t.height > 0);
        CHECK(finite(t.barycenter_x) && finite(t.barycenter_y));
        CHECK(finite(t.velocity_x) && finite(t.velocity_y));
        CHECK(t.confidence >= 0 && t.confidence <= 1);
        CHECK(t.state == CT_TRACK_CONFIRMED || t.state == CT_TRACK_LOST);
        CHECK(t.age >= 0 && t.hits >= 0);
        CHECK(std::isfinite(t.time_since_update) && t.time_since_update >= 0);
        CHECK(t.detection_index >= -1 && t.detection_index < (int64_t)n_dets);
        if (cfg.clip_boxes && f && f->format != CT_FORMAT_NONE) {
            CHECK(t.left >= 0 && t.top >= 0);
            CHECK(t.left + t.width <= (float)f->width + 0.01f);
            CHECK(t.top + t.height <= (float)f->height + 0.01f);
        }
    }
    *max_id = new_max;
    CHECK(o.tracks.size() <= o.live);
    for (const ct_candidate &c : o.candidates) {
        CHECK(finite(c.left) && finite(c.top) && finite(c.width) && finite(c.height));
        CHECK(c.width >= 0 && c.height >= 0);
        CHECK(c.score >= 0 && c.score <= 1);
        CHECK(c.voters >= 0 && c.voters <= CT_REGIONS && c.votes_yes >= 0 &&
              c.votes_yes <= c.voters);
        CHECK(finite(c.fill) && finite(c.top_width));
        for (int g = 0; g < CT_REGIONS; g++) // -1: the region abstained
            CHECK(c.region_distance[g] == -1.0f ||
                  (std::isfinite(c.region_distance[g]) && c.region_distance[g] >= 0));
    }
    CHECK(std::isfinite(o.size.height_slope) && std::isfinite(o.size.height_intercept) &&
          std::isfinite(o.size.width_ratio));
    // Counting: events of reported ids, on lines and zones that exist, at
    // finite points; each name NUL-terminated.
    for (const ct_event &e : o.events) {
        CHECK(e.kind >= CT_EVENT_LINE_IN && e.kind <= CT_EVENT_ZONE_EXIT);
        const bool line = e.kind <= CT_EVENT_LINE_OUT;
        CHECK(e.index >= 0 && (size_t)e.index < (line ? o.lines.size() : o.zones.size()));
        CHECK(e.track_id > 0 && e.track_id <= *max_id);
        CHECK(std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.dwell) &&
              e.dwell >= 0);
    }
    for (const ct_line_count &c : o.lines)
        CHECK(std::memchr(c.name, 0, sizeof c.name));
    for (const ct_zone_count &c : o.zones)
        CHECK(std::memchr(c.name, 0, sizeof c.name) && c.inside >= 0);
}

// A fuzzed point: mostly inside a small image, sometimes NaN, huge, far.
ct_point fuzz_point(FuzzedDataProvider &in, const int shape[2])
{
    return ct_point{fuzz_float(in, -20.0f, (float)shape[0] + 20),
                    fuzz_float(in, -20.0f, (float)shape[1] + 20)};
}

// Adds a fuzzed line or zone to both trackers: refused by both, or added to
// both.
void add_counting(FuzzedDataProvider &in, ct_tracker *a, ct_tracker *b, const int shape[2])
{
    const std::string name = in.ConsumeRandomLengthString(40);
    const char *pname = in.ConsumeBool() ? name.c_str() : nullptr;
    int r;
    if (in.ConsumeBool()) {
        ct_line l;
        ct_line_default(&l, sizeof l);
        l.a = fuzz_point(in, shape);
        l.b = fuzz_point(in, shape);
        l.name = pname;
        if (in.ConsumeBool())
            l.hysteresis = fuzz_float(in, -0.5f, 3.0f);
        r = ct_tracker_add_line(a, &l, nullptr);
        CHECK(ct_tracker_add_line(b, &l, nullptr) == r);
    } else {
        std::vector<ct_point> p(in.ConsumeIntegralInRange<size_t>(0, CT_ZONE_MAX_POINTS + 2));
        for (ct_point &q : p)
            q = fuzz_point(in, shape);
        ct_zone z;
        ct_zone_default(&z, sizeof z);
        z.points = p.empty() ? nullptr : p.data();
        z.n_points = (int32_t)p.size();
        z.name = pname;
        if (in.ConsumeBool())
            z.hysteresis = fuzz_float(in, -0.5f, 3.0f);
        r = ct_tracker_add_zone(a, &z, nullptr);
        CHECK(ct_tracker_add_zone(b, &z, nullptr) == r);
    }
    CHECK(r == CT_OK || r == CT_ERROR_INVALID_ARGUMENT);
    CHECK(r == CT_OK || ct_tracker_last_error(a)[0] != '\0');
}

// A street scene (scene.h) through two trackers alike: from the pixels
// alone (the contour template or size and aspect), or the figures' boxes as
// detections with the pixels (verified or not), with a counting line and
// zone, and now and then the fuzzer's bytes as noise on a frame.
void run_scene(FuzzedDataProvider &in)
{
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    const int mode = in.ConsumeIntegralInRange<int>(0, 3);
    if (mode <= 1)
        cfg.source = CT_SOURCE_PIXELS;
    if (mode == 1)
        cfg.pedestrian_test = CT_PEDESTRIAN_SIZE;
    cfg.verify_detections = mode == 3;
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0)
        cfg.candidate_min_score = in.ConsumeFloatingPointInRange<float>(0.3f, 1.0f);
    ct_tracker *a = nullptr, *b = nullptr;
    CHECK(ct_tracker_create(&cfg, &a) == CT_OK && ct_tracker_create(&cfg, &b) == CT_OK);
    const scene::Script script = scene::read_script(in);
    const int shape[2] = {scene::kWidth, scene::kHeight};
    add_counting(in, a, b, shape);
    std::vector<uint8_t> y(scene::kWidth * scene::kHeight),
        u(scene::kWidth * scene::kHeight / 4), v(u.size());
    std::vector<float> boxes;
    ct_frame f;
    ct_frame_default(&f, sizeof f);
    f.format = CT_FORMAT_I420;
    f.width = scene::kWidth;
    f.height = scene::kHeight;
    f.planes[0] = y.data();
    f.planes[1] = u.data();
    f.planes[2] = v.data();
    f.strides[0] = scene::kWidth;
    f.strides[1] = f.strides[2] = scene::kWidth / 2;
    uint64_t max_id = 0;
    // Long enough, now and then, for the people's size to halve its counts
    // (a band holds 1,000 boxes at most); short when the input ran out
    // (fuzz_detections() says why).
    const int frames = in.ConsumeIntegralInRange<int>(0, 15) == 15
                           ? in.ConsumeIntegralInRange<int>(200, 500)
                           : in.ConsumeIntegralInRange<int>(20, 100);
    for (int t = 0; t < frames; t++) {
        scene::render(script, t, y.data(), u.data(), v.data(), &boxes);
        if (in.remaining_bytes() > 0 && in.ConsumeIntegralInRange<int>(0, 7) == 0) {
            const std::vector<uint8_t> noise = in.ConsumeBytes<uint8_t>(64);
            for (size_t k = 0; k < noise.size(); k++)
                y[(k * 1031 + (size_t)t * 77) % y.size()] ^= noise[k];
        }
        f.timestamp_us += in.remaining_bytes() > 0 && in.ConsumeIntegralInRange<int>(0, 15) == 0
                              ? 120000
                              : 40000;
        std::vector<ct_detection> dets;
        if (cfg.source == CT_SOURCE_DETECTIONS)
            for (size_t k = 0; k + 3 < boxes.size(); k += 4)
                dets.push_back({boxes[k], boxes[k + 1], boxes[k + 2], boxes[k + 3], 0.9f, 0});
        const ct_detection *dp = dets.empty() ? nullptr : dets.data();
        CHECK(ct_tracker_feed(a, &f, dp, dets.size()) == CT_OK);
        CHECK(ct_tracker_feed(b, &f, dp, dets.size()) == CT_OK);
        const Output o = output_of(a);
        CHECK(same(o, output_of(b)));
        // From the pixels, a track's detection_index is its candidate's.
        check_output(o, cfg, cfg.source == CT_SOURCE_PIXELS ? o.candidates.size() : dets.size(),
                     &f, &max_id);
    }
    ct_tracker_destroy(a);
    ct_tracker_destroy(b);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzedDataProvider in(data, size);
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0) {
        run_scene(in);
        return 0;
    }
    ct_config cfg;
    fuzz_config(in, &cfg);
    Sized cfg_as_passed;
    cfg_as_passed.wrap(in, cfg);
    const ct_config *pcfg = cfg_as_passed.as<ct_config>();
    char msg[256];
    std::memset(msg, 'x', sizeof msg);
    const int valid = ct_config_check(pcfg, msg, sizeof msg);
    if (valid != CT_OK) // a message naming the field, NUL-terminated
        CHECK(msg[0] != 'x' && msg[0] != '\0' && std::memchr(msg, 0, sizeof msg));
    ct_tracker *a = nullptr, *b = nullptr;
    const int st = ct_tracker_create(pcfg, &a);
    CHECK(st == valid);
    if (st != CT_OK) {
        CHECK(a == nullptr);
        return 0;
    }
    CHECK(ct_tracker_create(pcfg, &b) == CT_OK);

    int shape[2] = {in.ConsumeIntegralInRange<int>(8, 96), in.ConsumeIntegralInRange<int>(8, 96)};
    int64_t clock = in.ConsumeIntegralInRange<int64_t>(-1000000, 1000000);
    uint64_t max_id = 0;
    size_t last_n = 0;
    Output before = output_of(a);
    for (int step = 0; step < 48 && in.remaining_bytes() > 0; step++) {
        const int op = in.ConsumeIntegralInRange<int>(0, 11);
        if (op <= 6) {
            Frame fr;
            const int64_t last_clock = clock;
            fuzz_frame(in, &fr, &clock, shape);
            std::vector<ct_detection> dets = fuzz_detections(in, shape);
            const ct_detection *dp = dets.empty() ? nullptr : dets.data();
            if (!dets.empty() && in.ConsumeIntegralInRange<int>(0, 31) == 0)
                dp = nullptr; // n > 0 with no array
            const ct_frame *pf = fr.header.as<ct_frame>();
            const int r = ct_tracker_feed(a, pf, dp, dets.size());
            CHECK(r == CT_OK || r == CT_ERROR_INVALID_ARGUMENT || r == CT_ERROR_BAD_STATE ||
                  r == CT_ERROR_UNSUPPORTED);
            const char *err = ct_tracker_last_error(a);
            CHECK(err);
            if (r != CT_OK) {
                CHECK(err[0] != '\0');
                clock = last_clock; // the tracker's clock did not move
            } else {
                CHECK(ct_tracker_feed(b, pf, dp, dets.size()) == CT_OK);
            }
            Output now = output_of(a);
            if (r != CT_OK)
                CHECK(same(now, before));
            CHECK(same(now, output_of(b)));
            if (r == CT_OK)
                last_n = dets.size(); // detection_index refers to the last step's
            check_output(now, cfg, last_n, r == CT_OK ? &fr.f : nullptr, &max_id);
            before = now;
        } else if (op == 7) {
            CHECK(ct_tracker_reset(a) == CT_OK);
            CHECK(ct_tracker_reset(b) == CT_OK);
            before = output_of(a);
            CHECK(before.tracks.empty() && before.candidates.empty());
            CHECK(same(before, output_of(b)));
        } else if (op == 8) {
            // Getters with another header's struct sizes: refused or
            // answered, never written past.
            const size_t elem = in.ConsumeIntegralInRange<size_t>(0, 2 * sizeof(ct_track));
            std::vector<uint8_t> buf(elem * 4 + 1);
            size_t count = 0;
            const int r = ct_tracker_get_tracks(a, (ct_track *)buf.data(), 4, elem, &count);
            CHECK(r == CT_OK || r == CT_ERROR_INVALID_ARGUMENT || r == CT_ERROR_BUFFER_TOO_SMALL);
            std::vector<uint8_t> sbuf(in.ConsumeIntegralInRange<size_t>(sizeof(size_t), 1024));
            const size_t claimed = sbuf.size();
            std::memcpy(sbuf.data(), &claimed, sizeof claimed);
            const int rs = ct_tracker_get_stats(a, (ct_stats *)sbuf.data());
            CHECK(rs == CT_OK || rs == CT_ERROR_INVALID_ARGUMENT);
        } else if (op == 9) {
            shape[0] = in.ConsumeIntegralInRange<int>(8, 96);
            shape[1] = in.ConsumeIntegralInRange<int>(8, 96);
        } else if (op == 11) {
            add_counting(in, a, b, shape);
            before = output_of(a);
            CHECK(same(before, output_of(b)));
        } else {
            // Priming on a few fuzzed frames (any of them NULL, without
            // pixels, of other sizes, out of order): refused with nothing
            // changed, or the tracks and the time forgotten, in both
            // trackers alike.
            const size_t n = in.ConsumeIntegralInRange<size_t>(0, 4);
            std::vector<Frame> frames(n);
            std::vector<const ct_frame *> ptrs(n);
            int64_t prime_clock = clock;
            for (size_t i = 0; i < n; i++) {
                fuzz_frame(in, &frames[i], &prime_clock, shape);
                ptrs[i] = in.ConsumeIntegralInRange<int>(0, 31) == 0
                              ? nullptr
                              : frames[i].header.as<ct_frame>();
            }
            const ct_frame *const *pp = n && in.ConsumeBool() ? ptrs.data() : nullptr;
            const int r = ct_tracker_prime(a, pp, n);
            CHECK(r == CT_OK || r == CT_ERROR_INVALID_ARGUMENT || r == CT_ERROR_UNSUPPORTED);
            if (r == CT_OK) {
                CHECK(ct_tracker_prime(b, pp, n) == CT_OK);
                before = output_of(a);
                CHECK(before.tracks.empty() && before.candidates.empty());
                CHECK(same(before, output_of(b)));
            } else {
                CHECK(ct_tracker_last_error(a)[0] != '\0');
            }
        }
        CHECK(same(before, output_of(a)));
    }
    ct_tracker_destroy(a);
    ct_tracker_destroy(b);
    return 0;
}
