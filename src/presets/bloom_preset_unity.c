/* Preset "unity", the default pipeline (bloom-model.md; Catlike Coding's
 * "Bloom", Unity PPv2 style): sRGB decode, 4x4 box down with the soft knee
 * on level 1, box down to level L, tent up adding each level, a final tent
 * composited onto the source, sRGB encode. */
#include "bloom_stages.h"

static void defaults(bloom_config_t *cfg)
{
    (void)cfg; /* bloom_config_default's values are this preset's */
}

static bloom_status_t validate(const bloom_config_t *cfg)
{
    if (cfg->flags & (BLOOM_FLAG_SATURATE | BLOOM_FLAG_BAKED | BLOOM_FLAG_ADDITIVE | BLOOM_FLAG_KEEP_LEVELS))
        return BLOOM_E_FLAGS;
    if (cfg->aux_fmt != BLOOM_AUX_NONE)
        return BLOOM_E_AUX;
    return BLOOM_OK;
}

static bloom_status_t build(bg_graph_t *g, bg_params_t *par)
{
    bg_build_out_add(g, bg_build_updown(g, bg_fn_d1, false));
#if BLOOM_USE_S16
    if (g->cfg->sample_bits == 16)
        bloom_stages_s16(g, par, bg_fn_d1_16);
#endif
    if (!BLOOM_SMALL)
        par->views = true; /* the stages read their widths by bg_in_w */
    if (BLOOM_USE_SKIP)
        par->dark_cut = bg_knee_cut(par); /* a source row with nothing above t - k makes zeros */
    if (BG_DARK_COPY)
        par->dark_copy = true; /* zero bloom: the source copied (bg_fn_out_add) */
    return BLOOM_OK;
}

const bloom_preset_ops_t bloom_preset_unity = {"unity", defaults, validate, build};
