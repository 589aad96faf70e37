/* Preset "gamedev": the game-dev article's bloom (sim/docs/presets/gamedev.md).
 *
 *   D1 = threshold(box4x4(S)), D2 = box4x4(D1), D3 = box4x4(D2)
 *        threshold: L = 0.2126 R + 0.7152 G + 0.0722 B,
 *                   RGB *= max(0, L - t) / max(L, 1e-4)
 *   G_k = gauss9(D_k), 9 taps 0.227027, 0.194595, 0.121622, 0.054054, 0.016216
 *        (vertical, rounded, then horizontal, rounded; Q24 weights)
 *   U3 = G3, U2 = G2 + tent(U3), U1 = G1 + tent(U2), B = tent(U1)
 *   c = S + strength * B (debug view: strength * B)
 *   out = round((c / (c + 1))^(1/2.2) * n)   (linear flag: no gamma;
 *         RGBQ16 out: round(c / (c + 1) * 65536), the tone-mapped linear value)
 *
 * Always 3 levels (1/2, 1/4, 1/8), fewer only when the frame is too small
 * for them (the common level rule); cfg->levels, cfg->soft_knee and
 * cfg->intensity are ignored (strength replaces intensity). The output
 * codes come from generated thresholds (bloom_preset_gamedev_tables.c), so
 * Reinhard and gamma cost no division and no float. */
#include <string.h>

#include "bloom_stages.h"
#include "bloom_pixel.h"
#include "bloom_preset_gamedev_k.h"

#if BLOOM_USE_GAMEDEV

#define GD_LEVELS 3
#define GD_MAX_STRENGTH (16u << BLOOM_FRAC_BITS)

/* Rec.709 luminance as exact integers: Lx = 2126 R + 7152 G + 722 B is
 * 10000 L exactly (< 10000 * 2^28 < 2^42, 64-bit). In those units the
 * threshold is 10000 t and the recipe's floor 1e-4 of the divisor is
 * 10000 * 1e-4 = 1.0 = 2^F, exactly. */
#define LUM_R 2126u
#define LUM_G 7152u
#define LUM_B 722u
#define LUM_DEN 10000u

/* ---- level 1: box down, then the luminance threshold -------------------- */

/* In place on w level-1 pixels. Lx <= tx = 10000 t: the pixel is 0.
 * Else the contribution (Lx - tx) / max(Lx, 2^F) as a Q32 fraction: both
 * terms shifted right by the same sh (0 .. 10) until the divisor fits in 32
 * bits (each truncation is below 2^-31 of it), then f = round(n * 2^32 / d)
 * < 2^32, one 64-by-32 division; each channel (c * f + 2^31) >> 32 (c <
 * 2^28: product < 2^60). A numerator not below the divisor (t = 0 and
 * L >= 1e-4) is the factor 1 exactly: the pixel is kept. */
static bool threshold_row(uint32_t *row, int w, uint32_t t)
{
    const uint64_t tx = (uint64_t)t * LUM_DEN;
    uint32_t any = 0;
    for (int x = 0; x < w; x++) {
        uint32_t *p = row + 3 * x;
        const uint64_t lx = (uint64_t)LUM_R * p[0] + (uint64_t)LUM_G * p[1] + (uint64_t)LUM_B * p[2];
        if (lx <= tx) {
            p[0] = p[1] = p[2] = 0;
            continue;
        }
        const uint64_t den = lx > BLOOM_LIN_ONE ? lx : BLOOM_LIN_ONE;
        int sh = 0;
        while ((den >> sh) > 0xFFFFFFFFu)
            sh++;
        const uint32_t d = (uint32_t)(den >> sh), n = (uint32_t)((lx - tx) >> sh);
        if (n >= d) { /* kept: lx > 0, so a channel is not 0 */
            any = 1;
            continue;
        }
        const uint64_t f = bloom_div_u64_u32(((uint64_t)n << 32) + (d >> 1), d);
        for (int ch = 0; ch < 3; ch++)
            p[ch] = (uint32_t)((p[ch] * f + 0x80000000u) >> 32);
        any |= p[0] | p[1] | p[2];
    }
    return any != 0;
}

#if !BLOOM_SMALL
/* Whether level-1 pixel x reads a source code above the dark code: bytes
 * (pixels 2x-1 .. 2x+2) of the dark-block test's row b, which has zero
 * bytes before and after it (a clamped pixel is one of the others). */
static inline bool bright(const uint8_t *b, int x, int bpp)
{
    uint64_t p, q = 0;
    if (bpp == 3) {
        uint32_t q32;
        memcpy(&p, b + 6 * x - 3, 8);
        memcpy(&q32, b + 6 * x + 5, 4);
        q = q32;
    } else {
        memcpy(&p, b + 8 * x - 4, 8);
        memcpy(&q, b + 8 * x + 4, 8);
    }
    return (p | q) != 0;
}

/* Level 1 of RGB888 / XRGB8888 input by dark blocks: the pixels whose 4x4
 * source block has no code above the dark code are zero (the box of
 * samples at most t is at most t, and then Lx <= Tx: "Zero rows" in
 * sim/docs/presets/gamedev.md), the others boxed and thresholded in runs.
 * The test's bytes go to scratch row 0 (w0 * bpp + 20 bytes <= 12 w0 + 64). */
static bool d1_blocks(const bg_ctx_t *ctx, const gd_kern_t *k, const uint8_t *const s[4], uint32_t *d, int w,
                      int w0)
{
    const int bpp = ctx->src_bpp;
    uint8_t *b = (uint8_t *)bg_scratch(ctx, 0);
    memset(b, 0, 4);
    b += 4;
    k->bright(s, b, w0 * bpp, ctx->dark.c8);
    memset(b + w0 * bpp, 0, 16);
    bool any = false;
    for (int x = 0; x < w;) {
        int xa = x;
        while (x < w && !bright(b, x, bpp))
            x++;
        if (x > xa)
            memset(d + 3 * xa, 0, (size_t)(x - xa) * 3u * sizeof *d);
        xa = x;
        while (x < w && bright(b, x, bpp))
            x++;
        if (x > xa) {
            ctx->kern.box_src(s, ctx->par.out.in_fmt, ctx->par.out.linear, d, xa, x, w0); /* C or AVX2 */
            any |= threshold_row(d + 3 * xa, x - xa, ctx->par.knee.t);
        }
    }
    return any;
}
#endif

/* Input 0: source rows 2r-1 .. 2r+2 (BG_DOWN). False when the row came out
 * all zero (the engine then tags it zero). */
static bool gd_d1(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    (void)r;
    const uint8_t *const s[4] = {(const uint8_t *)in[0][0], (const uint8_t *)in[0][1],
                                 (const uint8_t *)in[0][2], (const uint8_t *)in[0][3]};
#if !BLOOM_SMALL
    const gd_kern_t *k = gd_kern_for(ctx->kern.isa);
    if (ctx->dark_src && k->bright &&
        (ctx->par.out.in_fmt == BLOOM_FMT_RGB888 || ctx->par.out.in_fmt == BLOOM_FMT_XRGB8888))
        return d1_blocks(ctx, k, s, (uint32_t *)dst, n->w, bg_in_w(ctx, n, 0));
#endif
    bloom_row_box_src_c(s, ctx->par.out.in_fmt, ctx->par.out.linear, (uint32_t *)dst, n->w,
                        bg_in_w(ctx, n, 0));
    return threshold_row((uint32_t *)dst, n->w, ctx->par.knee.t);
}

/* ---- the Gaussian ----------------------------------------------------------- */

/* U_k = gauss9(D_k) (+ tent(U_k+1)). Inputs: [U_k+1 rows m-1 .. m+1 (BG_UP),]
 * D_k rows r-4 .. r+4 (BG_SAME), the last input. The vertical pass goes to
 * scratch row 0. Zero rows: gauss9 of nine zero rows is 0 ((0 + 2^23) >>
 * 24) and the tent of three zero rows is 0, so the node is zero-preserving
 * (bg_zero); with D_k's rows zero the row is the tent alone, with U_k+1's
 * the Gaussian alone. */
static bool gd_up(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    const int di = n->nin - 1;
    const void *const *d = in[di];
    uint32_t *out = (uint32_t *)dst;
    const bool dz = bg_in_zero(ctx, di, 0, 8), uz = n->nin == 1 || bg_in_zero(ctx, 0, 0, 2);
    if (dz && uz) { /* not run when the engine skips: all zero */
        memset(out, 0, (size_t)n->w * 3u * sizeof *out);
        return false;
    }
    if (!dz) {
        const gd_kern_t *k = gd_kern_for(ctx->kern.isa);
        const uint32_t *const rows[9] = {
            (const uint32_t *)d[0], (const uint32_t *)d[1], (const uint32_t *)d[2],
            (const uint32_t *)d[3], (const uint32_t *)d[4], (const uint32_t *)d[5],
            (const uint32_t *)d[6], (const uint32_t *)d[7], (const uint32_t *)d[8]};
        uint32_t *v = bg_scratch(ctx, 0);
        k->gauss_v(rows, v, 3 * n->w);
        gd_gauss_h_row(k, v, out, n->w);
    }
    if (!uz) {
        const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                      (const uint32_t *)in[0][2]};
        /* the engine's tent, C or its SIMD twin (same bits), picked once at
         * bloom_init: picking it per row ran CPUID per row (a VM exit each
         * under virtualisation: 12x the default's time at 1080p) */
        ctx->kern.tent(u, r & 1, dz ? NULL : out, out, 0, n->w, bg_in_w(ctx, n, 0));
    }
    return true;
}

/* ---- output: composite, Reinhard, gamma, encode ------------------------------ */

/* The output code of v (Q12.20, saturated below 2^32 - 1): the number of
 * thresholds t[1 .. n] at or below it (t[n+1] = 2^32 - 1 is a sentinel).
 * Fast builds look the code of v's bucket up and finish with two compares
 * (the generator checks that no bucket holds more than two thresholds);
 * BLOOM_SMALL builds search t (branch-free binary search, h = (n+1)/2).
 * Same result. */
#if !BLOOM_SMALL
typedef const uint8_t *gd_bk_t;
#define GD_TABLE(name) bloom_gd_##name##_bk
static inline uint32_t code_of(const uint32_t *t, gd_bk_t bk, uint32_t half, uint32_t v)
{
    (void)half;
    return gd_code_bk(t, bk, v);
}
#else
typedef const void *gd_bk_t;
#define GD_TABLE(name) NULL
static inline uint32_t code_of(const uint32_t *t, gd_bk_t bk, uint32_t half, uint32_t v)
{
    (void)bk;
    uint32_t k = 0;
    for (uint32_t s = half; s; s >>= 1)
        k += s & (0u - (uint32_t)(t[k + s] <= v));
    return k;
}

static inline uint32_t gd_to_q20(uint64_t c)
{
    c <<= 20 - BLOOM_LIN_BITS;
    return c > 0xFFFFFFFEu ? 0xFFFFFFFEu : (uint32_t)c;
}
#endif
#define to_q20 gd_to_q20

/* round(c / (c + 1) * 65536) = floor((2^17 c + d) / 2d), d = c + 2^F: the
 * tone-mapped value in Q16.16. c < 2^34, so the numerator is < 2^52 and the
 * quotient <= 65536; 2d passes 32 bits only for c above 2^31 (HDR input at
 * a high strength): then a short shift-subtract division. */
static uint32_t tonemap_q16(uint64_t c)
{
    const uint64_t d2 = 2u * (c + BLOOM_LIN_ONE), num = (c << 17) + (d2 >> 1);
    if (d2 <= 0xFFFFFFFFu)
        return bloom_div_u64_u32(num, (uint32_t)d2);
    uint64_t rem = num;
    uint32_t q = 0;
    for (int i = 16; i >= 0; i--)
        if ((d2 << i) <= rem) {
            rem -= d2 << i;
            q |= 1u << i;
        }
    return q;
}

/* ---- rows without bloom: a table of each input code's output ----------------- */

/* Where U_1's rows are zero, B = 0 and c = S (the debug view: c = 0): the
 * output of a channel is a function of its input code alone, for 8/6/5-bit
 * input. The table of those outputs (one uint32_t per input code and
 * output class: 256 or 512 words for 8-bit input, 96 for RGB565) lives in
 * scratch row 1, the decoded-source row of rows with bloom, and its last
 * word GD_ZT_AT says whether it is there: cleared at row 0 of every frame
 * (the scratch is the caller's memory, never assumed) and whenever a row
 * with bloom decodes the source into that row, set when the table is
 * built. No memory beyond the two scratch rows the preset had. */
#define GD_ZT_MARK 0x67645a54u
#define GD_ZT_AT(ctx) (bg_scratch((ctx), 1)[(ctx)->par.scratch_len - 1u])

/* The output of a decoded sample S at output class cls: 8, 6 or 5 (codes
 * by the gamma or linear thresholds), 16 (RGBQ16: the tone-mapped Q16). */
static uint32_t out_value(const bg_ctx_t *ctx, uint32_t S, int cls)
{
    const bool lin = ctx->par.out.linear;
    if (ctx->par.out.debug)
        S = 0;
    if (cls == 16)
        return tonemap_q16(S);
    if (cls == 8)
        return code_of(lin ? bloom_gd_lin8 : bloom_gd_gamma8, lin ? GD_TABLE(lin8) : GD_TABLE(gamma8), 128,
                       to_q20(S));
    if (cls == 6)
        return code_of(lin ? bloom_gd_lin6 : bloom_gd_gamma6, lin ? GD_TABLE(lin6) : GD_TABLE(gamma6), 32,
                       to_q20(S));
    return code_of(lin ? bloom_gd_lin5 : bloom_gd_gamma5, lin ? GD_TABLE(lin5) : GD_TABLE(gamma5), 16,
                   to_q20(S));
}

/* The tables of channels R, G, B into tab[0..2], built in scratch row 1
 * when it has room; NULL tab[0] when not (RGBQ16 input, or a row too short:
 * the caller takes the general path). RGB888 to RGB888 also has the table
 * as 256 bytes after its 256 words (the lut8 kernels' form, packed once a
 * frame, not once a row), returned when the row has room, else NULL. */
static const uint8_t *zero_tables(const bg_ctx_t *ctx, const uint32_t *tab[3])
{
    const bloom_format_t in = ctx->par.out.in_fmt, of = ctx->par.out.out_fmt;
    const int ocls = of == BLOOM_FMT_RGBQ16 ? 16 : of == BLOOM_FMT_RGB565 ? 5 : 8;
    const int gcls = of == BLOOM_FMT_RGB565 ? 6 : ocls;
    const bool in8 = in == BLOOM_FMT_RGB888 || in == BLOOM_FMT_XRGB8888;
    const size_t size = in8 ? (gcls != ocls ? 512u : 256u) : 96u;
    uint32_t *t = bg_scratch(ctx, 1);
    tab[0] = NULL;
    if ((!in8 && in != BLOOM_FMT_RGB565) || size + 1u > ctx->par.scratch_len)
        return NULL;
    uint8_t *bytes =
        in == BLOOM_FMT_RGB888 && of == BLOOM_FMT_RGB888 && 256u + 64u + 1u <= ctx->par.scratch_len
            ? (uint8_t *)(void *)(t + 256)
            : NULL;
    const uint32_t *tg = in8 && gcls == ocls ? t : t + (in8 ? 256 : 32);
    tab[0] = tab[2] = t;
    tab[1] = tg;
    if (GD_ZT_AT(ctx) == GD_ZT_MARK)
        return bytes;
    uint32_t o[3];
    if (in8) {
        for (uint32_t c = 0; c < 256; c++) {
            bloom_dec3(c, c, c, o, ctx->par.out.linear);
            t[c] = out_value(ctx, o[0], ocls);
            if (tg != t)
                t[256 + c] = out_value(ctx, o[1], gcls);
        }
    } else {
        for (uint32_t c = 0; c < 64; c++) {
            const uint32_t wd = ((c & 31u) << 11) | (c << 5);
            const uint8_t px[2] = {(uint8_t)wd, (uint8_t)(wd >> 8)};
            bloom_dec_rgb565(px, o, ctx->par.out.linear);
            if (c < 32)
                t[c] = out_value(ctx, o[0], ocls);
            t[32 + c] = out_value(ctx, o[1], gcls);
        }
    }
    if (bytes)
        for (int c = 0; c < 256; c++)
            bytes[c] = (uint8_t)t[c];
    GD_ZT_AT(ctx) = GD_ZT_MARK;
    return bytes;
}

/* The output row from the tables: each pixel read whole before it is
 * written (in place: same format, same place). False when there are no
 * tables. */
static bool zero_row(const bg_ctx_t *ctx, const uint8_t *s, uint8_t *d, int w)
{
    const uint32_t *tab[3];
    const uint8_t *bytes = zero_tables(ctx, tab);
    if (!tab[0])
        return false;
    const bloom_format_t in = ctx->par.out.in_fmt, of = ctx->par.out.out_fmt;
    const uint32_t *t0 = tab[0], *t1 = tab[1], *t2 = tab[2];
    if (bytes) { /* RGB888 to RGB888 */
        gd_kern_for(ctx->kern.isa)->lut8(s, bytes, d, 3 * w);
        return true;
    }
    const int ib = bloom_format_bpp(in), ob = bloom_format_bpp(of);
    for (int x = 0; x < w; x++, s += ib, d += ob) {
        uint32_t c[3];
        if (in == BLOOM_FMT_RGB565) {
            const uint32_t wd = (uint32_t)s[0] | ((uint32_t)s[1] << 8);
            c[0] = t0[wd >> 11];
            c[1] = t1[(wd >> 5) & 63u];
            c[2] = t2[wd & 31u];
        } else {
            const int o = in == BLOOM_FMT_XRGB8888 ? 2 : 0; /* XRGB8888 bytes: B, G, R, X */
            c[0] = t0[s[o]];
            c[1] = t1[s[1]];
            c[2] = t2[s[2 - o]];
        }
        if (of == BLOOM_FMT_RGBQ16) {
            memcpy(d, c, sizeof c);
        } else if (of == BLOOM_FMT_RGB565) {
            const uint32_t wd = (c[0] << 11) | (c[1] << 5) | c[2];
            d[0] = (uint8_t)wd;
            d[1] = (uint8_t)(wd >> 8);
        } else if (of == BLOOM_FMT_XRGB8888) {
            d[0] = (uint8_t)c[2];
            d[1] = (uint8_t)c[1];
            d[2] = (uint8_t)c[0];
            d[3] = 0xFF;
        } else {
            d[0] = (uint8_t)c[0];
            d[1] = (uint8_t)c[1];
            d[2] = (uint8_t)c[2];
        }
    }
    return true;
}

/* ---- the output row ------------------------------------------------------------ */

/* Input 0: U_1 rows m-1 .. m+1 (BG_UP); input 1: the source row (BG_SAME).
 * B = tent(U_1) into scratch 0 (U_1's rows zero: B = 0, by the tables above
 * where they apply), S decoded into scratch 1 (8-bit output of sRGB RGB888
 * input: decoded by the tone kernel on the fly), then per sample c = S +
 * ((strength * B + 2^15) >> 16) (u64: B < 3 * 2^28, strength <= 2^20) and
 * the code by the thresholds. */
static bool gd_out(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2]};
    const int w = n->w;
    const uint8_t *src = (const uint8_t *)in[1][0];
    uint32_t *bl = bg_scratch(ctx, 0), *sv = bg_scratch(ctx, 1);
    const uint32_t s = ctx->cfg->p.strength;
    const bool zero = bg_in_zero(ctx, 0, 0, 2);
    if (r == 0) /* a new frame: no table is trusted (an earlier engine's, or none) */
        GD_ZT_AT(ctx) = 0;
    if (zero && zero_row(ctx, src, (uint8_t *)dst, w))
        return true;
    if (zero)
        memset(bl, 0, (size_t)w * 3u * sizeof *bl);
    else
        ctx->kern.tent(u, r & 1, NULL, bl, 0, w, bg_in_w(ctx, n, 0)); /* picked at bloom_init */
    const bool lin = ctx->par.out.linear;
    uint8_t *p = (uint8_t *)dst;
#if !BLOOM_SMALL
    if (ctx->par.out.out_fmt == BLOOM_FMT_RGB888 || ctx->par.out.out_fmt == BLOOM_FMT_XRGB8888) {
        const bool fused = ctx->par.out.in_fmt == BLOOM_FMT_RGB888 && !lin && !ctx->par.out.debug;
        if (!fused) {
            GD_ZT_AT(ctx) = 0; /* sv is the zero tables' row */
            if (ctx->par.out.debug)
                memset(sv, 0, (size_t)w * 3u * sizeof *sv);
            else
                bloom_decode_row(ctx->par.out.in_fmt, lin, src, sv, w);
        }
        const bool xrgb = ctx->par.out.out_fmt == BLOOM_FMT_XRGB8888;
        uint8_t *codes = xrgb ? (uint8_t *)bl : p;
        gd_kern_for(ctx->kern.isa)
            ->tone8(bl, sv, fused ? src : NULL, bloom_srgb_dec8, codes, 3 * w, s,
                    lin ? bloom_gd_lin8 : bloom_gd_gamma8, lin ? GD_TABLE(lin8) : GD_TABLE(gamma8));
        if (xrgb)
            for (int x = 0; x < w; x++, p += 4) {
                p[0] = codes[3 * x + 2];
                p[1] = codes[3 * x + 1];
                p[2] = codes[3 * x];
                p[3] = 0xFF;
            }
        return true;
    }
#endif
    GD_ZT_AT(ctx) = 0;
    if (ctx->par.out.debug)
        memset(sv, 0, (size_t)w * 3u * sizeof *sv);
    else
        bloom_decode_row(ctx->par.out.in_fmt, lin, src, sv, w);
    if (ctx->par.out.out_fmt == BLOOM_FMT_RGBQ16) {
        for (int x = 0; x < w; x++, p += 12) {
            uint32_t q[3];
            for (int ch = 0; ch < 3; ch++)
                q[ch] = tonemap_q16(((s * (uint64_t)bl[3 * x + ch] + 32768u) >> 16) + sv[3 * x + ch]);
            memcpy(p, q, sizeof q);
        }
        return true;
    }
    const uint32_t *t8 = lin ? bloom_gd_lin8 : bloom_gd_gamma8;
    const uint32_t *t6 = lin ? bloom_gd_lin6 : bloom_gd_gamma6;
    const uint32_t *t5 = lin ? bloom_gd_lin5 : bloom_gd_gamma5;
    const gd_bk_t b8 = lin ? GD_TABLE(lin8) : GD_TABLE(gamma8);
    const gd_bk_t b6 = lin ? GD_TABLE(lin6) : GD_TABLE(gamma6);
    const gd_bk_t b5 = lin ? GD_TABLE(lin5) : GD_TABLE(gamma5);
    /* codes in place of the composite, in bl */
    if (ctx->par.out.out_fmt == BLOOM_FMT_RGB565) {
        for (int x = 0; x < w; x++) {
            uint32_t *c = bl + 3 * x;
            const uint32_t *sx = sv + 3 * x;
            c[0] = code_of(t5, b5, 16, to_q20(((s * (uint64_t)c[0] + 32768u) >> 16) + sx[0]));
            c[1] = code_of(t6, b6, 32, to_q20(((s * (uint64_t)c[1] + 32768u) >> 16) + sx[1]));
            c[2] = code_of(t5, b5, 16, to_q20(((s * (uint64_t)c[2] + 32768u) >> 16) + sx[2]));
            const uint32_t wd = (c[0] << 11) | (c[1] << 5) | c[2];
            p[2 * x] = (uint8_t)wd;
            p[2 * x + 1] = (uint8_t)(wd >> 8);
        }
        return true;
    }
    for (int i = 0; i < 3 * w; i++)
        bl[i] = code_of(t8, b8, 128, to_q20(((s * (uint64_t)bl[i] + 32768u) >> 16) + sv[i]));
    if (ctx->par.out.out_fmt == BLOOM_FMT_XRGB8888) {
        for (int x = 0; x < w; x++, p += 4) {
            p[0] = (uint8_t)bl[3 * x + 2];
            p[1] = (uint8_t)bl[3 * x + 1];
            p[2] = (uint8_t)bl[3 * x];
            p[3] = 0xFF;
        }
    } else {
        for (int i = 0; i < 3 * w; i++)
            p[i] = (uint8_t)bl[i];
    }
    return true;
}

/* ---- hooks ------------------------------------------------------------------ */

static void defaults(bloom_config_t *cfg)
{
    cfg->threshold = BLOOM_ONE * 3u / 4u; /* 0.75: LDR input blooms its brightest quarter */
    cfg->soft_knee = 0;                   /* the recipe has no knee (ignored anyway) */
    cfg->levels = GD_LEVELS;              /* 1/2, 1/4, 1/8 (cfg->levels is ignored) */
    cfg->p.strength = BLOOM_ONE;          /* 1.0 */
}

static bloom_status_t validate(const bloom_config_t *cfg)
{
    if (cfg->aux_fmt != BLOOM_AUX_NONE)
        return BLOOM_E_AUX;
    if (cfg->flags & (BLOOM_FLAG_SATURATE | BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE | BLOOM_FLAG_KEEP_LEVELS))
        return BLOOM_E_FLAGS;
    if (cfg->p.strength > GD_MAX_STRENGTH)
        return BLOOM_E_STRENGTH;
    return BLOOM_OK;
}

static bloom_status_t build(bg_graph_t *g, bg_params_t *par)
{
    bg_levels(g, GD_LEVELS);
    const int L = g->L;
    par->knee.k = 0;                         /* no soft knee: bloom_query reports knee_q = 0 */
    par->out.intensity = g->cfg->p.strength; /* ... and intensity_q = the strength (linear Q16.16) */
    int D[GD_LEVELS + 1];
    /* a source pixel with no channel above t is zero after the box and the
     * threshold (sim/docs/presets/gamedev.md, "Zero rows"); every node but
     * the output is zero-preserving */
    par->dark_cut = par->knee.t;
    D[1] = bg_node(g, gd_d1, g->w[1], g->h[1], 3, 1);
    bg_input(g, D[1], BG_SRC, BG_DOWN, -1, 2);
    bg_zero(g, D[1]);
    for (int k = 2; k <= L; k++) {
        D[k] = bg_node(g, bg_fn_box, g->w[k], g->h[k], 3, k);
        bg_input(g, D[k], D[k - 1], BG_DOWN, -1, 2);
        bg_zero(g, D[k]);
    }
    int U = bg_node(g, gd_up, g->w[L], g->h[L], 3, L);
    bg_input(g, U, D[L], BG_SAME, -4, 4);
    bg_zero(g, U);
    for (int k = L - 1; k >= 1; k--) {
        int dk = D[k];
        if (k == 1) { /* D_1 again for the up pass: no delay line at the widest level */
            dk = bg_node(g, gd_d1, g->w[1], g->h[1], 3, 1);
            bg_input(g, dk, BG_SRC, BG_DOWN, -1, 2);
            bg_zero(g, dk);
        }
        const int u = bg_node(g, gd_up, g->w[k], g->h[k], 3, k);
        bg_input(g, u, U, BG_UP, -1, 1); /* first: D_k rows are made only when U_k+1 is ready */
        bg_input(g, u, dk, BG_SAME, -4, 4);
        bg_zero(g, u);
        U = u;
    }
    const int o = bg_node(g, gd_out, g->w[0], g->h[0], 3, 0);
    bg_input(g, o, U, BG_UP, -1, 1);
    bg_input(g, o, BG_SRC, BG_SAME, 0, 0);
    g->out_node = o;
    par->scratch_rows = 2; /* the Gaussian's vertical pass, the output's bloom row */
    if (!BLOOM_SMALL)
        par->views = true; /* every row function reads its widths by bg_in_w (or clamps at its own) */
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_gamedev = {"gamedev", defaults, validate, build};

#else
typedef int bloom_preset_gamedev_unused_t;
#endif
