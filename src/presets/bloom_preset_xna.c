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
 *   screen: b = min(B, 2^F); v = b + ((S (2^F - b) + 2^(F-1)) >> F)  (u64 product). */
#include "bloom_stages.h"
#include "bloom_pixel.h"

#include <string.h>

#if BLOOM_USE_XNA

#define XNA_MAX_PASSES 8
#define XNA_DEFAULT_PASSES 3
/* k[1] bits of a Kawase node */
#define XNA_FIRST 1u
#define XNA_LAST 2u
#define XNA_SAT 4u

/* Half resolution: 4x4 box of the source rows base-1 .. base+2 (input 0). */
static bool fn_half(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                    void *dst)
{
    (void)r;
    const uint8_t *const s[4] = {(const uint8_t *)in[0][0], (const uint8_t *)in[0][1],
                                 (const uint8_t *)in[0][2], (const uint8_t *)in[0][3]};
    bloom_row_box_src_c(s, g->out.in_fmt, g->out.linear, (uint32_t *)dst, n->w, g->w[0]);
    return true;
}

/* Quarter resolution: 4x4 box of H, then the threshold subtraction (and
 * the clamp to 1.0 with SATURATE). Input 0: H rows base-1 .. base+2. */
static bool fn_quarter(const bloom_graph_t *g, const bg_node_t *n, int r,
                       const void *const *const in[BG_MAX_IN], void *dst)
{
    (void)r;
    const uint32_t *const s[4] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2], (const uint32_t *)in[0][3]};
    uint32_t *row = (uint32_t *)dst;
    g->kern.box(s, row, n->w, g->node[n->in[0].node].w); /* C or SIMD, same bits */
    const uint32_t t = g->knee.t, cap = (n->k[1] & XNA_SAT) ? BLOOM_LIN_ONE : 0xFFFFFFFFu;
    const int cnt = 3 * n->w;
    for (int i = 0; i < cnt; i++) {
        uint32_t v = row[i] > t ? row[i] - t : 0u;
        row[i] = v > cap ? cap : v;
    }
    return true;
}

/* Sum of the four column sums at x-i-1, x-i, x+i, x+i+1 (clamped) of
 * cs, for destination columns xa .. xb-1 into dst. Each column sum is below
 * 2^30 (four samples <= LIN_MAX < 2^28), so the sum stays below 2^32. */
static void kawase_h(const uint32_t *cs, uint32_t *dst, int xa, int xb, int i, int w)
{
    for (int x = xa; x < xb; x++) {
        const int a = x - i - 1 < 0 ? 0 : x - i - 1, b = x - i < 0 ? 0 : x - i;
        const int c = x + i > w - 1 ? w - 1 : x + i, d = x + i + 1 > w - 1 ? w - 1 : x + i + 1;
        for (int ch = 0; ch < 3; ch++)
            dst[3 * x + ch] = cs[3 * a + ch] + cs[3 * b + ch] + cs[3 * c + ch] + cs[3 * d + ch];
    }
}

/* Kawase pass i = k[0] at quarter resolution. Input 0: rows r-i-1 .. r+i+1
 * of the previous pass (or Q); the pass reads the first two and the last
 * two of them. k[1]: XNA_FIRST/LAST/SAT; k[2], k[3]: low and high word of
 * the range-restore factor f (Q24, up to 2^40). */
static bool fn_kawase(const bloom_graph_t *g, const bg_node_t *n, int r,
                      const void *const *const in[BG_MAX_IN], void *dst)
{
    (void)r;
    const int i = (int)n->k[0], w = n->w, cnt = 3 * w;
    const uint32_t *r0 = (const uint32_t *)in[0][0], *r1 = (const uint32_t *)in[0][1];
    const uint32_t *r2 = (const uint32_t *)in[0][2 * i + 1], *r3 = (const uint32_t *)in[0][2 * i + 2];
    uint32_t *cs = bg_scratch(g, 0), *row = (uint32_t *)dst;
    for (int j = 0; j < cnt; j++)
        cs[j] = r0[j] + r1[j] + r2[j] + r3[j];
    /* interior columns need no clamping: i + 1 <= x <= w - i - 2 */
    const int xa = imin(i + 1, w), xb = w - i - 1 > xa ? w - i - 1 : xa;
    kawase_h(cs, row, 0, xa, i, w);
    for (int x = xa; x < xb; x++) {
        const uint32_t *a = cs + 3 * (x - i - 1), *c = cs + 3 * (x + i);
        row[3 * x] = a[0] + a[3] + c[0] + c[3];
        row[3 * x + 1] = a[1] + a[4] + c[1] + c[4];
        row[3 * x + 2] = a[2] + a[5] + c[2] + c[5];
    }
    kawase_h(cs, row, xb, w, i, w);
    const uint32_t flags = n->k[1];
    const uint64_t f = (uint64_t)n->k[2] | ((uint64_t)n->k[3] << 32);
    if ((flags & XNA_FIRST) && f != 1u << 24) {
        for (int j = 0; j < cnt; j++) {
            /* sum f / 2^28 with f <= 2^40: the sum split at bit 16 keeps both
             * products below 2^56 (the low one's 16 dropped bits are below
             * 1/16 LSB of the result) */
            const uint64_t sh = row[j] >> 16, sl = row[j] & 0xFFFFu;
            const uint64_t v = (sh * f + ((sl * f) >> 16) + (1u << 11)) >> 12;
            row[j] = v > BLOOM_LIN_MAX ? BLOOM_LIN_MAX : (uint32_t)v;
        }
    } else {
        for (int j = 0; j < cnt; j++)
            row[j] = BLOOM_BOX_RND(row[j]); /* sum / 16, half to even (bloom_internal.h) */
    }
    if ((flags & XNA_LAST) && g->out.intensity != 65536u) {
        const uint64_t I = g->out.intensity;
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

/* Half resolution, the way back: tent of the last pass (input 0: rows
 * m-1 .. m+1, BG_UP), nothing added. */
static bool fn_up(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                  void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[0][0], (const uint32_t *)in[0][1],
                                  (const uint32_t *)in[0][2]};
    g->kern.tent(u, r & 1, NULL, (uint32_t *)dst, 0, n->w, g->node[n->in[0].node].w);
    return true;
}

/* Output: input 0 the source row (BG_SAME 0..0), input 1 the half-resolution
 * bloom rows m-1 .. m+1 (BG_UP). B = tent; screen combine; encode. */
static bool fn_out(const bloom_graph_t *g, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                   void *dst)
{
    const uint32_t *const u[3] = {(const uint32_t *)in[1][0], (const uint32_t *)in[1][1],
                                  (const uint32_t *)in[1][2]};
    const uint8_t *src = (const uint8_t *)in[0][0];
    uint8_t *out = (uint8_t *)dst;
    const bloom_out_t *o = &g->out;
    const size_t ibpp = (size_t)bloom_format_bpp(o->in_fmt), obpp = (size_t)bloom_format_bpp(o->out_fmt);
    const int w = n->w, sw = g->node[n->in[1].node].w;
    uint32_t bl[3 * BLOOM_OUT_CHUNK], sv[3 * BLOOM_OUT_CHUNK];
    for (int x0 = 0; x0 < w; x0 += BLOOM_OUT_CHUNK) {
        const int cnt = imin(BLOOM_OUT_CHUNK, w - x0);
        g->kern.tent(u, r & 1, NULL, bl, x0, cnt, sw);
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
    if (cfg->flags & (BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE))
        return BLOOM_E_FLAGS;
    return BLOOM_OK;
}

static bloom_status_t build(bloom_graph_t *g)
{
    const int P = g->cfg.p.passes;
    const uint32_t sat = (g->cfg.flags & BLOOM_FLAG_SATURATE) ? XNA_SAT : 0u;
    /* always half and quarter (ceil sizes; a 1-pixel side stays 1) */
    g->L = 2;
    for (int k = 1; k <= 2; k++) {
        g->w[k] = (g->w[k - 1] + 1) / 2;
        g->h[k] = (g->h[k - 1] + 1) / 2;
    }
    /* range restore 1 / (1 - t), t = threshold / 2^16 < 1: f = round(2^40 / d) (Q24),
     * d = 2^16 - threshold; f <= 2^40, the quotient can pass 32 bits: two divisions */
    const uint32_t d = BLOOM_ONE - g->cfg.threshold;
    const uint32_t qh = 256u / d, rh = 256u % d; /* 2^40 = 256 * 2^32, divided in two steps */
    const uint32_t ql = bloom_div_u64_u32((uint64_t)rh << 32, d); /* no 64-bit divide on Cortex-M */
    const uint64_t fr = ((uint64_t)rh << 32) - (uint64_t)ql * d;
    const uint64_t f = ((uint64_t)qh << 32) + ql + (fr >= (d + 1u) / 2u);

    const int hn = bg_node(g, fn_half, g->w[1], g->h[1], 3, 1);
    bg_input(g, hn, BG_SRC, BG_DOWN, -1, 2);
    const int q = bg_node(g, fn_quarter, g->w[2], g->h[2], 3, 2);
    bg_input(g, q, hn, BG_DOWN, -1, 2);
    if (q >= 0)
        g->node[q].k[1] = sat;
    int prev = q;
    for (int i = 0; i < P; i++) {
        const int kn = bg_node(g, fn_kawase, g->w[2], g->h[2], 3, 2);
        bg_input(g, kn, prev, BG_SAME, -i - 1, i + 1);
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
    const int o = bg_node(g, fn_out, g->w[0], g->h[0], 3, 0);
    bg_input(g, o, BG_SRC, BG_SAME, 0, 0);
    bg_input(g, o, up, BG_UP, -1, 1);
    g->out_node = o;
    g->scratch_rows = 1; /* fn_kawase's column sums */
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_xna = {"xna", defaults, validate, build};

#else
typedef int bloom_preset_xna_unused_t;
#endif
