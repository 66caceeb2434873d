// What the C++ suites read from a tracker, and a frame repacked for it:
// shared by check_oom.cc and check_allocator.cc.
#ifndef CTRACK_TESTS_TRACKER_IO_H
#define CTRACK_TESTS_TRACKER_IO_H

#include <check.h>

#include <cstring>
#include <vector>

#include "ctrack/ctrack.h"
#include "video.h"

static inline std::vector<ct_track> tracks_of(ct_tracker *t)
{
    std::vector<ct_track> out(512);
    size_t count = 0;
    ck_assert_int_eq(ct_tracker_get_tracks(t, out.data(), out.size(), sizeof(ct_track), &count),
                     CT_OK);
    out.resize(count);
    return out;
}

static inline std::vector<ct_candidate> candidates_of(ct_tracker *t)
{
    std::vector<ct_candidate> out(512);
    size_t count = 0;
    ck_assert_int_eq(ct_tracker_get_candidates(t, out.data(), out.size(), sizeof(ct_candidate),
                                               &count),
                     CT_OK);
    out.resize(count);
    return out;
}

// The two lists are the same, byte for byte.
template <typename T> static void assert_equal(const std::vector<T> &a, const std::vector<T> &b)
{
    ck_assert_uint_eq(a.size(), b.size());
    if (!a.empty())
        ck_assert_int_eq(std::memcmp(a.data(), b.data(), a.size() * sizeof(T)), 0);
}

// The frame's pixels as packed BGR24 in bgr, for the library's own
// conversion.
static inline ct_frame as_bgr24(const ct_frame &f, std::vector<uint8_t> *bgr)
{
    bgr->resize((size_t)3 * f.width * f.height);
    i420_to_bgr24(&f, bgr->data());
    ct_frame out = f;
    out.format = CT_FORMAT_BGR24;
    out.planes[0] = bgr->data();
    out.planes[1] = out.planes[2] = nullptr;
    out.strides[0] = 3 * f.width;
    out.strides[1] = out.strides[2] = 0;
    return out;
}

#endif
