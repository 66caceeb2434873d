// The CPU dispatch (internal API): every build of each pixel kernel that
// this CPU can run gives the portable build's output, bit for bit; the mask
// forces the portable path.
#include <check.h>

#include "common.h"

#include <cstdint>
#include <algorithm>
#include <cstring>
#include <vector>

#include "api/convert.h"
#include "dsp/cpu.h"
#include "dsp/dsp.h"

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
Vec<unsigned> runnable()
{
    set_cpu_mask(~0u);
    const unsigned all = cpu_flags();
    Vec<unsigned> out = {0};
    for (unsigned f : {(unsigned)kCpuSSSE3, kCpuSSSE3 | kCpuAVX2, (unsigned)kCpuNEON})
        if ((all & f) == f)
            out.push_back(f);
    return out;
}

// Calls f(portable, build, flags) for each build this CPU runs (the
// portable one first, against itself).
template <typename F> void against_portable(F &&f)
{
    Dsp ref;
    dsp_init(&ref, 0);
    for (unsigned flags : runnable()) {
        Dsp d;
        dsp_init(&d, flags);
        f(ref, d, flags);
    }
}

} // namespace

START_TEST(rows_match_the_portable_build)
{
    against_portable([](const Dsp &ref, const Dsp &d, unsigned flags) {
        for (int w : {1, 2, 7, 15, 16, 17, 31, 32, 33, 63, 640, 1921}) {
            Vec<uint8_t> src(3 * (size_t)w);
            for (uint8_t &b : src)
                b = next_byte();
            // The extremes too: all black, all white.
            if (w == 15)
                std::memset(src.data(), 0, src.size());
            if (w == 17)
                std::memset(src.data(), 255, src.size());
            for (int rgb = 0; rgb < 2; rgb++) {
                auto fa = rgb ? ref.rgb_row : ref.bgr_row, fb = rgb ? d.rgb_row : d.bgr_row;
                Vec<uint8_t> ya(w), yb(w);
                Vec<int16_t> ua(w), ub(w), va(w), vb(w);
                fa(src.data(), w, ya.data(), ua.data(), va.data());
                fb(src.data(), w, yb.data(), ub.data(), vb.data());
                ck_assert_msg(ya == yb && ua == ub && va == vb,
                              "flags 0x%x, width %d, %s: differs from the portable build",
                              flags, w, rgb ? "RGB" : "BGR");
            }
        }
    });
}
END_TEST

// The background model's row update and gathering: random rows of every
// width up to 70 (each vector build's tail), colour and grey, warming up or
// not, frozen pixels, every byte value in every input, rates over their
// range and beyond it; then values near the decisions' edges (model and
// image a few levels apart).
START_TEST(background_rows_match_the_portable_build)
{
    against_portable([](const Dsp &ref, const Dsp &d, unsigned flags) {
        for (int trial = 0; trial < 400; trial++) {
            const int w = 1 + trial % 70;
            const bool near = trial % 3 == 0;
            Vec<uint8_t> in[8];
            for (auto &v : in) {
                v.resize(w);
                for (uint8_t &b : v)
                    b = next_byte();
            }
            if (near) // image within a few levels of the model
                for (int x = 0; x < w; x++) {
                    in[0][x] = (uint8_t)std::min(255, in[3][x] + next_byte() % 9);
                    in[1][x] = (uint8_t)std::min(255, in[5][x] + next_byte() % 5);
                }
            for (int x = 0; x < w; x++)
                in[7][x] = next_byte() % 4 == 0; // frozen
            BgRow r;
            r.iy = in[0].data();
            r.iu = in[1].data();
            r.iv = in[2].data();
            r.om = in[3].data();
            r.ov = in[4].data();
            r.ou = in[5].data();
            r.ow = in[6].data();
            r.frozen = in[7].data();
            r.w = w;
            r.color = trial % 2 == 0;
            r.warm = trial % 5 == 0;
            // Usual rates, and in two trials of seven the extremes: a start's
            // step up to 255, levels past 255 (a very noisy sensor's).
            const bool wide = trial % 7 < 2;
            r.step = r.warm ? 1 + next_byte() % (wide ? 255 : 16) : 1;
            r.vmin = wide ? next_byte() + next_byte() / 4 : 25 + next_byte() % 30;
            r.chroma_fg = wide ? next_byte() + next_byte() / 4 : 24 + next_byte() % 20;
            r.shadow_chroma = wide ? next_byte() + next_byte() / 4 : 8 + next_byte() % 10;
            // The black level: none, a scene's (up to 60), or anywhere in
            // the byte range and past it.
            r.black = wide ? next_byte() + next_byte() / 4 : trial % 3 == 0 ? 0 : next_byte() % 61;
            // The model, the mask, and (every other trial) the noise's
            // differences.
            Vec<uint8_t> out_a[7], out_b[7];
            BgRow a = r, b = r;
            for (int k = 0; k < 7; k++) {
                out_a[k].assign(w, 7);
                out_b[k].assign(w, 7);
            }
            const bool noise = trial % 2 == 1;
            a.my = out_a[0].data(), a.vy = out_a[1].data(), a.mu = out_a[2].data();
            a.mv = out_a[3].data(), a.mask = out_a[4].data();
            a.noise_y = noise ? out_a[5].data() : nullptr, a.noise_c = out_a[6].data();
            b.my = out_b[0].data(), b.vy = out_b[1].data(), b.mu = out_b[2].data();
            b.mv = out_b[3].data(), b.mask = out_b[4].data();
            b.noise_y = noise ? out_b[5].data() : nullptr, b.noise_c = out_b[6].data();
            ref.bg_update_row(a);
            d.bg_update_row(b);
            for (int k = 0; k < 7; k++)
                ck_assert_msg(out_a[k] == out_b[k],
                              "flags 0x%x, width %d, trial %d, output %d: differs from the "
                              "portable build", flags, w, trial, k);

            // Gathering at each working scale: luma every scale-th pixel,
            // with and without the exposure table; NV12's interleaved
            // chroma, one sample for two working pixels at scale 1. Each
            // build gives what the definition says.
            static const int kScales[] = {1, 2, 4};
            const int sc = kScales[trial % 3];
            const int c_step = sc == 1 ? 2 : sc; // NV12's bytes between samples used
            Vec<uint8_t> src(sc * (size_t)w + 1), lut(256), uv(c_step * (size_t)w + 2);
            for (uint8_t &v : src)
                v = next_byte();
            for (uint8_t &v : uv)
                v = next_byte();
            for (int i = 0; i < 256; i++)
                lut[i] = (uint8_t)(255 - i / 2);
            Vec<uint8_t> ga[3], gb[3];
            for (int k = 0; k < 3; k++) {
                ga[k].assign(w, 1);
                gb[k].assign(w, 1);
            }
            BgGather g;
            g.src_y = src.data();
            g.lut = trial % 2 ? lut.data() : nullptr;
            g.su = trial % 5 ? uv.data() : nullptr;
            g.sv = uv.data() + 1;
            g.c_step = c_step;
            g.c_half = sc == 1;
            g.scale = sc;
            g.w = w;
            BgGather ha = g, hb = g;
            ha.iy = ga[0].data(), ha.iu = ga[1].data(), ha.iv = ga[2].data();
            hb.iy = gb[0].data(), hb.iu = gb[1].data(), hb.iv = gb[2].data();
            ref.bg_gather_row(ha);
            d.bg_gather_row(hb);
            for (int k = 0; k < 3; k++)
                ck_assert_msg(ga[k] == gb[k], "flags 0x%x, width %d, scale %d: gathering differs",
                              flags, w, sc);
            for (int x = 0; x < w; x++) {
                const uint8_t l = src[(size_t)x * sc];
                ck_assert_int_eq(ga[0][x], g.lut ? lut[l] : l);
                if (g.su) {
                    const size_t c = (size_t)(sc == 1 ? x >> 1 : x) * c_step;
                    ck_assert_int_eq(ga[1][x], uv[c]);
                    ck_assert_int_eq(ga[2][x], uv[c + 1]);
                }
            }
        }
    });
}
END_TEST

// The closing's row kernels: every width up to 70 (each vector build's
// tail), one to five rows, max and min, random bytes and the mask's 0 and
// 255.
START_TEST(closing_rows_match_the_portable_build)
{
    against_portable([](const Dsp &ref, const Dsp &d, unsigned flags) {
        for (int trial = 0; trial < 700; trial++) {
            const int n = 1 + trial % 70, rows = 1 + trial % 5;
            const bool max = trial % 2 == 0, mask = trial % 3 == 0;
            const size_t stride = (size_t)n + trial % 7;
            Vec<uint8_t> src(stride * 5);
            for (uint8_t &b : src)
                b = mask ? (next_byte() % 2 ? 255 : 0) : next_byte();
            Vec<uint8_t> a(n, 7), b(n, 7);
            ref.close_row3(src.data(), a.data(), n, max);
            d.close_row3(src.data(), b.data(), n, max);
            ck_assert_msg(a == b, "flags 0x%x, width %d, %s: the row differs", flags, n,
                          max ? "max" : "min");
            ref.close_rows(src.data(), stride, rows, a.data(), n, max);
            d.close_rows(src.data(), stride, rows, b.data(), n, max);
            ck_assert_msg(a == b, "flags 0x%x, width %d, %d rows, %s: differs", flags, n, rows,
                          max ? "max" : "min");
        }
    });
}
END_TEST

// A whole odd-sized frame with padded rows through packed_to_i420.
START_TEST(frames_match_the_portable_build)
{
    const int w = 333, h = 101, stride = 3 * w + 17;
    Vec<uint8_t> px((size_t)stride * h);
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
    Vec<int16_t> buf_ref;
    const Planes a = packed_to_i420(f, ref, &buf_ref);
    const size_t bytes = (size_t)w * h + 2 * (size_t)((w + 1) / 2) * ((h + 1) / 2);
    for (unsigned flags : runnable()) {
        Dsp d;
        dsp_init(&d, flags);
        Vec<int16_t> buf;
        const Planes b = packed_to_i420(f, d, &buf);
        ck_assert_msg(std::memcmp(a.y, b.y, bytes) == 0, "flags 0x%x: planes differ", flags);
    }
}
END_TEST

// The nearest-neighbour search's distances (nnindex.cc): random points and
// queries, every dimension up to 20 (the groups of four and the rest),
// strides up to 128 floats (the most the index stores), values over a
// descriptor's range and tiny ones (rounding), to the bit.
START_TEST(nn_distances_match_the_portable_build)
{
    against_portable([](const Dsp &ref, const Dsp &d, unsigned flags) {
        for (int trial = 0; trial < 300; trial++) {
            const int dim = 1 + trial % 20, stride = 8 * (1 + trial % 16);
            const float scale = trial % 5 == 0 ? 1e-3f : 255.0f;
            Vec<float> pts((size_t)dim * stride), q(dim);
            for (float &v : pts)
                v = scale * next_byte() / 255.0f + next_byte() / 65536.0f;
            for (float &v : q)
                v = scale * next_byte() / 255.0f;
            // n points, the rest padding; some points repeated (ties).
            const int n = stride - next_byte() % 8;
            for (int i = n; i < stride; i++)
                for (int k = 0; k < dim; k++)
                    pts[(size_t)k * stride + i] = INFINITY;
            if (trial % 4 == 1)
                for (int k = 0; k < dim; k++)
                    pts[(size_t)k * stride + n - 1] = pts[(size_t)k * stride + n / 2];
            float da, db;
            const int ia = ref.nn_nearest(pts.data(), stride, dim, q.data(), &da);
            const int ib = d.nn_nearest(pts.data(), stride, dim, q.data(), &db);
            ck_assert_msg(ia == ib && std::memcmp(&da, &db, sizeof da) == 0,
                          "flags 0x%x, dim %d, stride %d: point %d at %.9g, the portable "
                          "build's %d at %.9g", flags, dim, stride, ib, (double)db, ia,
                          (double)da);
            // And the portable build is the scan for the first least.
            int want = 0;
            float wd = INFINITY;
            for (int i = 0; i < n; i++) {
                float s2 = 0;
                int k = 0;
                for (; k + 4 <= dim; k += 4) {
                    float g = 0;
                    for (int j = k; j < k + 4; j++) {
                        const float t = pts[(size_t)j * stride + i] - q[j];
                        g = j == k ? t * t : g + t * t;
                    }
                    s2 += g;
                }
                for (; k < dim; k++) {
                    const float t = pts[(size_t)k * stride + i] - q[k];
                    s2 += t * t;
                }
                if (s2 < wd) {
                    wd = s2;
                    want = i;
                }
            }
            ck_assert_int_eq(ia, want);
        }
    });
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
    tcase_add_test(tc, background_rows_match_the_portable_build);
    tcase_add_test(tc, closing_rows_match_the_portable_build);
    tcase_add_test(tc, nn_distances_match_the_portable_build);
    tcase_add_test(tc, mask_forces_the_portable_path);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
