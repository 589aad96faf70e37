/* Presets by name, their defaults and what each reads (sim/docs/presets.md),
 * and the table of their hooks. Each function is its own section: a
 * firmware that never names a preset links none of the names. */

#include "bloom_presets.h"

static const char *const preset_names[BLOOM_PRESET_COUNT] = {"unity",       "gamedev", "xna",
                                                             "attenuation", "arm",     "cod"};

const char *bloom_preset_name(bloom_preset_t p)
{
    return (unsigned)p < BLOOM_PRESET_COUNT ? preset_names[p] : NULL;
}

/* No strcmp: a freestanding build links nothing but memcpy/memset. */
static bool same_name(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

int bloom_preset_from_name(const char *name)
{
    for (int i = 0; name && i < BLOOM_PRESET_COUNT; i++)
        if (same_name(name, preset_names[i]))
            return i;
    return -1;
}

int bloom_preset_available(bloom_preset_t p)
{
    return bloom_preset_ops(p) != NULL;
}

uint32_t bloom_preset_params(bloom_preset_t p)
{
    static const uint32_t reads[BLOOM_PRESET_COUNT] = {
        [BLOOM_PRESET_UNITY] = 0u,
        [BLOOM_PRESET_GAMEDEV] = BLOOM_PARAM_STRENGTH,
        [BLOOM_PRESET_XNA] = BLOOM_PARAM_PASSES | BLOOM_PARAM_SATURATE,
        [BLOOM_PRESET_ATTENUATION] = BLOOM_PARAM_ATTENUATION | BLOOM_PARAM_MAX_REDUCTION | BLOOM_PARAM_AUX,
        [BLOOM_PRESET_ARM] = BLOOM_PARAM_STRENGTH | BLOOM_PARAM_AUX | BLOOM_PARAM_TINT | BLOOM_PARAM_BAKED,
        [BLOOM_PRESET_COD] = BLOOM_PARAM_TINT | BLOOM_PARAM_WEIGHTS | BLOOM_PARAM_ADDITIVE |
                             BLOOM_PARAM_RADIUS | BLOOM_PARAM_KEEP_LEVELS,
    };
    return (unsigned)p < BLOOM_PRESET_COUNT ? reads[p] : 0u;
}

bloom_status_t bloom_config_preset(bloom_config_t *cfg, bloom_preset_t p)
{
    if (!cfg)
        return BLOOM_E_NULL;
    if (!bloom_preset_available(p))
        return BLOOM_E_PRESET;
    bloom_config_t d;
    bloom_config_default(&d, cfg->width, cfg->height);
    d.in_fmt = cfg->in_fmt;
    d.out_fmt = cfg->out_fmt;
    if (cfg->levels >= 1 && cfg->levels <= BLOOM_MAX_LEVELS)
        d.levels = cfg->levels; /* cod's default weights follow the depth */
    d.flags = cfg->flags & (uint32_t)(BLOOM_FLAG_LINEAR | BLOOM_FLAG_DEBUG_VIEW | BLOOM_FLAG_COPY_SOURCE |
                                      BLOOM_FLAG_NO_SKIP | BLOOM_FLAG_NO_SIMD | BLOOM_FLAG_NO_AVX2);
    d.preset = p;
    bloom_preset_ops(p)->defaults(&d);
    *cfg = d;
    return BLOOM_OK;
}

const bloom_preset_ops_t *bloom_preset_ops(bloom_preset_t p)
{
    switch (p) {
    case BLOOM_PRESET_UNITY:
        return &bloom_preset_unity;
#if BLOOM_USE_GAMEDEV
    case BLOOM_PRESET_GAMEDEV:
        return &bloom_preset_gamedev;
#endif
#if BLOOM_USE_XNA
    case BLOOM_PRESET_XNA:
        return &bloom_preset_xna;
#endif
#if BLOOM_USE_ATTENUATION
    case BLOOM_PRESET_ATTENUATION:
        return &bloom_preset_attenuation;
#endif
#if BLOOM_USE_ARM
    case BLOOM_PRESET_ARM:
        return &bloom_preset_arm;
#endif
#if BLOOM_USE_COD
    case BLOOM_PRESET_COD:
        return &bloom_preset_cod;
#endif
    default:
        return NULL;
    }
}
