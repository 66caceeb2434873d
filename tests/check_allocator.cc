// A host's allocator (ct_tracker_create_with_allocator): a counting one is
// given to a tracker, which runs over TUD-Campus in every mode beside a
// tracker of the default allocator. Every block the tracker allocates must
// come from the callbacks and go back to them by ct_tracker_destroy(), no
// allocation may reach operator new or malloc from inside its calls (both
// are replaced here and count what a call makes on this thread), the tracks
// must be the default tracker's, and a callback that returns NULL fails the
// call with CT_ERROR_OUT_OF_MEMORY and changes nothing.
#include <check.h>

#include "common.h"

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "ctrack/ctrack.h"
#include "detfile.h"
#include "video.h"

static const char *data_dir;
static const char *tud_video;

// Set around each call into the tracker under test: allocations made on
// this thread meanwhile, other than the callbacks' own, are strays.
static thread_local bool inside = false;
static thread_local bool in_callback = false;
static long strays = 0;

static void note_allocation()
{
    if (inside && !in_callback) {
        strays++;
        if (std::getenv("CT_ABORT_ON_STRAY"))
            std::abort();
    }
}

// The hook of alloc_hooks.h: every allocation goes through, counted.
static bool allocation_allowed(bool)
{
    note_allocation();
    return true;
}

#include "alloc_hooks.h"
#include "tracker_io.h"

namespace {

// The host's allocator: counts blocks and bytes, and can refuse.
struct Counting {
    long allocs = 0, frees = 0, refused = 0;
    long long live = 0, peak = 0;
    long fail_countdown = -1; // the allocation that fails (0: the next); -1 none
};

struct Header {
    size_t size;
    Counting *owner;
    alignas(std::max_align_t) unsigned char data[1];
};

// What the callbacks do is theirs, Check's bookkeeping included.
struct InCallback {
    InCallback() { in_callback = true; }
    ~InCallback() { in_callback = false; }
};

void *counting_alloc(void *opaque, size_t size)
{
    InCallback mark;
    Counting *c = static_cast<Counting *>(opaque);
    ck_assert_uint_gt(size, 0);
    if (c->fail_countdown >= 0 && c->fail_countdown-- == 0) {
        c->refused++;
        return nullptr;
    }
    Header *h = static_cast<Header *>(std::malloc(offsetof(Header, data) + size));
    ck_assert_ptr_nonnull(h);
    h->size = size;
    h->owner = c;
    c->allocs++;
    c->live += (long long)size;
    if (c->live > c->peak)
        c->peak = c->live;
    ck_assert_uint_eq((uintptr_t)h->data % alignof(std::max_align_t), 0);
    return h->data;
}

void counting_free(void *opaque, void *p)
{
    InCallback mark;
    Counting *c = static_cast<Counting *>(opaque);
    ck_assert_ptr_nonnull(p);
    Header *h = reinterpret_cast<Header *>(static_cast<unsigned char *>(p) -
                                           offsetof(Header, data));
    // Given back to the allocator that gave it.
    ck_assert_ptr_eq(h->owner, c);
    c->frees++;
    c->live -= (long long)h->size;
    std::free(h);
}

// Runs f with the stray count armed. A call in which the host refused a
// block throws std::bad_alloc inside, and the C++ runtime allocates the
// exception object with malloc: not counted.
template <typename F> auto watched(const Counting &host, F &&f)
{
    const long before = strays, refused = host.refused;
    inside = true;
    auto r = f();
    inside = false;
    if (host.refused != refused)
        strays = before;
    return r;
}

enum Mode { DETECTIONS, DETECTIONS_AND_PIXELS, PIXELS, PIXELS_BGR24, VERIFY };

// TUD-Campus in one mode: the tracker of the counting allocator against
// one of the default allocator. In the first 10 steps and every
// kFailEvery-th the callback first refuses one of the step's allocations.
void replay(Mode mode)
{
    constexpr int kFailEvery = 7;
    det_file df;
    char path[1024], err[512];
    std::snprintf(path, sizeof path, "%s/TUD-Campus/det/det.txt", data_dir);
    ck_assert_msg(detfile_load(path, &df, err, sizeof err) == 0, "%s", err);
    video_params ip = {0, 0, CT_FORMAT_I420};
    video_info info;
    video_input *in = nullptr;
    ck_assert_msg(video_open(tud_video, &ip, &in, &info, err, sizeof err) == 0, "%s", err);

    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    cfg.source = mode == PIXELS || mode == PIXELS_BGR24 ? CT_SOURCE_PIXELS : CT_SOURCE_DETECTIONS;
    cfg.verify_detections = mode == VERIFY;
    Counting host;
    ct_allocator a = {sizeof a, counting_alloc, counting_free, &host};
    ct_tracker *ref = nullptr, *t = nullptr;
    ck_assert_int_eq(ct_tracker_create(&cfg, &ref), CT_OK);
    strays = 0;
    ck_assert_int_eq(watched(host, [&] { return ct_tracker_create_with_allocator(&cfg, &a, &t); }),
                     CT_OK);
    ck_assert_int_gt(host.allocs, 0); // the tracker itself, at least

    std::vector<uint8_t> bgr;
    int frames = 0, refused = 0;
    for (int k = 1;; k++) {
        ct_frame f;
        const int r = video_read(in, &f, err, sizeof err);
        ck_assert_msg(r >= 0, "%s", err);
        if (r == 0)
            break;
        frames++;
        if (mode == PIXELS_BGR24)
            f = as_bgr24(f, &bgr);
        if (mode == DETECTIONS) {
            const ct_frame pixels = f;
            ct_frame_default(&f, sizeof f);
            f.width = pixels.width;
            f.height = pixels.height;
        }
        f.timestamp_us = (int64_t)((k - 1) * 1e6 / 25);
        size_t n = 0;
        const ct_detection *d = detfile_frame(&df, k, &n);
        if (cfg.source == CT_SOURCE_PIXELS)
            d = nullptr, n = 0;
        ck_assert_int_eq(ct_tracker_feed(ref, &f, d, n), CT_OK);
        if (k <= 10 || k % kFailEvery == 0) {
            const std::vector<ct_track> before = tracks_of(t);
            host.fail_countdown = k % 3;
            const int st = watched(host, [&] { return ct_tracker_feed(t, &f, d, n); });
            if (host.fail_countdown < 0) {
                ck_assert_int_eq(st, CT_ERROR_OUT_OF_MEMORY);
                assert_equal(tracks_of(t), before);
                refused++;
            } else {
                ck_assert_int_eq(st, CT_OK);
            }
            host.fail_countdown = -1;
            if (st == CT_OK) {
                assert_equal(tracks_of(t), tracks_of(ref));
                continue;
            }
        }
        ck_assert_int_eq(watched(host, [&] { return ct_tracker_feed(t, &f, d, n); }), CT_OK);
        assert_equal(tracks_of(t), tracks_of(ref));
    }
    ck_assert_int_gt(frames, 60);
    ck_assert_int_eq(watched(host, [&] { return ct_tracker_reset(t); }), CT_OK);
    ct_stats s;
    s.size = sizeof s;
    ck_assert_int_eq(ct_tracker_get_stats(t, &s), CT_OK);
    watched(host, [&] {
        ct_tracker_destroy(t);
        return 0;
    });
    ct_tracker_destroy(ref);
    std::printf("host allocator, mode %d: %ld blocks (peak %lld bytes live, the tracker says "
                "%llu now), %d feeds refused, %ld stray allocations\n",
                (int)mode, host.allocs, host.peak, (unsigned long long)s.memory_bytes, refused,
                strays);
    ck_assert_int_eq(strays, 0);
    ck_assert_int_eq(host.frees, host.allocs);
    ck_assert_int_eq(host.live, 0);
    ck_assert_int_gt(refused, 0);
    // With pixels the tracker's buffers come from the host too.
    if (mode != DETECTIONS)
        ck_assert_int_gt(host.peak, 100000);
    video_close(in);
    detfile_free(&df);
}

} // namespace

START_TEST(detections_only)
{
    replay(DETECTIONS);
}
END_TEST

START_TEST(detections_and_pixels)
{
    replay(DETECTIONS_AND_PIXELS);
}
END_TEST

START_TEST(pixels_only)
{
    replay(PIXELS);
}
END_TEST

START_TEST(pixels_only_bgr24)
{
    replay(PIXELS_BGR24);
}
END_TEST

START_TEST(verify_detections)
{
    replay(VERIFY);
}
END_TEST

// Creation: a refused first block fails it cleanly; a struct too small or
// a callback missing is refused; NULL is the default allocator.
START_TEST(create_checks_the_allocator)
{
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    Counting host;
    ct_allocator a = {sizeof a, counting_alloc, counting_free, &host};
    ct_tracker *t = reinterpret_cast<ct_tracker *>(&cfg);
    // Each of its allocations refused in turn, until it makes fewer.
    long k = 0;
    for (;; k++) {
        host.fail_countdown = k;
        const int st = ct_tracker_create_with_allocator(&cfg, &a, &t);
        if (st == CT_OK)
            break;
        ck_assert_int_eq(st, CT_ERROR_OUT_OF_MEMORY);
        ck_assert_ptr_null(t);
        ck_assert_int_eq(host.live, 0);
    }
    ck_assert_int_gt(k, 0);
    ck_assert_int_ge(host.fail_countdown, 0); // the refusal was never reached
    host.fail_countdown = -1;
    ct_tracker_destroy(t);
    ck_assert_int_eq(host.live, 0);
    ck_assert_int_eq(host.frees, host.allocs);
    host = Counting();
    ct_allocator bad = a;
    bad.size = sizeof(size_t);
    ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, &bad, &t), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_ptr_null(t);
    bad = a;
    bad.alloc = nullptr;
    ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, &bad, &t), CT_ERROR_INVALID_ARGUMENT);
    bad = a;
    bad.free = nullptr;
    ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, &bad, &t), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, &a, nullptr),
                     CT_ERROR_INVALID_ARGUMENT);
    cfg.min_hits = 0; // a bad config, checked as by ct_tracker_create()
    ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, &a, &t), CT_ERROR_INVALID_ARGUMENT);
    ck_assert_int_eq(host.allocs, 0);
    ct_config_default(&cfg, sizeof cfg);
    ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, nullptr, &t), CT_OK);
    ck_assert_ptr_nonnull(t);
    ct_tracker_destroy(t);
    ck_assert_int_eq(host.allocs, 0);
}
END_TEST

// ct_tracker_prime() on TUD-Campus's first 20 frames, with a host's
// allocator: its blocks come from the callbacks and nothing strays; a
// refused block fails it with CT_ERROR_OUT_OF_MEMORY and leaves the tracker
// as after ct_tracker_reset() (it then tracks the frames as a tracker never
// primed does), each of its allocations refused in turn until it makes
// fewer; then it goes through and tracks them as a primed tracker of the
// default allocator does.
START_TEST(prime_with_the_host_allocator)
{
    constexpr int kFrames = 20;
    char err[512];
    video_params ip = {0, 0, CT_FORMAT_I420};
    video_info info;
    video_input *in = nullptr;
    ck_assert_msg(video_open(tud_video, &ip, &in, &info, err, sizeof err) == 0, "%s", err);
    ck_assert_int_eq(video_keep(in, kFrames, err, sizeof err), 0);
    ct_frame frames[kFrames];
    const ct_frame *pf[kFrames];
    for (int k = 0; k < kFrames; k++) {
        pf[k] = &frames[k];
        ck_assert_int_eq(video_read(in, &frames[k], err, sizeof err), 1);
        ck_assert_int_eq(video_kept(in, k, &frames[k]), 1);
        frames[k].timestamp_us = k * 40000;
    }
    ct_config cfg;
    ct_config_default(&cfg, sizeof cfg);
    cfg.source = CT_SOURCE_PIXELS;
    // What the default allocator's trackers give, primed and live.
    auto run = [&](ct_tracker *t, const Counting *host) {
        std::vector<std::vector<ct_track>> out;
        for (int k = 0; k < kFrames; k++) {
            const int st = host ? watched(*host, [&] { return ct_tracker_feed(t, &frames[k], nullptr, 0); })
                                : ct_tracker_feed(t, &frames[k], nullptr, 0);
            ck_assert_int_eq(st, CT_OK);
            out.push_back(tracks_of(t));
        }
        return out;
    };
    auto same = [](const std::vector<std::vector<ct_track>> &a,
                   const std::vector<std::vector<ct_track>> &b) {
        ck_assert_uint_eq(a.size(), b.size());
        for (size_t k = 0; k < a.size(); k++)
            assert_equal(a[k], b[k]);
    };
    ct_tracker *ref = nullptr;
    ck_assert_int_eq(ct_tracker_create(&cfg, &ref), CT_OK);
    const auto live = run(ref, nullptr);
    ct_tracker_destroy(ref);
    ck_assert_int_eq(ct_tracker_create(&cfg, &ref), CT_OK);
    ck_assert_int_eq(ct_tracker_prime(ref, pf, kFrames), CT_OK);
    const auto primed = run(ref, nullptr);
    ct_tracker_destroy(ref);
    // The priming is seen: the primed tracker's tracks are not the live
    // one's (else the comparisons below would pass on a priming that did
    // nothing).
    bool differ = false;
    for (int k = 0; k < kFrames && !differ; k++) {
        differ = primed[k].size() != live[k].size();
        for (size_t i = 0; i < live[k].size() && !differ; i++) {
            const ct_track &p = primed[k][i], &l = live[k][i];
            differ = p.id != l.id || p.left != l.left || p.top != l.top ||
                     p.width != l.width || p.height != l.height;
        }
    }
    ck_assert_msg(differ, "the primed tracker tracks as the live one does");

    Counting host;
    ct_allocator a = {sizeof a, counting_alloc, counting_free, &host};
    strays = 0;
    long k = 0;
    for (;; k = k < 8 ? k + 1 : k * 3 / 2) {
        ct_tracker *t = nullptr;
        ck_assert_int_eq(ct_tracker_create_with_allocator(&cfg, &a, &t), CT_OK);
        host.fail_countdown = k;
        const int st = watched(host, [&] { return ct_tracker_prime(t, pf, kFrames); });
        const bool refused = host.fail_countdown < 0;
        host.fail_countdown = -1;
        if (!refused) {
            ck_assert_int_eq(st, CT_OK);
            same(run(t, &host), primed);
            watched(host, [&] { ct_tracker_destroy(t); return 0; });
            break;
        }
        ck_assert_int_eq(st, CT_ERROR_OUT_OF_MEMORY);
        ck_assert_str_eq(ct_tracker_last_error(t), "out of memory");
        same(run(t, &host), live);
        watched(host, [&] { ct_tracker_destroy(t); return 0; });
    }
    ck_assert_int_gt(k, 8);
    ck_assert_int_eq(strays, 0);
    ck_assert_int_eq(host.frees, host.allocs);
    ck_assert_int_eq(host.live, 0);
    video_close(in);
}
END_TEST

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: check_allocator MOT15_DIR TUD_CAMPUS_Y4M\n");
        return 2;
    }
    data_dir = argv[1];
    tud_video = argv[2];
    Suite *s = suite_create("allocator");
    TCase *tc = tcase_create("allocator");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, create_checks_the_allocator);
    tcase_add_test(tc, detections_only);
    tcase_add_test(tc, detections_and_pixels);
    tcase_add_test(tc, pixels_only);
    tcase_add_test(tc, pixels_only_bgr24);
    tcase_add_test(tc, verify_detections);
    tcase_add_test(tc, prime_with_the_host_allocator);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
