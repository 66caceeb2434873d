"""ctypes mirrors of the structs in include/ctrack/ctrack.h (ABI 1).

tests/python/test_abi.py checks their sizes and offsets against the C
compiler's, so a change to the header that is not made here fails a test.
"""
import ctypes as C

ABI_VERSION = 1
# The version of include/ctrack/ctrack.h these mirrors follow, and the Python
# package's (python/pyproject.toml); test_abi.py checks it against the
# library's.
VERSION = "0.10.0"

OK = 0
ERROR_INVALID_ARGUMENT = -1
ERROR_OUT_OF_MEMORY = -2
ERROR_UNSUPPORTED = -3
ERROR_BUFFER_TOO_SMALL = -4
ERROR_BAD_STATE = -5
ERROR_INTERNAL = -6

SOURCE_DETECTIONS = 0
SOURCE_PIXELS = 1
PEDESTRIAN_TEMPLATE = 0
PEDESTRIAN_SIZE = 1
# Priming, a look-ahead for recorded files (ct_tracker_prime()): the
# seconds of a recording's start that ct-track and ctrack.batch suggest when
# asked to prime (CT_PRIME_SECONDS), the most frames the library takes
# (CT_PRIME_MAX_FRAMES), and the most memory the tools keep frames in for it
# (ct-track's PRIME_MAX_BYTES).
PRIME_SECONDS = 3.0
PRIME_MAX_FRAMES = 65536
PRIME_MAX_BYTES = 512 << 20


def fourcc(s):
    return s[0] | (s[1] << 8) | (s[2] << 16) | (s[3] << 24)


FORMAT_NONE = 0
FORMAT_I420 = fourcc(b"I420")
FORMAT_NV12 = fourcc(b"NV12")
FORMAT_GRAY8 = fourcc(b"Y800")
FORMAT_BGR24 = fourcc(b"24BG")  # 0.8.0
FORMAT_RGB24 = fourcc(b"raw ")  # 0.8.0

TRACK_TENTATIVE = 0
TRACK_CONFIRMED = 1
TRACK_LOST = 2


class Config(C.Structure):
    _fields_ = [
        ("size", C.c_size_t),
        ("source", C.c_int32),
        ("high_score", C.c_float),
        ("low_score", C.c_float),
        ("match_iou", C.c_float),
        ("low_match_iou", C.c_float),
        ("tentative_match_iou", C.c_float),
        ("min_hits", C.c_int32),
        ("lost_lifetime", C.c_double),
        ("report_lost_time", C.c_double),
        ("motion_noise", C.c_float),
        ("detection_noise", C.c_float),
        ("clip_boxes", C.c_int32),
        ("max_tracks", C.c_int32),
        ("mean_shift", C.c_int32),
        ("mean_shift_min_similarity", C.c_float),
        ("mean_shift_max_time", C.c_double),
        ("model_learning_rate", C.c_float),
        ("mean_shift_coarse_below", C.c_float),
        ("appearance", C.c_int32),
        ("appearance_weight", C.c_float),
        ("reid_min_similarity", C.c_float),
        ("reid_max_speed", C.c_float),
        ("candidate_min_score", C.c_float),
        ("verify_detections", C.c_int32),
        ("start_score", C.c_float),
        ("report_lost_sd", C.c_float),
        ("pedestrian_test", C.c_int32),
        ("size_gate", C.c_float),
        ("confirm_score", C.c_float),
        ("refine_boxes", C.c_int32),  # 0.10.0
    ]


class Frame(C.Structure):
    _fields_ = [
        ("size", C.c_size_t),
        ("format", C.c_uint32),
        ("width", C.c_int32),
        ("height", C.c_int32),
        ("planes", C.c_void_p * 3),
        ("strides", C.c_int32 * 3),
        ("timestamp_us", C.c_int64),
    ]


class Detection(C.Structure):
    _fields_ = [
        ("left", C.c_float),
        ("top", C.c_float),
        ("width", C.c_float),
        ("height", C.c_float),
        ("score", C.c_float),
        ("class_id", C.c_int32),
    ]


class Track(C.Structure):
    _fields_ = [
        ("id", C.c_uint64),
        ("left", C.c_float),
        ("top", C.c_float),
        ("width", C.c_float),
        ("height", C.c_float),
        ("barycenter_x", C.c_float),
        ("barycenter_y", C.c_float),
        ("velocity_x", C.c_float),
        ("velocity_y", C.c_float),
        ("confidence", C.c_float),
        ("state", C.c_int32),
        ("age", C.c_int32),
        ("hits", C.c_int32),
        ("time_since_update", C.c_double),
        ("detection_index", C.c_int32),
        ("class_id", C.c_int32),
    ]


STATS_MAX_STAGES = 16
REGIONS = 9


class Candidate(C.Structure):
    _fields_ = [
        ("left", C.c_float),
        ("top", C.c_float),
        ("width", C.c_float),
        ("height", C.c_float),
        ("score", C.c_float),
        ("votes_yes", C.c_int32),
        ("voters", C.c_int32),
        ("region_distance", C.c_float * REGIONS),
        ("fill", C.c_float),
        ("top_width", C.c_float),
    ]


class Stats(C.Structure):
    _fields_ = [
        ("size", C.c_size_t),
        ("steps", C.c_uint64),
        ("feed_ns", C.c_uint64),
        ("stage_ns", C.c_uint64 * STATS_MAX_STAGES),
        ("live_tracks", C.c_uint64),
        ("memory_bytes", C.c_uint64),
        ("mean_shift_runs", C.c_uint64),
        ("ddis_runs", C.c_uint64),
        ("template_builds", C.c_uint64),
        ("blobs_dropped", C.c_uint64),
        ("masks_flooded", C.c_uint64),
    ]


class PersonSize(C.Structure):
    _fields_ = [
        ("size", C.c_size_t),
        ("known", C.c_int32),
        ("height_slope", C.c_float),
        ("height_intercept", C.c_float),
        ("width_ratio", C.c_float),
        ("samples", C.c_uint64),
        ("typical_height", C.c_float),
        ("working_scale", C.c_int32),
    ]


# Added in 0.9.0: a host's allocator (ct_tracker_create_with_allocator). A
# Python host has no use for it; the binding mirrors it for completeness.
ALLOC_FN = C.CFUNCTYPE(C.c_void_p, C.c_void_p, C.c_size_t)
FREE_FN = C.CFUNCTYPE(None, C.c_void_p, C.c_void_p)


class Allocator(C.Structure):
    _fields_ = [
        ("size", C.c_size_t),
        ("alloc", ALLOC_FN),
        ("free", FREE_FN),
        ("opaque", C.c_void_p),
    ]


# Added in 0.10.0: counting on lines and zones.
COUNT_MAX_LINES = 64
COUNT_MAX_ZONES = 64
ZONE_MAX_POINTS = 64
NAME_SIZE = 32
EVENT_LINE_IN = 1
EVENT_LINE_OUT = 2
EVENT_ZONE_ENTER = 3
EVENT_ZONE_EXIT = 4


class Point(C.Structure):
    _fields_ = [("x", C.c_float), ("y", C.c_float)]


class Line(C.Structure):
    _fields_ = [
        ("size", C.c_size_t),
        ("a", Point),
        ("b", Point),
        ("name", C.c_char_p),
        ("hysteresis", C.c_float),
    ]


class Zone(C.Structure):
    _fields_ = [
        ("size", C.c_size_t),
        ("points", C.POINTER(Point)),
        ("n_points", C.c_int32),
        ("name", C.c_char_p),
        ("hysteresis", C.c_float),
    ]


class Event(C.Structure):
    _fields_ = [
        ("kind", C.c_int32),
        ("index", C.c_int32),
        ("track_id", C.c_uint64),
        ("timestamp_us", C.c_int64),
        ("x", C.c_float),
        ("y", C.c_float),
        ("dwell", C.c_double),
        ("ended", C.c_int32),
    ]


class LineCount(C.Structure):
    _fields_ = [
        ("index", C.c_int32),
        ("name", C.c_char * NAME_SIZE),
        ("in_", C.c_uint64),  # "in" in C
        ("out", C.c_uint64),
    ]


class ZoneCount(C.Structure):
    _fields_ = [
        ("index", C.c_int32),
        ("name", C.c_char * NAME_SIZE),
        ("entered", C.c_uint64),
        ("exited", C.c_uint64),
        ("inside", C.c_int32),
    ]


class Occupant(C.Structure):
    _fields_ = [
        ("zone", C.c_int32),
        ("track_id", C.c_uint64),
        ("dwell", C.c_double),
    ]


def declare(lib):
    """Sets the argument and result types of every function of `lib`."""
    P = C.POINTER
    sig = {
        "ct_status_str": (C.c_char_p, [C.c_int]),
        "ct_version_string": (C.c_char_p, []),
        "ct_version_number": (C.c_uint32, []),
        "ct_abi_version": (C.c_uint32, []),
        "ct_config_default": (C.c_int, [P(Config), C.c_size_t]),
        "ct_config_check": (C.c_int, [P(Config), C.c_char_p, C.c_size_t]),
        "ct_frame_default": (C.c_int, [P(Frame), C.c_size_t]),
        "ct_tracker_create": (C.c_int, [P(Config), P(C.c_void_p)]),
        "ct_tracker_destroy": (None, [C.c_void_p]),
        "ct_tracker_feed": (C.c_int, [C.c_void_p, P(Frame), C.c_void_p, C.c_size_t]),
        "ct_tracker_get_tracks": (C.c_int, [C.c_void_p, C.c_void_p, C.c_size_t, C.c_size_t,
                                            P(C.c_size_t)]),
        "ct_tracker_reset": (C.c_int, [C.c_void_p]),
        "ct_tracker_last_error": (C.c_char_p, [C.c_void_p]),
        "ct_tracker_get_stats": (C.c_int, [C.c_void_p, P(Stats)]),
        "ct_stage_name": (C.c_char_p, [C.c_int]),
        "ct_tracker_get_candidates": (C.c_int, [C.c_void_p, C.c_void_p, C.c_size_t, C.c_size_t,
                                                P(C.c_size_t)]),
    }
    # Added in 0.9.0: declared where the library has it.
    if hasattr(lib, "ct_tracker_get_person_size"):
        sig["ct_tracker_get_person_size"] = (C.c_int, [C.c_void_p, P(PersonSize)])
    if hasattr(lib, "ct_tracker_prime"):
        sig["ct_tracker_prime"] = (C.c_int, [C.c_void_p, P(P(Frame)), C.c_size_t])
    if hasattr(lib, "ct_tracker_create_with_allocator"):
        sig["ct_tracker_create_with_allocator"] = (C.c_int, [P(Config), P(Allocator),
                                                             P(C.c_void_p)])
    # Added in 0.10.0.
    if hasattr(lib, "ct_tracker_add_line"):
        getter = (C.c_int, [C.c_void_p, C.c_void_p, C.c_size_t, C.c_size_t, P(C.c_size_t)])
        sig.update({
            "ct_line_default": (C.c_int, [P(Line), C.c_size_t]),
            "ct_zone_default": (C.c_int, [P(Zone), C.c_size_t]),
            "ct_tracker_add_line": (C.c_int, [C.c_void_p, P(Line), P(C.c_int32)]),
            "ct_tracker_add_zone": (C.c_int, [C.c_void_p, P(Zone), P(C.c_int32)]),
            "ct_tracker_get_events": getter,
            "ct_tracker_get_line_counts": getter,
            "ct_tracker_get_zone_counts": getter,
            "ct_tracker_get_occupants": getter,
        })
    for name, (res, args) in sig.items():
        f = getattr(lib, name)
        f.restype = res
        f.argtypes = args
    return lib
