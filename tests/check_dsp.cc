// The CPU dispatch (internal API): every build of each pixel kernel that
// this CPU can run gives the portable build's output, bit for bit; the mask
// forces the portable path.
#include <check.h>

#include "common.h"

#include <cstdint>
#include <cstring>
#include <vector>

#include "convert.h"
#include "cpu.h"
#include "dsp.h"

using namespace ctrack;

namespace {

uint64_t rng = 0x2545F4914F6CDD1Dull;
uint8_t next_byte()
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint8_t)(rng >> 32);
}

// The flag sets this CPU can run, the portable one (0) first.
std::vector<unsigned> runnable()
{
    set_cpu_mask(~0u);
    const unsigned all = cpu_flags();
    std::vector<unsigned> out = {0};
    for (unsigned f : {(unsigned)kCpuSSSE3, kCpuSSSE3 | kCpuAVX2, (unsigned)kCpuNEON})
        if ((all & f) == f)
            out.push_back(f);
    return out;
}

} // namespace

START_TEST(rows_match_the_portable_build)
{
    Dsp ref;
    dsp_init(&ref, 0);
    for (unsigned flags : runnable()) {
        Dsp d;
        dsp_init(&d, flags);
        for (int w : {1, 2, 7, 15, 16, 17, 31, 32, 33, 63, 640, 1921}) {
            std::vector<uint8_t> src(3 * (size_t)w);
            for (uint8_t &b : src)
                b = next_byte();
            // The extremes too: all black, all white.
            if (w == 15)
                std::memset(src.data(), 0, src.size());
            if (w == 17)
                std::memset(src.data(), 255, src.size());
            for (int rgb = 0; rgb < 2; rgb++) {
                auto fa = rgb ? ref.rgb_row : ref.bgr_row, fb = rgb ? d.rgb_row : d.bgr_row;
                std::vector<uint8_t> ya(w), yb(w);
                std::vector<int16_t> ua(w), ub(w), va(w), vb(w);
                fa(src.data(), w, ya.data(), ua.data(), va.data());
                fb(src.data(), w, yb.data(), ub.data(), vb.data());
                ck_assert_msg(ya == yb && ua == ub && va == vb,
                              "flags 0x%x, width %d, %s: differs from the portable build",
                              flags, w, rgb ? "RGB" : "BGR");
            }
        }
    }
}
END_TEST

// A whole odd-sized frame with padded rows through packed_to_i420.
START_TEST(frames_match_the_portable_build)
{
    const int w = 333, h = 101, stride = 3 * w + 17;
    std::vector<uint8_t> px((size_t)stride * h);
    for (uint8_t &b : px)
        b = next_byte();
    ct_frame f;
    ct_frame_default(&f, sizeof f);
    f.format = CT_FORMAT_BGR24;
    f.width = w;
    f.height = h;
    f.planes[0] = px.data();
    f.strides[0] = stride;
    Dsp ref;
    dsp_init(&ref, 0);
    std::vector<int16_t> buf_ref;
    const Planes a = packed_to_i420(f, ref, &buf_ref);
    const size_t bytes = (size_t)w * h + 2 * (size_t)((w + 1) / 2) * ((h + 1) / 2);
    for (unsigned flags : runnable()) {
        Dsp d;
        dsp_init(&d, flags);
        std::vector<int16_t> buf;
        const Planes b = packed_to_i420(f, d, &buf);
        ck_assert_msg(std::memcmp(a.y, b.y, bytes) == 0, "flags 0x%x: planes differ", flags);
    }
}
END_TEST

// The mask takes features away, and back.
START_TEST(mask_forces_the_portable_path)
{
    set_cpu_mask(~0u);
    const unsigned all = cpu_flags();
    set_cpu_mask(0);
    ck_assert_uint_eq(cpu_flags(), 0);
    set_cpu_mask(kCpuSSSE3);
    ck_assert_uint_eq(cpu_flags(), all & kCpuSSSE3);
    set_cpu_mask(~0u);
    ck_assert_uint_eq(cpu_flags(), all);
#if defined(__x86_64__)
    // Every x86-64 machine this runs on has SSSE3 (since 2006).
    ck_assert_uint_ne(all & kCpuSSSE3, 0);
#endif
}
END_TEST

int main()
{
    Suite *s = suite_create("dsp");
    TCase *tc = tcase_create("dsp");
    tcase_add_test(tc, rows_match_the_portable_build);
    tcase_add_test(tc, frames_match_the_portable_build);
    tcase_add_test(tc, mask_forces_the_portable_path);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
