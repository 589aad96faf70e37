/* Reference model of the bloom engine: the maths of sim/docs/bloom-model.md in
 * double precision (float mode), or the integer pipeline of
 * sim/docs/fixed-point.md one rounding point at a time (bit-true mode).
 *
 * Full-frame, heap-allocated, plain loops: this is the readable
 * specification, not a fast implementation. */
#ifndef BLOOM_MODEL_H
#define BLOOM_MODEL_H

#include <stdint.h>

#define BLOOM_MODEL_MAX_LEVELS 16

typedef struct {
    int width, height; /* source size, >= 1 each */
    int levels;        /* requested N, 1..16; the level-count rule of bloom-model.md decides L */
    int linear;        /* 1: no sRGB curves (linear input decode and linear output encode) */
    int debug_view;    /* 1: out = I*B instead of S + I*B */
    int bittrue;       /* 0: float model; 1: bit-true model */
    /* float model parameters (real values; intensity in gamma space as the user gives it) */
    double threshold, soft_knee, intensity;
    /* bit-true parameters: the quantized values (fixed-point.md, "Parameters
     * at setup"), T_q and K_q in Q12.20, I_q in Q16.16: from
     * bloom_model_quantize, never read back from the engine */
    uint32_t threshold_q, knee_q, intensity_q;
    int lin_bits; /* bit-true: fraction bits F of the internal samples (BLOOM_LIN_BITS,
                     16..20); 0 means 20. T_q and K_q are then in Q(32-F).F */
    /* Optional factor per level-1 pixel (w1*h1, row-major) applied to D1
     * after the knee (the attenuation preset): real factors in float mode,
     * Q24 integers (0 .. 2^24) in bit-true mode, there D1 = (D1*f + 2^23) >> 24.
     * NULL: none. */
    const double *d1_scale;
    /* Bits of the pyramid samples (bit-true mode; the float model ignores
     * it): 32 (or 0), or 16: D_1 is narrowed to Q(16-G).G, G = 16 - bitlen(L),
     * by F - G bits half to even after the knee (and d1_scale); the down and
     * up chains then run in those units (the pyramid hooks hold them); U_1
     * is widened back (times 2^(F-G)) before the final tent
     * (sim/docs/fixed-point.md, "16-bit samples"). The arm and xna models
     * read cfg.sample_bits for their own formats (their pages, "16-bit
     * samples"). */
    int sample_bits;
    int s16_levels; /* with 16: levels 1 .. s16_levels 16-bit, the deeper ones in
                       internal units (BLOOM_S16_LEVELS; 0: all) */
} bloom_model_params_t;

#define BLOOM_MODEL_F32 (-1) /* src_max: the word is a binary32 linear value */

/* src: width*height pixels, 3 words each (R,G,B), row-major, top row first.
 * src_max[c] is the largest code of channel c (255, 63 or 31), or 0 meaning the
 * word is a linear Q16.16 value (the RGBQ16 format; the bit-true mode clamps it to 2^24-1
 * as the core does; the float model uses word/65536 unclamped), or BLOOM_MODEL_F32
 * meaning the word holds the bits of a linear IEEE-754 binary32 value (RGBF32; the
 * bit-true mode rounds v * 2^F half to even and clamps it as the core does, the float
 * model uses v; both read negative values and NaN as 0). Output has no such code.
 * dst_codes (may be NULL): width*height*3 output codes; dst_max[c] as src_max
 * (0 = Q16.16 output: bit-true min((v + 8) >> 4, 2^24-1); float: round-half-up(v*65536) clamped to [0, 2^24-1]).
 * dst_value (may be NULL): width*height*3 doubles, the linear value v before encoding
 * (in bit-true mode: the Q12.20 integer v / 2^20).
 * Returns the number of levels L actually used (>= 1), or -1 on bad arguments.
 *
 * Bad arguments (also -1): a NULL pointer that is required, a size < 1,
 * levels outside 1..16, a max code outside 0..65535, a source code above its
 * max, float threshold < 0, soft_knee outside [0, 1], intensity < 0 (or any
 * of them not finite); bit-true threshold_q > 2^28, knee_q > threshold_q
 * (the core's K_q = (T_q*s + 32768) >> 16 never exceeds T_q), intensity_q > 2^24.
 * Out of memory also returns -1. */
int bloom_model_run(const bloom_model_params_t *p, const uint32_t *src, const int src_max[3],
                    uint32_t *dst_codes, const int dst_max[3], double *dst_value);

/* helpers, also used by tests and the preset models */
/* A code (0..n, or n = 0: a Q16.16 word) decoded as the core does (step 1 of
 * fixed-point.md): real linear light in float mode, the Q(32-F).F integer in
 * bit-true mode (lin_bits F, 0 = 20). */
double bloom_model_decode(int bittrue, int linear, uint32_t code, int n, int lin_bits);
/* The inverse (step 7): v in the same units -> output code 0..n (n = 0: Q16.16). */
uint32_t bloom_model_encode(int bittrue, int linear, double v, int n, int lin_bits);
/* floor(a / b) for integers a < 2^53, b >= 1 held in doubles, exactly. */
double bloom_model_fdiv(double a, double b);
/* G of 16-bit samples for a bit-true p whose largest row value is L times
 * the knee's peak (fixed-point.md, "16-bit samples"). */
int bloom_model_s16_frac(const bloom_model_params_t *p, int L);
/* a / den for integers a < 2^53, den >= 1, rounded half to even. */
double bloom_model_round_even(double a, double den);
double bloom_srgb_to_linear(double x); /* the sRGB curve of bloom-model.md, extended unchanged above 1 */
double bloom_linear_to_srgb(double x); /* its inverse, for x >= 0 */
int bloom_model_levels(int w, int h, int requested); /* L by the level-count rule; -1 on bad arguments */

/* ---- Inspection hooks (tests, debugging) --------------------------------
 * Values are in model units: real linear light in float mode, Q12.20
 * integers (not divided by 2^20) in bit-true mode. */

typedef struct {
    int w, h;
    double *px; /* w*h*3 values (R,G,B), row-major */
} bloom_model_image_t;

typedef struct {
    int levels;                                        /* L */
    bloom_model_image_t S;                             /* decoded source, level 0 */
    bloom_model_image_t D[BLOOM_MODEL_MAX_LEVELS + 1]; /* D[1..L]; D[1] after the knee */
    bloom_model_image_t U[BLOOM_MODEL_MAX_LEVELS + 1]; /* U[1..L]; U[L] = D[L] */
    bloom_model_image_t B;                             /* tentup(U[1]), full resolution */
} bloom_model_pyramid_t;

/* Runs decode, down chain, knee and up chain (everything before the
 * composite). Returns L, or -1 as bloom_model_run (then *out holds nothing
 * to free). Release with bloom_model_pyramid_free. */
int bloom_model_pyramid(const bloom_model_params_t *p, const uint32_t *src, const int src_max[3],
                        bloom_model_pyramid_t *out);
void bloom_model_pyramid_free(bloom_model_pyramid_t *pyr);

/* Single stages. dst is allocated here (free with bloom_model_image_free).
 * box_down gives ceil(w/2) x ceil(h/2); tent_up gives w x h and requires
 * ceil(w/2) x ceil(h/2) == low's size. Both return 0, or -1 on bad size or
 * out of memory. */
int bloom_model_box_down(const bloom_model_image_t *src, bloom_model_image_t *dst, int bittrue);
int bloom_model_tent_up(const bloom_model_image_t *low, int w, int h, bloom_model_image_t *dst, int bittrue);
void bloom_model_image_free(bloom_model_image_t *im);

/* The prefilter (soft knee) on one pixel in place, with p's mode and
 * parameters (p is not otherwise validated). */
void bloom_model_knee(const bloom_model_params_t *p, double rgb[3]);

/* ---- presets (sim/docs/presets.md) --------------------------------------
 * The model of every preset of the core, driven by the core's own
 * configuration: float mode takes the parameters as the real values they
 * stand for (Q16.16 / 65536; intensity through the sRGB curve), bit-true
 * mode the values bloom_model_quantize computes by the written rules. */
#include "bloom.h"

typedef struct {
    const bloom_config_t *cfg; /* preset, sizes, formats, flags, parameters */
    int bittrue;
    const uint32_t *src; /* w*h*3 codes as for bloom_model_run */
    int src_max[3];
    const uint32_t *aux; /* w*h one-channel codes (0..aux_max), or NULL */
    int aux_max;         /* 255 (BLOOM_AUX_U8) or 65535 (BLOOM_AUX_U16) */
    uint32_t *dst_codes; /* w*h*3, or NULL */
    int dst_max[3];
    double *dst_value; /* w*h*3 linear values before the encode, or NULL */
} bloom_model_preset_args_t;

/* Returns the number of levels used (>= 1), or -1 on bad arguments. */
int bloom_model_preset_run(const bloom_model_preset_args_t *a);
/* One per preset (sim/model/model_<name>.c); same contract. */
int bloom_model_unity(const bloom_model_preset_args_t *a);
int bloom_model_attenuation(const bloom_model_preset_args_t *a);
int bloom_model_gamedev(const bloom_model_preset_args_t *a);
int bloom_model_xna(const bloom_model_preset_args_t *a);
int bloom_model_arm(const bloom_model_preset_args_t *a);
int bloom_model_cod(const bloom_model_preset_args_t *a);
/* The quantized threshold, knee and intensity of cfg (any preset) by the
 * rules of fixed-point.md, computed in double from cfg alone; lin_bits F
 * (0 = 20). The tests hold bloom_query's figures equal to these. */
void bloom_model_quantize(const bloom_config_t *c, int lin_bits, uint32_t *threshold_q, uint32_t *knee_q,
                          uint32_t *intensity_q);
/* bloom_model_params_t for a preset args' common part (sizes, knee,
 * intensity, flags, mode), quantized by bloom_model_quantize. Returns 0,
 * or -1 when bloom_query refuses cfg (only its verdict is used). */
int bloom_model_params_from(const bloom_model_preset_args_t *a, bloom_model_params_t *p);

#endif
