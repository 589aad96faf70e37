/* The cod preset's host helpers (sim/model/model_cod.c): Bevy's blend factors as
 * the preset's Q16 level weights, and the model with the Karis average
 * switchable (for the firefly comparison). Doubles; not part of the core. */
#ifndef BLOOM_MODEL_COD_H
#define BLOOM_MODEL_COD_H

#include <stdint.h>

#include "bloom_model.h"

/* Bevy's BloomSettings (crates/bevy_core_pipeline/src/bloom/settings.rs). */
typedef struct {
    double intensity;                     /* 0 .. 1 */
    double low_frequency_boost;           /* 0 .. 1 */
    double low_frequency_boost_curvature; /* 0 .. 1 */
    double high_pass_frequency;           /* (0, 1] */
    int additive;                         /* BloomCompositeMode::Additive */
} bloom_cod_bevy_t;

extern const bloom_cod_bevy_t bloom_cod_natural;     /* intensity 0.15, 0.7, 0.95, 1.0 */
extern const bloom_cod_bevy_t bloom_cod_old_school;  /* 0.05, 0.7, 0.95, 1.0, additive */
extern const bloom_cod_bevy_t bloom_cod_screen_blur; /* 1.0, 0, 0, 1/3 */

/* Bevy's compute_blend_factor(settings, mip, max_mip); max_mip 0 reads
 * mip / max_mip as 0 (a one-level pyramid). */
double bloom_cod_blend_factor(const bloom_cod_bevy_t *s, int mip, int max_mip);
/* The level weights c_k = compute_blend_factor(k, L - 1), k = 0 .. L-1, as
 * Q16 rounded to nearest and clamped to [0, 1.0] (the preset's range).
 * w[k] for k >= L (unused by an engine of L levels) is the curve's value at
 * the lowest frequency (mip = max_mip), so that a caller who deepens the
 * pyramid without recomputing the weights keeps blending the deeper levels
 * in instead of cutting the glow off at level L. */
void bloom_cod_weights(const bloom_cod_bevy_t *s, int L, uint32_t w[BLOOM_MAX_LEVELS]);

/* bloom_model_cod with the Karis average on (1, the preset) or off (0: the
 * plain 13-tap on level 1 too). */
int bloom_model_cod_ex(const bloom_model_preset_args_t *a, int karis);

#endif
