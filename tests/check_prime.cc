// ct_tracker_prime() keeps its promises, on TUD-Campus's real frames and
// detections, in each mode: it teaches the background model and nothing
// else (the models learnt in time do not age through the primed stretch,
// whatever its length); it forgets the tracks and the time; a refused
// allocation anywhere in it leaves the tracker exactly as before the call.
// operator new (and, outside the sanitizers, malloc) is replaced to fail on
// demand, as in check_oom.cc.
#include <check.h>

#include "common.h"

#include <cstdio>
#include <cstring>
#include <vector>

#include "ctrack/ctrack.h"
#include "detfile.h"
#include "video.h"

static const char *data_dir;
static const char *tud_video; // TUD-Campus as Y4M (made by the build)
// The allocation that fails (0: the next one); -1: none. Allocations are
// counted.
static long fail_countdown = -1;
static long allocations = 0;

static bool allocation_allowed(bool)
{
    allocations++;
    return fail_countdown < 0 || fail_countdown-- != 0;
}

#include "alloc_hooks.h"
#include "tracker_io.h"

namespace {

enum Mode { DETECTIONS, DETECTIONS_AND_PIXELS, VERIFY, PIXELS };
const char *const kModeNames[] = {"detections", "detections + pixels", "verify", "pixels"};

// TUD-Campus's 71 frames and detections, in memory.
struct Clip {
    std::vector<ct_frame> frames;
    det_file df;
    video_input *in = nullptr;
    Clip()
    {
        char path[1024], err[512];
        std::snprintf(path, sizeof path, "%s/TUD-Campus/det/det.txt", data_dir);
        ck_assert_msg(detfile_load(path, &df, err, sizeof err) == 0, "%s", err);
        video_params ip = {0, 0, CT_FORMAT_I420};
        video_info info;
        ck_assert_msg(video_open(tud_video, &ip, &in, &info, err, sizeof err) == 0, "%s", err);
        ck_assert_int_eq(video_keep(in, 71, err, sizeof err), 0);
        ct_frame f;
        while (video_read(in, &f, err, sizeof err) == 1)
            frames.push_back(f);
        ck_assert_uint_eq(frames.size(), 71);
        for (size_t k = 0; k < frames.size(); k++)
            ck_assert_int_eq(video_kept(in, (long long)k, &frames[k]), 1);
    }
    ~Clip()
    {
        video_close(in);
        detfile_free(&df);
    }
    // Frame k (0-based) at time t_us, as the mode feeds it.
    ct_frame frame(int k, int64_t t_us, Mode mode) const
    {
        ct_frame f = frames[(size_t)k];
        if (mode == DETECTIONS) {
            const ct_frame pixels = f;
            ct_frame_default(&f, sizeof f);
            f.width = pixels.width;
            f.height = pixels.height;
        }
        f.timestamp_us = t_us;
        return f;
    }
};

ct_config config_of(Mode mode)
{
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    cfg.source = mode == PIXELS ? CT_SOURCE_PIXELS : CT_SOURCE_DETECTIONS;
    cfg.verify_detections = mode == VERIFY;
    return cfg;
}

// Feeds frames [from, to) at 25 frames/s from time t0_us; the tracks of
// each step.
std::vector<std::vector<ct_track>> feed(ct_tracker *t, Clip &clip, Mode mode, int from, int to,
                                        int64_t t0_us)
{
    std::vector<std::vector<ct_track>> out;
    clip.df.cursor = 0; // detfile_frame() walks forward from here
    for (int k = from; k < to; k++) {
        const ct_frame f = clip.frame(k, t0_us + (int64_t)(k - from) * 40000, mode);
        size_t n = 0;
        const ct_detection *d = detfile_frame(&clip.df, k + 1, &n);
        if (mode == PIXELS)
            d = nullptr, n = 0;
        ck_assert_int_eq(ct_tracker_feed(t, &f, d, n), CT_OK);
        out.push_back(tracks_of(t));
    }
    return out;
}

void same(const std::vector<std::vector<ct_track>> &a, const std::vector<std::vector<ct_track>> &b)
{
    ck_assert_uint_eq(a.size(), b.size());
    for (size_t k = 0; k < a.size(); k++)
        assert_equal(a[k], b[k]);
}

// Primes t on frames [from, to) of the clip, 40 ms apart, with pixels; the
// call's allocation `refuse` is refused (-1: none). *refused says whether
// one was.
int prime(ct_tracker *t, Clip &clip, int from, int to, long refuse = -1, bool *refused = nullptr)
{
    std::vector<ct_frame> f;
    std::vector<const ct_frame *> p;
    for (int k = from; k < to; k++)
        f.push_back(clip.frame(k, (int64_t)(k - from) * 40000, PIXELS));
    for (const ct_frame &x : f)
        p.push_back(&x);
    fail_countdown = refuse;
    const int st = ct_tracker_prime(t, p.data(), p.size());
    if (refused)
        *refused = refuse >= 0 && fail_countdown < 0;
    fail_countdown = -1;
    return st;
}

ct_person_size person_size_of(ct_tracker *t)
{
    ct_person_size s;
    std::memset(&s, 0, sizeof s);
    s.size = sizeof s;
    ck_assert_int_eq(ct_tracker_get_person_size(t, &s), CT_OK);
    return s;
}

ct_stats stats_of(ct_tracker *t)
{
    ct_stats s;
    std::memset(&s, 0, sizeof s);
    s.size = sizeof s;
    ck_assert_int_eq(ct_tracker_get_stats(t, &s), CT_OK);
    return s;
}

} // namespace

// After 40 fed frames, priming on 1 frame or on all 71 (2.84 s) teaches
// the learnt models nothing and ages none of them: with a detector's boxes
// alone (no background to teach) the same 31 frames fed next give the same
// tracks to the byte, and in every mode the people's size is what it was
// before the call.
START_TEST(priming_ages_no_learnt_model)
{
    const Mode mode = (Mode)_i;
    Clip clip;
    const ct_config cfg = config_of(mode);
    std::vector<std::vector<ct_track>> after[2];
    for (int v = 0; v < 2; v++) {
        ct_tracker *t = test_tracker(&cfg);
        feed(t, clip, mode, 0, 40, 0);
        const ct_person_size before = person_size_of(t);
        ck_assert_int_eq(prime(t, clip, 0, v == 0 ? 1 : 71), CT_OK);
        const ct_person_size primed = person_size_of(t);
        ck_assert_int_eq(std::memcmp(&before, &primed, offsetof(ct_person_size, working_scale)),
                         0);
        after[v] = feed(t, clip, mode, 40, 71, 0);
        ct_tracker_destroy(t);
    }
    size_t n = 0;
    for (const auto &step : after[1])
        n += step.size();
    ck_assert_uint_gt(n, 50);
    if (mode == DETECTIONS)
        same(after[0], after[1]);
}
END_TEST

// Each allocation of a prime call refused in turn, after 30 fed frames:
// the call fails with CT_ERROR_OUT_OF_MEMORY, and the tracker is as it was
// before it: its statistics, and its tracks over the next frames fed on
// from where it was (as a host that saw the call fail goes on), are those
// of a tracker never asked. Once no allocation is refused, the call goes
// through and the tracker tracks as a primed one does.
START_TEST(a_refused_allocation_in_priming_changes_nothing)
{
    const Mode mode = (Mode)_i;
    Clip clip;
    const ct_config cfg = config_of(mode);
    ct_tracker *ref = test_tracker(&cfg);
    feed(ref, clip, mode, 0, 30, 0);
    const ct_stats ref_stats = stats_of(ref);
    const auto unprimed = feed(ref, clip, mode, 30, 50, 30 * 40000);
    ct_tracker_destroy(ref);
    ref = test_tracker(&cfg);
    feed(ref, clip, mode, 0, 30, 0);
    const long before = allocations;
    ck_assert_int_eq(prime(ref, clip, 30, 71), CT_OK);
    const long made = allocations - before; // the call's, and the helper's few
    const auto primed = feed(ref, clip, mode, 30, 50, 0);
    ct_tracker_destroy(ref);

    int refused = 0;
    for (long k = 0;; k++) {
        ct_tracker *t = test_tracker(&cfg);
        feed(t, clip, mode, 0, 30, 0);
        bool was_refused;
        const int st = prime(t, clip, 30, 71, k, &was_refused);
        if (!was_refused) {
            ck_assert_int_eq(st, CT_OK);
            same(feed(t, clip, mode, 30, 50, 0), primed);
            ct_tracker_destroy(t);
            break;
        }
        refused++;
        ck_assert_int_le(k, made);
        ck_assert_int_eq(st, CT_ERROR_OUT_OF_MEMORY);
        const ct_stats s = stats_of(t);
        ck_assert_uint_eq(s.steps, ref_stats.steps);
        ck_assert_uint_eq(s.live_tracks, ref_stats.live_tracks);
        // Fed on from its last timestamp: no CT_ERROR_BAD_STATE, the same
        // tracks.
        same(feed(t, clip, mode, 30, 50, 30 * 40000), unprimed);
        ct_tracker_destroy(t);
    }
    std::printf("prime, %s: %d refused allocations, each leaving the tracker as it was\n",
                kModeNames[mode], refused);
    ck_assert_int_gt(refused, 3);
}
END_TEST

// Frames of two formats in one call: the message names both.
START_TEST(mixed_formats_are_named)
{
    Clip clip;
    ct_config cfg = config_of(PIXELS);
    ct_tracker *t = test_tracker(&cfg);
    ct_frame f[2] = {clip.frame(0, 0, PIXELS), clip.frame(1, 40000, PIXELS)};
    f[1].format = CT_FORMAT_GRAY8;
    const ct_frame *p[2] = {&f[0], &f[1]};
    ck_assert_int_eq(ct_tracker_prime(t, p, 2), CT_ERROR_INVALID_ARGUMENT);
    const char *msg = ct_tracker_last_error(t);
    ck_assert_msg(std::strstr(msg, "GRAY8") && std::strstr(msg, "I420") &&
                      std::strstr(msg, "frames[1]"),
                  "%s", msg);
    ct_tracker_destroy(t);
}
END_TEST

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: check_prime MOT15_DIR TUD_CAMPUS_Y4M\n");
        return 2;
    }
    data_dir = argv[1];
    tud_video = argv[2];
    Suite *s = suite_create("prime");
    TCase *tc = tcase_create("prime");
    tcase_set_timeout(tc, 240);
    tcase_add_loop_test(tc, priming_ages_no_learnt_model, DETECTIONS, PIXELS + 1);
    tcase_add_loop_test(tc, a_refused_allocation_in_priming_changes_nothing, DETECTIONS,
                        PIXELS + 1);
    tcase_add_test(tc, mixed_formats_are_named);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
