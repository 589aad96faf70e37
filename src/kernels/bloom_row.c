/* Row kernels: one row of output from a few rows of input, rounding written
 * out in full (sim/docs/fixed-point.md steps 2-7). Samples are interleaved
 * R, G, B uint32_t, Q16.16. The frame-level code only schedules these. */
#include <string.h>

#include "bloom_kernels.h"
#include "bloom_pixel.h"

/* Column sum of four rows at column c (three channels). */
static inline void colsum4(const uint32_t *const s[4], int c, uint32_t out[3])
{
    const size_t i = (size_t)c * 3u;
#if BLOOM_SMALL /* (the loop: less code) */
    for (int ch = 0; ch < 3; ch++)
        out[ch] = s[0][i + ch] + s[1][i + ch] + s[2][i + ch] + s[3][i + ch];
#else /* (the SIMD boxes' edge columns: gcc -O2 keeps a 3-step loop a loop) */
    const uint32_t *a = s[0] + i, *b = s[1] + i, *c2 = s[2] + i, *d = s[3] + i;
    out[0] = a[0] + b[0] + c2[0] + d[0];
    out[1] = a[1] + b[1] + c2[1] + d[1];
    out[2] = a[2] + b[2] + c2[2] + d[2];
#endif
}

void bloom_row_box_range_c(const uint32_t *const s[4], uint32_t *dst, int xa, int xb, int sw)
{
    uint32_t a[3], b[3], c[3], d[3];
    if (xa >= xb)
        return;
    colsum4(s, imin(imax(2 * xa - 1, 0), sw - 1), a); /* column 2x-1 = -1 clamps to 0 */
    colsum4(s, imin(2 * xa, sw - 1), b);
    for (int x = xa; x < xb; x++) {
        colsum4(s, imin(2 * x + 1, sw - 1), c);
        colsum4(s, imin(2 * x + 2, sw - 1), d);
#if BLOOM_SMALL
        for (int ch = 0; ch < 3; ch++) {
            dst[3 * x + ch] = BLOOM_BOX_RND(a[ch] + b[ch] + c[ch] + d[ch]);
            a[ch] = c[ch];
            b[ch] = d[ch];
        }
#else
        uint32_t *o = dst + 3 * (size_t)x;
        o[0] = BLOOM_BOX_RND(a[0] + b[0] + c[0] + d[0]);
        o[1] = BLOOM_BOX_RND(a[1] + b[1] + c[1] + d[1]);
        o[2] = BLOOM_BOX_RND(a[2] + b[2] + c[2] + d[2]);
        a[0] = c[0], a[1] = c[1], a[2] = c[2]; /* (not memcpy: -Os calls it) */
        b[0] = d[0], b[1] = d[1], b[2] = d[2];
#endif
    }
}

void bloom_row_box_c(const uint32_t *const s[4], uint32_t *dst, int dw, int sw)
{
    bloom_row_box_range_c(s, dst, 0, dw, sw);
}

/* One pixel's knee (at or below cut: zeros), its samples ORed into *any. */
static BLOOM_ALWAYS_INLINE void knee_px(uint32_t *p, int64_t t, int64_t k, uint32_t cut, uint32_t *any)
{
    uint32_t bmax = p[0] > p[1] ? p[0] : p[1];
    bmax = bmax > p[2] ? bmax : p[2];
    if (bmax <= cut || bmax == 0) {
        p[0] = p[1] = p[2] = 0;
        return;
    }
    int64_t xs = (int64_t)bmax - t + k; /* > 0 here */
    if (xs > 2 * k)
        xs = 2 * k;
    /* soft = x^2 / (4K + 0.00004), rounded: 2x^2 <= 2^59, 8K + E < 2^32 */
    uint32_t soft = 0;
    if (k > 0) {
        const uint32_t den = (uint32_t)(8 * k) + BLOOM_KNEE_E8;
        soft = bloom_div_u64_u32(2u * (uint64_t)(xs * xs) + den / 2u, den);
    }
    int64_t over = (int64_t)bmax - t;
    uint64_t num = over > (int64_t)soft ? (uint64_t)over : soft;
    if (num == 0) {
        p[0] = p[1] = p[2] = 0;
        return;
    }
    /* f = num / max(bmax, 0.00001) in Q24, rounded (tiny bmax: exact
     * product); num <= bmax, so f <= 2^24, num << 24 <= 2^53, c f <= 2^52 */
    const uint32_t f = bmax < BLOOM_KNEE_TINY_B
                           ? (uint32_t)num * BLOOM_KNEE_TINY_F
                           : bloom_div_u64_u32((num << BLOOM_KNEE_FBITS) + (bmax >> 1), bmax);
    for (int ch = 0; ch < 3; ch++) {
        p[ch] = (uint32_t)(((uint64_t)p[ch] * f + (1u << (BLOOM_KNEE_FBITS - 1))) >> BLOOM_KNEE_FBITS);
        *any |= p[ch];
    }
}

bool bloom_row_knee_c(uint32_t *row, int w, const bloom_knee_t *kn)
{
    uint32_t any = 0;
    const int64_t t = kn->t, k = kn->k;
    /* Below t - k nothing passes: the common case costs three compares. */
    const uint32_t cut = kn->t > kn->k ? kn->t - kn->k : 0u;
    int x = 0;
#if !BLOOM_SMALL
    /* Four pixels at once: the OR of their samples bounds every sample
     * from above, so OR <= cut means all four are zeroed. */
    for (; x + 4 <= w; x += 4) {
        uint32_t *p = row + 3 * x, o = 0;
        for (int i = 0; i < 12; i++)
            o |= p[i];
        if (o <= cut) {
            for (int i = 0; i < 12; i++)
                p[i] = 0;
            continue;
        }
        for (int i = 0; i < 4; i++)
            knee_px(p + 3 * i, t, k, cut, &any);
    }
#endif
    for (; x < w; x++)
        knee_px(row + 3 * x, t, k, cut, &any);
    return any != 0;
}

bool bloom_row_d1_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw, int sw,
                    const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp)
{
    (void)dk;
#if BLOOM_SMALL
    (void)kp;
    bloom_row_box_src_c(s, fmt, linear, dst, dw, sw);
#else
    bloom_row_box_src_kept_c(s, fmt, linear, dst, 0, dw, sw, kp);
#endif
    return bloom_row_knee_c(dst, dw, kn);
}

/* Vertical tent of one column: weights (3,4,1) even, (1,4,3) odd. U is
 * below 2^32, so the weighted sums need 64 bits (one UMLAL per tap on
 * Cortex-M); the results fit in 32 again. `odd` is a constant after
 * inlining, so the weights are shifts and adds. */
static BLOOM_ALWAYS_INLINE void vtent(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, int odd,
                                      uint32_t v[3])
{
    for (int ch = 0; ch < 3; ch++) {
        const uint64_t a = u0[ch], b = u1[ch], c = u2[ch];
        v[ch] = (uint32_t)(((odd ? a + 4u * b + 3u * c : 3u * a + 4u * b + c) + BLOOM_VT_RND) >> 3);
    }
}

static BLOOM_ALWAYS_INLINE uint32_t htent(uint64_t a, uint64_t b, uint64_t c)
{
    return (uint32_t)((a + 4u * b + c + BLOOM_HT_RND) >> 3);
}

static BLOOM_ALWAYS_INLINE void tent_impl(const uint32_t *const u[3], int odd, const uint32_t *add,
                                          uint32_t *dst, int x0, int n, int sw, bool has_add)
{
    const uint32_t *u0 = u[0], *u1 = u[1], *u2 = u[2];
    int x = x0, m = x0 >> 1;
    const int end = x0 + n;
    uint32_t vp[3], vc[3], vn[3];
    size_t i = (size_t)(m > 0 ? m - 1 : 0) * 3u;
    vtent(u0 + i, u1 + i, u2 + i, odd, vp);
    i = (size_t)m * 3u;
    vtent(u0 + i, u1 + i, u2 + i, odd, vc);
    uint32_t *d = dst;
    const uint32_t *ad = add;
    while (x < end) {
        i = (size_t)imin(m + 1, sw - 1) * 3u;
        vtent(u0 + i, u1 + i, u2 + i, odd, vn);
        if (!(x & 1)) { /* even column: (3, 4, 1) */
            for (int ch = 0; ch < 3; ch++)
                d[ch] = htent(3u * (uint64_t)vp[ch], vc[ch], vn[ch]) + (has_add ? ad[ch] : 0u);
            d += 3;
            if (has_add)
                ad += 3;
            x++;
        }
        if (x < end) { /* odd column: (1, 4, 3) */
            for (int ch = 0; ch < 3; ch++)
                d[ch] = htent(vp[ch], vc[ch], 3u * (uint64_t)vn[ch]) + (has_add ? ad[ch] : 0u);
            d += 3;
            if (has_add)
                ad += 3;
            x++;
        }
        for (int ch = 0; ch < 3; ch++) {
            vp[ch] = vc[ch];
            vc[ch] = vn[ch];
        }
        m++;
    }
}

/* The row parity as a constant: four specializations. */
static BLOOM_ALWAYS_INLINE void tent(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst,
                                     int x0, int n, int sw, bool has_add)
{
    if (odd)
        tent_impl(u, 1, add, dst, x0, n, sw, has_add);
    else
        tent_impl(u, 0, add, dst, x0, n, sw, has_add);
}

void bloom_row_tent_c(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0, int n,
                      int sw)
{
    if (add)
        tent(u, odd, add, dst, x0, n, sw, true);
    else
        tent(u, odd, NULL, dst, x0, n, sw, false);
}

void bloom_row_copy_c(const uint8_t *src, uint8_t *dst, int w, const bloom_out_t *o)
{
    const size_t ibpp = (size_t)bloom_bpp(o->in_fmt), obpp = (size_t)bloom_bpp(o->out_fmt);
    if (bloom_copy_is_bytes(o)) {
        if (src != dst)
            memcpy(dst, src, (size_t)w * ibpp); /* in place is src == dst: rows never half-overlap */
        return;
    }
#if BLOOM_USE_XRGB8888 && !BLOOM_SMALL
    if (!o->debug && o->in_fmt == BLOOM_FMT_XRGB8888 && o->out_fmt == BLOOM_FMT_XRGB8888) {
        /* the same, with X written as 0xFF: a word OR, whatever the byte order */
        static const uint8_t xb[4] = {0, 0, 0, 0xFF};
        uint32_t xm;
        memcpy(&xm, xb, 4);
        for (int x = 0; x < w; x++) {
            uint32_t v;
            memcpy(&v, src + 4 * x, 4);
            v |= xm;
            memcpy(dst + 4 * x, &v, 4);
        }
        return;
    }
#endif
    uint32_t v[3 * BLOOM_OUT_CHUNK];
    memset(v, 0, sizeof v);
    for (int x0 = 0; x0 < w; x0 += BLOOM_OUT_CHUNK) {
        const int n = imin(BLOOM_OUT_CHUNK, w - x0);
        if (!o->debug)
            bloom_decode_row(o->in_fmt, o->linear, src + (size_t)x0 * ibpp, v, n);
        bloom_encode_row(o->out_fmt, o->linear, v, dst + (size_t)x0 * obpp, n);
    }
}

void bloom_row_composite_c(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity)
{
    const uint64_t I = intensity;
    for (int i = 0; i < n; i++) {
        uint64_t v = ((I * bl[i] + 32768u) >> 16) + sv[i];
        bl[i] = v > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)v;
    }
}

void bloom_row_out_c(const uint32_t *const u[3], int odd, const uint8_t *src, uint8_t *dst, int w, int sw,
                     const bloom_out_t *o)
{
    const size_t ibpp = (size_t)bloom_bpp(o->in_fmt), obpp = (size_t)bloom_bpp(o->out_fmt);
    const uint64_t I = o->intensity;
    uint32_t bl[3 * BLOOM_OUT_CHUNK], sv[3 * BLOOM_OUT_CHUNK];
    for (int x0 = 0; x0 < w; x0 += BLOOM_OUT_CHUNK) {
        const int n = imin(BLOOM_OUT_CHUNK, w - x0);
        tent(u, odd, NULL, bl, x0, n, sw, false);
        if (o->debug)
            memset(sv, 0, sizeof sv);
        else
            bloom_decode_row(o->in_fmt, o->linear, src + (size_t)x0 * ibpp, sv, n);
        for (int i = 0; i < 3 * n; i++) {
            uint64_t v = ((I * bl[i] + 32768u) >> 16) + sv[i];
            bl[i] = v > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)v;
        }
        bloom_encode_row(o->out_fmt, o->linear, bl, dst + (size_t)x0 * obpp, n);
    }
}

uint32_t bloom_row_vtent_c(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    uint32_t any = 0;
    for (int i = 0; i < n; i++) {
        dst[i] = (3u * a[i] + 4u * b[i] + c[i] + BLOOM_VT_RND) >> 3;
        any |= dst[i];
    }
    return any;
}

uint32_t bloom_row_htent_eo_c(const uint32_t *v, uint32_t *e, uint32_t *o, int n)
{
    uint32_t any = 0;
    for (int i = 0; i < n; i++) {
        const uint32_t p = v[i - 3], c = v[i], q = v[i + 3];
        e[i] = (3u * p + 4u * c + q + BLOOM_HT_RND) >> 3;
        o[i] = (p + 4u * c + 3u * q + BLOOM_HT_RND) >> 3;
        any |= e[i] | o[i];
    }
    return any;
}

void bloom_row_scale_c(uint32_t *x, int n, uint32_t intensity)
{
    for (int i = 0; i < n; i++)
        x[i] = (uint32_t)(((uint64_t)intensity * x[i] + 32768u) >> 16);
}

void bloom_kernels_select(bloom_kernels_t *k, uint32_t flags)
{
    k->box = bloom_row_box_c;
    k->tent = bloom_row_tent_c;
    k->composite = bloom_row_composite_c;
#if !BLOOM_SMALL
    k->d1 = bloom_row_d1_c;
    k->vtent = bloom_row_vtent_c;
    k->htent_eo = bloom_row_htent_eo_c;
    k->scale = bloom_row_scale_c;
    k->eo = bloom_encode_eo;
    k->box_src = bloom_row_box_src_range_c;
    k->dark = bloom_row_dark;
    k->dark_copy = bloom_row_dark_copy;
#else
    k->box_src = NULL;
    k->d1 = NULL; /* compute_d1 calls the box and the knee itself */
    k->vtent = NULL;
    k->htent_eo = NULL;
    k->scale = NULL;
    k->eo = NULL;
#endif
    k->name = "c";
    k->isa = BLOOM_ISA_C;
    if (flags & BLOOM_FLAG_NO_SIMD)
        return;
#if defined(BLOOM_SIMD_SSE2)
    k->box = bloom_row_box_sse2_any;
    k->tent = bloom_row_tent_sse2_any;
    k->composite = bloom_row_composite_sse2_any;
#if !BLOOM_SMALL
    k->d1 = bloom_row_d1_sse2;
    k->vtent = bloom_row_vtent_sse2;
    k->htent_eo = bloom_row_htent_eo_sse2;
    k->scale = bloom_row_scale_sse2;
    k->dark = bloom_row_dark_sse2;
    k->dark_copy = bloom_row_dark_copy_sse2;
#endif
    k->name = "sse2";
    k->isa = BLOOM_ISA_SSE2;
#if defined(BLOOM_SIMD_AVX2)
    if (!(flags & BLOOM_FLAG_NO_AVX2) && bloom_cpu_avx2()) {
        k->box = bloom_row_box_avx2;
        k->tent = bloom_row_tent_avx2;
        k->d1 = bloom_row_d1_avx2;
        k->vtent = bloom_row_vtent_avx2;
        k->htent_eo = bloom_row_htent_eo_avx2;
        k->eo = bloom_encode_eo_avx2;
        k->dark = bloom_row_dark_avx2;
        k->dark_copy = bloom_row_dark_copy_avx2;
        k->name = "avx2";
        k->isa = BLOOM_ISA_AVX2;
    }
#endif
#elif defined(BLOOM_SIMD_NEON)
    k->box = bloom_row_box_neon_any;
    k->tent = bloom_row_tent_neon_any;
    k->composite = bloom_row_composite_neon_any;
#if !BLOOM_SMALL
    k->d1 = bloom_row_d1_neon;
    k->vtent = bloom_row_vtent_neon;
    k->htent_eo = bloom_row_htent_eo_neon;
    k->scale = bloom_row_scale_neon;
    k->tent = bloom_row_tent_neon_flat;
    k->eo = bloom_encode_eo_neon;
    k->dark = bloom_row_dark_neon;
    k->dark_copy = bloom_row_dark_copy_neon;
#endif
    k->name = "neon";
    k->isa = BLOOM_ISA_NEON;
#endif
}
