/* NEON twins of the cod preset's up-pass blends and 13-tap
 * (bloom_preset_cod.h), aarch64 only; the other cod kernels stay C on
 * NEON (no table gathers). Same bits as the C kernels
 * (tests/test_simd_cod.c under aarch64 emulation); the bounds are those of
 * the AVX2 twins (sim/docs/presets/cod.md, "SIMD twins"), tested per row, the C
 * kernel taking the row when they fail. Empty on other targets. */
#include "bloom_preset_cod.h"

#if BLOOM_USE_COD && defined(BLOOM_SIMD_NEON)
#include <arm_neon.h>

/* The vertical sums as in C; h = (sO + 4 sI + 64) >> 7 flat, in place in
 * vo, when every vo is below 2^26; the even columns by de-interleaving
 * loads (vld3q: 4 columns, one channel a register) and vuzp1q. */
uint32_t cod_down13_neon(const uint32_t *const r[6], uint32_t *vo, uint32_t *vi, uint32_t *o, int w, int sw)
{
    const int nw = 3 * sw;
    if (w < 4)
        return cod_down13_c(r, vo, vi, o, w, sw);
    uint32x4_t vor = vdupq_n_u32(0);
    int i = 0;
    for (; i + 4 <= nw; i += 4) {
        const uint32x4_t mid = vaddq_u32(vld1q_u32(r[2] + i), vld1q_u32(r[3] + i));
        const uint32x4_t vin = vaddq_u32(vaddq_u32(vld1q_u32(r[1] + i), vld1q_u32(r[4] + i)), mid);
        const uint32x4_t von =
            vaddq_u32(vaddq_u32(vin, mid), vaddq_u32(vld1q_u32(r[0] + i), vld1q_u32(r[5] + i)));
        vst1q_u32(vi + COD_PAD + i, vin);
        vst1q_u32(vo + COD_PAD + i, von);
        vor = vorrq_u32(vor, von);
    }
    uint32_t bor = vmaxvq_u32(vor);
    for (; i < nw; i++) {
        const uint32_t mid = r[2][i] + r[3][i];
        vi[COD_PAD + i] = r[1][i] + mid + r[4][i];
        vo[COD_PAD + i] = r[0][i] + r[1][i] + 2u * mid + r[4][i] + r[5][i];
        bor |= vo[COD_PAD + i];
    }
    if (bor >> 26) /* the maximum, or the OR of the tail: either bounds every vo */
        return cod_down13_c(r, vo, vi, o, w, sw);
    cod_pad_edges(vo, sw);
    cod_pad_edges(vi, sw);
    const int m = 6 * w - 3; /* h at words j < 6 w - 3, reads vo to 6 w + 11 */
    int j = 0;
    for (; j + 4 <= m; j += 4) {
        const uint32x4_t so =
            vaddq_u32(vaddq_u32(vaddq_u32(vld1q_u32(vo + j), vld1q_u32(vo + j + 3)),
                                vaddq_u32(vld1q_u32(vo + j + 12), vld1q_u32(vo + j + 15))),
                      vshlq_n_u32(vaddq_u32(vld1q_u32(vo + j + 6), vld1q_u32(vo + j + 9)), 1));
        const uint32x4_t si = vaddq_u32(vaddq_u32(vld1q_u32(vi + j + 3), vld1q_u32(vi + j + 6)),
                                        vaddq_u32(vld1q_u32(vi + j + 9), vld1q_u32(vi + j + 12)));
        vst1q_u32(vo + j, vshrq_n_u32(vaddq_u32(vaddq_u32(so, vshlq_n_u32(si, 2)), vdupq_n_u32(64)), 7));
    }
    for (; j < m; j++) {
        const uint32_t so = vo[j] + vo[j + 3] + 2u * (vo[j + 6] + vo[j + 9]) + vo[j + 12] + vo[j + 15];
        const uint32_t si = vi[j + 3] + vi[j + 6] + vi[j + 9] + vi[j + 12];
        vo[j] = (so + 4u * si + 64u) >> 7;
    }
    uint32x4_t any = vdupq_n_u32(0);
    int x = 0;
    /* 4 output pixels = columns 2x .. 2x + 7 = words 6x .. 6x + 23 (< m + 3
     * for x + 4 <= w - 1; the last pixels by the scalar loop) */
    for (; x + 5 <= w; x += 4) {
        const uint32x4x3_t a = vld3q_u32(vo + 6 * x), b = vld3q_u32(vo + 6 * x + 12);
        uint32x4x3_t e;
        for (int ch = 0; ch < 3; ch++) {
            e.val[ch] = vuzp1q_u32(a.val[ch], b.val[ch]);
            any = vorrq_u32(any, e.val[ch]);
        }
        vst3q_u32(o + 3 * x, e);
    }
    uint32_t an = vmaxvq_u32(any);
    for (int k = 3 * x; k < 3 * w; k++)
        an |= o[k] = vo[2 * k - k % 3];
    return an;
}

/* The tent's halves in 32-bit lanes when every sample of the four rows is
 * below 2^24 (as tent32 of bloom_preset_cod_avx2_up.c). */
static bool tent32(const uint32_t *const u[4], int odd, int w, int sw, uint32_t *scr, uint32_t **e,
                   uint32_t **o)
{
    uint32_t *v = scr + 6, *ev = v + 3 * sw + 6, *ov = ev + 3 * sw;
    const uint32_t wa = odd ? 3u : 1u, wb = odd ? 7u : 5u, wc = odd ? 5u : 7u, wd = odd ? 1u : 3u;
    const int n = 3 * sw;
    uint32x4_t bor = vdupq_n_u32(0);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t a = vld1q_u32(u[0] + i), b = vld1q_u32(u[1] + i), c = vld1q_u32(u[2] + i),
                         d = vld1q_u32(u[3] + i);
        bor = vorrq_u32(bor, vorrq_u32(vorrq_u32(a, b), vorrq_u32(c, d)));
        vst1q_u32(v + i, vmlaq_n_u32(vmlaq_n_u32(vmlaq_n_u32(vmulq_n_u32(a, wa), b, wb), c, wc), d, wd));
    }
    uint32_t sor = vmaxvq_u32(bor);
    for (; i < n; i++) {
        sor |= u[0][i] | u[1][i] | u[2][i] | u[3][i];
        v[i] = wa * u[0][i] + wb * u[1][i] + wc * u[2][i] + wd * u[3][i];
    }
    if (sor >> 24)
        return false;
    for (int ch = 0; ch < 3; ch++) {
        v[ch - 6] = v[ch - 3] = v[ch];
        v[n + ch] = v[n + 3 + ch] = v[n - 3 + ch];
    }
    const int m = 3 * ((w + 1) >> 1);
    int j = 0;
    for (; j + 4 <= m; j += 4) {
        const uint32x4_t vm2 = vld1q_u32(v + j - 6), vm1 = vld1q_u32(v + j - 3), v0 = vld1q_u32(v + j),
                         v1 = vld1q_u32(v + j + 3), v2 = vld1q_u32(v + j + 6);
        vst1q_u32(ev + j, vmlaq_n_u32(vmlaq_n_u32(vmlaq_n_u32(vm2, vm1, 5u), v0, 7u), v1, 3u));
        vst1q_u32(ov + j, vmlaq_n_u32(vmlaq_n_u32(vmlaq_n_u32(v2, vm1, 3u), v0, 7u), v1, 5u));
    }
    for (; j < m; j++) {
        ev[j] = v[j - 6] + 5u * v[j - 3] + 7u * v[j] + 3u * v[j + 3];
        ov[j] = 3u * v[j - 3] + 7u * v[j] + 5u * v[j + 3] + v[j + 6];
    }
    *e = ev;
    *o = ov;
    return true;
}

/* 8 output pixels from 4 even and 4 odd columns, channel planar: the tent
 * sums t[half][ch] of pixels x .. x + 3 (half 0) and x + 4 .. x + 7. */
static inline void tents8(const uint32_t *e, const uint32_t *o, uint32x4_t t[2][3])
{
    const uint32x4x3_t ea = vld3q_u32(e), oa = vld3q_u32(o);
    for (int ch = 0; ch < 3; ch++) {
        t[0][ch] = vzip1q_u32(ea.val[ch], oa.val[ch]);
        t[1][ch] = vzip2q_u32(ea.val[ch], oa.val[ch]);
    }
}

/* o = (a d + f_ch T + 2^23) >> 24 over w pixels, T the tents of ev/ov:
 * the low 32 bits (the blend, whose sums the C twin keeps as they are) or
 * saturated at 2^32 - 1 (sat: the output mix); the blend and the mix of
 * cod_kern.c. Inlined with sat a constant. */
static inline void weigh(const uint32_t *ev, const uint32_t *ov, const uint32_t *d, uint32_t *o, int w,
                         uint32_t a, const uint32_t f[3], bool sat)
{
    int x = 0;
    for (; x + 8 <= w; x += 8) {
        uint32x4_t t[2][3];
        tents8(ev + 3 * (x >> 1), ov + 3 * (x >> 1), t);
        for (int h = 0; h < 2; h++) {
            const uint32x4x3_t dv = vld3q_u32(d + 3 * (x + 4 * h));
            uint32x4x3_t r;
            for (int ch = 0; ch < 3; ch++) {
                const uint32x4_t dd = dv.val[ch], tt = t[h][ch];
                const uint64x2_t lo = vmlal_n_u32(vmull_n_u32(vget_low_u32(dd), a), vget_low_u32(tt), f[ch]);
                const uint64x2_t hi = vmlal_high_n_u32(vmull_high_n_u32(dd, a), tt, f[ch]);
                /* (q + 2^23) >> 24: the saturating narrow, or the low 32 bits */
                r.val[ch] = sat ? vcombine_u32(vqrshrn_n_u64(lo, 24), vqrshrn_n_u64(hi, 24))
                                : vrshrn_high_n_u64(vrshrn_n_u64(lo, 24), hi, 24);
            }
            vst3q_u32(o + 3 * (x + 4 * h), r);
        }
    }
    for (; x < w; x++) {
        const uint32_t *t = ((x & 1) ? ov : ev) + 3 * (x >> 1);
        for (int ch = 0; ch < 3; ch++) {
            const uint64_t q = ((uint64_t)a * d[3 * x + ch] + (uint64_t)f[ch] * t[ch] + (1u << 23)) >> 24;
            o[3 * x + ch] = sat && q > UINT32_MAX ? UINT32_MAX : (uint32_t)q;
        }
    }
}

void cod_blend_neon(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                    uint32_t a, uint32_t c, uint32_t *scr)
{
    uint32_t *ev, *ov;
    if (w < 8 || !tent32(u, odd, w, sw, scr, &ev, &ov)) {
        cod_blend_c(u, odd, d, o, w, sw, a, c, scr);
        return;
    }
    const uint32_t f[3] = {c, c, c};
    weigh(ev, ov, d, o, w, a, f, false);
}

void cod_mix_neon(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                  uint32_t a, const uint32_t f[3], uint32_t *scr)
{
    uint32_t *ev, *ov;
    if (w < 8 || !tent32(u, odd, w, sw, scr, &ev, &ov)) {
        cod_mix_c(u, odd, d, o, w, sw, a, f, scr);
        return;
    }
    weigh(ev, ov, d, o, w, a, f, true);
}

#else
typedef int bloom_preset_cod_neon_unused_t;
#endif
