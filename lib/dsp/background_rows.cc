// The background model's row kernels (Dsp::bg_update_row, bg_gather_row):
// Sigma-Delta's update and foreground test of one row of working pixels,
// and the gathering of a row's samples, built for the portable path (the
// reference), for 16-byte vectors (SSE2, NEON) and for AVX2.
#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "dsp/cpu.h"
#include "dsp/dsp.h"

#if defined(__GNUC__)
// The 32-byte vectors of the AVX2 build live only inside its inlined loop:
// no call passes one, whatever -Wpsabi fears.
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace ctrack {

namespace {

// The model's update and test of one pixel, in ints: the reference, which
// the vector builds (luma_bytes() and colour_bytes() below) match bit for
// bit. A mask is non-zero where true.
template <typename T> CT_ALWAYS_INLINE T splat(int v) { return T{} + (int16_t)v; }
template <typename T> CT_ALWAYS_INLINE T vmin(T a, T b) { return a < b ? a : b; }
template <typename T> CT_ALWAYS_INLINE T vmax(T a, T b) { return a > b ? a : b; }
template <typename T> CT_ALWAYS_INLINE T vabs(T a) { return a < splat<T>(0) ? -a : a; }
template <typename T> CT_ALWAYS_INLINE T step_toward(T m, T target, int step)
{
    return m + vmin(vmax(target - m, splat<T>(-step)), splat<T>(step));
}

struct Rates {
    int step; // levels a frame, for M, the chroma and V alike
    bool warm;
    // This frame's decision levels: V's floor, and the chroma differences
    // over which a pixel is foreground and under which a shadow keeps its
    // colour.
    int vmin, chroma_fg, shadow_chroma;
    int black; // the scene's black level: shadows are ratios above it
};

// Luma: M and V learn where `live` (the pixel is not frozen); returns the
// foreground mask.
template <typename T> CT_ALWAYS_INLINE T luma(T I, T &M, T &V, T live, const Rates &r)
{
    const T Mn = live ? step_toward(M, I, r.step) : M;
    const T D = vabs(I - Mn);
    const T learn = live & ((D != splat<T>(0)) | splat<T>(r.warm ? -1 : 0));
    const T Vt = V + (splat<T>(kSigmaDeltaN) * D > V ? splat<T>(r.step) : splat<T>(-r.step));
    V = learn ? vmin(splat<T>(kBgVMax), vmax(splat<T>(r.vmin), Vt)) : V;
    M = Mn;
    return D > V;
}

// Luma and chroma: shadows (darker, same colour) are background, another
// colour at the same brightness is foreground.
template <typename T>
CT_ALWAYS_INLINE T colour(T I, T U, T W, T &M, T &V, T &BU, T &BV, T live, const Rates &r)
{
    const T dc = vmax(vabs(U - BU), vabs(W - BV));
    BU = live ? step_toward(BU, U, r.step) : BU;
    BV = live ? step_toward(BV, W, r.step) : BV;
    const T fg = luma(I, M, V, live, r);
    const T Ib = vmax(I - splat<T>(r.black), splat<T>(0));
    const T Mb = vmax(M - splat<T>(r.black), splat<T>(0));
    const T shadow = fg & (I < M) & (splat<T>(16) * Ib >= splat<T>(kBgShadowLow) * Mb) &
                     (splat<T>(16) * Ib <= splat<T>(kBgShadowHigh) * Mb) &
                     (dc <= splat<T>(r.shadow_chroma));
    return shadow ? splat<T>(0) : fg | (dc > splat<T>(r.chroma_fg));
}

#if defined(__GNUC__)
// The vector builds work on N pixels at once in byte lanes (GCC and Clang
// vector extensions: SSE2 or NEON for 16, AVX2 for 32), with the same
// decisions as luma() and colour() rewritten so that no value leaves
// [0, 255]: additions and subtractions saturate where the exact result
// would be clamped anyway, and the products compare as quotients
// (tests/check_dsp.cc checks them against the portable build over the
// whole byte range of every input, and rates up to 255).
template <int N> struct Bytes {
    typedef uint8_t T __attribute__((vector_size(N)));
};
template <typename B> CT_ALWAYS_INLINE B bsplat(int v) { return B{} + (uint8_t)v; }
template <typename B> CT_ALWAYS_INLINE B umin(B a, B b) { return a < b ? a : b; }
template <typename B> CT_ALWAYS_INLINE B umax(B a, B b) { return a > b ? a : b; }
template <typename B> CT_ALWAYS_INLINE B absdiff(B a, B b) { return umax(a, b) - umin(a, b); }
// a + b and a - b saturated to [0, 255].
template <typename B> CT_ALWAYS_INLINE B adds(B a, B b) { return a + umin(b, ~a); }
template <typename B> CT_ALWAYS_INLINE B subs(B a, B b) { return a - umin(b, a); }
// step_toward(): M + clamp(target - M, -step, step).
template <typename B> CT_ALWAYS_INLINE B toward(B m, B target, B step)
{
    return target > m ? umin(target, adds(m, step)) : umax(target, subs(m, step));
}

// The rates as byte lanes; the levels are clamped to [0, 255], which
// changes no decision (the differences they are compared with lie there;
// V's floor is at least 0, as BgRow says).
template <typename B> struct ByteRates {
    B step, vmin, chroma_fg, shadow_chroma, warm, black;
    explicit ByteRates(const Rates &r)
        : step(bsplat<B>(r.step)), vmin(bsplat<B>(std::min(r.vmin, 255))),
          chroma_fg(bsplat<B>(std::min(r.chroma_fg, 255))),
          shadow_chroma(bsplat<B>(std::min(r.shadow_chroma, 255))),
          warm(bsplat<B>(r.warm ? 255 : 0)), black(bsplat<B>(std::min(r.black, 255)))
    {
    }
};

// luma(): N |I - M| > V is |I - M| > V / N (kSigmaDeltaN = 4: V >> 2,
// exact for integers); V +- step, then clamped to [vmin, kBgVMax],
// saturates first.
template <typename B> CT_ALWAYS_INLINE B luma_bytes(B I, B &M, B &V, B live, const ByteRates<B> &r)
{
    static_assert(kSigmaDeltaN == 4, "V / kSigmaDeltaN is V >> 2");
    const B Mn = live ? toward(M, I, r.step) : M;
    const B D = absdiff(I, Mn);
    const B learn = live & ((B)(D != bsplat<B>(0)) | r.warm);
    const B Vt = D > (V >> 2) ? adds(V, r.step) : subs(V, r.step);
    V = learn ? umin(bsplat<B>(kBgVMax), umax(r.vmin, Vt)) : V;
    M = Mn;
    return (B)(D > V);
}

// colour(): with I and M above the black level (saturated at 0), 16 I >=
// kBgShadowLow M is I >= ceil(M / 2), and 16 I <= kBgShadowHigh M is I <=
// M - ceil(M / 16).
// dc is the chroma's difference from the model before the update:
// max(|U - BU|, |W - BV|).
template <typename B>
CT_ALWAYS_INLINE B colour_bytes(B I, B U, B W, B dc, B &M, B &V, B &BU, B &BV, B live,
                                const ByteRates<B> &r)
{
    static_assert(kBgShadowLow == 8 && kBgShadowHigh == 15, "the shadow's bounds as shifts");
    BU = live ? toward(BU, U, r.step) : BU;
    BV = live ? toward(BV, W, r.step) : BV;
    const B fg = luma_bytes(I, M, V, live, r);
    const B Ib = subs(I, r.black), Mb = subs(M, r.black);
    const B half = Mb - (Mb >> 1);
    const B sixteenth = (Mb >> 4) - (B)((Mb & bsplat<B>(15)) != bsplat<B>(0));
    const B shadow = fg & (B)(I < M) & (B)(Ib >= half) & (B)(Ib <= Mb - sixteenth) &
                     (B)(dc <= r.shadow_chroma);
    return shadow ? bsplat<B>(0) : fg | (B)(dc > r.chroma_fg);
}

template <typename B> CT_ALWAYS_INLINE B load_bytes(const uint8_t *p)
{
    B b;
    std::memcpy(&b, p, sizeof b);
    return b;
}
template <typename B> CT_ALWAYS_INLINE void store_bytes(uint8_t *p, B b)
{
    std::memcpy(p, &b, sizeof b);
}
#endif

// One row of the model's update (BgRow): written once, built for the
// portable path (N = 0: one pixel at a time, the reference) and for vectors
// of N byte lanes, which dsp_init() picks by the CPU (tests/check_dsp.cc
// checks every build against the portable one, bit for bit).
template <int N> CT_ALWAYS_INLINE void update_row(const BgRow &a)
{
    const Rates r{a.step, a.warm, a.vmin, a.chroma_fg, a.shadow_chroma, a.black};
    const uint8_t *__restrict iy = a.iy, *__restrict iu = a.iu, *__restrict iv = a.iv;
    const uint8_t *__restrict om = a.om, *__restrict ov = a.ov;
    const uint8_t *__restrict ou = a.ou, *__restrict ow = a.ow;
    const uint8_t *__restrict frozen = a.frozen;
    uint8_t *__restrict my = a.my, *__restrict vy = a.vy, *__restrict mu = a.mu;
    uint8_t *__restrict mv = a.mv, *__restrict mask = a.mask;
    uint8_t *__restrict noise_y = a.noise_y, *__restrict noise_c = a.noise_c;
    const int w = a.w;
    int x = 0;
#if defined(__GNUC__)
    if (N > 0) {
        constexpr int L = N > 0 ? N : 16;
        typedef typename Bytes<L>::T B;
        const ByteRates<B> br(r);
        for (; x + L <= w; x += L) {
            B M = load_bytes<B>(om + x), V = load_bytes<B>(ov + x);
            const B I = load_bytes<B>(iy + x);
            const B live = (B)(load_bytes<B>(frozen + x) == bsplat<B>(0));
            if (noise_y)
                store_bytes(noise_y + x, absdiff(I, M));
            B fg;
            if (a.color) {
                B BU = load_bytes<B>(ou + x), BV = load_bytes<B>(ow + x);
                const B U = load_bytes<B>(iu + x), W = load_bytes<B>(iv + x);
                const B dc = umax(absdiff(U, BU), absdiff(W, BV));
                if (noise_y)
                    store_bytes(noise_c + x, dc);
                fg = colour_bytes(I, U, W, dc, M, V, BU, BV, live, br);
                store_bytes(mu + x, BU);
                store_bytes(mv + x, BV);
            } else {
                fg = luma_bytes(I, M, V, live, br);
            }
            store_bytes(my + x, M);
            store_bytes(vy + x, V);
            store_bytes(mask + x, fg);
        }
    }
#endif
    for (; x < w; x++) {
        int M = om[x], V = ov[x];
        const int live = !frozen[x];
        if (noise_y) {
            noise_y[x] = (uint8_t)std::abs(iy[x] - M);
            if (a.color)
                noise_c[x] = (uint8_t)std::max(std::abs(iu[x] - ou[x]), std::abs(iv[x] - ow[x]));
        }
        int fg;
        if (a.color) {
            int BU = ou[x], BV = ow[x];
            fg = colour<int>(iy[x], iu[x], iv[x], M, V, BU, BV, live, r);
            mu[x] = (uint8_t)BU;
            mv[x] = (uint8_t)BV;
        } else {
            fg = luma<int>(iy[x], M, V, live, r);
        }
        my[x] = (uint8_t)M;
        vy[x] = (uint8_t)V;
        mask[x] = fg ? 255 : 0;
    }
}

// The frame's samples at the working pixels: every scale-th luma (or the
// mean of the 2 x 2 pixels there, with src_y2) through the exposure table
// (or as they are, lut null), and the chroma samples
// when they are not read in place (NV12's interleaved ones, and every
// scale but 2). Scale 2, the usual one, has its own loops: a constant
// stride vectorises.
template <int S> CT_ALWAYS_INLINE void gather_luma(const BgGather &g, int s)
{
    const uint8_t *__restrict src = g.src_y;
    uint8_t *__restrict iy = g.iy;
    const int w = g.w, step = S ? S : s;
    if (g.src_y2) {
        const uint8_t *__restrict below = g.src_y2;
        const int pairs = std::min(g.pairs, w);
        if (g.lut) {
            const uint8_t *__restrict lut = g.lut;
            for (int x = 0; x < pairs; x++) {
                const int i = x * step;
                iy[x] = lut[(src[i] + src[i + 1] + below[i] + below[i + 1] + 2) >> 2];
            }
        } else {
            for (int x = 0; x < pairs; x++) {
                const int i = x * step;
                iy[x] = (uint8_t)((src[i] + src[i + 1] + below[i] + below[i + 1] + 2) >> 2);
            }
        }
        // The last column of an odd-sized frame pairs with itself.
        for (int x = pairs; x < w; x++) {
            const int m = (src[x * step] + below[x * step] + 1) >> 1;
            iy[x] = g.lut ? g.lut[m] : (uint8_t)m;
        }
        return;
    }
    if (g.lut) {
        const uint8_t *__restrict lut = g.lut;
        for (int x = 0; x < w; x++)
            iy[x] = lut[src[x * step]];
    } else {
        for (int x = 0; x < w; x++)
            iy[x] = src[x * step];
    }
}

CT_ALWAYS_INLINE void gather_row(const BgGather &g)
{
    if (g.scale == 2)
        gather_luma<2>(g, 2);
    else
        gather_luma<0>(g, g.scale);
    if (!g.su || (g.c_step == 1 && !g.c_half))
        return;
    const uint8_t *__restrict su = g.su, *__restrict sv = g.sv;
    uint8_t *__restrict iu = g.iu, *__restrict iv = g.iv;
    const int w = g.w, c = g.c_step;
    if (g.c_half) {
        for (int x = 0; x < w; x++) {
            iu[x] = su[(x >> 1) * c];
            iv[x] = sv[(x >> 1) * c];
        }
    } else {
        for (int x = 0; x < w; x++) {
            iu[x] = su[x * c];
            iv[x] = sv[x * c];
        }
    }
}

void update_row_c(const BgRow &a) { update_row<0>(a); }
void gather_row_c(const BgGather &g) { gather_row(g); }
#if defined(__GNUC__)
// 128-bit vectors: x86-64's baseline (SSE2) and aarch64's (NEON).
void update_row_v16(const BgRow &a) { update_row<16>(a); }
#endif
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) void update_row_avx2(const BgRow &a) { update_row<32>(a); }
__attribute__((target("avx2"))) void gather_row_avx2(const BgGather &g) { gather_row(g); }
#endif

} // namespace

void background_dsp_init(Dsp *dsp, unsigned flags)
{
    dsp->bg_update_row = update_row_c;
    dsp->bg_gather_row = gather_row_c;
#if defined(__GNUC__)
    // The 16-lane build wherever the CPU has more than the portable path:
    // every x86-64 since 2006 (SSSE3) and every aarch64 (NEON).
    if (flags & (kCpuSSSE3 | kCpuNEON))
        dsp->bg_update_row = update_row_v16;
#endif
#if defined(__x86_64__) && defined(__GNUC__)
    if (flags & kCpuAVX2) {
        dsp->bg_update_row = update_row_avx2;
        dsp->bg_gather_row = gather_row_avx2;
    }
#endif
    (void)flags;
}

} // namespace ctrack
