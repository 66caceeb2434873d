#include "api/config.h"

#include <cmath>
#include <cstdio>

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
    return c;
}

namespace {

bool in_range(double x, double lo, double hi)
{
    return std::isfinite(x) && x >= lo && x <= hi;
}

} // namespace

int load_config(const ct_config *in, ct_config *out, char *msg, size_t msg_len)
{
    if (msg && msg_len > 0)
        msg[0] = '\0';
    if (!in)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT, "config: NULL pointer");
    ct_config c = default_config();
    switch (read_sized(in, in->size, kConfigSizeV1, &c)) {
    case SizedResult::too_small:
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.size: %zu is smaller than any ct_config (%zu); "
                    "fill it with ct_config_default()",
                    in->size, kConfigSizeV1);
    case SizedResult::too_large:
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.size: %zu is larger than any ct_config can be (%zu): not set, or "
                    "overwritten?",
                    in->size, kMaxStructSize);
    case SizedResult::unknown_fields:
        return fail(msg, msg_len, CT_ERROR_UNSUPPORTED,
                    "config.size: %zu bytes, of which this library (ctrack %s) knows %zu; "
                    "the newer fields are set",
                    in->size, ct_version_string(), sizeof(ct_config));
    case SizedResult::ok:
        break;
    }
    if (c.source != CT_SOURCE_DETECTIONS && c.source != CT_SOURCE_PIXELS)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.source: %d is not a ct_source value", (int)c.source);
    if (!in_range(c.high_score, 0, 1))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.high_score: %g is not in [0, 1]", (double)c.high_score);
    if (!in_range(c.low_score, 0, c.high_score))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.low_score: %g is not in [0, high_score = %g]",
                    (double)c.low_score, (double)c.high_score);
    const struct {
        const char *name;
        float value;
    } ious[] = {{"match_iou", c.match_iou},
                {"low_match_iou", c.low_match_iou},
                {"tentative_match_iou", c.tentative_match_iou}};
    for (const auto &g : ious)
        if (!in_range(g.value, 0, 1) || g.value == 0)
            return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                        "config.%s: %g is not in (0, 1]", g.name, (double)g.value);
    if (c.min_hits < 1 || c.min_hits > 1000)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.min_hits: %d is not in [1, 1000]", (int)c.min_hits);
    if (!in_range(c.lost_lifetime, 0, 3600))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.lost_lifetime: %g s is not in [0, 3600]", c.lost_lifetime);
    if (!in_range(c.report_lost_time, 0, c.lost_lifetime))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.report_lost_time: %g s is not in [0, lost_lifetime = %g]",
                    c.report_lost_time, c.lost_lifetime);
    if (!in_range(c.motion_noise, 0, 100) || c.motion_noise == 0)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.motion_noise: %g is not in (0, 100] box heights/s^2",
                    (double)c.motion_noise);
    if (!in_range(c.detection_noise, 0, 10) || c.detection_noise == 0)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.detection_noise: %g is not in (0, 10] box heights",
                    (double)c.detection_noise);
    if (c.clip_boxes != 0 && c.clip_boxes != 1)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.clip_boxes: %d is not 0 or 1", (int)c.clip_boxes);
    if (c.max_tracks < 1 || c.max_tracks > 100000)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.max_tracks: %d is not in [1, 100000]", (int)c.max_tracks);
    if (c.mean_shift != 0 && c.mean_shift != 1)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.mean_shift: %d is not 0 or 1", (int)c.mean_shift);
    if (!in_range(c.mean_shift_min_similarity, 0, 1) || c.mean_shift_min_similarity == 0 ||
        c.mean_shift_min_similarity == 1)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.mean_shift_min_similarity: %g is not in (0, 1)",
                    (double)c.mean_shift_min_similarity);
    if (!in_range(c.mean_shift_max_time, 0, 3600))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.mean_shift_max_time: %g s is not in [0, 3600]",
                    c.mean_shift_max_time);
    if (!in_range(c.model_learning_rate, 0, 1))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.model_learning_rate: %g is not in [0, 1]",
                    (double)c.model_learning_rate);
    if (!in_range(c.mean_shift_coarse_below, 0, 1) || c.mean_shift_coarse_below == 1)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.mean_shift_coarse_below: %g is not in [0, 1)",
                    (double)c.mean_shift_coarse_below);
    if (c.appearance != 0 && c.appearance != 1)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.appearance: %d is not 0 or 1", (int)c.appearance);
    if (!in_range(c.appearance_weight, 0, 100))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.appearance_weight: %g is not in [0, 100]",
                    (double)c.appearance_weight);
    if (!in_range(c.reid_min_similarity, 0, 1) || c.reid_min_similarity == 0 ||
        c.reid_min_similarity == 1)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.reid_min_similarity: %g is not in (0, 1)",
                    (double)c.reid_min_similarity);
    if (!in_range(c.reid_max_speed, 0, 1000))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.reid_max_speed: %g is not in [0, 1000] box heights/s",
                    (double)c.reid_max_speed);
    if (!in_range(c.candidate_min_score, c.low_score, 1))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.candidate_min_score: %g is not in [low_score = %g, 1]",
                    (double)c.candidate_min_score, (double)c.low_score);
    if (c.verify_detections != 0 && c.verify_detections != 1)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.verify_detections: %d is not 0 or 1", (int)c.verify_detections);
    if (!in_range(c.start_score, 0, 1))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.start_score: %g is not in [0, 1]", (double)c.start_score);
    if (!in_range(c.report_lost_sd, 0, 10))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.report_lost_sd: %g is not in [0, 10]", (double)c.report_lost_sd);
    if (c.pedestrian_test != CT_PEDESTRIAN_TEMPLATE && c.pedestrian_test != CT_PEDESTRIAN_SIZE)
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.pedestrian_test: %d is not CT_PEDESTRIAN_TEMPLATE (0) or "
                    "CT_PEDESTRIAN_SIZE (1)",
                    (int)c.pedestrian_test);
    if (!in_range(c.size_gate, 0, 10))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.size_gate: %g is not in [0, 10]", (double)c.size_gate);
    if (!in_range(c.confirm_score, 0, 1))
        return fail(msg, msg_len, CT_ERROR_INVALID_ARGUMENT,
                    "config.confirm_score: %g is not in [0, 1]", (double)c.confirm_score);
    if (out)
        *out = c;
    return CT_OK;
}

} // namespace ctrack
