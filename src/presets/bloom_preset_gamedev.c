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
#include "bloom_preset_gamedev.h"

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
/* The 9-tap Gaussian: the article's weights divided by their printed sum
 * (1.000001), in Q24, rounded to nearest, the centre one 1 lower so that
 * 3808876 + 2 * (3264759 + 2040477 + 906875 + 272059) = 2^24 exactly (a
 * flat field stays flat). Each weight is within 1.21 * 2^-24 of its real
 * value. */
#define GW0 3808876u
#define GW1 3264759u
#define GW2 2040477u
#define GW3 906875u
#define GW4 272059u
#define GQ 24
#define GHALF (1u << (GQ - 1))

/* ---- level 1: box down, then the luminance threshold -------------------- */

/* In place on w level-1 pixels. Lx <= tx = 10000 t: the pixel is 0.
 * Else the contribution (Lx - tx) / max(Lx, 2^F) as a Q32 fraction: both
 * terms shifted right by the same sh (0 .. 10) until the divisor fits in 32
 * bits (each truncation is below 2^-31 of it), then f = round(n * 2^32 / d)
 * < 2^32, one 64-by-32 division; each channel (c * f + 2^31) >> 32 (c <
 * 2^28: product < 2^60). A numerator not below the divisor (t = 0 and
 * L >= 1e-4) is the factor 1 exactly: the pixel is kept. */
static void threshold_row(uint32_t *row, int w, uint32_t t)
{
    const uint64_t tx = (uint64_t)t * LUM_DEN;
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
        if (n >= d)
            continue;
        const uint64_t f = bloom_div_u64_u32(((uint64_t)n << 32) + (d >> 1), d);
        for (int ch = 0; ch < 3; ch++)
            p[ch] = (uint32_t)((p[ch] * f + 0x80000000u) >> 32);
    }
}

/* Input 0: source rows 2r-1 .. 2r+2 (BG_DOWN). */
static bool gd_d1(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    (void)r;
    const uint8_t *const s[4] = {(const uint8_t *)in[0][0], (const uint8_t *)in[0][1],
                                 (const uint8_t *)in[0][2], (const uint8_t *)in[0][3]};
    bloom_row_box_src_c(s, g->out.in_fmt, g->out.linear, (uint32_t *)dst, n->w, g->w[0]);
    threshold_row((uint32_t *)dst, n->w, g->knee.t);
    return true;
}

/* ---- the Gaussian ----------------------------------------------------------- */

/* Vertical pass over m samples of the nine rows a[0..8] (rows r-4 .. r+4,
 * clamped by the engine). Symmetric pairs are added first (< 2^29), each
 * product < 2^51, the sum < 2^24 * 2^28 = 2^52: a 64-bit sum, one UMLAL
 * per pair on Cortex-M. */
static void gauss_v(const uint32_t *const a[9], uint32_t *dst, int m)
{
    const uint32_t *a0 = a[0], *a1 = a[1], *a2 = a[2], *a3 = a[3], *a4 = a[4], *a5 = a[5], *a6 = a[6],
                   *a7 = a[7], *a8 = a[8];
    for (int i = 0; i < m; i++) {
        const uint64_t s = (uint64_t)GW0 * a4[i] + (uint64_t)GW1 * (a3[i] + a5[i]) +
                           (uint64_t)GW2 * (a2[i] + a6[i]) + (uint64_t)GW3 * (a1[i] + a7[i]) +
                           (uint64_t)GW4 * (a0[i] + a8[i]) + GHALF;
        dst[i] = (uint32_t)(s >> GQ);
    }
}

static inline int clampx(int x, int w)
{
    return x < 0 ? 0 : x >= w ? w - 1 : x;
}

/* Horizontal pass at an edge pixel x (columns clamped). */
static void gauss_h_edge(const uint32_t *v, uint32_t *dst, int x, int w)
{
    static const uint32_t wt[5] = {GW0, GW1, GW2, GW3, GW4};
    for (int ch = 0; ch < 3; ch++) {
        uint64_t s = (uint64_t)GW0 * v[3 * x + ch] + GHALF;
        for (int j = 1; j <= 4; j++)
            s += (uint64_t)wt[j] * (v[3 * clampx(x - j, w) + ch] + v[3 * clampx(x + j, w) + ch]);
        dst[3 * x + ch] = (uint32_t)(s >> GQ);
    }
}

/* Horizontal pass of a row of w pixels: v (3 samples per pixel) -> dst. */
static void gauss_h(const uint32_t *v, uint32_t *dst, int w)
{
    const int lo = w < 4 ? w : 4, hi = w - 4 > lo ? w - 4 : lo;
    for (int x = 0; x < lo; x++)
        gauss_h_edge(v, dst, x, w);
    for (int i = 3 * lo; i < 3 * hi; i++) {
        const uint64_t s = (uint64_t)GW0 * v[i] + (uint64_t)GW1 * (v[i - 3] + v[i + 3]) +
                           (uint64_t)GW2 * (v[i - 6] + v[i + 6]) + (uint64_t)GW3 * (v[i - 9] + v[i + 9]) +
                           (uint64_t)GW4 * (v[i - 12] + v[i + 12]) + GHALF;
        dst[i] = (uint32_t)(s >> GQ);
    }
    for (int x = hi; x < w; x++)
        gauss_h_edge(v, dst, x, w);
}

/* U_k = gauss9(D_k) (+ tent(U_k+1)). Inputs: [U_k+1 rows m-1 .. m+1 (BG_UP),]
 * D_k rows r-4 .. r+4 (BG_SAME), the last input. The vertical pass goes to
 * scratch row 0. */
static bool gd_up(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    const void *const *d = in[n->nin - 1];
    const uint32_t *const rows[9] = {(const uint32_t *)d[0], (const uint32_t *)d[1], (const uint32_t *)d[2],
                                     (const uint32_t *)d[3], (const uint32_t *)d[4], (const uint32_t *)d[5],
                                     (const uint32_t *)d[6], (const uint32_t *)d[7], (const uint32_t *)d[8]};
    uint32_t *v = bg_scratch(g, 0), *out = (uint32_t *)dst;
    gauss_v(rows, v, 3 * n->w);
    gauss_h(v, out, n->w);
    if (n->nin == 2) {
        const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                      (const uint32_t *)in[0][2]};
        /* the engine's tent, C or its SIMD twin (same bits), picked once at
         * bloom_init: picking it per row ran CPUID per row (a VM exit each
         * under virtualisation: 12x the default's time at 1080p) */
        g->kern.tent(u, r & 1, out, out, 0, n->w, g->node[n->in[0].node].w);
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
static inline uint32_t gd_key(uint32_t v)
{
    if (v < 64)
        return v;
#if defined(__GNUC__)
    const int e = 31 - __builtin_clz(v);
#else
    int e = 31;
    while (!(v >> e))
        e--;
#endif
    return 64u + 32u * (uint32_t)(e - 6) + ((v >> (e - 5)) & 31u);
}

typedef const uint8_t *gd_bk_t;
#define GD_TABLE(name) bloom_gd_##name##_bk
static inline uint32_t code_of(const uint32_t *t, gd_bk_t bk, uint32_t half, uint32_t v)
{
    (void)half;
    uint32_t k = bk[gd_key(v)];
    k += t[k + 1] <= v;
    k += t[k + 1] <= v;
    return k;
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
#endif

/* c at F bits as the tables' Q12.20, saturated at 2^32 - 2 (every
 * threshold is below 2^30, so that changes no code). */
static inline uint32_t to_q20(uint64_t c)
{
    c <<= 20 - BLOOM_LIN_BITS;
    return c > 0xFFFFFFFEu ? 0xFFFFFFFEu : (uint32_t)c;
}

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

/* Input 0: U_1 rows m-1 .. m+1 (BG_UP); input 1: the source row (BG_SAME).
 * B = tent(U_1) into scratch 0, S decoded into scratch 1, then per sample
 * c = S + ((strength * B + 2^15) >> 16) (u64: B < 3 * 2^28, strength <=
 * 2^20) and the code by the thresholds. */
static bool gd_out(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2]};
    const int w = n->w;
    uint32_t *bl = bg_scratch(g, 0), *sv = bg_scratch(g, 1);
    const uint64_t s = g->cfg.p.strength;
    g->kern.tent(u, r & 1, NULL, bl, 0, w, g->node[n->in[0].node].w); /* picked at bloom_init */
    if (g->out.debug)
        memset(sv, 0, (size_t)w * 3u * sizeof *sv);
    else
        bloom_decode_row(g->out.in_fmt, g->out.linear, (const uint8_t *)in[1][0], sv, w);
    uint8_t *p = (uint8_t *)dst;
    if (g->out.out_fmt == BLOOM_FMT_RGBQ16) {
        for (int x = 0; x < w; x++, p += 12) {
            uint32_t q[3];
            for (int ch = 0; ch < 3; ch++)
                q[ch] = tonemap_q16(((s * bl[3 * x + ch] + 32768u) >> 16) + sv[3 * x + ch]);
            memcpy(p, q, sizeof q);
        }
        return true;
    }
    const bool lin = g->out.linear;
    const uint32_t *t8 = lin ? bloom_gd_lin8 : bloom_gd_gamma8;
    const uint32_t *t6 = lin ? bloom_gd_lin6 : bloom_gd_gamma6;
    const uint32_t *t5 = lin ? bloom_gd_lin5 : bloom_gd_gamma5;
    const gd_bk_t b8 = lin ? GD_TABLE(lin8) : GD_TABLE(gamma8);
    const gd_bk_t b6 = lin ? GD_TABLE(lin6) : GD_TABLE(gamma6);
    const gd_bk_t b5 = lin ? GD_TABLE(lin5) : GD_TABLE(gamma5);
    /* codes in place of the composite, in bl */
    if (g->out.out_fmt == BLOOM_FMT_RGB565) {
        for (int x = 0; x < w; x++) {
            uint32_t *c = bl + 3 * x;
            const uint32_t *sx = sv + 3 * x;
            c[0] = code_of(t5, b5, 16, to_q20(((s * c[0] + 32768u) >> 16) + sx[0]));
            c[1] = code_of(t6, b6, 32, to_q20(((s * c[1] + 32768u) >> 16) + sx[1]));
            c[2] = code_of(t5, b5, 16, to_q20(((s * c[2] + 32768u) >> 16) + sx[2]));
            const uint32_t wd = (c[0] << 11) | (c[1] << 5) | c[2];
            p[2 * x] = (uint8_t)wd;
            p[2 * x + 1] = (uint8_t)(wd >> 8);
        }
        return true;
    }
    for (int i = 0; i < 3 * w; i++)
        bl[i] = code_of(t8, b8, 128, to_q20(((s * bl[i] + 32768u) >> 16) + sv[i]));
    if (g->out.out_fmt == BLOOM_FMT_XRGB8888) {
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
    if (cfg->flags & (BLOOM_FLAG_SATURATE | BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE))
        return BLOOM_E_FLAGS;
    if (cfg->p.strength > GD_MAX_STRENGTH)
        return BLOOM_E_STRENGTH;
    return BLOOM_OK;
}

static bloom_status_t build(bloom_graph_t *g)
{
    bg_levels(g, GD_LEVELS);
    const int L = g->L;
    g->knee.k = 0;                        /* no soft knee: bloom_query reports knee_q = 0 */
    g->out.intensity = g->cfg.p.strength; /* ... and intensity_q = the strength (linear Q16.16) */
    int D[GD_LEVELS + 1];
    D[1] = bg_node(g, gd_d1, g->w[1], g->h[1], 3, 1);
    bg_input(g, D[1], BG_SRC, BG_DOWN, -1, 2);
    for (int k = 2; k <= L; k++) {
        D[k] = bg_node(g, bg_fn_box, g->w[k], g->h[k], 3, k);
        bg_input(g, D[k], D[k - 1], BG_DOWN, -1, 2);
    }
    int U = bg_node(g, gd_up, g->w[L], g->h[L], 3, L);
    bg_input(g, U, D[L], BG_SAME, -4, 4);
    for (int k = L - 1; k >= 1; k--) {
        int dk = D[k];
        if (k == 1) { /* D_1 again for the up pass: no delay line at the widest level */
            dk = bg_node(g, gd_d1, g->w[1], g->h[1], 3, 1);
            bg_input(g, dk, BG_SRC, BG_DOWN, -1, 2);
        }
        const int u = bg_node(g, gd_up, g->w[k], g->h[k], 3, k);
        bg_input(g, u, U, BG_UP, -1, 1); /* first: D_k rows are made only when U_k+1 is ready */
        bg_input(g, u, dk, BG_SAME, -4, 4);
        U = u;
    }
    const int o = bg_node(g, gd_out, g->w[0], g->h[0], 3, 0);
    bg_input(g, o, U, BG_UP, -1, 1);
    bg_input(g, o, BG_SRC, BG_SAME, 0, 0);
    g->out_node = o;
    g->scratch_rows = 2; /* the Gaussian's vertical pass, the output's bloom row */
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_gamedev = {"gamedev", defaults, validate, build};

#else
typedef int bloom_preset_gamedev_unused_t;
#endif
