/* Preset "attenuation": the default pipeline with its first pass (D_1,
 * after the knee) multiplied by max(lerp(1, d, a), r), d the depth plane
 * (aux, 0 = near, max code = far) averaged over the 2x2 block of the
 * half-resolution pixel (sim/docs/presets.md).
 *
 * Integer form, in Q24 (a Q16 factor, constant over a flat depth, put the
 * same rounding on every pixel: a bias of up to 1.2e-5 of each sample):
 * d_q = (sum of the four samples' Q24 values + 2) >> 2,
 * f = 2^24 - ((a * (2^24 - d_q) + 32768) >> 16), factor = max(f, r * 2^8),
 * D_1 = (D_1 * factor + 2^23) >> 24 (a 64-bit product: D_1 < 2^28,
 * factor <= 2^24). With a = 0 the factor is exactly 1 and the preset
 * computes the default's bits. */
#include "bloom_stages.h"

#if BLOOM_USE_ATTENUATION

/* The factor of a half-resolution pixel from its four depth samples' Q24
 * values (summed): f = max(2^24 - ((a (2^24 - d_q) + 2^15) >> 16), r 2^8). */
static inline uint32_t factor(uint32_t q24_sum, uint32_t a, uint32_t fmin)
{
    const uint32_t d = (q24_sum + 2u) >> 2;
    const uint32_t f = (1u << 24) - (uint32_t)(((uint64_t)a * ((1u << 24) - d) + 32768u) >> 16);
    return f < fmin ? fmin : f;
}

/* The four depth codes under half-resolution pixel x, as the sum of their
 * Q24 values (bg_aux_q24 each: for U8, c 2^24 / 255 rounded is 65793 c +
 * [c >= 128], so the sum is 65793 (sum of c) + the count of c >= 128). */
static inline uint32_t depth_sum(const bg_ctx_t *ctx, const void *r0, const void *r1, int x0, int x1)
{
    if (ctx->aux_bpp == 1) {
        const uint8_t *a = (const uint8_t *)r0, *b = (const uint8_t *)r1;
        const uint32_t c0 = a[x0], c1 = a[x1], c2 = b[x0], c3 = b[x1];
        return 65793u * (c0 + c1 + c2 + c3) + (c0 >> 7) + (c1 >> 7) + (c2 >> 7) + (c3 >> 7);
    }
    return bg_aux_q24(ctx, r0, x0) + bg_aux_q24(ctx, r0, x1) + bg_aux_q24(ctx, r1, x0) +
           bg_aux_q24(ctx, r1, x1);
}

static bool d1_atten(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                     void *dst)
{
    uint32_t *row = (uint32_t *)dst;
    if (!bg_fn_d1(ctx, n, r, in, dst))
        return false; /* zero times the factor */
    const uint32_t a = ctx->cfg->p.attenuation, fmin = ctx->cfg->p.max_reduction << 8;
    if (a == 0)
        return true;                   /* the factor is exactly 1 */
    const int w0 = bg_in_w(ctx, n, 1); /* the aux plane's columns from 2 xa on */
    for (int x = 0; x < n->w; x++) {
        uint32_t *p = row + 3 * x;
        if (x + 4 <= n->w && (x & 3) == 0) { /* four zero pixels stay zero: most of a dark scene */
            uint32_t o = 0;
            for (int i = 0; i < 12; i++)
                o |= p[i];
            if (!o) {
                x += 3;
                continue;
            }
        }
        if (!(p[0] | p[1] | p[2]))
            continue;
        const int x0 = 2 * x, x1 = 2 * x + 1 < w0 ? 2 * x + 1 : w0 - 1;
        const uint32_t f = factor(depth_sum(ctx, in[1][0], in[1][1], x0, x1), a, fmin);
        if (f == 1u << 24)
            continue;
        for (int c = 0; c < 3; c++)
            p[c] = (uint32_t)(((uint64_t)p[c] * f + (1u << 23)) >> 24);
    }
    return true;
}

#if BLOOM_USE_S16
/* 16-bit samples: d1_atten's row narrowed (the factor is at most 1, so the
 * default's bound on D_1 holds). */
static bool d1_atten16(const bg_ctx_t *ctx, const bg_node_t *n, int r, const void *const *const in[BG_MAX_IN],
                       void *dst)
{
    return bg_s16_d1(ctx, n, r, in, dst, d1_atten);
}
#endif

static void defaults(bloom_config_t *cfg)
{
    cfg->aux_fmt = BLOOM_AUX_U8;
    cfg->p.attenuation = BLOOM_ONE * 3u / 4u; /* a = 0.75 */
    cfg->p.max_reduction = BLOOM_ONE / 4u;    /* r = 0.25 */
}

static bloom_status_t validate(const bloom_config_t *cfg)
{
    if (cfg->aux_fmt != BLOOM_AUX_U8 && cfg->aux_fmt != BLOOM_AUX_U16)
        return BLOOM_E_AUX;
    if (cfg->p.attenuation > BLOOM_ONE || cfg->p.max_reduction > BLOOM_ONE)
        return BLOOM_E_ATTENUATION;
    if (cfg->flags & (BLOOM_FLAG_SATURATE | BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE | BLOOM_FLAG_KEEP_LEVELS))
        return BLOOM_E_FLAGS;
    return BLOOM_OK;
}

static bloom_status_t build(bg_graph_t *g, bg_params_t *par)
{
    bg_build_out_add(g, bg_build_updown(g, d1_atten, true));
#if BLOOM_USE_S16
    if (g->cfg->sample_bits == 16)
        bloom_stages_s16(g, par, d1_atten16);
#endif
    if (!BLOOM_SMALL)
        par->views = true; /* the stages and d1_atten read their widths by bg_in_w */
    /* the factor is at most 1: what the knee zeroes stays zero */
    par->dark_cut = bg_knee_cut(par);
    if (BG_DARK_COPY)
        par->dark_copy = true; /* zero bloom: the source copied (bg_fn_out_add) */
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_attenuation = {"attenuation", defaults, validate, build};

#else
typedef int bloom_preset_attenuation_unused_t;
#endif
