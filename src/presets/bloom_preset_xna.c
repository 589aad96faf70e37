/* Preset "xna": the XNA Bloom sample with Kawase passes
 * (sim/docs/presets/xna.md has the maths, the choices and the proofs).
 *
 *   H   = box4x4(S)                         half resolution
 *   Q   = max(0, box4x4(H) - T)             quarter resolution, per channel
 *   K_0 = Q;  K_{i+1} = kawase_i(K_i)       i = 0 .. P-1
 *         kawase_i: per axis pixels x-i-1, x-i, x+i, x+i+1, weight 1/4 each;
 *         pass 0 times 1/(1 - T), pass P-1 times I
 *   Bh  = tent(K_P) (half);  B = tent(Bh) (full)
 *   out = b + S (1 - b), b = min(B, 1)      screen; DEBUG_VIEW: out = B
 * BLOOM_FLAG_SATURATE clamps Q and every K_i to 1.0.
 *
 * Integer form (Q(32-F).F samples, F = BLOOM_LIN_BITS):
 *   Q  = max(0, D - T_q), T_q = threshold << (F - 16)      (exact)
 *   a Kawase pass sums its 16 samples exactly (< 2^32), then
 *     first pass:  v = min((sh f + ((sl f) >> 16) + 2^11) >> 12, LIN_MAX), sum = sh 2^16 + sl,
 *                  f = round(2^40 / (2^16 - t)) (Q24, u64; a Q16 f was a fixed error of up
 *                  to 5e-6 of the whole glow, one-sided for a given threshold)
 *     other pass:  v = sum / 16, rounded half to even
 *     last pass:   v = min((v * I_q + 2^15) >> 16, LIN_MAX)
 *     SATURATE:    v = min(v, 2^F)
 *   screen: b = min(B, 2^F); v = b + ((S (2^F - b) + 2^(F-1)) >> F)  (u64 product).
 *
 * Zero rows (xna.md, "Skipping"): dark source rows (no channel above T)
 * skip H through a 16-row window, Q, the passes and the tent; an output
 * row with B = 0 is the source copied. The passes' sums and the screen run
 * in the kernels of bloom_preset_xna.h (SSE2/AVX2/NEON twins by
 * ctx->kern.isa); the output row takes the default's flat tents and fused
 * encoder with the screen as an addend. */
#include "bloom_preset_xna.h"
#include "bloom_pixel.h"
#include "bloom_stages.h"

#include <string.h>

#if BLOOM_USE_XNA

#define XNA_MAX_PASSES 8
#define XNA_DEFAULT_PASSES 3
/* k[1] bits of a Kawase node */
#define XNA_FIRST 1u
#define XNA_LAST 2u
#define XNA_SAT 4u

/* Half resolution: 4x4 box of the source rows base-1 .. base+2 (input 0).
 * Input 1, source rows base-7 .. base+8, only gives the engine the window
 * of a dark skip: the node is marked zero-preserving, so where all 16 rows
 * are dark the row is not computed and holds zeros instead of its values
 * (<= T). Every quarter row that reads such a row is dark, so it is zero
 * whatever H holds (xna.md, "Skipping"). */
static bool fn_half(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                    void *dst)
{
    (void)r;
    const uint8_t *const s[4] = {(const uint8_t *)in[0][0], (const uint8_t *)in[0][1],
                                 (const uint8_t *)in[0][2], (const uint8_t *)in[0][3]};
#if BLOOM_SMALL
    bloom_row_box_src_c(s, ctx->par.out.in_fmt, ctx->par.out.linear, (uint32_t *)dst, n->w,
                        bg_in_w(ctx, n, 0));
#else
    ctx->kern.box_src(s, ctx->par.out.in_fmt, ctx->par.out.linear, (uint32_t *)dst, 0, n->w,
                      bg_in_w(ctx, n, 0)); /* C or AVX2 */
#endif
    return true;
}

/* Quarter resolution: 4x4 box of H, then the threshold subtraction (and
 * the clamp to 1.0 with SATURATE). Input 0: H rows base-1 .. base+2. A
 * zero-tagged H row among them (skipped: its window was dark) means the
 * row is dark, so zero; false when the row came out all zero. */
static bool fn_quarter(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                       void *dst)
{
    (void)r;
    const int cnt = 3 * n->w;
    uint32_t *row = (uint32_t *)dst;
    if (ctx->zin[0] != 0) {
        memset(row, 0, (size_t)cnt * sizeof *row);
        return false;
    }
    const uint32_t *const s[4] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2], (const uint32_t *)in[0][3]};
    ctx->kern.box(s, row, n->w, bg_in_w(ctx, n, 0)); /* C or SIMD, same bits */
    const uint32_t t = ctx->par.knee.t, cap = (n->k[1] & XNA_SAT) ? BLOOM_LIN_ONE : 0xFFFFFFFFu;
    uint32_t any = 0;
    for (int i = 0; i < cnt; i++) {
        uint32_t v = row[i] > t ? row[i] - t : 0u;
        row[i] = v > cap ? cap : v;
        any |= v;
    }
    return any != 0;
}

void xna_kawase_c(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i, bool rnd)
{
    const int cnt = 3 * w;
    for (int j = 0; j < cnt; j++)
        cs[j] = r[0][j] + r[1][j] + r[2][j] + r[3][j];
    int xa, xb;
    xna_kawase_edges(cs, dst, w, i, &xa, &xb);
    for (int j = 3 * xa; j < 3 * xb; j++) /* interior: flat in the sample index */
        dst[j] = cs[j - 3 * i - 3] + cs[j - 3 * i] + cs[j + 3 * i] + cs[j + 3 * i + 3];
    if (rnd)
        for (int j = 0; j < cnt; j++)
            dst[j] = BLOOM_BOX_RND(dst[j]); /* sum / 16, half to even (bloom_kernels.h) */
}

void xna_screen_c(const uint32_t *s, uint32_t *x, int n)
{
    for (int j = 0; j < n; j++) {
        const uint32_t b = x[j] > BLOOM_LIN_ONE ? BLOOM_LIN_ONE : x[j];
        const uint64_t p = ((uint64_t)s[j] * b + (BLOOM_LIN_ONE >> 1) - 1u) >> BLOOM_LIN_BITS;
        x[j] = b - (uint32_t)p;
    }
}

void xna_kernels(bloom_isa_t isa, xna_kawase_fn *kawase, xna_screen_fn *screen)
{
    *kawase = xna_kawase_c;
    *screen = xna_screen_c;
    switch (isa) {
#if defined(BLOOM_SIMD_AVX2)
    case BLOOM_ISA_AVX2:
        *kawase = xna_kawase_avx2;
        *screen = xna_screen_avx2;
        break;
#endif
#if defined(BLOOM_SIMD_SSE2)
    case BLOOM_ISA_SSE2:
        *kawase = xna_kawase_sse2;
        *screen = xna_screen_sse2;
        break;
#endif
#if defined(BLOOM_SIMD_NEON)
    case BLOOM_ISA_NEON:
        *kawase = xna_kawase_neon;
        *screen = xna_screen_neon;
        break;
#endif
    default:
        break;
    }
}

/* Kawase pass i = k[0] at quarter resolution. Input 0: rows r-i-1 .. r+i+1
 * of the previous pass (or Q); the pass reads the first two and the last
 * two of them (all four zero: a zero row). k[1]: XNA_FIRST/LAST/SAT;
 * k[2], k[3]: low and high word of the range-restore factor f (Q24, up to
 * 2^40). */
static bool fn_kawase(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                      void *dst)
{
    (void)r;
    const int i = (int)n->k[0], w = n->w, cnt = 3 * w;
    uint32_t *row = (uint32_t *)dst;
    if (bg_in_zero(ctx, 0, 0, 1) && bg_in_zero(ctx, 0, 2 * i + 1, 2 * i + 2)) {
        memset(row, 0, (size_t)cnt * sizeof *row);
        return false;
    }
    const uint32_t *const rows[4] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                     (const uint32_t *)in[0][2 * i + 1], (const uint32_t *)in[0][2 * i + 2]};
    const uint32_t flags = n->k[1];
    const uint64_t f = (uint64_t)n->k[2] | ((uint64_t)n->k[3] << 32);
    const bool restore = (flags & XNA_FIRST) && f != 1u << 24;
    xna_kawase_fn kawase;
    xna_screen_fn screen;
    xna_kernels(ctx->kern.isa, &kawase, &screen);
    kawase(rows, bg_scratch(ctx, 0), row, w, i, !restore);
    if (restore) {
        for (int j = 0; j < cnt; j++) {
            /* sum f / 2^28 with f <= 2^40: the sum split at bit 16 keeps both
             * products below 2^56 (the low one's 16 dropped bits are below
             * 1/16 LSB of the result) */
            const uint64_t sh = row[j] >> 16, sl = row[j] & 0xFFFFu;
            const uint64_t v = (sh * f + ((sl * f) >> 16) + (1u << 11)) >> 12;
            row[j] = v > BLOOM_LIN_MAX ? BLOOM_LIN_MAX : (uint32_t)v;
        }
    }
    if ((flags & XNA_LAST) && ctx->par.out.intensity != 65536u) {
        const uint64_t I = ctx->par.out.intensity;
        for (int j = 0; j < cnt; j++) {
            const uint64_t v = ((uint64_t)row[j] * I + 32768u) >> 16; /* < 2^28 * 2^24 */
            row[j] = v > BLOOM_LIN_MAX ? BLOOM_LIN_MAX : (uint32_t)v;
        }
    }
    if (flags & XNA_SAT)
        for (int j = 0; j < cnt; j++)
            row[j] = row[j] > BLOOM_LIN_ONE ? BLOOM_LIN_ONE : row[j];
    return true;
}

#if BLOOM_USE_S16
/* 16-bit samples (cfg.sample_bits = 16; xna.md, "16-bit samples"): H, Q
 * and every pass but the last hold uint16_t at G = F - par.s16 = 15 (each
 * is at most 1.0 on 8/6/5-bit input: averages of decoded samples, Q minus
 * the threshold, the first pass's range restore back to at most 1.0); the
 * last pass, which multiplies by I, and the tent keep 32-bit rows. */
static bool fn_half16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                      void *dst)
{
    uint32_t *t = bg_scratch(ctx, 0);
    (void)fn_half(ctx, n, r, in, t);
    (void)bloom_row_narrow16_k(&ctx->kern, t, (uint16_t *)dst, 3 * n->w, ctx->par.s16);
    return true;
}

/* Q from 16-bit H: the box's sums widened (<< F - G, the 32-bit box's
 * rounding), the threshold subtracted in internal units, then narrowed
 * half to even. */
static bool fn_quarter16(const bg_ctx_t *ctx, const bg_node_t *n, int r,
                         const void *const *const in[BG_MAX_IN], void *dst)
{
    (void)r;
    const int cnt = 3 * n->w;
    if (ctx->zin[0] != 0) {
        memset(dst, 0, (size_t)cnt * sizeof(uint16_t));
        return false;
    }
    const uint16_t *const s[4] = {(const uint16_t *)in[0][0], (const uint16_t *)in[0][1],
                                  (const uint16_t *)in[0][2], (const uint16_t *)in[0][3]};
    uint32_t *row = bg_scratch(ctx, 0);
    bloom_row_box16_k(&ctx->kern, s, row, true, n->w, bg_in_w(ctx, n, 0), ctx->par.s16);
    const uint32_t t = ctx->par.knee.t, cap = (n->k[1] & XNA_SAT) ? BLOOM_LIN_ONE : 0xFFFFFFFFu;
    for (int i = 0; i < cnt; i++) {
        const uint32_t v = row[i] > t ? row[i] - t : 0u;
        row[i] = v > cap ? cap : v;
    }
    return bloom_row_narrow16_k(&ctx->kern, row, (uint16_t *)dst, cnt, ctx->par.s16) != 0;
}

/* A Kawase pass over 16-bit rows: fn_kawase's steps on its sums, in G
 * units into a 16-bit row, or (the last pass) widened first (<< F - G,
 * exact) into a 32-bit row in internal units. */
static bool fn_kawase16(const bg_ctx_t *ctx, const bg_node_t *n, int r,
                        const void *const *const in[BG_MAX_IN], void *dst)
{
    (void)r;
    const int i = (int)n->k[0], w = n->w, cnt = 3 * w;
    const uint32_t flags = n->k[1];
    const bool last = (flags & XNA_LAST) != 0;
    if (bg_in_zero(ctx, 0, 0, 1) && bg_in_zero(ctx, 0, 2 * i + 1, 2 * i + 2)) {
        memset(dst, 0, (size_t)cnt * (last ? 4u : 2u));
        return false;
    }
    const uint16_t *const rows[4] = {(const uint16_t *)in[0][0], (const uint16_t *)in[0][1],
                                     (const uint16_t *)in[0][2 * i + 1], (const uint16_t *)in[0][2 * i + 2]};
    uint32_t *cs = bg_scratch(ctx, 0), *sum = last ? (uint32_t *)dst : bg_scratch(ctx, 1);
    for (int j = 0; j < cnt; j++)
        cs[j] = (uint32_t)rows[0][j] + rows[1][j] + rows[2][j] + rows[3][j];
    int xa, xb;
    xna_kawase_edges(cs, sum, w, i, &xa, &xb);
    for (int j = 3 * xa; j < 3 * xb; j++)
        sum[j] = cs[j - 3 * i - 3] + cs[j - 3 * i] + cs[j + 3 * i] + cs[j + 3 * i + 3];
    const uint64_t f = (uint64_t)n->k[2] | ((uint64_t)n->k[3] << 32);
    const bool restore = (flags & XNA_FIRST) && f != 1u << 24;
    const int sh = last ? ctx->par.s16 : 0;
    const uint32_t one = last ? BLOOM_LIN_ONE : 1u << (BLOOM_LIN_BITS - ctx->par.s16);
    const uint64_t I = last ? ctx->par.out.intensity : 65536u;
    uint16_t *d16 = (uint16_t *)dst;
    uint32_t any = 0;
    for (int j = 0; j < cnt; j++) {
        uint32_t v = sum[j] << sh; /* 16 (2^16 - 1) << 5 < 2^26 */
        if (restore) {             /* as fn_kawase */
            const uint64_t q = ((uint64_t)(v >> 16) * f + (((v & 0xFFFFu) * f) >> 16) + (1u << 11)) >> 12;
            v = q > BLOOM_LIN_MAX ? BLOOM_LIN_MAX : (uint32_t)q;
        } else {
            v = BLOOM_BOX_RND(v);
        }
        if (I != 65536u) {
            const uint64_t q = ((uint64_t)v * I + 32768u) >> 16;
            v = q > BLOOM_LIN_MAX ? BLOOM_LIN_MAX : (uint32_t)q;
        }
        if (flags & XNA_SAT)
            v = v > one ? one : v;
        if (last)
            sum[j] = v;
        else
            d16[j] = (uint16_t)v; /* at most 2^G: the restore brings Q back to 1.0 at most */
        any |= v;
    }
    return any != 0 || last; /* (the 32-bit pass tags no row zero: neither does this one) */
}
#endif

/* Half resolution, the way back: tent of the last pass (input 0: rows
 * m-1 .. m+1, BG_UP), nothing added (zero-preserving: the tent of zeros is
 * zero). */
static bool fn_up(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2]};
    ctx->kern.tent(u, r & 1, NULL, (uint32_t *)dst, 0, n->w, bg_in_w(ctx, n, 0));
    return true;
}

#if !BLOOM_SMALL
/* Level-1 columns per chunk of the fast output path. */
#define XNA_OUT_CH 32

/* The decoded source (8-bit sRGB codes, channel c at byte c or 2 - c)
 * of nx pixels of bpp bytes: even pixels into se, odd into so. Inlined with
 * constant bpp and cr. */
static BLOOM_ALWAYS_INLINE void gather_s(const uint8_t *s, uint32_t *se, uint32_t *so, int nx, size_t bpp,
                                         size_t cr)
{
    const uint32_t *dec = bloom_srgb_dec8;
    int x = 0;
    for (; x + 2 <= nx; x += 2, s += 2 * bpp, se += 3, so += 3) {
        se[0] = dec[s[cr]];
        se[1] = dec[s[1]];
        se[2] = dec[s[2 - cr]];
        so[0] = dec[s[bpp + cr]];
        so[1] = dec[s[bpp + 1]];
        so[2] = dec[s[bpp + 2 - cr]];
    }
    if (x < nx) {
        se[0] = dec[s[cr]];
        se[1] = dec[s[1]];
        se[2] = dec[s[2 - cr]];
    }
}

/* The output row through the flat tent kernels (their 32-bit sums are exact:
 * every sample is at most LIN_MAX < 2^29) and the fused encoder of the
 * default's fast path (ctx->kern.eo: out = enc(S + P)), with P the screen as
 * an addend (xna_screen_fn): enc(S + P) = enc(b + S (1 - b)). Per chunk of
 * level-1 columns: V, the even and odd columns e, od of B, then P in place
 * of B (the debug view: B itself). RGB888 and XRGB8888 input, 8/6/5-bit
 * sRGB output (bloom_encode_eo_ok); B = 0 on a chunk: the source copied. */
static void out_fast(const bg_ctx_t *ctx, const uint32_t *const u[3], int odd, const uint8_t *src,
                     uint8_t *dst, int w, int sw)
{
    const bloom_out_t *o = &ctx->par.out;
    const bloom_kernels_t *k = &ctx->kern;
    const bool x8 = o->in_fmt == BLOOM_FMT_XRGB8888;
    const size_t ibpp = x8 ? 4u : 3u, obpp = (size_t)bloom_format_bpp(o->out_fmt);
    const uint32_t *ua = odd ? u[2] : u[0], *ub = u[1], *uc = odd ? u[0] : u[2];
    uint32_t vb[3 * (XNA_OUT_CH + 2)], eo[6 * XNA_OUT_CH], se[6 * XNA_OUT_CH];
    uint32_t *e = eo, *od = eo + 3 * XNA_OUT_CH;
    xna_kawase_fn kawase;
    xna_screen_fn screen;
    xna_kernels(k->isa, &kawase, &screen);
    const int mw = (w + 1) / 2; /* the columns read, sw or fewer (a tile's output) */
    for (int m0 = 0; m0 < mw; m0 += XNA_OUT_CH) {
        const int nn = imin(XNA_OUT_CH, mw - m0);
        const int lo = m0 > 0 ? m0 - 1 : 0, hi = imin(m0 + nn, sw - 1); /* columns computed */
        const size_t c0 = (size_t)lo * 3u;
        const int x0 = 2 * m0, nx = imin(2 * nn, w - x0);
        const uint8_t *s = src + (size_t)x0 * ibpp;
        uint8_t *d = dst + (size_t)x0 * obpp;
        if (!k->vtent(ua + c0, ub + c0, uc + c0, vb + (size_t)(lo - m0 + 1) * 3u, 3 * (hi - lo + 1))) {
            bloom_row_copy_c(s, d, nx, o); /* V = 0: B = 0 here */
            continue;
        }
        if (m0 == 0)
            memcpy(vb, vb + 3, 3u * sizeof *vb);
        if (m0 + nn == sw)
            memcpy(vb + 3 * (nn + 1), vb + 3 * nn, 3u * sizeof *vb);
        if (!k->htent_eo(vb + 3, e, od, 3 * nn)) {
            bloom_row_copy_c(s, d, nx, o); /* B = 0 on this chunk */
            continue;
        }
        if (!o->debug) {
            /* S of every output pixel in the order of e (pixel 2j) and od (2j + 1) */
            uint32_t *sv = se, *so = se + 3 * XNA_OUT_CH;
            if (x8)
                gather_s(s, sv, so, nx, 4, 2);
            else
                gather_s(s, sv, so, nx, 3, 0);
            screen(sv, e, 3 * ((nx + 1) >> 1));
            screen(so, od, 3 * (nx >> 1));
        }
        k->eo(o->in_fmt, o->out_fmt, o->debug, s, e, od, d, nx);
    }
}
#endif

/* Output: input 0 the source row (BG_SAME 0..0), input 1 the half-resolution
 * bloom rows m-1 .. m+1 (BG_UP). B = tent; screen combine; encode. All
 * three bloom rows zero: B = 0, out = b + S (1 - b) = S exactly (debug
 * view: 0), which is bloom_row_copy_c. */
static bool fn_out(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[1][0], (const uint32_t *)in[1][1],
                                  (const uint32_t *)in[1][2]};
    const uint8_t *src = (const uint8_t *)in[0][0];
    uint8_t *out = (uint8_t *)dst;
    const bloom_out_t *o = &ctx->par.out;
    const size_t ibpp = (size_t)bloom_format_bpp(o->in_fmt), obpp = (size_t)bloom_format_bpp(o->out_fmt);
    const int w = n->w, sw = bg_in_w(ctx, n, 1);
    if (bg_in_zero(ctx, 1, 0, 2)) {
        bg_copy_row(ctx, src, out, w);
        return true;
    }
#if !BLOOM_SMALL
    if (ctx->kern.vtent && (o->in_fmt == BLOOM_FMT_RGB888 || o->in_fmt == BLOOM_FMT_XRGB8888) &&
        bloom_encode_eo_ok(o->in_fmt, o->out_fmt, o->linear)) {
        out_fast(ctx, u, r & 1, src, out, w, sw);
        return true;
    }
#endif
    uint32_t bl[3 * BLOOM_OUT_CHUNK], sv[3 * BLOOM_OUT_CHUNK];
    for (int x0 = 0; x0 < w; x0 += BLOOM_OUT_CHUNK) {
        const int cnt = imin(BLOOM_OUT_CHUNK, w - x0);
        ctx->kern.tent(u, r & 1, NULL, bl, x0, cnt, sw);
        if (!o->debug) {
            /* the source row is read before the encoded row is written: dst may alias src */
            bloom_decode_row(o->in_fmt, o->linear, src + (size_t)x0 * ibpp, sv, cnt);
            for (int j = 0; j < 3 * cnt; j++) {
                const uint32_t b = bl[j] > BLOOM_LIN_ONE ? BLOOM_LIN_ONE : bl[j];
                /* S (1 - b): S < 2^28, 1 - b <= 2^F: below 2^48 */
                const uint64_t p =
                    ((uint64_t)sv[j] * (BLOOM_LIN_ONE - b) + (BLOOM_LIN_ONE >> 1)) >> BLOOM_LIN_BITS;
                bl[j] = b + (uint32_t)p;
            }
        }
        bloom_encode_row(o->out_fmt, o->linear, bl, out + (size_t)x0 * obpp, cnt);
    }
    return true;
}

static void defaults(bloom_config_t *cfg)
{
    cfg->threshold = BLOOM_ONE / 4u; /* the XNA sample's "Default" setting: 0.25 */
    cfg->p.passes = XNA_DEFAULT_PASSES;
}

static bloom_status_t validate(const bloom_config_t *cfg)
{
    if (cfg->aux_fmt != BLOOM_AUX_NONE)
        return BLOOM_E_AUX;
    if (cfg->threshold >= BLOOM_ONE)
        return BLOOM_E_THRESHOLD; /* 1 / (1 - T) */
    if (cfg->p.passes < 1 || cfg->p.passes > XNA_MAX_PASSES)
        return BLOOM_E_PASSES;
    if (cfg->flags & (BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE | BLOOM_FLAG_KEEP_LEVELS))
        return BLOOM_E_FLAGS;
    return BLOOM_OK;
}

static bloom_status_t build(bg_graph_t *g, bg_params_t *par)
{
    const int P = g->cfg->p.passes;
    const uint32_t sat = (g->cfg->flags & BLOOM_FLAG_SATURATE) ? XNA_SAT : 0u;
    /* always half and quarter (ceil sizes; a 1-pixel side stays 1) */
    g->L = 2;
    for (int k = 1; k <= 2; k++) {
        g->w[k] = (g->w[k - 1] + 1) / 2;
        g->h[k] = (g->h[k - 1] + 1) / 2;
    }
    /* range restore 1 / (1 - t), t = threshold / 2^16 < 1: f = round(2^40 / d) (Q24),
     * d = 2^16 - threshold; f <= 2^40, the quotient can pass 32 bits: two divisions */
    const uint32_t d = BLOOM_ONE - g->cfg->threshold;
    const uint32_t qh = 256u / d, rh = 256u % d; /* 2^40 = 256 * 2^32, divided in two steps */
    const uint32_t ql = bloom_div_u64_u32((uint64_t)rh << 32, d); /* no 64-bit divide on Cortex-M */
    const uint64_t fr = ((uint64_t)rh << 32) - (uint64_t)ql * d;
    const uint64_t f = ((uint64_t)qh << 32) + ql + (fr >= (d + 1u) / 2u);

    /* zero rows (xna.md, "Skipping"): a source pixel with no channel above T
     * is dark; H skips where its 16-row window is dark, Q where any H row it
     * reads was skipped; the passes and the tent are zero-preserving */
    par->dark_cut = par->knee.t;
    if (BG_DARK_COPY)
        par->dark_copy = true; /* zero bloom: out = S, the source copied (fn_out) */
    const int hn = bg_node(g, fn_half, g->w[1], g->h[1], 3, 1);
    bg_input(g, hn, BG_SRC, BG_DOWN, -1, 2);
    if (!(g->cfg->flags & BLOOM_FLAG_COPY_SOURCE)) {
        /* the window keeps 6 more source rows: pointers here, but with
         * COPY_SOURCE 6 copied rows (34 KB at 1080p): there H is always made */
        bg_input(g, hn, BG_SRC, BG_DOWN, -7, 8);
        bg_zero(g, hn);
    }
    const int q = bg_node(g, fn_quarter, g->w[2], g->h[2], 3, 2);
    bg_input(g, q, hn, BG_DOWN, -1, 2);
    bg_zero(g, q);
    if (q >= 0)
        g->node[q].k[1] = sat;
    int prev = q;
    for (int i = 0; i < P; i++) {
        const int kn = bg_node(g, fn_kawase, g->w[2], g->h[2], 3, 2);
        bg_input(g, kn, prev, BG_SAME, -i - 1, i + 1);
        bg_zero(g, kn);
        if (kn < 0)
            return BLOOM_E_INTERNAL;
        bg_node_t *nd = &g->node[kn];
        nd->k[0] = (uint32_t)i;
        nd->k[1] = sat | (i == 0 ? XNA_FIRST : 0u) | (i == P - 1 ? XNA_LAST : 0u);
        nd->k[2] = (uint32_t)f;
        nd->k[3] = (uint32_t)(f >> 32);
        prev = kn;
    }
    const int up = bg_node(g, fn_up, g->w[1], g->h[1], 3, 1);
    bg_input(g, up, prev, BG_UP, -1, 1);
    bg_zero(g, up);
    const int o = bg_node(g, fn_out, g->w[0], g->h[0], 3, 0);
    bg_input(g, o, BG_SRC, BG_SAME, 0, 0);
    bg_input(g, o, up, BG_UP, -1, 1);
    g->out_node = o;
    par->scratch_rows = 1; /* fn_kawase's column sums */
#if BLOOM_USE_S16
    if (g->cfg->sample_bits == 16) { /* H, Q and the passes but the last on 16-bit rows */
        par->s16 = (uint8_t)(BLOOM_LIN_BITS - 15);
        par->scratch_rows = 2; /* and fn_kawase16's sums */
        for (int i = 0; i < g->nnodes; i++) {
            bg_node_t *nd = &g->node[i];
            if (nd->fn == fn_kawase)
                nd->fn = fn_kawase16;
            else if (nd->fn == fn_half)
                nd->fn = fn_half16;
            else if (nd->fn == fn_quarter)
                nd->fn = fn_quarter16;
            else
                continue;
            if (!(nd->fn == fn_kawase16 && (nd->k[1] & XNA_LAST)))
                bg_s16(g, i);
        }
    }
#endif
    if (!BLOOM_SMALL)
        par->views = true; /* every row function reads its widths by bg_in_w (or clamps at its own) */
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_xna = {"xna", defaults, validate, build};

#else
typedef int bloom_preset_xna_unused_t;
#endif
