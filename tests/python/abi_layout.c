/* Prints the layout of the public structs as JSON, for the Python binding's
 * test that its ctypes mirrors match the compiler's. */
#include <stddef.h>
#include <stdio.h>

#include "ctrack/ctrack.h"

#define FIELD(T, f) printf("%s\"%s\": %zu", first++ ? ", " : "", #f, offsetof(T, f))

int main(void)
{
    int first = 0;
    printf("{\"Config\": {\"sizeof\": %zu, ", sizeof(ct_config));
    FIELD(ct_config, size); FIELD(ct_config, source); FIELD(ct_config, high_score);
    FIELD(ct_config, low_score); FIELD(ct_config, match_iou); FIELD(ct_config, low_match_iou);
    FIELD(ct_config, tentative_match_iou); FIELD(ct_config, min_hits);
    FIELD(ct_config, lost_lifetime); FIELD(ct_config, report_lost_time);
    FIELD(ct_config, motion_noise); FIELD(ct_config, detection_noise);
    FIELD(ct_config, clip_boxes); FIELD(ct_config, max_tracks);
    FIELD(ct_config, mean_shift); FIELD(ct_config, mean_shift_min_similarity);
    FIELD(ct_config, mean_shift_max_time); FIELD(ct_config, model_learning_rate);
    FIELD(ct_config, mean_shift_coarse_below); FIELD(ct_config, appearance);
    FIELD(ct_config, appearance_weight); FIELD(ct_config, reid_min_similarity);
    FIELD(ct_config, reid_max_speed); FIELD(ct_config, candidate_min_score);
    FIELD(ct_config, verify_detections);
    FIELD(ct_config, start_score);
    FIELD(ct_config, report_lost_sd); FIELD(ct_config, pedestrian_test);
    FIELD(ct_config, size_gate);
    FIELD(ct_config, confirm_score);
    FIELD(ct_config, refine_boxes);
    first = 0;
    printf("}, \"Frame\": {\"sizeof\": %zu, ", sizeof(ct_frame));
    FIELD(ct_frame, size); FIELD(ct_frame, format); FIELD(ct_frame, width);
    FIELD(ct_frame, height); FIELD(ct_frame, planes); FIELD(ct_frame, strides);
    FIELD(ct_frame, timestamp_us);
    first = 0;
    printf("}, \"Detection\": {\"sizeof\": %zu, ", sizeof(ct_detection));
    FIELD(ct_detection, left); FIELD(ct_detection, top); FIELD(ct_detection, width);
    FIELD(ct_detection, height); FIELD(ct_detection, score); FIELD(ct_detection, class_id);
    first = 0;
    printf("}, \"Track\": {\"sizeof\": %zu, ", sizeof(ct_track));
    FIELD(ct_track, id); FIELD(ct_track, left); FIELD(ct_track, top); FIELD(ct_track, width);
    FIELD(ct_track, height); FIELD(ct_track, barycenter_x); FIELD(ct_track, barycenter_y);
    FIELD(ct_track, velocity_x); FIELD(ct_track, velocity_y); FIELD(ct_track, confidence);
    FIELD(ct_track, state); FIELD(ct_track, age); FIELD(ct_track, hits);
    FIELD(ct_track, time_since_update); FIELD(ct_track, detection_index);
    FIELD(ct_track, class_id);
    first = 0;
    printf("}, \"Stats\": {\"sizeof\": %zu, ", sizeof(ct_stats));
    FIELD(ct_stats, size); FIELD(ct_stats, steps); FIELD(ct_stats, feed_ns);
    FIELD(ct_stats, stage_ns); FIELD(ct_stats, live_tracks); FIELD(ct_stats, memory_bytes);
    FIELD(ct_stats, mean_shift_runs); FIELD(ct_stats, ddis_runs);
    FIELD(ct_stats, template_builds);
    FIELD(ct_stats, blobs_dropped);
    FIELD(ct_stats, masks_flooded);
    first = 0;
    printf("}, \"Candidate\": {\"sizeof\": %zu, ", sizeof(ct_candidate));
    FIELD(ct_candidate, left); FIELD(ct_candidate, top); FIELD(ct_candidate, width);
    FIELD(ct_candidate, height); FIELD(ct_candidate, score); FIELD(ct_candidate, votes_yes);
    FIELD(ct_candidate, voters); FIELD(ct_candidate, region_distance);
    FIELD(ct_candidate, fill);
    FIELD(ct_candidate, top_width);
    first = 0;
    printf("}, \"PersonSize\": {\"sizeof\": %zu, ", sizeof(ct_person_size));
    FIELD(ct_person_size, size); FIELD(ct_person_size, known);
    FIELD(ct_person_size, height_slope); FIELD(ct_person_size, height_intercept);
    FIELD(ct_person_size, width_ratio); FIELD(ct_person_size, samples);
    FIELD(ct_person_size, typical_height); FIELD(ct_person_size, working_scale);
    first = 0;
    printf("}, \"Allocator\": {\"sizeof\": %zu, ", sizeof(ct_allocator));
    FIELD(ct_allocator, size); FIELD(ct_allocator, alloc); FIELD(ct_allocator, free);
    FIELD(ct_allocator, opaque);
    first = 0;
    printf("}, \"Point\": {\"sizeof\": %zu, ", sizeof(ct_point));
    FIELD(ct_point, x); FIELD(ct_point, y);
    first = 0;
    printf("}, \"Line\": {\"sizeof\": %zu, ", sizeof(ct_line));
    FIELD(ct_line, size); FIELD(ct_line, a); FIELD(ct_line, b); FIELD(ct_line, name);
    FIELD(ct_line, hysteresis);
    first = 0;
    printf("}, \"Zone\": {\"sizeof\": %zu, ", sizeof(ct_zone));
    FIELD(ct_zone, size); FIELD(ct_zone, points); FIELD(ct_zone, n_points);
    FIELD(ct_zone, name); FIELD(ct_zone, hysteresis);
    first = 0;
    printf("}, \"Event\": {\"sizeof\": %zu, ", sizeof(ct_event));
    FIELD(ct_event, kind); FIELD(ct_event, index); FIELD(ct_event, track_id);
    FIELD(ct_event, timestamp_us); FIELD(ct_event, x); FIELD(ct_event, y);
    FIELD(ct_event, dwell); FIELD(ct_event, ended);
    first = 0;
    /* "in" is a Python keyword: the binding names it in_. */
    printf("}, \"LineCount\": {\"sizeof\": %zu, ", sizeof(ct_line_count));
    FIELD(ct_line_count, index); FIELD(ct_line_count, name);
    printf(", \"in_\": %zu", offsetof(ct_line_count, in));
    FIELD(ct_line_count, out);
    first = 0;
    printf("}, \"ZoneCount\": {\"sizeof\": %zu, ", sizeof(ct_zone_count));
    FIELD(ct_zone_count, index); FIELD(ct_zone_count, name); FIELD(ct_zone_count, entered);
    FIELD(ct_zone_count, exited); FIELD(ct_zone_count, inside);
    first = 0;
    printf("}, \"Occupant\": {\"sizeof\": %zu, ", sizeof(ct_occupant));
    FIELD(ct_occupant, zone); FIELD(ct_occupant, track_id); FIELD(ct_occupant, dwell);
    /* The constants the binding mirrors. */
    printf("}, \"Constants\": {\"FORMAT_NONE\": %u, \"FORMAT_I420\": %u, "
           "\"FORMAT_NV12\": %u, \"FORMAT_GRAY8\": %u, \"FORMAT_BGR24\": %u, "
           "\"FORMAT_RGB24\": %u, \"SOURCE_DETECTIONS\": %d, \"SOURCE_PIXELS\": %d, "
           "\"TRACK_TENTATIVE\": %d, \"TRACK_CONFIRMED\": %d, \"TRACK_LOST\": %d, "
           "\"PEDESTRIAN_TEMPLATE\": %d, \"PEDESTRIAN_SIZE\": %d, \"PRIME_SECONDS\": %.17g, "
           "\"COUNT_MAX_LINES\": %d, \"COUNT_MAX_ZONES\": %d, \"ZONE_MAX_POINTS\": %d, "
           "\"NAME_SIZE\": %d, \"EVENT_LINE_IN\": %d, \"EVENT_LINE_OUT\": %d, "
           "\"EVENT_ZONE_ENTER\": %d, \"EVENT_ZONE_EXIT\": %d",
           (unsigned)CT_FORMAT_NONE, (unsigned)CT_FORMAT_I420, (unsigned)CT_FORMAT_NV12,
           (unsigned)CT_FORMAT_GRAY8, (unsigned)CT_FORMAT_BGR24, (unsigned)CT_FORMAT_RGB24,
           (int)CT_SOURCE_DETECTIONS, (int)CT_SOURCE_PIXELS, (int)CT_TRACK_TENTATIVE,
           (int)CT_TRACK_CONFIRMED, (int)CT_TRACK_LOST, (int)CT_PEDESTRIAN_TEMPLATE,
           (int)CT_PEDESTRIAN_SIZE, (double)CT_PRIME_SECONDS, CT_COUNT_MAX_LINES,
           CT_COUNT_MAX_ZONES, CT_ZONE_MAX_POINTS, CT_NAME_SIZE, (int)CT_EVENT_LINE_IN,
           (int)CT_EVENT_LINE_OUT, (int)CT_EVENT_ZONE_ENTER, (int)CT_EVENT_ZONE_EXIT);
    printf("}}\n");
    return 0;
}
