/* The preset models: dispatch, the common parameters, and the two presets
 * that are the default pipeline itself (unity) or nearly (attenuation). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"

/* The quantized parameters by the rules of sim/docs/fixed-point.md
 * ("Parameters at setup"), computed here in double from the configuration
 * alone: never read back from the engine, so that a wrong quantization in
 * the core shows as a bit-true mismatch. Every product is an integer below
 * 2^53, so each step is exact; I_q is the correctly rounded sRGB curve
 * (the double is within 1e-9 of the real value, no value lies within 1e-6
 * of a tie: tests/test_fixed.c holds the core to it for every intensity). */
void bloom_model_quantize(const bloom_config_t *c, int lin_bits, uint32_t *threshold_q, uint32_t *knee_q,
                          uint32_t *intensity_q)
{
    const double t = (double)c->threshold * ldexp(1.0, (lin_bits ? lin_bits : 20) - 16);
    *threshold_q = (uint32_t)t;
    *knee_q = (uint32_t)floor((t * (double)c->soft_knee + 32768.0) / 65536.0);
    *intensity_q = (uint32_t)floor(bloom_srgb_to_linear(c->intensity / 65536.0) * 65536.0 + 0.5);
    if (c->preset == BLOOM_PRESET_GAMEDEV) { /* hard threshold; scene + strength * bloom, linear */
        *knee_q = 0;
        *intensity_q = c->p.strength;
    }
}

int bloom_model_params_from(const bloom_model_preset_args_t *a, bloom_model_params_t *p)
{
    const bloom_config_t *c = a ? a->cfg : NULL;
    /* bloom_query only says whether the core takes cfg (the model's own
     * checks are weaker); none of its numbers is used */
    if (!c || bloom_query(c, NULL) != BLOOM_OK)
        return -1;
    memset(p, 0, sizeof *p);
    p->width = c->width;
    p->height = c->height;
    p->levels = c->levels;
    p->linear = (c->flags & BLOOM_FLAG_LINEAR) != 0;
    p->debug_view = (c->flags & BLOOM_FLAG_DEBUG_VIEW) != 0;
    p->bittrue = a->bittrue;
    p->threshold = c->threshold / 65536.0;
    p->soft_knee = c->soft_knee / 65536.0;
    p->intensity = c->intensity / 65536.0;
    p->lin_bits = BLOOM_LIN_BITS;
    p->sample_bits = c->sample_bits;
    p->s16_levels = BLOOM_S16_LEVELS;
    bloom_model_quantize(c, p->lin_bits, &p->threshold_q, &p->knee_q, &p->intensity_q);
    return 0;
}

int bloom_model_preset_run(const bloom_model_preset_args_t *a)
{
    if (!a || !a->cfg)
        return -1;
    switch (a->cfg->preset) {
    case BLOOM_PRESET_UNITY:
        return bloom_model_unity(a);
#if BLOOM_USE_ATTENUATION
    case BLOOM_PRESET_ATTENUATION:
        return bloom_model_attenuation(a);
#endif
#if BLOOM_USE_GAMEDEV
    case BLOOM_PRESET_GAMEDEV:
        return bloom_model_gamedev(a);
#endif
#if BLOOM_USE_XNA
    case BLOOM_PRESET_XNA:
        return bloom_model_xna(a);
#endif
#if BLOOM_USE_ARM
    case BLOOM_PRESET_ARM:
        return bloom_model_arm(a);
#endif
#if BLOOM_USE_COD
    case BLOOM_PRESET_COD:
        return bloom_model_cod(a);
#endif
    default:
        return -1;
    }
}

int bloom_model_unity(const bloom_model_preset_args_t *a)
{
    bloom_model_params_t p;
    if (bloom_model_params_from(a, &p))
        return -1;
    return bloom_model_run(&p, a->src, a->src_max, a->dst_codes, a->dst_max, a->dst_value);
}

/* Attenuation: D1 scaled by max(lerp(1, d, a), r), d the depth averaged
 * over the half-resolution pixel's 2x2 block (edge rule at odd sizes).
 * Bit-true: the Q24 integer form of src/presets/bloom_preset_attenuation.c. */
int bloom_model_attenuation(const bloom_model_preset_args_t *a)
{
    bloom_model_params_t p;
    if (bloom_model_params_from(a, &p) || !a->aux || (a->aux_max != 255 && a->aux_max != 65535))
        return -1;
    const int w = a->cfg->width, h = a->cfg->height, w1 = (w + 1) / 2, h1 = (h + 1) / 2;
    const double att = a->cfg->p.attenuation / 65536.0, rmin = a->cfg->p.max_reduction / 65536.0;
    double *f = malloc((size_t)w1 * (size_t)h1 * sizeof *f);
    if (!f)
        return -1;
    for (int y = 0; y < h1; y++)
        for (int x = 0; x < w1; x++) {
            const int xs[2] = {2 * x, 2 * x + 1 < w ? 2 * x + 1 : w - 1};
            const int ys[2] = {2 * y, 2 * y + 1 < h ? 2 * y + 1 : h - 1};
            double sum = 0.0;
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++) {
                    const double c = a->aux[(size_t)ys[i] * (size_t)w + (size_t)xs[j]];
                    if (!a->bittrue)
                        sum += c / a->aux_max;
                    else /* c * 2^24 / max, rounded (max is odd: no tie) */
                        sum += floor((c * 16777216.0 + (a->aux_max - 1) / 2) / a->aux_max);
                }
            double v;
            if (!a->bittrue) {
                const double d = sum / 4.0;
                v = fmax(1.0 + att * (d - 1.0), rmin);
            } else { /* Q24 */
                const double d = floor((sum + 2.0) / 4.0);
                v = 16777216.0 -
                    floor(((double)a->cfg->p.attenuation * (16777216.0 - d) + 32768.0) / 65536.0);
                v = fmax(v, (double)a->cfg->p.max_reduction * 256.0);
            }
            f[(size_t)y * (size_t)w1 + (size_t)x] = v;
        }
    p.d1_scale = f;
    const int L = bloom_model_run(&p, a->src, a->src_max, a->dst_codes, a->dst_max, a->dst_value);
    free(f);
    return L;
}
