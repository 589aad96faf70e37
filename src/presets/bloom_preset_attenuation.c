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

static bool d1_atten(const bloom_graph_t *g, const bg_node_t *n, int r,
                     const void *const *const in[BG_MAX_IN], void *dst)
{
    uint32_t *row = (uint32_t *)dst;
    if (!bg_fn_d1(g, n, r, in, dst))
        return false; /* zero times the factor */
    const uint32_t a = g->cfg.p.attenuation, rmin = g->cfg.p.max_reduction;
    const int w0 = g->w[0];
    for (int x = 0; x < n->w; x++) {
        const int x0 = 2 * x, x1 = 2 * x + 1 < w0 ? 2 * x + 1 : w0 - 1;
        const uint32_t d = (bg_aux_q24(g, in[1][0], x0) + bg_aux_q24(g, in[1][0], x1) +
                            bg_aux_q24(g, in[1][1], x0) + bg_aux_q24(g, in[1][1], x1) + 2u) >>
                           2;
        uint32_t f = (1u << 24) - (uint32_t)(((uint64_t)a * ((1u << 24) - d) + 32768u) >> 16);
        if (f < rmin << 8)
            f = rmin << 8;
        if (f == 1u << 24)
            continue;
        for (int c = 0; c < 3; c++)
            row[3 * x + c] = (uint32_t)(((uint64_t)row[3 * x + c] * f + (1u << 23)) >> 24);
    }
    return true;
}

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
    if (cfg->flags & (BLOOM_FLAG_SATURATE | BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE))
        return BLOOM_E_FLAGS;
    return BLOOM_OK;
}

static bloom_status_t build(bloom_graph_t *g)
{
    bg_build_out_add(g, bg_build_updown(g, d1_atten, true));
    /* the factor is at most 1: what the knee zeroes stays zero */
    g->dark_cut = bg_knee_cut(g);
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_attenuation = {"attenuation", defaults, validate, build};

#else
typedef int bloom_preset_attenuation_unused_t;
#endif
