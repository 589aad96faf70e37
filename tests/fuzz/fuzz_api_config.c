/* fuzz_api's configurations (fuzz_api.h): a preset and its defaults, then
 * fields in and out of range, read from the input in the order
 * gen_seeds_api.c writes them. */
#include "fuzz_api.h"

#include <string.h>

static uint32_t pick(fz_in_t *in, uint32_t def, uint32_t max)
{
    switch (fz_u8(in) % 8) {
    case 0:
        return 0;
    case 1:
        return max;
    case 2:
        return max + 1; /* just out of range */
    case 3:
    case 4:
        return fz_u32(in) % (max + 1);
    case 5:
        return fz_u32(in);
    default:
        return def;
    }
}

/* Fills c; returns 1 when it is a preset's defaults at a valid size,
 * formats and depth, untouched since (bloom_query must take it). */
int fz_api_make_config(fz_in_t *in, bloom_config_t *c)
{
    const unsigned m = fz_u8(in);
    int w = 1 + (int)(fz_u8(in) % MAXW), h = 1 + (int)(fz_u8(in) % MAXW), valid = 1;
    if (m & 1) {
        static const int odd[] = {0, -1, BLOOM_MAX_DIM + 1, 1};
        const unsigned k = fz_u8(in);
        *(k & 1 ? &w : &h) = odd[(k >> 1) % 4];
        valid = odd[(k >> 1) % 4] == 1;
    }
    bloom_config_default(c, w, h);
    const unsigned fi = fz_u8(in), fo = fz_u8(in);
    /* 0 and 6: no such format; RGBF32 (5) is an input format only, so it
     * is a valid input and a refused output. */
    c->in_fmt = (bloom_format_t)(m & 2 ? fi % 7 : 1 + fi % 5);
    c->out_fmt = (bloom_format_t)(m & 2 ? fo % 7 : 1 + fo % 4);
    valid &= bloom_format_bpp(c->in_fmt) && bloom_format_bpp(c->out_fmt) && c->out_fmt != BLOOM_FMT_RGBF32;
    c->levels = m & 4 ? (int)(fz_u8(in) % 19) - 1 : 1 + (int)(fz_u8(in) % 16);
    valid &= c->levels >= 1 && c->levels <= BLOOM_MAX_LEVELS;
    const unsigned p = fz_u8(in) % 8;
    if (p < BLOOM_PRESET_COUNT) {
        FZ_CHECK(bloom_config_preset(c, (bloom_preset_t)p) == BLOOM_OK);
        FZ_CHECK(c->preset == (bloom_preset_t)p && c->width == w && c->height == h);
    } else if (p == 7) { /* no such preset: refused, c untouched */
        bloom_config_t before = *c;
        FZ_CHECK(bloom_config_preset(c, (bloom_preset_t)(fz_u8(in) & 1 ? -1 : BLOOM_PRESET_COUNT)) ==
                 BLOOM_E_PRESET);
        FZ_CHECK(!memcmp(&before, c, sizeof before));
    }
    /* the flags that must not change the bits, then the others */
    static const uint32_t same[] = {BLOOM_FLAG_COPY_SOURCE, BLOOM_FLAG_NO_SKIP, BLOOM_FLAG_NO_SIMD,
                                    BLOOM_FLAG_NO_AVX2};
    const unsigned f = fz_u8(in);
    for (int k = 0; k < 4; k++)
        if (f & (1u << k))
            c->flags |= same[k];
    if (f & 16)
        c->flags |= BLOOM_FLAG_LINEAR;
    if (f & 32)
        c->flags |= BLOOM_FLAG_DEBUG_VIEW;
    if (f & 64) { /* preset flags and unknown bits, given to anyone */
        c->flags ^= (uint32_t)1 << (fz_u8(in) % 32);
        valid = 0;
    }
    if (!(m & 8))
        return valid;
    /* fields in and out of range */
    for (unsigned n = 1 + fz_u8(in) % 4; n; n--) {
        const unsigned k = fz_u8(in) % 11;
        switch (k) {
        case 0:
            c->threshold = pick(in, c->threshold, BLOOM_MAX_THRESHOLD);
            break;
        case 1:
            c->soft_knee = pick(in, c->soft_knee, BLOOM_ONE);
            break;
        case 2:
            c->intensity = pick(in, c->intensity, BLOOM_MAX_INTENSITY);
            break;
        case 3:
            c->p.strength = pick(in, c->p.strength, 16u << 16);
            break;
        case 4:
            c->p.passes = (int)(fz_u8(in) % 11) - 1;
            break;
        case 5:
            c->p.attenuation = pick(in, c->p.attenuation, BLOOM_ONE);
            break;
        case 6:
            c->p.max_reduction = pick(in, c->p.max_reduction, BLOOM_ONE);
            break;
        case 7:
            c->p.tint[fz_u8(in) % 3] = pick(in, 0, BLOOM_ONE);
            break;
        case 8:
            c->p.level_weight[fz_u8(in) % BLOOM_MAX_LEVELS] = pick(in, 0, BLOOM_ONE);
            break;
        case 9:
            c->aux_fmt = (bloom_aux_format_t)(fz_u8(in) % 4);
            break;
        default:
            c->preset = (bloom_preset_t)((int)(fz_u8(in) % 8) - 1);
            break;
        }
    }
    return 0;
}

/* A configuration bloom_query took holds the documented ranges, for the
 * common fields and for the parameters its preset reads. */
void fz_api_check_taken(const bloom_config_t *c, const bloom_info_t *info)
{
    FZ_CHECK(c->width >= 1 && c->width <= BLOOM_MAX_DIM && c->height >= 1 && c->height <= BLOOM_MAX_DIM);
    FZ_CHECK(c->levels >= 1 && c->levels <= BLOOM_MAX_LEVELS);
    FZ_CHECK(c->threshold <= BLOOM_MAX_THRESHOLD && c->soft_knee <= BLOOM_ONE &&
             c->intensity <= BLOOM_MAX_INTENSITY);
    FZ_CHECK(bloom_format_bpp(c->in_fmt) && bloom_format_bpp(c->out_fmt));
    FZ_CHECK(bloom_preset_available(c->preset));
    const uint32_t reads = bloom_preset_params(c->preset);
    if (reads & BLOOM_PARAM_STRENGTH)
        FZ_CHECKF(c->p.strength <= 16u << 16, "strength %u", c->p.strength);
    if (reads & BLOOM_PARAM_PASSES)
        FZ_CHECKF(c->p.passes >= 1 && c->p.passes <= 8, "passes %d", c->p.passes);
    if (reads & BLOOM_PARAM_ATTENUATION)
        FZ_CHECK(c->p.attenuation <= BLOOM_ONE);
    if (reads & BLOOM_PARAM_MAX_REDUCTION)
        FZ_CHECK(c->p.max_reduction <= BLOOM_ONE);
    if (reads & BLOOM_PARAM_TINT)
        FZ_CHECK(c->p.tint[0] <= BLOOM_ONE && c->p.tint[1] <= BLOOM_ONE && c->p.tint[2] <= BLOOM_ONE);
    if (reads & BLOOM_PARAM_WEIGHTS)
        for (int k = 0; k < BLOOM_MAX_LEVELS; k++)
            FZ_CHECKF(c->p.level_weight[k] <= BLOOM_ONE, "weight %d %u", k, c->p.level_weight[k]);
    if (!(reads & BLOOM_PARAM_AUX))
        FZ_CHECK(c->aux_fmt == BLOOM_AUX_NONE);
    /* gamedev (3) and xna (2) have their own depth (sim/docs/presets/) */
    const int depth = c->preset == BLOOM_PRESET_GAMEDEV ? 3 : c->preset == BLOOM_PRESET_XNA ? 2 : c->levels;
    FZ_CHECKF(info->levels >= 0 && info->levels <= depth && info->latency_rows >= 0,
              "%s %dx%d, %d levels asked: %d built, latency %d", bloom_preset_name(c->preset), c->width,
              c->height, c->levels, info->levels, info->latency_rows);
    FZ_CHECK(info->workspace_bytes > 0 && info->workspace_bytes == bloom_workspace_size(c));
    if (c->preset == BLOOM_PRESET_UNITY) /* the static bound (bloom.h) holds */
        FZ_CHECK(info->workspace_bytes <= BLOOM_WORKSPACE_MAX(c->width, c->height, c->levels,
                                                              bloom_format_bpp(c->in_fmt),
                                                              (c->flags & BLOOM_FLAG_COPY_SOURCE) != 0));
}

/* The calls that take no engine: names, presets, statuses, formats. */
void fz_api_check_pure(fz_in_t *in)
{
    char name[17];
    const unsigned n = fz_u8(in) % sizeof name;
    for (unsigned i = 0; i < n; i++)
        name[i] = (char)fz_u8(in);
    name[n] = '\0';
    const int p = bloom_preset_from_name(name);
    FZ_CHECK(p >= -1 && p < BLOOM_PRESET_COUNT);
    for (int q = 0; q < BLOOM_PRESET_COUNT; q++)
        FZ_CHECK((strcmp(bloom_preset_name((bloom_preset_t)q), name) == 0) == (p == q));
    FZ_CHECK(bloom_preset_from_name(NULL) == -1);
    const int any = (int)fz_u32(in);
    const int known = any >= 0 && any < BLOOM_PRESET_COUNT;
    FZ_CHECK(!bloom_preset_name((bloom_preset_t)any) == !known);
    FZ_CHECK(known ||
             (bloom_preset_params((bloom_preset_t)any) == 0 && !bloom_preset_available((bloom_preset_t)any)));
    const int lv = bloom_levels_for_radius(any);
    FZ_CHECK(lv >= 1 && lv <= BLOOM_MAX_LEVELS);
    FZ_CHECK(bloom_status_str((bloom_status_t)any) != NULL);
    const int bpp = bloom_format_bpp((bloom_format_t)any);
    FZ_CHECK(bpp == 0 || bpp == 2 || bpp == 3 || bpp == 4 || bpp == 12);
    bloom_info_t info;
    FZ_CHECK(bloom_query(NULL, &info) == BLOOM_E_NULL && bloom_workspace_size(NULL) == 0);
    FZ_CHECK(bloom_config_preset(NULL, BLOOM_PRESET_UNITY) == BLOOM_E_NULL);
}
