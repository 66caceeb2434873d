#include "api/config.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "api/error.h"
#include "api/sized.h"

namespace ctrack {

// One set of defaults for every sequence; docs/tuning.md shows how each
// was chosen.
ct_config default_config()
{
    ct_config c = {};
    c.size = sizeof(ct_config);
    c.source = CT_SOURCE_DETECTIONS;
    c.high_score = 0.6f;
    c.low_score = 0.1f;
    c.match_iou = 0.2f;
    c.low_match_iou = 0.5f;
    c.tentative_match_iou = 0.3f;
    c.min_hits = 3;
    c.lost_lifetime = 3.0;
    c.report_lost_time = 0.5;
    c.motion_noise = 0.5f;
    c.detection_noise = 0.05f;
    c.clip_boxes = 0;
    c.max_tracks = 1000;
    c.mean_shift = 1;
    c.mean_shift_min_similarity = 0.7f;
    c.mean_shift_max_time = 1.0;
    c.model_learning_rate = 0.2f;
    c.mean_shift_coarse_below = 0.0f;
    c.appearance = 1;
    c.appearance_weight = 0.1f;
    c.reid_min_similarity = 0.1f;
    c.reid_max_speed = 1.5f;
    c.candidate_min_score = 0.8f;
    c.verify_detections = 0;
    c.start_score = 0.7f;
    c.report_lost_sd = 0.08f;
    c.pedestrian_test = CT_PEDESTRIAN_TEMPLATE;
    c.size_gate = 0.35f;
    c.confirm_score = 0.95f;
    c.refine_boxes = 1;
    return c;
}

namespace {

// Every field's range: [lo, hi], open at an end where said; a bound may be
// another field's value (low_score is at most high_score). The checks run
// in this order, and the first wrong field is the one reported.
struct FieldRange {
    const char *name;
    char type; // 'f' float, 'd' double, 'i' int32_t
    size_t offset;
    double lo, hi;
    bool lo_open, hi_open;
    const char *lo_field, *hi_field; // bounds that are fields, or null
    const char *unit;                // after the range in a message
};

#define CT_FIELD(name, type, ...) {#name, type, offsetof(ct_config, name), __VA_ARGS__}
constexpr FieldRange kRanges[] = {
    CT_FIELD(source, 'i', 0, 1, false, false, nullptr, nullptr,
             "(CT_SOURCE_DETECTIONS or CT_SOURCE_PIXELS)"),
    CT_FIELD(high_score, 'f', 0, 1, false, false, nullptr, nullptr, ""),
    CT_FIELD(low_score, 'f', 0, 1, false, false, nullptr, "high_score", ""),
    CT_FIELD(match_iou, 'f', 0, 1, true, false, nullptr, nullptr, ""),
    CT_FIELD(low_match_iou, 'f', 0, 1, true, false, nullptr, nullptr, ""),
    CT_FIELD(tentative_match_iou, 'f', 0, 1, true, false, nullptr, nullptr, ""),
    CT_FIELD(min_hits, 'i', 1, 1000, false, false, nullptr, nullptr, "steps"),
    CT_FIELD(lost_lifetime, 'd', 0, 3600, false, false, nullptr, nullptr, "s"),
    CT_FIELD(report_lost_time, 'd', 0, 3600, false, false, nullptr, "lost_lifetime", "s"),
    CT_FIELD(motion_noise, 'f', 0, 100, true, false, nullptr, nullptr, "box heights/s^2"),
    CT_FIELD(detection_noise, 'f', 0, 10, true, false, nullptr, nullptr, "box heights"),
    CT_FIELD(clip_boxes, 'i', 0, 1, false, false, nullptr, nullptr, "(0 or 1)"),
    CT_FIELD(max_tracks, 'i', 1, 100000, false, false, nullptr, nullptr, "tracks"),
    CT_FIELD(mean_shift, 'i', 0, 1, false, false, nullptr, nullptr, "(0 or 1)"),
    CT_FIELD(mean_shift_min_similarity, 'f', 0, 1, true, true, nullptr, nullptr, ""),
    CT_FIELD(mean_shift_max_time, 'd', 0, 3600, false, false, nullptr, nullptr, "s"),
    CT_FIELD(model_learning_rate, 'f', 0, 1, false, false, nullptr, nullptr, ""),
    CT_FIELD(mean_shift_coarse_below, 'f', 0, 1, false, true, nullptr, nullptr, ""),
    CT_FIELD(appearance, 'i', 0, 1, false, false, nullptr, nullptr, "(0 or 1)"),
    CT_FIELD(appearance_weight, 'f', 0, 100, false, false, nullptr, nullptr, ""),
    CT_FIELD(reid_min_similarity, 'f', 0, 1, true, true, nullptr, nullptr, ""),
    CT_FIELD(reid_max_speed, 'f', 0, 1000, false, false, nullptr, nullptr, "box heights/s"),
    CT_FIELD(candidate_min_score, 'f', 0, 1, false, false, "low_score", nullptr, ""),
    CT_FIELD(verify_detections, 'i', 0, 1, false, false, nullptr, nullptr, "(0 or 1)"),
    CT_FIELD(start_score, 'f', 0, 1, false, false, nullptr, nullptr, ""),
    CT_FIELD(report_lost_sd, 'f', 0, 10, false, false, nullptr, nullptr, ""),
    CT_FIELD(pedestrian_test, 'i', 0, 1, false, false, nullptr, nullptr,
             "(CT_PEDESTRIAN_TEMPLATE or CT_PEDESTRIAN_SIZE)"),
    CT_FIELD(size_gate, 'f', 0, 10, false, false, nullptr, nullptr, ""),
    CT_FIELD(confirm_score, 'f', 0, 1, false, false, nullptr, nullptr, ""),
    CT_FIELD(refine_boxes, 'i', 0, 1, false, false, nullptr, nullptr, "(0 or 1)"),
};
#undef CT_FIELD
const FieldRange *range_of(const char *name)
{
    for (const FieldRange &r : kRanges)
        if (std::strcmp(r.name, name) == 0)
            return &r;
    return nullptr;
}

double value_of(const ct_config &c, const FieldRange &r)
{
    const char *p = reinterpret_cast<const char *>(&c) + r.offset;
    switch (r.type) {
    case 'f': return *reinterpret_cast<const float *>(p);
    case 'd': return *reinterpret_cast<const double *>(p);
    default: return *reinterpret_cast<const int32_t *>(p);
    }
}

// A bound as a message shows it: a number, or the field it is and its value.
void bound_text(const ct_config &c, double v, const char *field, char *out, size_t len)
{
    if (field)
        std::snprintf(out, len, "%s = %g", field, value_of(c, *range_of(field)));
    else
        std::snprintf(out, len, "%g", v);
}

// Checks field r of c; on failure, the message and CT_ERROR_INVALID_ARGUMENT.
int check_field(const ct_config &c, const FieldRange &r, char *msg, size_t msg_len)
{
    const double v = value_of(c, r);
    const double lo = r.lo_field ? value_of(c, *range_of(r.lo_field)) : r.lo;
    const double hi = r.hi_field ? value_of(c, *range_of(r.hi_field)) : r.hi;
    if (std::isfinite(v) && (r.lo_open ? v > lo : v >= lo) && (r.hi_open ? v < hi : v <= hi))
        return CT_OK;
    char a[64], b[64], value[32];
    bound_text(c, lo, r.lo_field, a, sizeof a);
    bound_text(c, hi, r.hi_field, b, sizeof b);
    // An integer as it was given (%g wrote 2147483647 as 2.14748e+09).
    if (r.type == 'i')
        std::snprintf(value, sizeof value, "%.0f", v);
    else
        std::snprintf(value, sizeof value, "%g", v);
    return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT, "config.%s: %s is not in %c%s, %s%c%s%s",
                r.name, value, r.lo_open ? '(' : '[', a, b, r.hi_open ? ')' : ']',
                *r.unit ? " " : "", r.unit);
}

// The caller's struct over the defaults: sized as one this library can read.
int read_config(const ct_config *in, ct_config *c, char *msg, size_t msg_len)
{
    return explain_sized(read_sized(in, in->size, kConfigSizeV1, c), in->size, kConfigSizeV1,
                         sizeof(ct_config), "config", "ct_config", msg, msg_len);
}

} // namespace

int load_config(const ct_config *in, ct_config *out, char *msg, size_t msg_len)
{
    if (msg && msg_len > 0)
        msg[0] = '\0';
    if (!in)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT, "config: NULL pointer");
    ct_config c = default_config();
    if (const int st = read_config(in, &c, msg, msg_len))
        return st;
    for (const FieldRange &r : kRanges)
        if (const int st = check_field(c, r, msg, msg_len))
            return st;
    if (out)
        *out = c;
    return CT_OK;
}

} // namespace ctrack
