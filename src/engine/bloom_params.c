/* The configuration's vocabulary: pixel formats, status messages, the
 * defaults, and the checks every configuration goes through before the
 * engine (bloom.c) plans it. */
#include <string.h>

#include "bloom_engine.h"
#include "bloom_internal.h"

const char *bloom_status_str(bloom_status_t st)
{
    switch (st) {
    case BLOOM_OK:
        return "ok";
    case BLOOM_AGAIN:
        return "no output row ready: push more source rows";
    case BLOOM_DONE:
        return "frame complete";
    case BLOOM_E_NULL:
        return "null pointer argument";
    case BLOOM_E_SIZE:
        return "width and height must be 1 .. 16384";
    case BLOOM_E_LEVELS:
        return "levels must be 1 .. 16";
    case BLOOM_E_THRESHOLD:
        return "threshold above 256.0 (Q16.16 16777216)";
    case BLOOM_E_KNEE:
        return "soft knee above 1.0 (Q16.16 65536)";
    case BLOOM_E_INTENSITY:
        return "intensity above 10.0 (Q16.16 655360)";
    case BLOOM_E_FORMAT:
#if BLOOM_USE_RGBF32
        return "pixel format unknown or compiled out, or RGBF32 (input only) as the output";
#else
        return "pixel format unknown or compiled out";
#endif
    case BLOOM_E_FLAGS:
        return "unknown flag bits";
    case BLOOM_E_WORKSPACE:
        return "workspace smaller than bloom_workspace_size()";
    case BLOOM_E_ALIGN:
        return "workspace not aligned to BLOOM_WORKSPACE_ALIGN";
    case BLOOM_E_BUSY:
        return "source ring full: pull before pushing more";
    case BLOOM_E_STATE:
        return "out of order: push after the last row, or no bloom_begin";
    case BLOOM_E_INTERNAL:
        return "internal: a ring row was overwritten while needed";
    case BLOOM_E_TOO_BIG:
        return "workspace beyond the address space: fewer levels or a smaller frame";
    case BLOOM_E_PRESET:
        return "preset unknown or compiled out";
    case BLOOM_E_AUX:
        return "aux plane missing, not used by the preset, or of unknown format";
    case BLOOM_E_TILE:
        return "tile outside the frame";
    case BLOOM_E_ALIAS:
        return "dst overlaps src rows still needed (in place: same format, stride)";
    case BLOOM_E_SAMPLE_BITS:
#if BLOOM_USE_S16
        return "sample_bits must be 16 or 32; 16 takes unity, attenuation, xna and arm (not baked) on "
               "8/6/5-bit input only";
#else
        return "sample_bits not 32"; /* (16-bit samples compiled out: BLOOM_USE_S16 0) */
#endif
#if BLOOM_USE_GRAPH /* only presets other than the default return these */
    case BLOOM_E_STRENGTH:
        return "strength above 16.0 (Q16.16 1048576)";
    case BLOOM_E_PASSES:
        return "Kawase passes must be 1 .. 8";
    case BLOOM_E_ATTENUATION:
        return "attenuation or maximum reduction above 1.0 (Q16.16 65536)";
    case BLOOM_E_WEIGHT:
        return "level weight above 1.0 (Q16.16 65536)";
    case BLOOM_E_TINT:
        return "tint above 1.0 (Q16.16 65536)";
#else
    default:
        break;
#endif
    }
    return "unknown status";
}

void bloom_config_default(bloom_config_t *cfg, int width, int height)
{
    if (!cfg)
        return;
    memset(cfg, 0, sizeof *cfg);
    cfg->width = width;
    cfg->height = height;
    cfg->in_fmt = cfg->out_fmt = BLOOM_FMT_RGB888;
    cfg->levels = 5;
    cfg->threshold = BLOOM_ONE;
    cfg->soft_knee = BLOOM_ONE / 2u;
    cfg->intensity = BLOOM_ONE;
    cfg->flags = 0;
    cfg->sample_bits = 32;
}

bloom_status_t bloom_validate(const bloom_config_t *c)
{
    if (c->width < 1 || c->height < 1 || c->width > BLOOM_MAX_DIM || c->height > BLOOM_MAX_DIM)
        return BLOOM_E_SIZE;
    if (c->levels < 1 || c->levels > BLOOM_MAX_LEVELS)
        return BLOOM_E_LEVELS;
    if (c->threshold > BLOOM_MAX_THRESHOLD)
        return BLOOM_E_THRESHOLD;
    if (c->soft_knee > BLOOM_ONE)
        return BLOOM_E_KNEE;
    if (c->intensity > BLOOM_MAX_INTENSITY)
        return BLOOM_E_INTENSITY;
    if (bloom_format_bpp(c->in_fmt) == 0 || bloom_format_bpp(c->out_fmt) == 0)
        return BLOOM_E_FORMAT;
#if BLOOM_USE_RGBF32
    if (c->out_fmt == BLOOM_FMT_RGBF32) /* an input format only */
        return BLOOM_E_FORMAT;
#endif
    if (c->flags &
        ~(uint32_t)(BLOOM_FLAG_LINEAR | BLOOM_FLAG_DEBUG_VIEW | BLOOM_FLAG_COPY_SOURCE | BLOOM_FLAG_NO_SKIP |
                    BLOOM_FLAG_NO_SIMD | BLOOM_FLAG_NO_AVX2 | BLOOM_FLAG_SATURATE | BLOOM_FLAG_BAKED |
                    BLOOM_FLAG_ADDITIVE | BLOOM_FLAG_KEEP_LEVELS))
        return BLOOM_E_FLAGS;
    if ((c->tile_w | c->tile_h | c->tile_x | c->tile_y) != 0) {
        /* (compared by subtraction: no int overflow) */
#if BLOOM_SMALL
        return BLOOM_E_TILE; /* the size build has no tiles */
#else
        if (c->tile_w < 1 || c->tile_h < 1 || c->tile_x < 0 || c->tile_y < 0 ||
            c->tile_x > c->width - c->tile_w || c->tile_y > c->height - c->tile_h)
            return BLOOM_E_TILE;
#endif
    }
    const bloom_preset_ops_t *ops = bloom_preset_ops(c->preset);
    if (!ops)
        return BLOOM_E_PRESET;
#if BLOOM_USE_S16
    if (c->sample_bits != 0 && c->sample_bits != 32) {
        /* 16-bit rows carry samples up to 1.0 (fixed-point.md, "16-bit
         * samples"): what 8/6/5-bit codes decode to, not RGBQ16's or
         * RGBF32's 256.0; the default pipeline's stages (unity, and
         * attenuation, whose first stage multiplies by at most 1), xna's and
         * arm's pyramid (baked has none); gamedev and cod keep 32-bit rows
         * (their pages say why) */
        if (c->sample_bits != 16 ||
            (c->preset != BLOOM_PRESET_UNITY && c->preset != BLOOM_PRESET_ATTENUATION &&
             c->preset != BLOOM_PRESET_XNA &&
             (c->preset != BLOOM_PRESET_ARM || (c->flags & BLOOM_FLAG_BAKED))) ||
            c->in_fmt == BLOOM_FMT_RGBQ16 || c->in_fmt == BLOOM_FMT_RGBF32)
            return BLOOM_E_SAMPLE_BITS;
    }
#else
    if ((unsigned)c->sample_bits & ~32u) /* 0 or 32 */
        return BLOOM_E_SAMPLE_BITS;
#endif
    if (c->aux_fmt != BLOOM_AUX_NONE && c->aux_fmt != BLOOM_AUX_U8 && c->aux_fmt != BLOOM_AUX_U16)
        return BLOOM_E_AUX;
    return ops->validate(c); /* the preset checks its own parameters, flags and aux plane */
}
