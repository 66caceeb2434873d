// Allocation failures inside the library become CT_ERROR_OUT_OF_MEMORY, and a
// failed feed leaves the tracker as it was. operator new is replaced here to
// fail on demand (the library is linked statically so it uses this one),
// and so are malloc and its family: the executable's malloc interposes on
// every shared library's, so the C library's allocations fail on demand
// too. (Under AddressSanitizer or
// ThreadSanitizer, whose runtimes own malloc, only operator new fails.)
#include <check.h>

#include "common.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "ctrack/ctrack.h"
#include "detfile.h"
#include "pixels/background.h"
#include "pixels/blobs.h"
#include "appearance/nnindex.h"
#include "video.h"

static const char *data_dir;
static const char *tud_video; // TUD-Campus as Y4M (made by the build)
// The allocation that fails (0: the next one); -1: none. Counted down by
// every thread's allocations.
static std::atomic<long> fail_countdown{-1};
// While set, every allocation fails, in every thread.
static std::atomic<bool> fail_all{false};
static std::atomic<long> allocations{0};
// Failed allocations that came through malloc and not operator new: the C
// library's, FLANN's pool.
static std::atomic<long> failed_mallocs{0};

// Whether this allocation may go through.
static bool allowed()
{
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (fail_all.load(std::memory_order_relaxed))
        return false;
    long c = fail_countdown.load();
    while (c >= 0)
        if (fail_countdown.compare_exchange_weak(c, c - 1))
            return c != 0;
    return true;
}

// The hook of alloc_hooks.h: the countdown's, and failures through malloc
// counted apart.
static bool allocation_allowed(bool through_malloc)
{
    if (allowed())
        return true;
    if (through_malloc)
        failed_mallocs++;
    return false;
}

#include "alloc_hooks.h"

#include "tracker_io.h"

// Loads the public detections of a sequence of tests/data/mot15.
static void load_detections(const char *seq, det_file *df)
{
    char path[1024], err[512];
    std::snprintf(path, sizeof path, "%s/%s/det/det.txt", data_dir, seq);
    ck_assert_msg(detfile_load(path, df, err, sizeof err) == 0, "%s", err);
}

START_TEST(create_out_of_memory)
{
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    ct_tracker *t = reinterpret_cast<ct_tracker *>(&cfg);
    fail_countdown = 0;
    ck_assert_int_eq(ct_tracker_create(&cfg, &t), CT_ERROR_OUT_OF_MEMORY);
    ck_assert_ptr_null(t);
    fail_countdown = -1;
}
END_TEST

// Every frame of PETS09-S2L1 is first fed with an allocation failure armed
// (the first, second, ... allocation of the call). A refused feed must
// change nothing; the retry then must give what an undisturbed tracker gives.
START_TEST(feed_out_of_memory_changes_nothing)
{
    det_file df;
    load_detections("PETS09-S2L1", &df);
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    ct_tracker *ref = nullptr, *t = nullptr;
    ck_assert_int_eq(ct_tracker_create(&cfg, &ref), CT_OK);
    ck_assert_int_eq(ct_tracker_create(&cfg, &t), CT_OK);
    int refused = 0;
    for (int k = 1; k <= df.max_frame; k++) {
        ct_frame f;
        ct_frame_default(&f, sizeof f);
        f.timestamp_us = (int64_t)((k - 1) * 1e6 / 7);
        size_t n;
        const ct_detection *d = detfile_frame(&df, k, &n);
        ck_assert_int_eq(ct_tracker_feed(ref, &f, d, n), CT_OK);

        std::vector<ct_track> before = tracks_of(t);
        fail_countdown = k % 4;
        int st = ct_tracker_feed(t, &f, d, n);
        fail_countdown = -1;
        if (st != CT_OK) {
            ck_assert_int_eq(st, CT_ERROR_OUT_OF_MEMORY);
            ck_assert_str_eq(ct_tracker_last_error(t), "out of memory");
            assert_equal(tracks_of(t), before);
            refused++;
            ck_assert_int_eq(ct_tracker_feed(t, &f, d, n), CT_OK);
        }
        assert_equal(tracks_of(t), tracks_of(ref));
    }
    // Growth allocates early on; steady state does not, so only some feeds fail.
    ck_assert_int_gt(refused, 0);
    ct_tracker_destroy(ref);
    ct_tracker_destroy(t);
    detfile_free(&df);
}
END_TEST

// The same with the frames: TUD-Campus's, pixels only (background model,
// blobs, contour template) and with its public detections (mean shift,
// appearance templates). Each frame is refused twice, at two different
// allocations, before it goes through: the mask operations' buffers, the
// background model's update and the templates' rebuilding must all be
// undone, so that the tracks and candidates stay those of an undisturbed
// tracker, to the byte.

// TUD-Campus's frames and public detections, and two trackers of one
// source: the reference, never disturbed, and the one whose allocations
// fail.
struct TudReplay {
    det_file df;
    video_input *in = nullptr;
    ct_tracker *ref = nullptr, *t = nullptr;
    explicit TudReplay(int source)
    {
        load_detections("TUD-Campus", &df);
        char err[512];
        video_params ip = {0, 0, CT_FORMAT_I420};
        video_info info;
        ck_assert_msg(video_open(tud_video, &ip, &in, &info, err, sizeof err) == 0, "%s", err);
        ct_config cfg;
        ct_config_default(&cfg, sizeof cfg);
        cfg.source = source;
        ck_assert_int_eq(ct_tracker_create(&cfg, &ref), CT_OK);
        ck_assert_int_eq(ct_tracker_create(&cfg, &t), CT_OK);
    }
    ~TudReplay()
    {
        ct_tracker_destroy(ref);
        ct_tracker_destroy(t);
        video_close(in);
        detfile_free(&df);
    }
};

static void pixels_out_of_memory(int source, bool packed = false)
{
    std::vector<uint8_t> bgr;
    TudReplay replay(source);
    det_file &df = replay.df;
    video_input *in = replay.in;
    ct_tracker *ref = replay.ref, *t = replay.t;
    char err[512];
    int refused = 0, frames = 0;
    for (int k = 1;; k++) {
        ct_frame f;
        const int r = video_read(in, &f, err, sizeof err);
        ck_assert_msg(r >= 0, "%s", err);
        if (r == 0)
            break;
        if (packed)
            f = as_bgr24(f, &bgr);
        frames++;
        f.timestamp_us = (int64_t)((k - 1) * 1e6 / 25);
        size_t n = 0;
        const ct_detection *d = detfile_frame(&df, k, &n);
        if (source == CT_SOURCE_PIXELS)
            d = nullptr, n = 0;
        ck_assert_int_eq(ct_tracker_feed(ref, &f, d, n), CT_OK);

        const std::vector<ct_track> tracks = tracks_of(t);
        const std::vector<ct_candidate> cands = candidates_of(t);
        // Allocation k % 5, then a later one: a feed that makes fewer
        // allocations goes through at once.
        bool done = false;
        for (long countdown : {(long)(k % 5), (long)(k * 37 % 400)}) {
            fail_countdown = countdown;
            const int st = ct_tracker_feed(t, &f, d, n);
            fail_countdown = -1;
            if (st == CT_OK) {
                done = true;
                break;
            }
            ck_assert_msg(st == CT_ERROR_OUT_OF_MEMORY, "frame %d: %s", k,
                          ct_tracker_last_error(t));
            assert_equal(tracks_of(t), tracks);
            assert_equal(candidates_of(t), cands);
            refused++;
        }
        if (!done)
            ck_assert_int_eq(ct_tracker_feed(t, &f, d, n), CT_OK);
        assert_equal(tracks_of(t), tracks_of(ref));
        assert_equal(candidates_of(t), candidates_of(ref));
    }
    ck_assert_int_gt(frames, 20);
    // Most frames allocate nothing once the buffers have grown to the
    // scene (docs/bench.md, "Memory"): the refusals are the growing ones.
    ck_assert_int_gt(refused, 5);
}

START_TEST(pixels_only_out_of_memory_changes_nothing)
{
    pixels_out_of_memory(CT_SOURCE_PIXELS);
}
END_TEST

START_TEST(detections_and_pixels_out_of_memory_changes_nothing)
{
    pixels_out_of_memory(CT_SOURCE_DETECTIONS);
}
END_TEST

// Packed colour: the library's planes for it are one more allocation.
START_TEST(bgr24_out_of_memory_changes_nothing)
{
    pixels_out_of_memory(CT_SOURCE_PIXELS, true);
}
END_TEST

// The first kEveryAllocationSteps steps of TUD-Campus, in each mode: each
// step is fed once with every allocation failing (in every thread), then
// once for each allocation it makes with that one failing (the first, the
// second, ...: the C library's and ctrack's alike), each
// refused with CT_ERROR_OUT_OF_MEMORY and changing nothing, and then goes
// through and must give what a tracker that never saw a failed call gives;
// the rest of the sequence follows, compared step by step. 40 steps (1.6 s
// of video: the background model's start, the first tracks, their colour
// models and templates) keep the three modes within a minute here (about
// 20,000 refused feeds).
static const int kEveryAllocationSteps = 40;

struct Snapshot {
    std::vector<ct_track> tracks;
    std::vector<ct_candidate> candidates;
    uint64_t steps;
};

static Snapshot snapshot(ct_tracker *t)
{
    ct_stats st;
    st.size = sizeof st;
    ck_assert_int_eq(ct_tracker_get_stats(t, &st), CT_OK);
    return {tracks_of(t), candidates_of(t), st.steps};
}

static void assert_same(const Snapshot &a, const Snapshot &b, int step, long attempt)
{
    ck_assert_msg(a.tracks.size() == b.tracks.size() && a.candidates.size() == b.candidates.size() &&
                      a.steps == b.steps,
                  "step %d, allocation %ld: %zu/%zu tracks, %zu/%zu candidates, %llu/%llu steps",
                  step, attempt, a.tracks.size(), b.tracks.size(), a.candidates.size(),
                  b.candidates.size(), (unsigned long long)a.steps, (unsigned long long)b.steps);
    assert_equal(a.tracks, b.tracks);
    assert_equal(a.candidates, b.candidates);
}

enum Mode { DETECTIONS, DETECTIONS_AND_PIXELS, PIXELS };

static void every_allocation_fails(Mode mode)
{
    TudReplay replay(mode == PIXELS ? CT_SOURCE_PIXELS : CT_SOURCE_DETECTIONS);
    det_file &df = replay.df;
    video_input *in = replay.in;
    ct_tracker *ref = replay.ref, *t = replay.t;
    char err[512];
    long refused = 0, most = 0;
    const long mallocs_before = failed_mallocs;
    int k = 1;
    for (;; k++) {
        ct_frame f;
        const int r = video_read(in, &f, err, sizeof err);
        ck_assert_msg(r >= 0, "%s", err);
        if (r == 0)
            break;
        f.timestamp_us = (int64_t)((k - 1) * 1e6 / 25);
        if (mode == DETECTIONS) {
            const int w = f.width, h = f.height;
            ct_frame_default(&f, sizeof f);
            f.timestamp_us = (int64_t)((k - 1) * 1e6 / 25);
            f.width = w;
            f.height = h;
        }
        size_t n = 0;
        const ct_detection *d = detfile_frame(&df, k, &n);
        if (mode == PIXELS)
            d = nullptr, n = 0;
        ck_assert_int_eq(ct_tracker_feed(ref, &f, d, n), CT_OK);
        if (k <= kEveryAllocationSteps) {
            const Snapshot before = snapshot(t);
            for (long attempt = -1;; attempt++) {
                // -1: all of them; then the first, the second, ...
                if (attempt < 0)
                    fail_all = true;
                else
                    fail_countdown = attempt;
                const int st = ct_tracker_feed(t, &f, d, n);
                fail_all = false;
                fail_countdown = -1;
                if (st == CT_OK) { // a step that allocates nothing goes through at once
                    most = attempt > most ? attempt : most;
                    break;
                }
                ck_assert_msg(st == CT_ERROR_OUT_OF_MEMORY, "step %d, allocation %ld: %s", k,
                              attempt, ct_tracker_last_error(t));
                ck_assert_str_eq(ct_tracker_last_error(t), "out of memory");
                assert_same(snapshot(t), before, k, attempt);
                refused++;
            }
        } else {
            ck_assert_int_eq(ct_tracker_feed(t, &f, d, n), CT_OK);
        }
        assert_same(snapshot(t), snapshot(ref), k, 0);
    }
    ck_assert_int_gt(k, kEveryAllocationSteps);
    ck_assert_int_gt(refused, kEveryAllocationSteps / 2); // some steps allocate nothing
    std::printf("every allocation fails, %s: %ld refused feeds in %d steps (at most %ld "
                "allocations a step), %ld of the failed allocations through malloc\n",
                mode == PIXELS ? "pixels only"
                : mode == DETECTIONS ? "detections only" : "detections + pixels",
                refused, kEveryAllocationSteps, most, failed_mallocs - mallocs_before);
#if INTERPOSE_MALLOC
    // Allocations through malloc itself were among those that failed: the
    // interposition reaches them.
    ck_assert_int_gt(failed_mallocs - mallocs_before, 0);
#endif
}

START_TEST(every_allocation_fails_detections_only)
{
    every_allocation_fails(DETECTIONS);
}
END_TEST

START_TEST(every_allocation_fails_detections_and_pixels)
{
    every_allocation_fails(DETECTIONS_AND_PIXELS);
}
END_TEST

START_TEST(every_allocation_fails_pixels_only)
{
    every_allocation_fails(PIXELS);
}
END_TEST

// In steady state, a feed makes no heap allocation at all.
START_TEST(steady_state_does_not_allocate)
{
    det_file df;
    load_detections("PETS09-S2L1", &df);
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    ct_tracker *t = nullptr;
    ck_assert_int_eq(ct_tracker_create(&cfg, &t), CT_OK);
    ct_track out[512];
    long in_last_half = 0;
    // Twice through the sequence: the second pass meets no bigger crowd than
    // the first, so every buffer already has its size.
    for (int pass = 0; pass < 2; pass++) {
        df.cursor = 0;
        for (int k = 1; k <= df.max_frame; k++) {
            ct_frame f;
            ct_frame_default(&f, sizeof f);
            f.timestamp_us = (int64_t)((pass * df.max_frame + k - 1) * 1e6 / 7);
            size_t n, count;
            const ct_detection *d = detfile_frame(&df, k, &n);
            // Counted around the calls alone: Check's assertions allocate.
            const long a0 = allocations;
            const int st = ct_tracker_feed(t, &f, d, n);
            const int sg = ct_tracker_get_tracks(t, out, 512, sizeof out[0], &count);
            if (pass == 1)
                in_last_half += allocations - a0;
            ck_assert_int_eq(st, CT_OK);
            ck_assert_int_eq(sg, CT_OK);
        }
    }
    ck_assert_int_eq(in_last_half, 0);
    ct_tracker_destroy(t);
    detfile_free(&df);
}
END_TEST

// With the pixels too (since 0.9.0): through TUD-Campus again and again,
// from the pixels alone and with detections, until two passes in a row make
// no allocation (at most 12). The tracks carry over from one pass to the
// next, so a pass may still meet a larger need than any before (more tracks,
// more pairs to assign, a larger scratch) and grow a buffer once; a tracker
// that allocated every frame would never have a pass without.
static void pixels_steady_state(int source)
{
    TudReplay replay(source);
    ct_tracker *t = replay.t;
    ct_track out[512];
    constexpr int kMaxPasses = 12;
    int clean = 0, pass = 0; // passes in a row without an allocation
    long in_pass = 0;
    for (; pass < kMaxPasses && clean < 2; pass++) {
        char err[512];
        video_close(replay.in);
        video_params ip = {0, 0, CT_FORMAT_I420};
        video_info info;
        ck_assert_msg(video_open(tud_video, &ip, &replay.in, &info, err, sizeof err) == 0, "%s",
                      err);
        replay.df.cursor = 0;
        in_pass = 0;
        for (int k = 1;; k++) {
            ct_frame f;
            const int r = video_read(replay.in, &f, err, sizeof err);
            ck_assert_msg(r >= 0, "%s", err);
            if (r == 0)
                break;
            f.timestamp_us = (int64_t)((pass * 100 + k - 1) * 1e6 / 25);
            size_t n = 0, count;
            const ct_detection *d = detfile_frame(&replay.df, k, &n);
            if (source == CT_SOURCE_PIXELS)
                d = nullptr, n = 0;
            const long a0 = allocations;
            const int st = ct_tracker_feed(t, &f, d, n);
            const int sg = ct_tracker_get_tracks(t, out, 512, sizeof out[0], &count);
            in_pass += allocations - a0;
            ck_assert_int_eq(st, CT_OK);
            ck_assert_int_eq(sg, CT_OK);
        }
        clean = in_pass == 0 ? clean + 1 : 0;
    }
    ck_assert_msg(clean == 2, "%d passes, the last with %ld allocations", pass, in_pass);
}

START_TEST(steady_state_with_pixels_does_not_allocate)
{
    pixels_steady_state(CT_SOURCE_PIXELS);
    pixels_steady_state(CT_SOURCE_DETECTIONS);
}
END_TEST

// FLANN's kd-tree (sets of more than NNIndex::kBruteForceMax points) with
// each allocation of its build failing in turn: std::bad_alloc and an
// empty index, never a node at address 0 (FLANN's pool takes its blocks
// from malloc unchecked; lib/appearance/nnindex.cc routes them through a check).
START_TEST(kd_tree_build_out_of_memory)
{
    const int n = 300, dim = 11;
    std::vector<float> p((size_t)n * dim);
    for (size_t i = 0; i < p.size(); i++)
        p[i] = (float)((i * 7919) % 1000);
    int failed = 0;
    for (long k = 0;; k++) {
        ctrack::NNIndex index;
        fail_countdown = k;
        bool ok = true;
        try {
            index.build(p.data(), n, dim);
        } catch (const std::bad_alloc &) {
            ok = false;
        }
        const bool reached = fail_countdown.load() < 0;
        fail_countdown = -1;
        if (ok) {
            ck_assert(!reached); // every allocation went through
            int found;
            float d2;
            index.search(p.data() + 5 * dim, 1, &found, &d2);
            ck_assert_int_eq(found, 5);
            break;
        }
        ck_assert(index.empty());
        failed++;
    }
    ck_assert_int_gt(failed, 3);
}
END_TEST

// The blob finder's cleaned mask when the frame's size changes and the new
// mask cannot be had: the next frame, back at the old size, starts from a
// clean mask (the old one's foreground must not linger in it).
START_TEST(mask_resize_out_of_memory)
{
    ctrack::BlobFinder blobs;
    std::vector<uint8_t> a(100 * 80, 0), b(200 * 160, 0), empty(100 * 80, 0);
    for (int y = 20; y < 60; y++)
        for (int x = 30; x < 50; x++)
            a[(size_t)y * 100 + x] = 255;
    blobs.clean(a.data(), 100, 80);
    ck_assert_int_gt(std::count(blobs.cleaned(), blobs.cleaned() + 100 * 80, 255), 0);
    fail_countdown = 0;
    bool threw = false;
    try {
        blobs.clean(b.data(), 200, 160);
    } catch (const std::bad_alloc &) {
        threw = true;
    }
    fail_countdown = -1;
    ck_assert(threw);
    blobs.clean(empty.data(), 100, 80);
    ck_assert_int_eq(blobs.width(), 100);
    ck_assert_int_eq(std::count(blobs.cleaned(), blobs.cleaned() + 100 * 80, 0), 100 * 80);
}
END_TEST

// An I420 frame of w x h, grey-green with a bright square at (x, 8).
static std::vector<uint8_t> square_frame(int w, int h, int x, ctrack::Planes *p)
{
    const int cw = (w + 1) / 2, ch = (h + 1) / 2;
    std::vector<uint8_t> f((size_t)w * h + 2 * (size_t)cw * ch, 100);
    for (int y = 8; y < std::min(h, 24); y++)
        for (int c = x; c < std::min(w, x + 12); c++)
            f[(size_t)y * w + c] = 220;
    p->width = w;
    p->height = h;
    p->y = f.data();
    p->u = f.data() + (size_t)w * h;
    p->v = p->u + (size_t)cw * ch;
    p->y_stride = w;
    p->u_stride = p->v_stride = cw;
    p->color = true;
    return f;
}

// bg.apply() with its first allocation refused: it throws, and the step is
// rolled back as the engine does.
static void apply_without_memory(ctrack::Background &bg, int64_t t_us, const ctrack::Planes &p,
                                 int scale, const ctrack::Rect *frozen, int n_frozen)
{
    fail_countdown = 0;
    bool threw = false;
    try {
        bg.apply(t_us, p, scale, frozen, n_frozen);
    } catch (const std::bad_alloc &) {
        threw = true;
    }
    fail_countdown = -1;
    ck_assert(threw);
    bg.rollback();
}

// Frame k (64 x 48) into a model that met a failed step and into a clean
// one (asked for scale 2): both at 32 x 24 working pixels, the same mask.
static void same_step(ctrack::Background &failed, ctrack::Background &clean, int k,
                      const ctrack::Planes &p, int scale, const ctrack::Rect *frozen,
                      int n_frozen)
{
    failed.apply(k * 40000, p, scale, frozen, n_frozen);
    clean.apply(k * 40000, p, ctrack::Background::kStartScale, frozen, n_frozen);
    failed.commit();
    clean.commit();
    ck_assert_int_eq(failed.width(), 32);
    ck_assert_msg(std::memcmp(failed.mask(), clean.mask(), 32 * 24) == 0,
                  "frame %d: the mask differs from the clean model's", k);
}

// A frame of another size restarts the background model; when the restart
// cannot have its memory, the step fails and is rolled back, and the
// frames of the old size that follow give the masks of a model that never
// saw that frame (the mask and the frozen row kept their old size).
START_TEST(background_restart_out_of_memory)
{
    ctrack::Background failed, clean;
    const ctrack::Rect frozen{2, 2, 8, 10};
    for (int k = 0; k < 12; k++) {
        ctrack::Planes p;
        const std::vector<uint8_t> f = square_frame(64, 48, 4 * k, &p);
        if (k == 6) {
            ctrack::Planes q;
            const std::vector<uint8_t> g = square_frame(128, 8, 0, &q);
            apply_without_memory(failed, k * 40000 - 20000, q, ctrack::Background::kStartScale,
                                 &frozen, 1);
        }
        same_step(failed, clean, k, p, ctrack::Background::kStartScale, &frozen, 1);
        ck_assert_int_eq(failed.height(), 24);
    }
}
END_TEST

// A finer working scale needs 4 times the model's memory; when it cannot
// have it, the step fails and is rolled back, and from then on the model
// stays at the scale it had (a fixed heap keeps tracking rather than fail
// every frame): its masks are those of a model never asked to change, and
// a reset keeps the bound.
START_TEST(background_finer_scale_out_of_memory)
{
    ctrack::Background failed, clean;
    for (int k = 0; k < 12; k++) {
        ctrack::Planes p;
        const std::vector<uint8_t> f = square_frame(64, 48, 4 * k, &p);
        if (k == 6) {
            apply_without_memory(failed, k * 40000 - 20000, p, 1, nullptr, 0);
            ck_assert_int_eq(failed.finest_scale(), 2);
        }
        same_step(failed, clean, k, p, k >= 6 ? 1 : 2, nullptr, 0);
        ck_assert_int_eq(failed.scale(), 2);
    }
    failed.reset();
    ck_assert_int_eq(failed.finest_scale(), 2);
    // Coarser still goes.
    ctrack::Planes p;
    const std::vector<uint8_t> f = square_frame(64, 48, 0, &p);
    failed.apply(12 * 40000, p, 2, nullptr, 0);
    failed.apply(13 * 40000, p, 4, nullptr, 0);
    ck_assert_int_eq(failed.scale(), 4);
}
END_TEST

int main(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: check_oom DATA_DIR TUD_CAMPUS.y4m\n");
        return 2;
    }
    data_dir = argv[1];
    tud_video = argv[2];
    Suite *s = suite_create("oom");
    TCase *tc = tcase_create("oom");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, create_out_of_memory);
    tcase_add_test(tc, feed_out_of_memory_changes_nothing);
    tcase_add_test(tc, pixels_only_out_of_memory_changes_nothing);
    tcase_add_test(tc, bgr24_out_of_memory_changes_nothing);
    tcase_add_test(tc, detections_and_pixels_out_of_memory_changes_nothing);
    tcase_add_test(tc, steady_state_does_not_allocate);
    tcase_add_test(tc, steady_state_with_pixels_does_not_allocate);
    tcase_add_test(tc, kd_tree_build_out_of_memory);
    tcase_add_test(tc, mask_resize_out_of_memory);
    tcase_add_test(tc, background_restart_out_of_memory);
    tcase_add_test(tc, background_finer_scale_out_of_memory);
    tcase_add_test(tc, every_allocation_fails_detections_only);
    tcase_add_test(tc, every_allocation_fails_detections_and_pixels);
    tcase_add_test(tc, every_allocation_fails_pixels_only);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
