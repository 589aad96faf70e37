/* Whole-row kernels built from the flat row kernels of bloom_kernels_t:
 * the output row (bloom_row_out_k: its fast path for 8/6/5-bit sRGB and
 * the chunked general path) and the whole-row tent of the AVX2 and NEON
 * sets (bloom_row_tent_flat). Per chunk of low-resolution columns: the
 * vertical tent, the horizontal tent into even and odd columns, then the
 * encode or the interleave. Same bits as bloom_row_out_c and
 * bloom_row_tent_c (tests/test_simd.c). */
#include <string.h>

#include "bloom_kernels.h"
#include "bloom_pixel.h"

#if !BLOOM_SMALL
/* Level-1 columns per chunk of the fast output path (stack: 3 x 32 words). */
#define OUT_FAST_CH 32
/* The largest I_q (Q16.16) whose products stay below 2^32 there: 223.8,
 * srgb_to_linear(10.0), the largest intensity bloom_query takes. */
#define OUT_FAST_MAX_I 14668679u

/* The fast output path of bloom_row_out_k, taken only within the bounds
 * it relies on (checked there: I_q at most OUT_FAST_MAX_I; U <= 16 * 2^F
 * holds for every level sum, sim/docs/fixed-point.md). Per chunk of level-1 columns m0 .. m0+n-1: the
 * vertical tent V of columns m0-1 .. m0+n (edges replicated) in one flat
 * pass, the horizontal tent into the even (e) and odd (od) output columns,
 * the intensity, then the composite and encode per output pixel; the
 * chunks start at x0 / 2 (x0 even). Same bits as bloom_row_out_c: with U <= 16 * 2^F every 32-bit sum is exact, P < 2^32
 * for I <= 223.8 and P + S < 2^32. */
static void out_fast(const bloom_kernels_t *k, const void *const u[3], int sh, int odd, const uint8_t *src,
                     uint8_t *dst, int x0, int w, int sw, const bloom_out_t *o)
{
    const size_t ibpp = (size_t)bloom_bpp(o->in_fmt), obpp = (size_t)bloom_bpp(o->out_fmt);
    const void *ua = odd ? u[2] : u[0], *ub = u[1], *uc = odd ? u[0] : u[2];
    uint32_t vb[3 * (OUT_FAST_CH + 2)], eo[6 * OUT_FAST_CH]; /* even, then odd columns */
    uint32_t *e = eo, *od = eo + 3 * OUT_FAST_CH;
    const int mw = (w + 1) / 2; /* the columns read, sw or fewer (a tile's output) */
    for (int m0 = x0 / 2; m0 < mw; m0 += OUT_FAST_CH) {
        const int n = imin(OUT_FAST_CH, mw - m0);
        const int lo = m0 > 0 ? m0 - 1 : 0, hi = imin(m0 + n, sw - 1); /* columns computed */
        const size_t c0 = (size_t)lo * 3u;
        uint32_t *v0 = vb + (size_t)(lo - m0 + 1) * 3u; /* vb[3 j] is column m0 - 1 + j */
        const int xs = 2 * m0, nx = imin(2 * n, w - xs);
        const uint8_t *sc = src + (size_t)(xs - x0) * ibpp; /* column xs */
        uint8_t *dc = dst + (size_t)(xs - x0) * obpp;
        /* 16-bit rows (sh > 0: U_1 of cfg.sample_bits 16) are widened in the sums */
        const uint32_t any =
#if BLOOM_USE_S16
            sh ? bloom_row_vtent16w_k(k, (const uint16_t *)ua + c0, (const uint16_t *)ub + c0,
                                      (const uint16_t *)uc + c0, v0, 3 * (hi - lo + 1), sh)
               :
#endif
               k->vtent((const uint32_t *)ua + c0, (const uint32_t *)ub + c0, (const uint32_t *)uc + c0, v0,
                        3 * (hi - lo + 1));
        if (!any) { /* V = 0: B = 0 here */
            bloom_row_copy_c(sc, dc, nx, o);
            continue;
        }
        if (m0 == 0)
            memcpy(vb, vb + 3, 3u * sizeof *vb);
        if (m0 + n == sw)
            memcpy(vb + 3 * (n + 1), vb + 3 * n, 3u * sizeof *vb);
        if (!k->htent_eo(vb + 3, e, od, 3 * n)) { /* B = 0 on this chunk */
            bloom_row_copy_c(sc, dc, nx, o);
            continue;
        }
        if (o->intensity != 65536u) { /* (65536 x + 32768) >> 16 = x */
            k->scale(e, 3 * n, o->intensity);
            k->scale(od, 3 * n, o->intensity);
        }
        k->eo(o->in_fmt, o->out_fmt, o->debug, sc, e, od, dc, nx);
    }
}
#endif

#if defined(BLOOM_SIMD_AVX2) || defined(BLOOM_SIMD_NEON) /* their whole-row tent */
void bloom_row_il_add_c(const uint32_t *e, const uint32_t *o, const uint32_t *add, uint32_t *dst, int n)
{
    for (int x = 0; x < n; x++) { /* pixel x: column x / 2 of e or o */
        const uint32_t *p = (x & 1 ? o : e) + 3 * (x >> 1);
        for (int c = 0; c < 3; c++, dst++)
            *dst = p[c] + (add ? *add++ : 0u);
    }
}

/* Low-resolution columns per chunk of bloom_row_tent_flat (stack: 3 x 32 words). */
#define TENT_CH 32

void bloom_row_tent_flat(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0,
                         int n, int sw, bloom_vtent_in_fn vt, bloom_htent_eo_fn ht, bloom_il_add_fn il,
                         void (*exact)(const uint32_t *const u[3], int odd, const uint32_t *add,
                                       uint32_t *dst, int x0, int n, int sw))
{
    if (x0 != 0 || sw < 2 || sw < (n + 1) / 2) {
        exact(u, odd, add, dst, x0, n, sw);
        return;
    }
    const uint32_t *ua = odd ? u[2] : u[0], *ub = u[1], *uc = odd ? u[0] : u[2];
    uint32_t vb[3 * (TENT_CH + 2)], eo[6 * TENT_CH]; /* vb[3 j] is column m0 - 1 + j */
    const int mw = (n + 1) / 2;                      /* the columns read, sw or fewer (a tile's output) */
    for (int m0 = 0; m0 < mw; m0 += TENT_CH) {
        const int nn = imin(TENT_CH, mw - m0), np = imin(2 * nn, n - 2 * m0);
        const int lo = m0 > 0 ? m0 - 1 : 0, hi = imin(m0 + nn, sw - 1); /* columns read */
        const size_t c0 = (size_t)lo * 3u;
        uint32_t in;
        vt(ua + c0, ub + c0, uc + c0, vb + (size_t)(lo - m0 + 1) * 3u, 3 * (hi - lo + 1), &in);
        if (in >> 29) { /* 3a + 4b + c + 4 could pass 2^32: the exact tent */
            exact(u, odd, add ? add + (size_t)m0 * 6u : NULL, dst + (size_t)m0 * 6u, 2 * m0, np, sw);
            continue;
        }
        if (m0 == 0) /* edges replicated */
            memcpy(vb, vb + 3, 3u * sizeof *vb);
        if (m0 + nn == sw)
            memcpy(vb + 3 * (nn + 1), vb + 3 * nn, 3u * sizeof *vb);
        ht(vb + 3, eo, eo + 3 * TENT_CH, 3 * nn);
        il(eo, eo + 3 * TENT_CH, add ? add + (size_t)m0 * 6u : NULL, dst + (size_t)m0 * 6u, np);
    }
}
#endif

/* The general output path, chunk by chunk from column x0: tent, composite, encode. u
 * holds 32-bit rows, or with sh > 0 (U_1 of cfg.sample_bits 16) 16-bit
 * rows the tent widens in its sums. */
static void out_chunks(const bloom_kernels_t *k, const void *const u[3], int sh, int odd, const uint8_t *src,
                       uint8_t *dst, int x0, int w, int sw, const bloom_out_t *o)
{
    const size_t ibpp = (size_t)bloom_bpp(o->in_fmt), obpp = (size_t)bloom_bpp(o->out_fmt);
    uint32_t bl[3 * BLOOM_OUT_CHUNK], sv[3 * BLOOM_OUT_CHUNK];
    (void)sh; /* (0 where 16-bit samples are compiled out) */
    if (o->debug)
        memset(sv, 0, sizeof sv);
    for (int xs = x0; xs < w; xs += BLOOM_OUT_CHUNK) {
        const int n = imin(BLOOM_OUT_CHUNK, w - xs);
#if BLOOM_USE_S16
        if (sh) {
            const uint16_t *const u16[3] = {(const uint16_t *)u[0], (const uint16_t *)u[1],
                                            (const uint16_t *)u[2]};
            bloom_row_tent16w_c(u16, odd, bl, xs, n, sw, sh);
        } else
#endif
        {
            const uint32_t *const u32[3] = {(const uint32_t *)u[0], (const uint32_t *)u[1],
                                            (const uint32_t *)u[2]};
            k->tent(u32, odd, NULL, bl, xs, n, sw);
        }
        if (!o->debug)
            bloom_decode_row(o->in_fmt, o->linear, src + (size_t)(xs - x0) * ibpp, sv, n);
        k->composite(bl, sv, 3 * n, o->intensity);
        bloom_encode_row(o->out_fmt, o->linear, bl, dst + (size_t)(xs - x0) * obpp, n);
    }
}

/* Columns x0 .. w - 1 of one output row (src and dst from column x0 on)
 * from 32-bit U rows, or 16-bit ones widened by sh. */
static BLOOM_ALWAYS_INLINE void out_row(const bloom_kernels_t *k, const void *const u[3], int sh, int odd,
                                        const uint8_t *src, uint8_t *dst, int x0, int w, int sw,
                                        const bloom_out_t *o)
{
#if !BLOOM_SMALL
    if (k->vtent && sw >= 1 && sw >= (w + 1) / 2 && o->intensity <= OUT_FAST_MAX_I &&
        bloom_encode_eo_ok(o->in_fmt, o->out_fmt, o->linear)) {
        out_fast(k, u, sh, odd, src, dst, x0, w, sw, o);
        return;
    }
#endif
    out_chunks(k, u, sh, odd, src, dst, x0, w, sw, o);
}

void bloom_row_out_k(const bloom_kernels_t *k, const uint32_t *const u[3], int odd, const uint8_t *src,
                     uint8_t *dst, int x0, int w, int sw, const bloom_out_t *o)
{
    const void *const uv[3] = {u[0], u[1], u[2]};
    out_row(k, uv, 0, odd, src, dst, x0, w, sw, o);
}

#if BLOOM_USE_S16
void bloom_row_out16_k(const bloom_kernels_t *k, const uint16_t *const u[3], int sh, int odd,
                       const uint8_t *src, uint8_t *dst, int x0, int w, int sw, const bloom_out_t *o)
{
    const void *const uv[3] = {u[0], u[1], u[2]};
    out_row(k, uv, sh, odd, src, dst, x0, w, sw, o);
}
#endif
