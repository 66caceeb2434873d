/*
 * ctrack: multi-target pedestrian tracking.
 *
 * The stable C ABI. Plain C99, only <stdint.h> and <stddef.h>.
 *
 * Rules that hold for every function here:
 *  - Each returns a ct_status (0 on success, a negative code otherwise) unless
 *    it says otherwise. After a failure, ct_tracker_last_error() explains it.
 *  - The library keeps no pointer into caller memory after a call returns.
 *  - There is no mutable global state: different trackers may be used from
 *    different threads at the same time; one tracker is used by one thread at
 *    a time.
 *  - Structs that the caller fills start with a size field. Fill them with
 *    their *_default() function first; the library reads only what the
 *    caller's size covers and uses defaults for the rest, so a program built
 *    against an older header keeps working with a newer library.
 *
 * See docs/API.md for the full reference.
 */
#ifndef CTRACK_CTRACK_H
#define CTRACK_CTRACK_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The version, in one place: meson.build reads it from here. */
#define CT_VERSION_MAJOR 0
#define CT_VERSION_MINOR 10
#define CT_VERSION_PATCH 0
/* The ABI major: it is the shared library's SONAME number and moves only
 * when the ABI breaks. */
#define CT_ABI_VERSION 1

#define CT_VERSION_NUMBER \
    ((CT_VERSION_MAJOR << 16) | (CT_VERSION_MINOR << 8) | CT_VERSION_PATCH)

#if defined(_WIN32) || defined(__CYGWIN__)
#  if defined(CT_BUILDING_LIBRARY)
#    define CT_API __declspec(dllexport)
#  else
#    define CT_API
#  endif
#elif defined(__GNUC__) && __GNUC__ >= 4
#  define CT_API __attribute__((visibility("default")))
#else
#  define CT_API
#endif

/* ------------------------------------------------------------------------ */
/* Status codes. The values are pinned: they never change. */

typedef enum ct_status {
    CT_OK = 0,
    CT_ERROR_INVALID_ARGUMENT = -1, /* a NULL pointer, a bad size, a bad value */
    CT_ERROR_OUT_OF_MEMORY = -2,
    CT_ERROR_UNSUPPORTED = -3,      /* a pixel format or mode this build lacks */
    CT_ERROR_BUFFER_TOO_SMALL = -4, /* the count needed was reported */
    CT_ERROR_BAD_STATE = -5,        /* e.g. a timestamp that does not increase */
    CT_ERROR_INTERNAL = -6          /* a bug in ctrack: please report it */
} ct_status;

/* A static English description of a status; never NULL. */
CT_API const char *ct_status_str(int status);

/* ------------------------------------------------------------------------ */
/* Version. */

/* "MAJOR.MINOR.PATCH" of the library that is loaded. */
CT_API const char *ct_version_string(void);
/* (MAJOR << 16) | (MINOR << 8) | PATCH of the library that is loaded. */
CT_API uint32_t ct_version_number(void);
/* The ABI major of the library that is loaded (CT_ABI_VERSION when built). */
CT_API uint32_t ct_abi_version(void);

/* ------------------------------------------------------------------------ */
/* Configuration. */

/* Where the tracker's candidates come from. */
typedef enum ct_source {
    /* The host's detections given to ct_tracker_feed(). A feed with n == 0
     * means "the detector ran and found nobody". The default. */
    CT_SOURCE_DETECTIONS = 0,
    /* The pixels: a background model finds moving blobs and the contour
     * template scores how pedestrian-like each is; the host gives no
     * detections (n must be 0). */
    CT_SOURCE_PIXELS = 1
} ct_source;

/* From the pixels alone, what decides that a blob is a pedestrian (0.9.0). */
typedef enum ct_pedestrian_test {
    /* The contour template: its nine regions' vote and its vetoes. The
     * default. */
    CT_PEDESTRIAN_TEMPLATE = 0,
    /* The blob's size and aspect alone, for comparison: height over width
     * from 1 to 4.25 and a height from half to one and a half times the
     * learnt person's where its feet are (at least 30 pixels while the
     * size is not known). */
    CT_PEDESTRIAN_SIZE = 1
} ct_pedestrian_test;

/* Each field states its default (ct_config_default()) and its range:
 * ct_config_check() and ct_tracker_create() refuse a value outside it, or
 * NaN. A bound may be another field's value. */
typedef struct ct_config {
    /* sizeof(ct_config) as the caller's header knows it. */
    size_t size;
    /* A ct_source value.
     * Default 0 (CT_SOURCE_DETECTIONS); range [0, 1]. */
    int32_t source;
    /* Detections scoring at least this are matched first and may start a
     * track. Read on the detector's own scale: where the best 40% of its
     * boxes (from low_score up, learnt as the tracker runs, once 50 are
     * known) score r < 0.9, this and start_score are taken times r / 0.9,
     * never under low_score (scores on a scale of their own, such as an
     * SVM's margin through a logistic). The public MOTChallenge
     * detections' r is 0.96 to 0.99.
     * Default 0.6; range [0, 1]. */
    float high_score;
    /* Detections scoring below this are ignored; those between low_score and
     * high_score only continue existing confirmed tracks (second pass).
     * Default 0.1; range [0, high_score]. */
    float low_score;
    /* Minimum IoU between a track's predicted box and a high-score detection
     * for them to be matched.
     * Default 0.2; range (0, 1]. */
    float match_iou;
    /* Minimum IoU for the low-score second pass.
     * Default 0.5; range (0, 1]. */
    float low_match_iou;
    /* Minimum IoU for a tentative track to be matched. A
     * detection that misses it is matched when its centre lies within two
     * standard deviations of where the track's motion model predicts it
     * (at a few frames a second a new track's person walks out of their
     * last box; docs/API.md, "Each step").
     * Default 0.3; range (0, 1]. */
    float tentative_match_iou;
    /* Consecutive matched steps that confirm a new track.
     * Default 3; range [1, 1000]. */
    int32_t min_hits;
    /* Seconds a confirmed track that lost its detections is kept, predicted
     * by its motion model, before it is removed.
     * Default 3; range [0, 3600]. */
    double lost_lifetime;
    /* Seconds during which a lost track may still be reported by
     * ct_tracker_get_tracks() (its box predicted; report_lost_sd narrows
     * which); 0 reports only tracks that a detection updated this step.
     * Default 0.5; range [0, lost_lifetime]. */
    double report_lost_time;
    /* Motion model: standard deviation of the acceleration of the box centre
     * and size, in box heights per second squared.
     * Default 0.5; range (0, 100]. */
    float motion_noise;
    /* Standard deviation of a detection's position error, in box heights.
     * Without frames, each detection's is this times a factor its score
     * earned, learnt as the tracker runs (docs/API.md, "Each step").
     * Default 0.05; range (0, 10]. */
    float detection_noise;
    /* Non-zero: reported boxes are clipped to the image when its size is
     * known (a frame with width and height).
     * Default 0; range [0, 1]. */
    int32_t clip_boxes;
    /* Upper bound on live tracks (tentative, confirmed and lost); when it is
     * reached, new detections do not start tracks.
     * Default 1000; range [1, 100000]. */
    int32_t max_tracks;

    /* Added in 0.2.0. */

    /* Non-zero: with pixels, each confirmed track keeps a colour model and
     * multiscale mean shift refines its predicted box before association
     * and follows it when its detection is missing.
     * Default 1; range [0, 1]. */
    int32_t mean_shift;
    /* Bhattacharyya coefficient under which the pixels no longer
     * hold a track: it becomes lost.
     * Default 0.7; range (0, 1). */
    float mean_shift_min_similarity;
    /* Seconds mean shift may carry a track without a detection. Where
     * a background is read (source CT_SOURCE_PIXELS, verify_detections
     * or refine_boxes) and has learnt for a second with the camera still,
     * a window less than a tenth foreground does not carry it: the person
     * has gone. From the pixels alone, a track that never moved, stands
     * where it started and barely moves is carried whatever its window's
     * foreground, and a stir in its box counts as a detection: a person
     * standing since the first frame, whom the background holds.
     * Default 1; range [0, 3600]. */
    double mean_shift_max_time;
    /* Learning rate of the colour model (the paper's eq. 9).
     * Default 0.2; range [0, 1]. */
    float model_learning_rate;
    /* Coarse to fine, for fast motion: when the similarity at a track's
     * prediction is under this, mean shift first searches with a window 1.5
     * times larger. 0 never does.
     * Default 0; range [0, 1). */
    float mean_shift_coarse_below;

    /* Added in 0.3.0. */

    /* Non-zero: with pixels, each confirmed track keeps an appearance
     * template, compared with candidates by Deformable Diversity Similarity
     * (DDIS) in association and to re-identify lost tracks.
     * Default 1; range [0, 1]. */
    int32_t appearance;
    /* Weight of (1 - DDIS) beside (1 - IoU) in the association cost.
     * Default 0.1; range [0, 100]. */
    float appearance_weight;
    /* DDIS at or above which a lost track takes back a new
     * detection near where it was heading (re-identification).
     * Default 0.1; range (0, 1). */
    float reid_min_similarity;
    /* How far a lost track may be re-identified from its predicted centre,
     * in its box heights per second it has been lost (at least one box
     * height).
     * Default 1.5; range [0, 1000]. */
    float reid_max_speed;

    /* Added in 0.4.0. */

    /* With source CT_SOURCE_PIXELS, what high_score is to a detector's
     * scores: candidates whose contour-template vote reaches it are matched
     * first and may start tracks.
     * Default 0.8; range [low_score, 1]. */
    float candidate_min_score;

    /* Added in 0.5.0. */

    /* Non-zero: with source CT_SOURCE_DETECTIONS and frames that carry
     * pixels, the background model runs too and the contour template votes
     * on the foreground inside each detection's box. A detection the vote
     * rejects (at least 5 regions vote and no majority of them says
     * pedestrian) has its score multiplied by the vote's score: it may still
     * continue a confirmed track in the low-score pass, but it starts none.
     * Where too little of the box is foreground to vote (a person standing
     * still, or hidden), the detection is left as it is.
     * ct_tracker_get_candidates() then returns one vote per detection, in
     * their order. 0 does not verify.
     * Default 0; range [0, 1]. */
    int32_t verify_detections;

    /* Added in 0.9.0. */

    /* With source CT_SOURCE_DETECTIONS, detections scoring at least this
     * (and high_score) may start a (tentative) track; those between
     * high_score and this are matched first and continue tracks, but start
     * none. At or under high_score, every high-score detection may start
     * one. Read on the detector's scale, as high_score. See also
     * confirm_score.
     * Default 0.7; range [0, 1]. */
    float start_score;
    /* Non-zero: a lost track is reported (within report_lost_time) only
     * while its box is likely right and its person hidden: another track
     * covers a fifth of its box, and the standard deviation of its
     * predicted centre is at most this many box widths across and box
     * heights down. 0 reports every lost track within report_lost_time.
     * Default 0.08; range [0, 10]. */
    float report_lost_sd;
    /* With source CT_SOURCE_PIXELS: a ct_pedestrian_test, what gives each
     * candidate its score (1 or 0 with CT_PEDESTRIAN_SIZE; the candidates'
     * votes and distances are reported either way).
     * Default 0 (CT_PEDESTRIAN_TEMPLATE); range [0, 1]. */
    int32_t pedestrian_test;
    /* With source CT_SOURCE_DETECTIONS: as it runs, the tracker learns how
     * tall its confirmed people are where their feet stand (a line in the
     * feet's row, its samples fading with a time constant of half a second
     * so that a moving camera is followed), and ignores a detection whose
     * height differs from the line's by more than this natural log ratio
     * (0.35: a detection 42% taller or 30% shorter). 0 ignores none.
     * Default 0.35; range [0, 10]. */
    float size_gate;
    /* With source CT_SOURCE_DETECTIONS: a tentative track is confirmed
     * (given an id and reported) only once one of its detections scored at
     * least this, besides its min_hits hits, or at least what the best 40%
     * of the detector's boxes score (learnt as the tracker runs, over the
     * boxes that reach start_score) when that is lower, so that a detector
     * that is never this sure still confirms tracks; the tracks of the
     * first step after create or reset are confirmed at once. A
     * detector's middling scores are often wrong (on the six MOTChallenge
     * 2015 sequences, 56% of the public boxes scoring 0.8 to 0.95 match no
     * one at IoU 0.5, 13% of those above), and its false boxes come back
     * frame after frame: they may start tracks, which count once the
     * detector was sure. At or under start_score, every track is
     * confirmed after min_hits.
     * Default 0.95; range [0, 1]. */
    float confirm_score;

    /* Added in 0.10.0. */

    /* Wherever the tracker reads the pixels of a still camera (from the
     * pixels alone, and with detections and frames), each reported box is
     * fitted to the person's silhouette in the foreground: its centre
     * moves 0.7 of the way toward the body's axis and toward the middle
     * between the head's top and the feet; a detector's box much wider
     * than the silhouette is narrowed to it, its height moves 0.7 of the
     * way to the silhouette's head to feet, and with the people's size
     * known a box cut short of a person's height grows to the feet and a
     * detector's box more than a tenth taller than a person whose feet
     * are at its bottom becomes that person; one whose silhouette joins
     * someone's head behind to its feet moves 0.7 of the way to the
     * height of a person standing there. Where
     * the silhouette does not show one person clearly (the background
     * model's first second, the second after the camera moved, another
     * track over a sixth of the box) the box is left as it is, but for a
     * detector's box whose person is in front of the other, fitted from
     * the rows below the other's; a detector's box too faint in the
     * foreground to fit takes what the fit did to that detector's boxes on
     * average. With detections it
     * makes the tracker keep a background model, about 0.2 ms a 768x576
     * frame. 0 reports the boxes unfitted and, with detections, reads no
     * background (docs/API.md, "Boxes fitted to the silhouette").
     * Default 1; range [0, 1]. */
    int32_t refine_boxes;
} ct_config;

/* Fills *cfg (of the caller's size `size`, normally sizeof *cfg) with the
 * defaults and sets cfg->size. */
CT_API int ct_config_default(ct_config *cfg, size_t size);

/* Checks a configuration without creating a tracker. On failure, writes a
 * message naming the wrong field and why into msg (if msg_len > 0; always
 * NUL-terminated) and returns CT_ERROR_INVALID_ARGUMENT or
 * CT_ERROR_UNSUPPORTED. */
CT_API int ct_config_check(const ct_config *cfg, char *msg, size_t msg_len);

/* ------------------------------------------------------------------------ */
/* Frames. */

#define CT_FOURCC(a, b, c, d) \
    ((uint32_t)(a) | ((uint32_t)(b) << 8) | ((uint32_t)(c) << 16) | ((uint32_t)(d) << 24))

typedef enum ct_format {
    CT_FORMAT_NONE = 0,                         /* no pixels this step */
    CT_FORMAT_I420 = 0x30323449,                /* 'I420': Y, U, V planes */
    CT_FORMAT_NV12 = 0x3231564E,                /* 'NV12': Y, interleaved UV */
    CT_FORMAT_GRAY8 = 0x30303859,               /* 'Y800': Y only */
    /* Packed 8-bit colour, one plane: the library converts it to I420
     * planes of its own (BT.601, limited range, chroma the mean of each 2x2
     * block) before it reads the pixels. */
    CT_FORMAT_BGR24 = 0x47423432,               /* '24BG': B, G, R bytes (OpenCV's order) */
    CT_FORMAT_RGB24 = 0x20776172                /* 'raw ': R, G, B bytes */
} ct_format;

typedef struct ct_frame {
    /* sizeof(ct_frame) as the caller's header knows it. */
    size_t size;
    /* A ct_format value. */
    uint32_t format;
    /* Image size in pixels. With CT_FORMAT_NONE both may be 0 (unknown);
     * when given, boxes can be clipped to it. */
    int32_t width;
    int32_t height;
    /* Plane pointers and strides in bytes (strides > 0). I420: Y, U, V with
     * chroma planes of (width+1)/2 x (height+1)/2. NV12: Y, UV. GRAY8: Y.
     * BGR24, RGB24: the pixels, 3 bytes each (strides[0] >= 3 * width). */
    const uint8_t *planes[3];
    int32_t strides[3];
    /* Capture time in microseconds; must increase from one feed to the
     * next. Motion is predicted from it, so dropped frames and variable
     * frame rates are handled; with pixels, the background model's start
     * (its first 0.46 s) is timed by it as well. */
    int64_t timestamp_us;
} ct_frame;

/* Fills *frame with an empty CT_FORMAT_NONE frame and sets frame->size. */
CT_API int ct_frame_default(ct_frame *frame, size_t size);

/* ------------------------------------------------------------------------ */
/* Detections in, tracks out. */

typedef struct ct_detection {
    float left, top, width, height; /* pixels, top-left origin */
    float score;                    /* detector confidence, usually [0, 1] */
    int32_t class_id;               /* the host's class; carried, not used */
} ct_detection;

typedef enum ct_track_state {
    CT_TRACK_TENTATIVE = 0, /* not yet confirmed; never reported */
    CT_TRACK_CONFIRMED = 1, /* updated this step: by a detection, or (no
                               detection, detection_index -1) followed on
                               the pixels by mean shift */
    CT_TRACK_LOST = 2       /* neither; box predicted by the motion model */
} ct_track_state;

typedef struct ct_track {
    uint64_t id;                    /* > 0, never reused by a tracker */
    float left, top, width, height; /* pixels */
    float barycenter_x, barycenter_y;
    float velocity_x, velocity_y;   /* of the box centre, pixels per second */
    float confidence;               /* [0, 1] */
    int32_t state;                  /* a ct_track_state value */
    int32_t age;                    /* steps since the track started */
    int32_t hits;                   /* steps in which a detection updated it */
    double time_since_update;       /* seconds since a detection updated it */
    int32_t detection_index;        /* index of this step's input detection
                                       that updated it, -1 if none */
    int32_t class_id;               /* class of the last matched detection */
} ct_track;

/* ------------------------------------------------------------------------ */
/* The tracker. */

typedef struct ct_tracker ct_tracker;

/* Creates a tracker. On failure *out is NULL and, when the configuration is
 * at fault, ct_config_check() on it says why. */
CT_API int ct_tracker_create(const ct_config *cfg, ct_tracker **out);

/* Destroys a tracker; NULL is accepted and ignored. */
CT_API void ct_tracker_destroy(ct_tracker *tracker);

/* A host's allocator (added in 0.9.0), as zstd's ZSTD_customMem and libjxl's
 * JxlMemoryManager: a camera with a fixed heap hands the tracker its own. */
typedef struct ct_allocator {
    /* sizeof(ct_allocator) as the caller's header knows it. */
    size_t size;
    /* Returns `size` bytes (size > 0) aligned for any type, as malloc does,
     * or NULL when there are none: the call that needed them then fails
     * with CT_ERROR_OUT_OF_MEMORY and changes nothing. */
    void *(*alloc)(void *opaque, size_t size);
    /* Gives back a block alloc returned (never NULL). */
    void (*free)(void *opaque, void *ptr);
    /* Passed to both, untouched. */
    void *opaque;
} ct_allocator;

/* Like ct_tracker_create(), with every block the tracker allocates (the
 * tracker itself, its tracks, models, templates and buffers) taken from
 * `allocator` and given back to it, at the latest by ct_tracker_destroy().
 * `allocator` NULL is ct_tracker_create(); else alloc and free are both set.
 * The struct is copied. The callbacks are called only from inside
 * ct_tracker_create_with_allocator(), ct_tracker_feed(), ct_tracker_prime(),
 * ct_tracker_reset() and ct_tracker_destroy(), on the calling thread. Not the tracker's own,
 * and from the C++ runtime's operator new: FLANN's kd-tree, which serves
 * appearance templates of more than 128 points only (the library's have
 * 72), and the C++ runtime's exception objects. (docs/API.md, "Memory".) */
CT_API int ct_tracker_create_with_allocator(const ct_config *cfg, const ct_allocator *allocator,
                                            ct_tracker **out);

/* Runs one step. `frame` gives the timestamp and, unless its format is
 * CT_FORMAT_NONE, the pixels. `dets` holds `n` detections (NULL when n is
 * 0). A failed call changes nothing in the tracker. */
CT_API int ct_tracker_feed(ct_tracker *tracker, const ct_frame *frame,
                           const ct_detection *dets, size_t n);

/* Copies the tracks reported for the last step into out[0..count-1].
 * `elem_size` is sizeof(ct_track) as the caller knows it. When capacity is
 * too small, nothing is copied, *count is set to the number needed and
 * CT_ERROR_BUFFER_TOO_SMALL is returned; out may be NULL when capacity is
 * 0. Tracks are in increasing id order. */
CT_API int ct_tracker_get_tracks(const ct_tracker *tracker, ct_track *out,
                                 size_t capacity, size_t elem_size,
                                 size_t *count);

/* Forgets every track, the last timestamp and what the tracker learnt of
 * the scene (the background model, the scene's motion, the people's size,
 * the size gate's line, the detector's scale of scores): as a new tracker,
 * but ids keep increasing. */
CT_API int ct_tracker_reset(ct_tracker *tracker);

/* A look-ahead for recorded files (added in 0.9.0): learns the scene's
 * background from a recording's first seconds before tracking it from its
 * first frame, so that the people there when it starts are found from it
 * (where a live feed finds them only as they walk off their ground). Frame
 * 1's tracks then depend on later frames: a camera fed live has no such
 * frames, and nothing primes unless the host calls this.
 *
 * *frames[0..n-1]: the recording's first seconds, in order, with increasing
 * timestamps, all with pixels, of one size and format (each a ct_frame of
 * its own, sized by its own size field), read during the call only (at most
 * CT_PRIME_MAX_FRAMES). Each pixel's median over them (over 31 of them,
 * evenly spaced, when there are more) is the background behind the people
 * who walk through; the frames, with what differs from it by more than five
 * times their noise put back to it, then teach the background model its
 * levels and the scene's noise. Their steps count in ct_stats.
 *
 * What it changes: the background model, learnt from the frames (used from
 * the pixels, CT_SOURCE_PIXELS, or with verify_detections). What it
 * forgets, as ct_tracker_reset() does: the tracks and the last timestamp;
 * feed the recording from its first frame next, with any timestamps. What
 * it keeps as it was: everything else the tracker has learnt (the scene's
 * motion, the people's size, the size gate's line, the detector's scale of
 * scores), none of which ages through the primed frames whatever their
 * length, and the ids (none is taken). When it fails, for bad frames or for
 * memory, the tracker is exactly as it was before the call. (docs/API.md,
 * "A recording's start".) */
CT_API int ct_tracker_prime(ct_tracker *tracker, const ct_frame *const *frames, size_t n);

/* The seconds of a recording's start that ct-track (--prime) and the
 * Python batch runner suggest priming on, when asked to (docs/tuning.md,
 * "A recording's start"). */
#define CT_PRIME_SECONDS 3.0
/* The most frames ct_tracker_prime() takes. */
#define CT_PRIME_MAX_FRAMES 65536

/* ------------------------------------------------------------------------ */
/* Candidates found in the pixels (source CT_SOURCE_PIXELS), or the external
 * detections as the contour template voted on them (verify_detections). */

#define CT_REGIONS 9

typedef struct ct_candidate {
    float left, top, width, height; /* pixels */
    /* The contour template's vote: yes votes over voting regions (0 with
     * fewer than 5 voters; at most 0.5, not a pedestrian, when the blob
     * fills more of its convex hull than a walking person does, see fill,
     * or its top is as wide as its body, see top_width, or two people side
     * by side fit its outline better than every pedestrian silhouette and
     * its top edge shows two heads or none; with one head, 0.5 plus half
     * the regions' margin over 0.5, at most 0.75; at most 0.5 too when the
     * head, neck and shoulders all abstain, no upper body; 0 for a blob at
     * the image's left or right edge too narrow to have an outline);
     * candidates feed the tracker with this score. */
    float score;
    int32_t votes_yes, voters;
    /* The paper's eq. (1) per region (head, neck, shoulders, chest, back,
     * abdomen, buttocks, upper limbs, lower limbs): the mean distance, in
     * box heights, between the blob's contour and the best silhouette's; -1
     * where the region abstained (occluded or out of the frame). */
    float region_distance[CT_REGIONS];

    /* Added in 0.6.0: callers built against an older header pass a smaller
     * element size and get the fields above. */

    /* How much of its convex hull the blob fills, 0 to 1: the area inside
     * its outer contour (holes included) over the hull's. A walking
     * person's outline is concave at the neck, under the arms and between
     * the legs. */
    float fill;

    /* Added in 0.7.0. */

    /* How wide the blob's top is against its body: the median width of the
     * head's rows (the top eighth of the box; an empty row counts 0) over
     * the widest row from the shoulders (11/64 of the box's height down) to
     * the feet; 0 when fewer than half the rows from the shoulders to the
     * hips hold foreground. About 0.15 for a person, whose head is narrower
     * than their shoulders, arms or legs in stride; 1 or more for a T, an
     * H, a Y. Above 0.9 the score is at most 0.5, as for a blob that fills
     * its hull. */
    float top_width;
} ct_candidate;

/* Copies the candidates of the last step, like ct_tracker_get_tracks() (in
 * the order found): the blobs, and boxes the people's size draws for someone
 * partly hidden behind the person a blob is (each over that blob's box);
 * in the background model's first 1.2 s, after those, the blobs of what
 * changed since the frame before that no blob of the model's covers.
 * With source CT_SOURCE_DETECTIONS there are none, unless
 * verify_detections is set and the frame had pixels: then one per detection
 * given, in order, with the box as given. */
CT_API int ct_tracker_get_candidates(const ct_tracker *tracker, ct_candidate *out,
                                     size_t capacity, size_t elem_size, size_t *count);

/* ------------------------------------------------------------------------ */
/* Timing and memory, for benchmarks and monitoring. */

/* The stages of a step, each timed by the library. Values are pinned; later
 * versions add stages after the last. */
typedef enum ct_stage {
    CT_STAGE_VALIDATE = 0,  /* checking the frame and detections */
    CT_STAGE_PREDICT = 1,   /* motion prediction of every track */
    CT_STAGE_ASSOCIATE = 2, /* costs and assignment */
    CT_STAGE_LIFECYCLE = 3, /* updates, losses, removals, births */
    CT_STAGE_REPORT = 4,    /* building the reported tracks */
    CT_STAGE_MEAN_SHIFT = 5, /* colour models and mean shift */
    CT_STAGE_APPEARANCE = 6, /* descriptors, DDIS, templates */
    CT_STAGE_BACKGROUND = 7, /* background model, foreground mask */
    CT_STAGE_BLOBS = 8,      /* morphology, contours, merges and splits */
    CT_STAGE_CLASSIFY = 9,   /* contour template and region votes */
    CT_STAGE_CONVERT = 10    /* packed BGR24 / RGB24 to planes */
} ct_stage;

#define CT_STATS_MAX_STAGES 16

typedef struct ct_stats {
    /* sizeof(ct_stats) as the caller's header knows it; set it before the
     * call. */
    size_t size;
    /* Steps run since create (a refused feed is not a step). */
    uint64_t steps;
    /* Wall time spent in ct_tracker_feed() and in each stage, nanoseconds,
     * summed over the steps; stages this version lacks stay 0. */
    uint64_t feed_ns;
    uint64_t stage_ns[CT_STATS_MAX_STAGES];
    /* Tracks alive now (tentative, confirmed, lost). */
    uint64_t live_tracks;
    /* Heap bytes the tracker holds now (its buffers' capacity). */
    uint64_t memory_bytes;
    /* Added in 0.2.0: windows mean shift ran on (one a confirmed track a
     * step with pixels), so stage_ns[CT_STAGE_MEAN_SHIFT] / mean_shift_runs
     * is its cost per person. */
    uint64_t mean_shift_runs;
    /* Added in 0.3.0: DDIS evaluations and template (FLANN index) builds. */
    uint64_t ddis_runs;
    uint64_t template_builds;
    /* Added in 0.9.0: from the pixels, the blobs past a frame's cap (128:
     * the smallest were dropped), and the frames whose foreground covered
     * more than half the image and gave no candidate. */
    uint64_t blobs_dropped;
    uint64_t masks_flooded;
} ct_stats;

/* Fills *stats (stats->size must be set). Resetting the tracker does not
 * clear them. */
CT_API int ct_tracker_get_stats(const ct_tracker *tracker, ct_stats *stats);

/* ------------------------------------------------------------------------ */
/* The people's size, as the tracker learns it (0.9.0). */

/* A standing person whose feet are at image row y is about
 * height_slope * y + height_intercept pixels tall (a static camera over
 * flat ground; the fit to the boxes of confident single-person tracks), and
 * three people in four there are under width_ratio times that wide. From
 * the pixels alone it sets what counts as a speck, a fragment or a group. */
typedef struct ct_person_size {
    /* sizeof(ct_person_size) as the caller's header knows it; set it before
     * the call. */
    size_t size;
    /* Non-zero once enough people were seen (until then the tracker knows
     * only that people are 30 to 400 pixels tall, and the fields below are
     * 0). */
    int32_t known;
    float height_slope, height_intercept;
    float width_ratio;
    /* The boxes seen so far. */
    uint64_t samples;
    /* Added in 0.9.0 with the working scale: a typical person's height
     * where people were seen (pixels: the line's height at the mean feet
     * row of the boxes; 0 while unknown), and from the pixels the scale
     * the foreground is found at, in frame pixels a working pixel: 2 until
     * the size is known, then 1 while a typical person is under about 55
     * pixels tall (not with pedestrian_test = CT_PEDESTRIAN_SIZE), and 4
     * once the size rests on 200 boxes and a typical person is over about
     * 160 (0 until a foreground was found: with detections, frames
     * without pixels, or refine_boxes and verify_detections both 0, there
     * is none). The memory for the pixels follows it: 4 times as much at
     * 1. */
    float typical_height;
    int32_t working_scale;
} ct_person_size;

/* Fills *out (out->size must be set). ct_tracker_reset() forgets it, as a
 * new frame size does. */
CT_API int ct_tracker_get_person_size(const ct_tracker *tracker, ct_person_size *out);

/* ------------------------------------------------------------------------ */
/* Counting (added in 0.10.0): lines that people cross and zones they enter,
 * leave and stay in, counted from the tracks as they are made.
 *
 * A track's point (its anchor) is the bottom centre of its reported box:
 * where a standing person's feet are. A step counts only confirmed tracks,
 * and only at steps where they were seen (state CT_TRACK_CONFIRMED); a
 * track carried through an occlusion counts when it is seen again, by the
 * path from where it was last seen. A track's starting side of each line,
 * and whether it started in each zone, is that of its first observed box,
 * before it was confirmed: a person confirmed just after crossing is still
 * counted, at the step that confirms them. (docs/API.md, "Counting".) */

#define CT_COUNT_MAX_LINES 64
#define CT_COUNT_MAX_ZONES 64
#define CT_ZONE_MAX_POINTS 64
/* The bytes of a name, its terminating NUL included. */
#define CT_NAME_SIZE 32

typedef struct ct_point {
    float x, y; /* pixels, top-left origin */
} ct_point;

/* A counting line: the segment from a to b (not the infinite line through
 * them). A crossing is "in" when the anchor goes to the right-hand side of
 * the direction a -> b as the image shows it (for a segment drawn from left
 * to right, downward), "out" the other way. */
typedef struct ct_line {
    /* sizeof(ct_line) as the caller's header knows it; ct_line_default()
     * sets it. */
    size_t size;
    /* The end points, finite, at most 1e6 pixels from the origin, at least
     * a pixel apart. Default (0, 0) and (0, 0): set them. */
    ct_point a, b;
    /* Copied; at most CT_NAME_SIZE - 1 bytes, unique among the tracker's
     * lines. NULL or "" (default): "line<index>". */
    const char *name;
    /* How far past the line the anchor must go for a crossing to count,
     * and then again the other way before another counts, in heights of the
     * track's box: a person's feet jitter about a line they stand or walk
     * on. Default 0.1, range [0, 2]. */
    float hysteresis;
} ct_line;

/* A zone: a simple polygon (its edges do not cross or touch but at
 * neighbouring corners), of non-zero area. A track is in it when its anchor
 * is inside. */
typedef struct ct_zone {
    /* sizeof(ct_zone) as the caller's header knows it; ct_zone_default()
     * sets it. */
    size_t size;
    /* points[0..n_points-1], read during the call only: 3 to
     * CT_ZONE_MAX_POINTS corners in order (either way round), finite, at
     * most 1e6 pixels from the origin. Default NULL and 0: set them. */
    const ct_point *points;
    int32_t n_points;
    /* As ct_line's: NULL or "" (default) is "zone<index>". */
    const char *name;
    /* How far inside the zone (or outside it) the anchor must go, from its
     * nearest edge, for an entry (or an exit) to count, in heights of the
     * track's box. Default 0.1, range [0, 2]. */
    float hysteresis;
} ct_zone;

CT_API int ct_line_default(ct_line *line, size_t size);
CT_API int ct_zone_default(ct_zone *zone, size_t size);

/* Adds a line (at most CT_COUNT_MAX_LINES) or a zone (at most
 * CT_COUNT_MAX_ZONES); *index (when not NULL) receives its index, 0 for the
 * first, in the order added. Lines and zones stay for the tracker's life;
 * ct_tracker_reset() and ct_tracker_prime() keep them and their counts and
 * forget their tracks (as the tracker does). A line or zone added while
 * tracks run takes their side from their next observed box. A refused one
 * (CT_ERROR_INVALID_ARGUMENT: a point not finite, a segment under a pixel,
 * a polygon that crosses itself, has no area or too many corners, a name
 * too long or taken, too many) changes nothing. */
CT_API int ct_tracker_add_line(ct_tracker *tracker, const ct_line *line, int32_t *index);
CT_API int ct_tracker_add_zone(ct_tracker *tracker, const ct_zone *zone, int32_t *index);

typedef enum ct_event_kind {
    CT_EVENT_LINE_IN = 1,    /* crossed a line to its right-hand side */
    CT_EVENT_LINE_OUT = 2,   /* crossed a line to its left-hand side */
    CT_EVENT_ZONE_ENTER = 3, /* went into a zone */
    CT_EVENT_ZONE_EXIT = 4   /* came out of a zone, or ended in it */
} ct_event_kind;

typedef struct ct_event {
    int32_t kind;          /* a ct_event_kind value */
    int32_t index;         /* the line's or the zone's */
    uint64_t track_id;
    int64_t timestamp_us;  /* the step's */
    float x, y;            /* the anchor (for an ended track, its last) */
    /* CT_EVENT_ZONE_EXIT: the seconds it was in the zone; else 0. */
    double dwell;
    /* CT_EVENT_ZONE_EXIT: 1 when the track ended while in the zone (it
     * left the image from it, or was lost past lost_lifetime), 0 when it
     * was seen outside. */
    int32_t ended;
} ct_event;

/* Copies the events of the last step, like ct_tracker_get_tracks(), in
 * increasing track id, then line and zone order. */
CT_API int ct_tracker_get_events(const ct_tracker *tracker, ct_event *out, size_t capacity,
                                 size_t elem_size, size_t *count);

typedef struct ct_line_count {
    int32_t index;
    char name[CT_NAME_SIZE];
    uint64_t in, out; /* crossings since the line was added */
} ct_line_count;

typedef struct ct_zone_count {
    int32_t index;
    char name[CT_NAME_SIZE];
    uint64_t entered, exited; /* since the zone was added */
    /* The confirmed tracks in it now, lost ones included until they end. */
    int32_t inside;
} ct_zone_count;

/* A confirmed track in a zone now. */
typedef struct ct_occupant {
    int32_t zone;
    uint64_t track_id;
    /* Seconds since it entered, or since it was first seen when it
     * started in the zone. */
    double dwell;
} ct_occupant;

/* Copy every line's and zone's counts, and the occupants of every zone (in
 * zone, then track id order), as of the last step; like
 * ct_tracker_get_tracks(). */
CT_API int ct_tracker_get_line_counts(const ct_tracker *tracker, ct_line_count *out,
                                      size_t capacity, size_t elem_size, size_t *count);
CT_API int ct_tracker_get_zone_counts(const ct_tracker *tracker, ct_zone_count *out,
                                      size_t capacity, size_t elem_size, size_t *count);
CT_API int ct_tracker_get_occupants(const ct_tracker *tracker, ct_occupant *out,
                                    size_t capacity, size_t elem_size, size_t *count);

/* The name of a stage ("predict", ...), or NULL for a value that is not one. */
CT_API const char *ct_stage_name(int stage);

/* The message of the last failed call on this tracker ("" if none). The
 * string is owned by the tracker and valid until its next call. Accepts
 * NULL. */
CT_API const char *ct_tracker_last_error(const ct_tracker *tracker);

#ifdef __cplusplus
}
#endif

#endif /* CTRACK_CTRACK_H */
