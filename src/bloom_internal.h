/* The bloom core's shared base: the internal sample format, integer helpers,
 * the rounding rules, the knee/dark/output parameter types, the sRGB tables
 * and pixel access. Every module includes it; it includes nothing of
 * theirs. Row kernels: kernels/bloom_kernels.h; the engine's graph:
 * graph/bloom_graph.h. Nothing here is API. */
#ifndef BLOOM_INTERNAL_H
#define BLOOM_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "bloom.h"

/* Internal linear samples are Q12.20 (sim/docs/fixed-point.md): 16x finer
 * than the Q16.16 of the API, same 256.0 ceiling. BLOOM_LIN_BITS may be set
 * to 16..20 to measure precision against accuracy (make report); the tables
 * (src/pixel/bloom_tables.c) are generated for 20, `gen_tables F` for the others. */
#if BLOOM_LIN_BITS < 16 || BLOOM_LIN_BITS > 20
#error "BLOOM_LIN_BITS must be 16..20 (the overflow proof covers Q12.20)"
#endif
#define BLOOM_Q16_SHIFT (BLOOM_LIN_BITS - 16) /* Q16.16 -> internal */
#define BLOOM_LIN_ONE (1u << BLOOM_LIN_BITS)
#define BLOOM_LIN_MAX (BLOOM_MAX_LINEAR << BLOOM_Q16_SHIFT) /* 2^28 - 16 at 20 bits */

/* Bytes per pixel of a format built in, 0 otherwise (bloom_format_bpp,
 * inline for the row kernels). */
static inline int bloom_bpp(bloom_format_t fmt)
{
    switch (fmt) {
#if BLOOM_USE_RGB888
    case BLOOM_FMT_RGB888:
        return 3;
#endif
#if BLOOM_USE_XRGB8888
    case BLOOM_FMT_XRGB8888:
        return 4;
#endif
#if BLOOM_USE_RGB565
    case BLOOM_FMT_RGB565:
        return 2;
#endif
#if BLOOM_USE_RGBQ16
    case BLOOM_FMT_RGBQ16:
        return 12;
#endif
    default:
        return 0;
    }
}

/* Small integer helpers shared by the core's files. */
static inline int imin(int a, int b)
{
    return a < b ? a : b;
}
static inline int imax(int a, int b)
{
    return a > b ? a : b;
}
static inline int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Size, depth, parameters, formats, flags, preset and aux plane of cfg
 * (bloom_params.c): BLOOM_OK or the most specific refusal. */
bloom_status_t bloom_validate(const bloom_config_t *cfg);

/* Workspace carving (bloom.c), counted in 64 bits so that a
 * configuration too big for a 32-bit address space is refused, not wrapped.
 * BLOOM_TAKE places `count` objects of `type` at offset `off` of `base`
 * (with base NULL it only counts) and moves `off` on, 8-byte aligned. */
static inline uint64_t bloom_align8(uint64_t n)
{
    return (n + 7u) & ~(uint64_t)7u;
}
#define BLOOM_TAKE(base, off, ptr, type, count)                                                              \
    do {                                                                                                     \
        if (base)                                                                                            \
            (ptr) = (type *)(void *)((base) + (size_t)(off));                                                \
        (off) = bloom_align8((off) + sizeof(type) * (uint64_t)(count));                                      \
    } while (0)

/* Ring tags hold the row number; this bit marks a row known to be all zero
 * (or, in the source ring, a dark row). Rows are < 2^30. */
#define BLOOM_TAG_ZERO 0x40000000

/* Rounding without bias (sim/docs/fixed-point.md, "Rounding without
 * bias"). A rounding point whose ties are frequent (a shift of a sum of
 * integers) either rounds half to even, or is paired with one that rounds
 * half the other way: rounding every tie up adds +1/32 LSB per box and
 * +1/16 per tent pass on average, which the up chain sums.
 *   box:  sum / 16, half to even;
 *   tent: vertical pass (x + 4) >> 3 (half up), horizontal pass
 *         (x + 3) >> 3 (half down): the two ties cancel. */
#define BLOOM_BOX_RND(sum) (((sum) + 7u + (((sum) >> 4) & 1u)) >> 4)
#define BLOOM_VT_RND 4u
#define BLOOM_HT_RND 3u
/* The knee's epsilons of bloom-model.md in internal units:
 * soft = x^2 / (4K + 0.00004) is formed as 2x^2 / (8K + KNEE_E8), with
 * KNEE_E8 = round(0.00008 * 2^F); max(b, 0.00001) is b above
 * 2^F / 100000 (10.49 at F = 20) and makes the factor num * KNEE_TINY_F
 * below it (2^24 / (2^F / 100000), an integer for F <= 20). The factor
 * is Q24 (KNEE_FBITS): at Q16 its step was 8 internal LSB on a sample of
 * 0.5, and near the knee's lower edge, where most factors are small,
 * rounding it to the nearest step came out low on average. */
#define BLOOM_KNEE_E8 ((uint32_t)(((1ull << (BLOOM_LIN_BITS + 3)) + 50000u) / 100000u))
#define BLOOM_KNEE_FBITS 24
#define BLOOM_KNEE_TINY_F (100000u << (BLOOM_KNEE_FBITS - BLOOM_LIN_BITS))
/* b * 100000 < 2^F <=> b < ceil(2^F / 100000) (never an integer) */
#define BLOOM_KNEE_TINY_B ((uint32_t)(((1ull << BLOOM_LIN_BITS) + 99999u) / 100000u))

/* Internal -> Q16.16, round half to even (the value was rounded before:
 * half up here would put every tie on the same side). */
static inline uint32_t bloom_lin_to_q16(uint32_t v)
{
#if BLOOM_Q16_SHIFT == 0
    return v;
#else
    const uint32_t q = v >> BLOOM_Q16_SHIFT, r = v & ((1u << BLOOM_Q16_SHIFT) - 1u);
    const uint32_t h = 1u << (BLOOM_Q16_SHIFT - 1);
    return q + (uint32_t)(r > h || (r == h && (q & 1u)));
#endif
}

extern const uint32_t bloom_srgb_dec8[256], bloom_srgb_dec6[64], bloom_srgb_dec5[32];
extern const uint32_t bloom_srgb_enc8[256], bloom_srgb_enc6[64], bloom_srgb_enc5[32];
extern const uint8_t bloom_srgb_bkt8[4097], bloom_srgb_bkt6[1025], bloom_srgb_bkt5[513];

/* Knee parameters, Q12.20 (sim/docs/fixed-point.md step 3). */
typedef struct {
    uint32_t t, k;
} bloom_knee_t;

/* Largest codes (or Q16 word) that decode to a value the knee zeroes: a
 * source row with no channel above them is dark. */
typedef struct {
    uint32_t c8, c6, c5, q16;
} bloom_dark_t;

/* How the output kernel turns B into pixels. */
typedef struct {
    bloom_format_t in_fmt, out_fmt;
    bool linear, debug;
    uint32_t intensity; /* I_q, Q16.16 */
} bloom_out_t;

/* floor(n / d) where the quotient is known to fit in 32 bits: a native
 * divide on 64-bit hosts (inline: the knee calls it twice a pixel), the
 * shift-subtract loop elsewhere (no __aeabi_uldivmod on Cortex-M). */
#if UINTPTR_MAX > 0xFFFFFFFFu
static inline uint32_t bloom_div_u64_u32(uint64_t n, uint32_t d)
{
    return (uint32_t)(n / d);
}
#else
uint32_t bloom_div_u64_u32(uint64_t n, uint32_t d);
#endif
/* The portable shift-subtract loop behind it (tested against '/'). */
uint32_t bloom_div_u64_u32_loop(uint64_t n, uint32_t d);
/* srgb_to_linear of a gamma-space Q16.16 value, integer only. */
uint32_t bloom_srgb_to_linear_q16(uint32_t i);

/* Pixel access (bloom_pixel.c). */
void bloom_pixel_decode(bloom_format_t fmt, bool linear, const uint8_t *p, uint32_t rgb[3]);
/* Whether no channel of the n pixels exceeds the dark codes. */
bool bloom_row_dark(bloom_format_t fmt, const uint8_t *p, int n, const bloom_dark_t *d);
void bloom_pixel_encode(bloom_format_t fmt, bool linear, const uint32_t v[3], uint8_t *p);

#endif
