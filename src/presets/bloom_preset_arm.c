/* Preset "arm": the Arm mobile guide's bloom (sim/docs/presets/arm.md).
 *
 * Dual filtering (Bjorge, SIGGRAPH 2015) on a one-channel plane:
 *   P    = Y(S) * mask           full resolution, Y = Rec.709 luminance
 *   D_1  = knee(down(P))         the soft knee on one channel, no division
 *   D_k  = down(D_k-1)           k = 2 .. L
 *   U_L  = D_L,  U_k = up(U_k+1) k = L-1 .. 1 (a blur: no per-level sum)
 *   B    = up(U_1)               full resolution
 *   out  = S + I * tint * B      (DEBUG_VIEW: I * tint * B)
 * down: 4x4 [1 1 1 1; 1 5 5 1; 1 5 5 1; 1 1 1 1] / 32 over 2x-1 .. 2x+2,
 *       = (4x4 box + 4 * 2x2 centre) / 32, round half to even (a tie in
 *       32 sums, each up, was +1/64 LSB per level);
 * up:   3x3 per output parity, /192 (arm.md derives it from the 8 taps),
 *       round half up, the /3 as a multiply by 0xAAAAAAAB >> 33.
 * With BLOOM_FLAG_BAKED there is no pyramid: out = S + S * map * strength,
 * the aux plane being the map: one output node.
 *
 * Every value of the plane is a Q12.20 linear sample <= M = 2^28 - 16;
 * the sums that can pass 2^32 are formed in 64 bits (arm.md, overflow). */
#include "bloom_preset_arm.h"
#include "bloom_stages.h"
#include "bloom_pixel.h"

#include <string.h>

#if BLOOM_USE_ARM

#define ARM_WR BLOOM_ARM_WR /* Rec.709, Q24 (bloom_preset_arm.h) */
#define ARM_WG BLOOM_ARM_WG
#define ARM_WB BLOOM_ARM_WB

/* A mask or map code as Q24 (0 .. 2^24), = bg_aux_q24: U8 c*2^24/255
 * rounded = 65793c + (c >= 128); U16 c*2^24/65535 rounded. */
static inline uint32_t aux_q24(const uint8_t *row, int x, bool u16)
{
    if (u16) {
        uint16_t c16;
        memcpy(&c16, row + 2 * x, 2);
        const uint32_t c = c16;
        return 256u * c + (256u * c + 32767u) / 65535u;
    }
    const uint32_t c = row[x];
    return 65793u * c + (c >> 7);
}

/* Pad a column-sum row: p[0] = p[1] (column -1), p[sw+1] = p[sw+2] = p[sw]. */
static inline void pad(uint32_t *p, int sw)
{
    p[0] = p[1];
    p[sw + 1] = p[sw];
    p[sw + 2] = p[sw];
}

/* The soft knee on one channel, in place: max(soft, b - T), soft =
 * clamp(b - T + K, 0, 2K)^2 / (4K + 0.00004) rounded (as 2x^2 / (8K + E8),
 * bloom_kernels.h); 0 below T - K (returns the OR of the results). Below b = 2^F / 100000 the spec's
 * max(b, 0.00001) scales it by b / 0.00001 (exact product, rounded). */
static uint32_t knee1(uint32_t *row, int w, const bloom_knee_t *kn)
{
    const uint32_t t = kn->t, k = kn->k, cut = t > k ? t - k : 0u, hi = t + k;
    uint32_t any = 0;
    for (int x = 0; x < w; x++) {
        const uint32_t b = row[x];
        if (b <= cut) {
            row[x] = 0;
        } else if (b >= hi) {
            row[x] = b - t; /* soft < K <= b - T */
        } else {            /* T - K < b < T + K: K >= 1 */
            const uint64_t xx = (uint64_t)(b - cut);
            const uint32_t den = 8u * k + BLOOM_KNEE_E8;
            const uint32_t soft = bloom_div_u64_u32(2u * xx * xx + den / 2u, den);
            row[x] = b > t && b - t > soft ? b - t : soft;
        }
        if ((uint64_t)b * 100000u < (1ull << BLOOM_LIN_BITS)) /* tiny b: v * b / 0.00001 */
            row[x] =
                (uint32_t)(((uint64_t)row[x] * b * 100000u + (1u << (BLOOM_LIN_BITS - 1))) >> BLOOM_LIN_BITS);
        any |= row[x];
    }
    return any;
}

static inline uint32_t lum3(const uint32_t *o)
{
    /* Y <= M: 64-bit products (Q24 weights x 2^28, their sum < 2^53) */
    return (uint32_t)((ARM_WR * (uint64_t)o[0] + ARM_WG * (uint64_t)o[1] + ARM_WB * (uint64_t)o[2] +
                       (1u << 23)) >>
                      24);
}

/* Y of n source pixels, decoded inline (one loop per format and curve). */
#define ARM_LUM_LOOP(step, dec)                                                                              \
    for (int x = 0; x < n; x++, p += (step)) {                                                               \
        uint32_t o[3];                                                                                       \
        dec;                                                                                                 \
        y[x] = lum3(o);                                                                                      \
    }
static void lum_row(bloom_format_t fmt, bool lin, const uint8_t *p, uint32_t *y, int n)
{
    switch (fmt) {
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        if (lin)
            ARM_LUM_LOOP(3, BLOOM_DEC_RGB888(p, o, true))
        else
            ARM_LUM_LOOP(3, BLOOM_DEC_RGB888(p, o, false))
        return;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        if (lin)
            ARM_LUM_LOOP(4, BLOOM_DEC_XRGB8888(p, o, true))
        else
            ARM_LUM_LOOP(4, BLOOM_DEC_XRGB8888(p, o, false))
        return;
#endif
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        if (lin)
            ARM_LUM_LOOP(2, BLOOM_DEC_RGB565(p, o, true))
        else
            ARM_LUM_LOOP(2, BLOOM_DEC_RGB565(p, o, false))
        return;
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16:
        ARM_LUM_LOOP(12, BLOOM_DEC_RGBQ16(p, o))
        return;
#endif
#if BLOOM_USE_RGBF32
    case BLOOM_FMT_RGBF32:
        ARM_LUM_LOOP(12, BLOOM_DEC_RGBF32(p, o))
        return;
#endif
    default: /* refused by bloom_query */
        return;
    }
}
#undef ARM_LUM_LOOP

/* D_1 pixels xa .. xb-1 (in[] as fn_d1): P = Y * mask of source columns
 * 2xa-1 .. 2xb-2+2 (clamped), their column sums, dual down, knee. Returns
 * the OR of the pixels made. */
static uint32_t d1_range(const bg_ctx_t *ctx, const bg_node_t *n, const void *const *const in[BG_MAX_IN],
                         uint32_t *dst, int xa, int xb)
{
    const int w0 = bg_in_w(ctx, n, 0), ca = imax(2 * xa - 1, 0), cb = imin(2 * xb, w0 - 1), nc = cb - ca + 1;
    uint32_t *c4 = bg_scratch(ctx, 0), *c2 = bg_scratch(ctx, 1), *y = bg_scratch(ctx, 2);
    const bool u16 = ctx->aux_bpp == 2;
    const size_t bpp = (size_t)ctx->src_bpp;
    const bloom_arm_kern_t *K = bloom_arm_kern(ctx->kern.isa);
    const bloom_format_t fmt = ctx->par.out.in_fmt;
    if (!ctx->aux_bpp && !ctx->par.out.linear && (fmt == BLOOM_FMT_RGB888 || fmt == BLOOM_FMT_XRGB8888)) {
        for (int i = 0; i < 4; i++) /* 8-bit sRGB, no mask: Y summed into the column sums */
            K->lum8((const uint8_t *)in[0][i] + (size_t)ca * bpp, c4 + 1 + ca, c2 + 1 + ca, nc,
                    fmt == BLOOM_FMT_XRGB8888, i);
    } else {
        for (int i = 0; i < 4; i++) {
            lum_row(ctx->par.out.in_fmt, ctx->par.out.linear, (const uint8_t *)in[0][i] + (size_t)ca * bpp,
                    y + ca, nc);
            if (ctx->aux_bpp) { /* P = (Y * mask + 2^23) >> 24, 64-bit: 2^28 * 2^24 */
                const uint8_t *m = (const uint8_t *)in[1][i];
                for (int x = ca; x <= cb; x++) {
                    const uint32_t q = aux_q24(m, x, u16);
                    if (q != 1u << 24)
                        y[x] = (uint32_t)(((uint64_t)y[x] * q + (1u << 23)) >> 24);
                }
            }
            uint32_t *c = c4 + 1, *h = c2 + 1;
            if (i == 0)
                memcpy(c + ca, y + ca, (size_t)nc * sizeof *y);
            else
                for (int x = ca; x <= cb; x++)
                    c[x] += y[x];
            if (i == 1)
                memcpy(h + ca, y + ca, (size_t)nc * sizeof *y);
            else if (i == 2)
                for (int x = ca; x <= cb; x++)
                    h[x] += y[x];
        }
    }
    if (ca == 0)
        c4[0] = c4[1], c2[0] = c2[1];
    if (cb == w0 - 1)
        pad(c4, w0), pad(c2, w0);
    K->down_h(c4 + 2 * xa, c2 + 2 * xa, dst + xa, xb - xa);
    return knee1(dst + xa, xb - xa, &ctx->par.knee);
}

/* D_1 pixels per block of ARM_DB whose source columns 2x-1 .. 2x+2 (x in
 * the block) are dark in all four rows: zeros (arm.md, "skipping"). */
#define ARM_DB 16

/* D_1. Input 0: source rows 2r-1 .. 2r+2; input 1 (with a mask): aux rows
 * 2r-1 .. 2r+2. P = Y * mask per source pixel, dual down, knee; blocks of
 * dark source pixels are zeros without being computed. False when the row
 * came out all zero. */
static bool fn_d1(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    (void)r;
    const int dw = n->w, w0 = bg_in_w(ctx, n, 0);
    uint32_t *d = (uint32_t *)dst;
    if (!ctx->dark_src)
        return d1_range(ctx, n, in, d, 0, dw) != 0;
    const size_t bpp = (size_t)ctx->src_bpp;
    const bloom_dark_fn dark_row = BLOOM_KERN_DARK(&ctx->kern);
    uint32_t any = 0;
    int run = 0; /* first pixel not written yet */
    for (int x = 0; x < dw; x += ARM_DB) {
        const int xe = imin(x + ARM_DB, dw), ca = imax(2 * x - 1, 0), cb = imin(2 * xe, w0 - 1);
        bool dark = true;
        for (int i = 0; i < 4 && dark; i++) /* a row tagged dark needs no test */
            dark = bg_in_zero(ctx, 0, i, i) ||
                   dark_row(ctx->par.out.in_fmt, (const uint8_t *)in[0][i] + (size_t)ca * bpp, cb - ca + 1,
                            &ctx->dark);
        if (!dark)
            continue; /* computed with its run */
        if (run < x)
            any |= d1_range(ctx, n, in, d, run, x);
        memset(d + x, 0, (size_t)(xe - x) * sizeof *d);
        run = xe;
    }
    if (run < dw)
        any |= d1_range(ctx, n, in, d, run, dw);
    return any != 0;
}

/* D_k, k >= 2. Input 0: D_k-1 rows 2r-1 .. 2r+2 (one channel). False when
 * the row came out all zero. */
static bool fn_down(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                    void *dst)
{
    (void)r;
    const bloom_arm_kern_t *K = bloom_arm_kern(ctx->kern.isa);
    const int sw = bg_in_w(ctx, n, 0);
    uint32_t *c4 = bg_scratch(ctx, 0), *c2 = bg_scratch(ctx, 1);
    K->down_v((const uint32_t *)in[0][0], (const uint32_t *)in[0][1], (const uint32_t *)in[0][2],
              (const uint32_t *)in[0][3], c4 + 1, c2 + 1, sw);
    pad(c4, sw);
    pad(c2, sw);
    return K->down_h(c4, c2, (uint32_t *)dst, n->w) != 0;
}

/* The dual up filter of rows u[0..2] = m-1, m, m+1 (width sw) onto a row of
 * parity odd (width dw = 2sw or 2sw - 1), in two halves (bloom_preset_arm.h).
 * Vertical, lower columns c0 .. c1: a = A0 (1,3,0), v = T (3,4,1) (mirrored
 * for odd rows) into a, v (column j at index j + 1), padded at the edges;
 * horizontal, output pairs n0 .. n1-1 (columns 2n, 2n+1 < dw) into
 * dst[2n - base]: even column 2n 11a(n-1) + 28a(n) + a(n+1) + v(n-1) +
 * 3v(n), odd 2n+1 mirrored; the sum S <= 192M is 64-bit; out =
 * floor((S + 96) / 192) = floor(q / 3), q = (S + 96) >> 6 < 2^30,
 * q / 3 = (q * 0xAAAAAAAB) >> 33. Returns the OR of the pixels made. */
static void up_av(const bloom_arm_kern_t *K, const void *const u[3], int sh, int odd, uint32_t *a,
                  uint32_t *v, int c0, int c1, int sw)
{
    const void *u0 = odd ? u[2] : u[0], *u2 = odd ? u[0] : u[2];
#if BLOOM_USE_S16
    if (sh >= 0) /* 16-bit rows (fn_up16, fn_out): their sums << sh */
        bloom_arm_up_v16((const uint16_t *)u0 + c0, (const uint16_t *)u[1] + c0, (const uint16_t *)u2 + c0,
                         a + 1 + c0, v + 1 + c0, c1 - c0 + 1, sh);
    else
#else
    (void)sh;
#endif
        K->up_v((const uint32_t *)u0 + c0, (const uint32_t *)u[1] + c0, (const uint32_t *)u2 + c0, a + 1 + c0,
                v + 1 + c0, c1 - c0 + 1);
    if (c0 == 0)
        a[0] = a[1], v[0] = v[1];
    if (c1 == sw - 1)
        a[sw + 1] = a[sw], v[sw + 1] = v[sw];
}

static uint32_t up_out(const bloom_arm_kern_t *K, const uint32_t *a, const uint32_t *v, uint32_t *dst, int n0,
                       int n1, int dw, int base)
{
    const bool last_even = 2 * (n1 - 1) + 1 >= dw; /* the last pair has no odd column */
    const int np = n1 - n0 - (last_even ? 1 : 0);
    uint32_t any = np > 0 ? K->up_h(a + n0, v + n0, dst + 2 * n0 - base, np) : 0u;
    if (last_even) {
        const uint64_t a0 = a[n1 - 1], a1 = a[n1], a2 = a[n1 + 1], v0 = v[n1 - 1], v1 = v[n1];
        dst[2 * (n1 - 1) - base] = bloom_arm_div192(11u * a0 + 28u * a1 + a2 + v0 + 3u * v1);
        any |= dst[2 * (n1 - 1) - base];
    }
    return any;
}

/* U_k. Input 0: U_k+1 rows m-1 .. m+1 (BG_UP). False when the row came out
 * all zero. */
static bool fn_up(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    const bloom_arm_kern_t *K = bloom_arm_kern(ctx->kern.isa);
    const int sw = bg_in_w(ctx, n, 0), np = imin(sw, (n->w + 1) / 2); /* (sw is more in a tile) */
    uint32_t *a = bg_scratch(ctx, 0), *v = bg_scratch(ctx, 1);
    up_av(K, in[0], -1, r & 1, a, v, 0, imin(np, sw - 1), sw);
    return up_out(K, a, v, (uint32_t *)dst, 0, np, n->w, 0) != 0;
}

#if BLOOM_USE_S16
/* The nodes on 16-bit rows (cfg.sample_bits = 16; arm.md, "16-bit
 * samples"): the 32-bit node's work into a scratch row, then its samples
 * stored as uint16_t. D_1 is narrowed by F - G bits, half to even; the
 * filters average values already in G units, so their results fit and are
 * copied as they are. */
static uint32_t store16(const uint32_t *t, uint16_t *dst, int n)
{
    uint32_t any = 0;
    for (int i = 0; i < n; i++) { /* t[i] <= 2^G: an average of values that are */
        dst[i] = (uint16_t)t[i];
        any |= t[i];
    }
    return any;
}

static bool fn_d1_16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                     void *dst)
{
    uint32_t *t = bg_scratch(ctx, 3); /* (d1_range takes rows 0 .. 2) */
    (void)fn_d1(ctx, n, r, in, t);
    return bloom_row_narrow16_k(&ctx->kern, t, (uint16_t *)dst, n->w, ctx->par.s16) != 0;
}

static bool fn_down16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                      void *dst)
{
    (void)r;
    const bloom_arm_kern_t *K = bloom_arm_kern(ctx->kern.isa);
    const int sw = bg_in_w(ctx, n, 0);
    uint32_t *c4 = bg_scratch(ctx, 0), *c2 = bg_scratch(ctx, 1), *t = bg_scratch(ctx, 2);
    bloom_arm_down_v16((const uint16_t *)in[0][0], (const uint16_t *)in[0][1], (const uint16_t *)in[0][2],
                       (const uint16_t *)in[0][3], c4 + 1, c2 + 1, sw);
    pad(c4, sw);
    pad(c2, sw);
    K->down_h(c4, c2, t, n->w);
    return store16(t, (uint16_t *)dst, n->w) != 0;
}

static bool fn_up16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                    void *dst)
{
    const bloom_arm_kern_t *K = bloom_arm_kern(ctx->kern.isa);
    const int sw = bg_in_w(ctx, n, 0), np = imin(sw, (n->w + 1) / 2);
    uint32_t *a = bg_scratch(ctx, 0), *v = bg_scratch(ctx, 1), *t = bg_scratch(ctx, 2);
    up_av(K, in[0], 0, r & 1, a, v, 0, imin(np, sw - 1), sw);
    (void)up_out(K, a, v, t, 0, np, n->w, 0);
    return store16(t, (uint16_t *)dst, n->w) != 0;
}
#endif

/* Per-channel composite factors g_c = I * tint_c, Q16.16 (< 2^24). */
static void tint_factors(const bg_ctx_t *ctx, uint32_t f[3])
{
    for (int c = 0; c < 3; c++)
        f[c] = (uint32_t)(((uint64_t)ctx->par.out.intensity * ctx->cfg->p.tint[c] + 32768u) >> 16);
}

/* The largest U_1 value of columns c0 .. c0+n-1 of three rows, in internal
 * units (16-bit rows when sh >= 0). */
static uint32_t max3(const bloom_arm_kern_t *K, const void *const u[3], int sh, int c0, int n)
{
#if BLOOM_USE_S16
    if (sh >= 0)
        return bloom_arm_max3_16((const uint16_t *)u[0] + c0, (const uint16_t *)u[1] + c0,
                                 (const uint16_t *)u[2] + c0, n)
               << sh;
#else
    (void)sh;
#endif
    return K->max3((const uint32_t *)u[0] + c0, (const uint32_t *)u[1] + c0, (const uint32_t *)u[2] + c0, n);
}

static inline uint32_t sat32(uint64_t v)
{
    return v > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)v;
}

/* Output. Input 0: the source row; input 1: U_1 rows m-1 .. m+1 (BG_UP).
 * v_c = S_c + ((g_c * B + 32768) >> 16), encoded, in chunks of 64 pixels.
 * Unless BLOOM_FLAG_NO_SKIP (same bits either way), a chunk is the source
 * decoded and encoded again (bloom_row_copy_c: the bytes themselves where
 * that is the identity) when its B is all zero, or, without computing B,
 * when the U_1 values it reads are all zero, or for 8-bit sRGB in and out
 * of one format when they bound every P_c by BLOOM_KEEP8_H0 (B <= max U:
 * arm.md, skipping); so is a row whose U_1 rows are all zero. */
#define ARM_CHUNK 64
static bool fn_out(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst)
{
    const int w = n->w, sw = bg_in_w(ctx, n, 1);
    const uint8_t *src = (const uint8_t *)in[0][0];
    uint8_t *out = (uint8_t *)dst;
    const bool skip = ctx->skip;
    if (skip && bg_in_zero(ctx, 1, 0, 2)) { /* B = 0: the source row (debug view: zeros) */
        bg_copy_row(ctx, src, out, w);
        return true;
    }
    const bloom_arm_kern_t *K = bloom_arm_kern(ctx->kern.isa);
    const void *const *const u = in[1];
    /* U_1 in 16-bit rows: widened (<< F - G, exact) in the up filter's sums */
    const int sh = ctx->par.s16 ? ctx->par.s16 : -1;
    uint32_t *a = bg_scratch(ctx, 0), *av = bg_scratch(ctx, 1), *b = bg_scratch(ctx, 2),
             *v = bg_scratch(ctx, 3);
    const size_t ibpp = (size_t)ctx->src_bpp, obpp = (size_t)bloom_format_bpp(ctx->par.out.out_fmt);
    uint32_t f[3];
    tint_factors(ctx, f);
    const uint64_t fmax = f[0] > f[1] ? (f[0] > f[2] ? f[0] : f[2]) : (f[1] > f[2] ? f[1] : f[2]);
    const bool keep8 = !BLOOM_SMALL && skip && !ctx->par.out.debug && !ctx->par.out.linear &&
                       ctx->par.out.in_fmt == ctx->par.out.out_fmt &&
                       (ctx->par.out.in_fmt == BLOOM_FMT_RGB888 || ctx->par.out.in_fmt == BLOOM_FMT_XRGB8888);
    for (int x0 = 0; x0 < w; x0 += ARM_CHUNK) {
        const int cn = imin(ARM_CHUNK, w - x0), n0 = x0 >> 1, n1 = ((x0 + cn - 1) >> 1) + 1;
        const int c0 = imax(n0 - 1, 0), c1 = imin(n1, sw - 1);
        if (skip) {
            const uint64_t um = max3(K, u, sh, c0, c1 - c0 + 1);
            if (um == 0 || (keep8 && ((fmax * um + 32768u) >> 16) <= BLOOM_KEEP8_H0)) {
                bloom_row_copy_c(src + (size_t)x0 * ibpp, out + (size_t)x0 * obpp, cn, &ctx->par.out);
                continue;
            }
        }
        up_av(K, u, sh, r & 1, a, av, c0, c1, sw);
        if (!up_out(K, a, av, b, n0, n1, w, x0) && skip) {
            bloom_row_copy_c(src + (size_t)x0 * ibpp, out + (size_t)x0 * obpp, cn, &ctx->par.out);
            continue;
        }
#if !BLOOM_SMALL
        if (keep8) {
            K->out8(src + (size_t)x0 * ibpp, b, f, out + (size_t)x0 * obpp, cn, ibpp == 4);
            continue;
        }
#endif
        if (ctx->par.out.debug)
            memset(v, 0, (size_t)cn * 3u * sizeof *v);
        else
            bloom_decode_row(ctx->par.out.in_fmt, ctx->par.out.linear, src + (size_t)x0 * ibpp, v, cn);
        for (int x = 0; x < cn; x++) {
            const uint64_t bx = b[x];
            uint32_t *p = v + 3 * x;
            p[0] = sat32(((f[0] * bx + 32768u) >> 16) + p[0]);
            p[1] = sat32(((f[1] * bx + 32768u) >> 16) + p[1]);
            p[2] = sat32(((f[2] * bx + 32768u) >> 16) + p[2]);
        }
        bloom_encode_row(ctx->par.out.out_fmt, ctx->par.out.linear, v, out + (size_t)x0 * obpp, cn);
    }
    return true;
}

/* Whether map codes x0 .. x0+n-1 are all 0 (f = 0 there). */
static bool map_zero(const uint8_t *map, int x0, int n, bool u16)
{
    const size_t b = u16 ? 2u : 1u;
    uint8_t any = 0;
    for (size_t i = (size_t)x0 * b; i < (size_t)(x0 + n) * b; i++)
        any |= map[i];
    return any == 0;
}

/* Baked output. Input 0: the source row; input 1: the map row.
 * f = (map_q24 * strength + 32768) >> 16 (Q24, <= 2^28), v = S + ((S f + 2^23) >> 24)
 * computed as (S (2^24 + f) + 2^23) >> 24 (S * 2^24 is a multiple of
 * 2^24; S (2^24 + f) <= 2^56.1): one multiply-add per channel. Debug view:
 * (S f + 2^23) >> 24. Where f = 0 (strength 0, or a chunk of zero map
 * codes) v = S: the source copied (bloom_row_copy_c), unless
 * BLOOM_FLAG_NO_SKIP (same bits). */
static bool fn_out_baked(const bg_ctx_t *ctx, const bg_node_t *n, int r,
                         const void *const *const in[BG_MAX_IN], void *dst)
{
    (void)r;
    const int w = n->w;
    uint32_t *v = bg_scratch(ctx, 0);
    const uint8_t *map = (const uint8_t *)in[1][0];
    const bool u16 = ctx->aux_bpp == 2;
    const uint64_t strength = ctx->cfg->p.strength, one = ctx->par.out.debug ? 0u : 1u << 24;
    const size_t obpp = (size_t)bloom_format_bpp(ctx->par.out.out_fmt), ibpp = (size_t)ctx->src_bpp;
    const uint8_t *src = (const uint8_t *)in[0][0];
    uint8_t *out = (uint8_t *)dst;
    if (ctx->skip && strength == 0) { /* f = 0: v = S (debug view: 0) */
        bloom_row_copy_c(src, out, w, &ctx->par.out);
        return true;
    }
    for (int x0 = 0; x0 < w; x0 += 256) { /* chunks of 256 pixels stay in the cache */
        const int cn = imin(256, w - x0);
        if (ctx->skip && map_zero(map, x0, cn, u16)) {
            bloom_row_copy_c(src + (size_t)x0 * ibpp, out + (size_t)x0 * obpp, cn, &ctx->par.out);
            continue;
        }
        bloom_decode_row(ctx->par.out.in_fmt, ctx->par.out.linear, src + (size_t)x0 * ibpp, v, cn);
        for (int x = 0; x < cn; x++) {
            const uint64_t f = ((uint64_t)aux_q24(map, x0 + x, u16) * strength + 32768u) >> 16;
            const uint64_t m = one + f;
            uint32_t *p = v + 3 * x;
            p[0] = sat32((p[0] * m + (1u << 23)) >> 24);
            p[1] = sat32((p[1] * m + (1u << 23)) >> 24);
            p[2] = sat32((p[2] * m + (1u << 23)) >> 24);
        }
        bloom_encode_row(ctx->par.out.out_fmt, ctx->par.out.linear, v, out + (size_t)x0 * obpp, cn);
    }
    return true;
}

static void defaults(bloom_config_t *cfg)
{
    cfg->aux_fmt = BLOOM_AUX_NONE; /* no mask: every pixel may bloom */
    cfg->p.tint[0] = cfg->p.tint[1] = cfg->p.tint[2] = BLOOM_ONE;
    cfg->p.strength = BLOOM_ONE; /* baked map strength 1.0 */
}

static bloom_status_t validate(const bloom_config_t *cfg)
{
    if (cfg->flags & (BLOOM_FLAG_SATURATE | BLOOM_FLAG_ADDITIVE | BLOOM_FLAG_KEEP_LEVELS))
        return BLOOM_E_FLAGS;
    if ((cfg->flags & BLOOM_FLAG_BAKED) && cfg->aux_fmt == BLOOM_AUX_NONE)
        return BLOOM_E_AUX; /* the baked map is the aux plane */
    if (cfg->aux_fmt != BLOOM_AUX_NONE && cfg->aux_fmt != BLOOM_AUX_U8 && cfg->aux_fmt != BLOOM_AUX_U16)
        return BLOOM_E_AUX;
    for (int c = 0; c < 3; c++)
        if (cfg->p.tint[c] > BLOOM_ONE)
            return BLOOM_E_TINT;
    if (cfg->p.strength > 16u * BLOOM_ONE)
        return BLOOM_E_STRENGTH;
    return BLOOM_OK;
}

/* Scratch: one-channel rows of at most w0 + 2 samples (luminance, column
 * sums, the up filter's padded rows), or the output's 3-channel chunks of
 * ARM_CHUNK (bloom) and 256 (baked) pixels. */
#define ARM_SCRATCH_MIN (3u * 256u + 16u)

static bloom_status_t build(bg_graph_t *g, bg_params_t *par)
{
    const int L = g->L;
    const size_t one = (size_t)g->w[0] + 16u;
    par->scratch_len = one > ARM_SCRATCH_MIN ? one : ARM_SCRATCH_MIN;
    if (g->cfg->flags & BLOOM_FLAG_BAKED) {
        const int o = bg_node(g, fn_out_baked, g->w[0], g->h[0], 3, 0);
        bg_input(g, o, BG_SRC, BG_SAME, 0, 0);
        bg_input(g, o, BG_AUX, BG_SAME, 0, 0);
        g->out_node = o;
        par->scratch_rows = 1;
        return BLOOM_OK;
    }
    /* every node but the output is zero-preserving, and a source pixel with
     * no channel above the knee's t - k makes zeros of D_1 (arm.md, skipping) */
    par->dark_cut = bg_knee_cut(par);
    if (BG_DARK_COPY)
        par->dark_copy = true; /* zero bloom: the source copied (fn_out) */
    int d = bg_node(g, fn_d1, g->w[1], g->h[1], 1, 1);
    bg_input(g, d, BG_SRC, BG_DOWN, -1, 2);
    if (g->cfg->aux_fmt != BLOOM_AUX_NONE)
        bg_input(g, d, BG_AUX, BG_DOWN, -1, 2);
    bg_zero(g, d);
    for (int k = 2; k <= L; k++) {
        const int nd = bg_node(g, fn_down, g->w[k], g->h[k], 1, k);
        bg_input(g, nd, d, BG_DOWN, -1, 2);
        bg_zero(g, nd);
        d = nd;
    }
    int u = d; /* U_L = D_L */
    for (int k = L - 1; k >= 1; k--) {
        const int nu = bg_node(g, fn_up, g->w[k], g->h[k], 1, k);
        bg_input(g, nu, u, BG_UP, -1, 1);
        bg_zero(g, nu);
        u = nu;
    }
    const int o = bg_node(g, fn_out, g->w[0], g->h[0], 3, 0);
    bg_input(g, o, BG_SRC, BG_SAME, 0, 0);
    bg_input(g, o, u, BG_UP, -1, 1);
    g->out_node = o;
    par->scratch_rows = 4;
#if BLOOM_USE_S16
    if (g->cfg->sample_bits == 16) { /* every node but the output on 16-bit rows */
        /* G: every value is at most the knee's peak (no per-level sums) */
        par->s16 = (uint8_t)(BLOOM_LIN_BITS - bloom_s16_frac(1, bloom_knee_peak(&par->knee)));
        for (int i = 0; i < g->nnodes; i++) {
            bg_node_t *nd = &g->node[i];
            if (i == o)
                continue;
            nd->fn = nd->fn == fn_d1 ? fn_d1_16 : nd->fn == fn_down ? fn_down16 : fn_up16;
            bg_s16(g, i);
        }
    }
#endif
    if (!BLOOM_SMALL)
        par->views = true; /* every row function reads its widths by bg_in_w */
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_arm = {"arm", defaults, validate, build};

#else
typedef int bloom_preset_arm_unused_t;
#endif
