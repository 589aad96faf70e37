/* Row kernels on 16-bit samples (cfg.sample_bits = 16): the box and the
 * tent of bloom_row.c on uint16_t rows, and the conversions between the
 * internal format and the rings' Q(16-G).G (bloom_s16_frac). The sums are
 * formed in 32 bits and rounded as the 32-bit kernels round them
 * (sim/docs/fixed-point.md, "16-bit samples": every result fits in 16
 * bits by the bound U_k <= (L - k + 1) * 2^G < 2^16). */
#include <string.h>

#include "bloom_kernels.h"

#if BLOOM_USE_S16

uint32_t bloom_knee_peak(const bloom_knee_t *kn)
{
    /* num(b) = max(soft(b), b - T) of bloom_row_knee_c grows with b, and a
     * channel comes out at most num(bmax) + 1 (c <= bmax, f rounded to the
     * nearest 2^-24): on codes' input (b <= 2^F) D_1 <= num(2^F) + 1 */
    const int64_t t = kn->t, k = kn->k;
    int64_t x = (int64_t)BLOOM_LIN_ONE - t + k;
    x = x < 0 ? 0 : x > 2 * k ? 2 * k : x;
    uint32_t soft = 0;
    if (k > 0) {
        const uint32_t den = (uint32_t)(8 * k) + BLOOM_KNEE_E8;
        soft = bloom_div_u64_u32(2u * (uint64_t)(x * x) + den / 2u, den);
    }
    const int64_t over = (int64_t)BLOOM_LIN_ONE - t;
    const uint32_t num = over > (int64_t)soft ? (uint32_t)over : soft;
    return num + 1u;
}

uint32_t bloom_row_narrow16_c(const uint32_t *src, uint16_t *dst, int n, int sh)
{
    /* half to even: sum / 2^sh with the tie to the even quotient (a value
     * made by the knee ties one time in 2^sh at most: unbiased all the same) */
    const uint32_t h = (1u << (sh - 1)) - 1u;
    uint32_t any = 0;
    for (int i = 0; i < n; i++) {
        const uint32_t v = (src[i] + h + ((src[i] >> sh) & 1u)) >> sh;
        dst[i] = (uint16_t)v;
        any |= v;
    }
    return any;
}

void bloom_row_narrow16_add_c(const uint32_t *src, const uint16_t *add, uint16_t *dst, int n, int sh)
{
    const uint32_t h = (1u << (sh - 1)) - 1u;
    for (int i = 0; i < n; i++)
        dst[i] = (uint16_t)(((src[i] + h + ((src[i] >> sh) & 1u)) >> sh) + (add ? add[i] : 0u));
}

uint32_t bloom_row_vtent16w_c(const uint16_t *a, const uint16_t *b, const uint16_t *c, uint32_t *dst, int n,
                              int sh)
{
    uint32_t any = 0;
    for (int i = 0; i < n; i++) { /* (3a + 4b + c) << sh < 2^19 << 9: no wrap */
        dst[i] = ((((uint32_t)3u * a[i] + 4u * b[i] + c[i]) << sh) + BLOOM_VT_RND) >> 3;
        any |= dst[i];
    }
    return any;
}

void bloom_row_tent16w_c(const uint16_t *const u[3], int odd, uint32_t *dst, int x0, int n, int sw, int sh)
{
    uint32_t v[3][3]; /* the vertical tents of columns m - 1, m, m + 1 */
    for (int x = x0, m = -1; x < x0 + n; x++) {
        if (x >> 1 != m) {
            m = x >> 1;
            const int col[3] = {imax(m - 1, 0), m, imin(m + 1, sw - 1)};
            for (int j = 0; j < 3; j++)
                for (int ch = 0; ch < 3; ch++) {
                    const size_t i = (size_t)col[j] * 3u + (size_t)ch;
                    const uint32_t s3 = odd ? (uint32_t)u[0][i] + 4u * u[1][i] + 3u * u[2][i]
                                            : 3u * u[0][i] + 4u * u[1][i] + u[2][i];
                    v[j][ch] = ((s3 << sh) + BLOOM_VT_RND) >> 3;
                }
        }
        for (int ch = 0; ch < 3; ch++) { /* (3, 4, 1) even, (1, 4, 3) odd; 8 V < 2^32 */
            const uint64_t t = x & 1 ? (uint64_t)v[0][ch] + 4u * (uint64_t)v[1][ch] + 3u * (uint64_t)v[2][ch]
                                     : 3u * (uint64_t)v[0][ch] + 4u * (uint64_t)v[1][ch] + v[2][ch];
            dst[(size_t)(x - x0) * 3u + (size_t)ch] = (uint32_t)((t + BLOOM_HT_RND) >> 3);
        }
    }
}

/* Column sum of four rows at column c (three channels). */
static inline void colsum4(const uint16_t *const s[4], int c, uint32_t out[3])
{
    const size_t i = (size_t)c * 3u;
    for (int ch = 0; ch < 3; ch++)
        out[ch] = (uint32_t)s[0][i + ch] + s[1][i + ch] + s[2][i + ch] + s[3][i + ch];
}

/* Both boxes for destination pixels xa .. xb-1: each sum widened by sh (0:
 * none) and rounded as the 32-bit box rounds it, stored as 16-bit samples
 * or (wide) 32-bit ones. */
static BLOOM_ALWAYS_INLINE void box16(const uint16_t *const s[4], void *dst, bool wide, int xa, int xb,
                                      int sw, int sh)
{
    uint32_t a[3], b[3], c[3], d[3];
    if (xb <= xa)
        return;
    colsum4(s, imax(2 * xa - 1, 0), a); /* column -1 clamps to 0 */
    colsum4(s, 2 * xa, b);
    for (int x = xa; x < xb; x++) {
        colsum4(s, imin(2 * x + 1, sw - 1), c);
        colsum4(s, imin(2 * x + 2, sw - 1), d);
        for (int ch = 0; ch < 3; ch++) {
            const uint32_t sum = (a[ch] + b[ch] + c[ch] + d[ch]) << sh; /* < 2^20 << 9 */
            if (wide)
                ((uint32_t *)dst)[3 * x + ch] = BLOOM_BOX_RND(sum);
            else
                ((uint16_t *)dst)[3 * x + ch] = (uint16_t)BLOOM_BOX_RND(sum);
            a[ch] = c[ch];
            b[ch] = d[ch];
        }
    }
}

void bloom_row_box16_c(const uint16_t *const s[4], uint16_t *dst, int dw, int sw)
{
    box16(s, dst, false, 0, dw, sw, 0);
}

void bloom_row_box16w_c(const uint16_t *const s[4], uint32_t *dst, int dw, int sw, int sh)
{
    box16(s, dst, true, 0, dw, sw, sh);
}

void bloom_row_box16_range_c(const uint16_t *const s[4], void *dst, bool wide, int xa, int xb, int sw, int sh)
{
    if (wide)
        box16(s, dst, true, xa, xb, sw, sh);
    else
        box16(s, dst, false, xa, xb, sw, 0);
}

void bloom_row_il16_c(const uint32_t *e, const uint32_t *o, const uint16_t *add, uint16_t *dst, int x0,
                      int np)
{
    for (int x = x0; x < np; x++) { /* pixel x: column x / 2 of the even or the odd half */
        const uint32_t *p = (x & 1 ? o : e) + 3 * (x >> 1);
        for (int c = 0; c < 3; c++)
            dst[3 * x + c] = (uint16_t)(p[c] + (add ? add[3 * x + c] : 0u));
    }
}

/* The vertical tent of rows u0..u2 at sample i: (3, 4, 1) or (1, 4, 3), half up. */
static inline void vtent(const uint16_t *const u[3], size_t i, int odd, uint32_t v[3])
{
    for (int ch = 0; ch < 3; ch++) {
        const uint32_t a = u[0][i + ch], b = u[1][i + ch], c = u[2][i + ch];
        v[ch] = ((odd ? a : 3u * a) + 4u * b + (odd ? 3u * c : c) + BLOOM_VT_RND) >> 3;
    }
}

void bloom_row_tent16_c(const uint16_t *const u[3], int odd, const uint16_t *add, uint16_t *dst, int x0,
                        int n, int sw)
{
    int m = x0 >> 1;
    uint32_t vp[3], vc[3], vn[3];
    vtent(u, (size_t)imax(m - 1, 0) * 3u, odd, vp);
    vtent(u, (size_t)m * 3u, odd, vc);
    for (int x = x0; x < x0 + n; m++) {
        vtent(u, (size_t)imin(m + 1, sw - 1) * 3u, odd, vn);
        for (int side = x & 1; side < 2 && x < x0 + n; side++, x++) {
            const size_t o = (size_t)(x - x0) * 3u;
            for (int ch = 0; ch < 3; ch++) { /* horizontal: (3, 4, 1) even, (1, 4, 3) odd, half down */
                const uint32_t t = ((side ? vp[ch] : 3u * vp[ch]) + 4u * vc[ch] +
                                    (side ? 3u * vn[ch] : vn[ch]) + BLOOM_HT_RND) >>
                                   3;
                dst[o + ch] = (uint16_t)(t + (add ? add[o + ch] : 0u));
            }
        }
        for (int ch = 0; ch < 3; ch++) {
            vp[ch] = vc[ch];
            vc[ch] = vn[ch];
        }
    }
}

uint32_t bloom_row_narrow16_k(const bloom_kernels_t *k, const uint32_t *src, uint16_t *dst, int n, int sh)
{
#if defined(BLOOM_SIMD_AVX2)
    if (k->isa == BLOOM_ISA_AVX2)
        return bloom_row_narrow16_avx2(src, dst, n, sh);
#endif
#if defined(BLOOM_SIMD_NEON)
    if (k->isa == BLOOM_ISA_NEON)
        return bloom_row_narrow16_neon(src, dst, n, sh);
#endif
#if defined(BLOOM_SIMD_SSE2)
    if (bloom_kernels_simd(k))
        return bloom_row_narrow16_sse2(src, dst, n, sh);
#endif
    (void)k;
    return bloom_row_narrow16_c(src, dst, n, sh);
}

void bloom_row_narrow16_add_k(const bloom_kernels_t *k, const uint32_t *src, const uint16_t *add,
                              uint16_t *dst, int n, int sh)
{
#if defined(BLOOM_SIMD_AVX2)
    if (k->isa == BLOOM_ISA_AVX2) {
        bloom_row_narrow16_add_avx2(src, add, dst, n, sh);
        return;
    }
#endif
#if defined(BLOOM_SIMD_NEON)
    if (k->isa == BLOOM_ISA_NEON) {
        bloom_row_narrow16_add_neon(src, add, dst, n, sh);
        return;
    }
#endif
    (void)k;
    bloom_row_narrow16_add_c(src, add, dst, n, sh);
}

uint32_t bloom_row_vtent16w_k(const bloom_kernels_t *k, const uint16_t *a, const uint16_t *b,
                              const uint16_t *c, uint32_t *dst, int n, int sh)
{
#if defined(BLOOM_SIMD_AVX2)
    if (k->isa == BLOOM_ISA_AVX2)
        return bloom_row_vtent16w_avx2(a, b, c, dst, n, sh);
#endif
#if defined(BLOOM_SIMD_NEON)
    if (k->isa == BLOOM_ISA_NEON)
        return bloom_row_vtent16w_neon(a, b, c, dst, n, sh);
#endif
#if defined(BLOOM_SIMD_SSE2)
    if (bloom_kernels_simd(k))
        return bloom_row_vtent16w_sse2(a, b, c, dst, n, sh);
#endif
    (void)k;
    return bloom_row_vtent16w_c(a, b, c, dst, n, sh);
}

void bloom_row_box16_k(const bloom_kernels_t *k, const uint16_t *const s[4], void *dst, bool wide, int dw,
                       int sw, int sh)
{
#if defined(BLOOM_SIMD_AVX2)
    if (k->isa == BLOOM_ISA_AVX2) {
        if (wide)
            bloom_row_box16w_avx2(s, (uint32_t *)dst, dw, sw, sh);
        else
            bloom_row_box16_avx2(s, (uint16_t *)dst, dw, sw);
        return;
    }
#endif
#if defined(BLOOM_SIMD_NEON)
    if (k->isa == BLOOM_ISA_NEON) {
        if (wide)
            bloom_row_box16w_neon(s, (uint32_t *)dst, dw, sw, sh);
        else
            bloom_row_box16_neon(s, (uint16_t *)dst, dw, sw);
        return;
    }
#endif
#if defined(BLOOM_SIMD_SSE2)
    if (bloom_kernels_simd(k)) {
        if (wide)
            bloom_row_box16w_sse2(s, (uint32_t *)dst, dw, sw, sh);
        else
            bloom_row_box16_sse2(s, (uint16_t *)dst, dw, sw);
        return;
    }
#endif
    (void)k;
    bloom_row_box16_range_c(s, dst, wide, 0, dw, sw, sh);
}

/* Low-resolution columns per chunk of bloom_row_tent16_k (stack: 9 x 32 words). */
#define TENT16_CH 32

void bloom_row_tent16_k(const bloom_kernels_t *k, const uint16_t *const u[3], int odd, const uint16_t *add,
                        uint16_t *dst, int n, int sw)
{
    if (!k->htent_eo || sw < 2 || sw < (n + 1) / 2) {
        bloom_row_tent16_c(u, odd, add, dst, 0, n, sw);
        return;
    }
    const uint16_t *ua = odd ? u[2] : u[0], *ub = u[1], *uc = odd ? u[0] : u[2];
    uint32_t vb[3 * (TENT16_CH + 2)], eo[6 * TENT16_CH]; /* vb[3 j] is column m0 - 1 + j */
    const int mw = (n + 1) / 2;
    for (int m0 = 0; m0 < mw; m0 += TENT16_CH) {
        const int nn = imin(TENT16_CH, mw - m0), np = imin(2 * nn, n - 2 * m0);
        const int lo = m0 > 0 ? m0 - 1 : 0, hi = imin(m0 + nn, sw - 1); /* columns read */
        const size_t c0 = (size_t)lo * 3u;
        /* the vertical tent's (3, 4, 1) with the rows in that order: sh 0 */
        (void)bloom_row_vtent16w_k(k, ua + c0, ub + c0, uc + c0, vb + (size_t)(lo - m0 + 1) * 3u,
                                   3 * (hi - lo + 1), 0);
        if (m0 == 0) /* column -1 is column 0 */
            memcpy(vb, vb + 3, 3u * sizeof *vb);
        if (m0 + nn == sw) /* column sw is column sw - 1 */
            memcpy(vb + 3 * (nn + 1), vb + 3 * nn, 3u * sizeof *vb);
        (void)k->htent_eo(vb + 3, eo, eo + 3 * TENT16_CH, 3 * nn);
        uint16_t *d = dst + (size_t)m0 * 6u;
        const uint16_t *ad = add ? add + (size_t)m0 * 6u : NULL;
#if defined(BLOOM_SIMD_AVX2)
        if (k->isa == BLOOM_ISA_AVX2) {
            bloom_row_il16_avx2(eo, eo + 3 * TENT16_CH, ad, d, np);
            continue;
        }
#endif
#if defined(BLOOM_SIMD_NEON)
        if (k->isa == BLOOM_ISA_NEON) {
            bloom_row_il16_neon(eo, eo + 3 * TENT16_CH, ad, d, np);
            continue;
        }
#endif
        bloom_row_il16_c(eo, eo + 3 * TENT16_CH, ad, d, 0, np);
    }
}

#else
typedef int bloom_row16_empty_t; /* (16-bit samples compiled out) */
#endif
