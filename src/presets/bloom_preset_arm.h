/* The arm preset's own row kernels (bloom_preset_arm.c) and their SIMD
 * twins (bloom_preset_arm_sse2.c, _avx2.c, _neon.c), bit-identical to the
 * C ones (tests/test_simd_arm.c), picked by the engine's instruction set
 * (g->kern.isa). One-channel rows of Q12.20 samples <= M = 2^28 - 16
 * (sim/docs/presets/arm.md, overflow). */
#ifndef BLOOM_PRESET_ARM_H
#define BLOOM_PRESET_ARM_H

#include "bloom_kernels.h"

typedef struct {
    /* Vertical half of the down filter: c2[i] = s1[i] + s2[i],
     * c4[i] = c2[i] + s0[i] + s3[i], i < n. */
    void (*down_v)(const uint32_t *s0, const uint32_t *s1, const uint32_t *s2, const uint32_t *s3,
                   uint32_t *c4, uint32_t *c2, int n);
    /* Horizontal half: dst[i] = (S16 + 4 C4) / 32 rounded half to even,
     * S16 = c4[2i] + .. + c4[2i+3], C4 = c2[2i+1] + c2[2i+2], i < n (reads
     * c4, c2 [0 .. 2n+1]). Returns the OR of dst[0 .. n-1]. */
    uint32_t (*down_h)(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n);
    /* Vertical half of the up filter: a[i] = u0[i] + 3 u1[i],
     * v[i] = 3 u0[i] + 4 u1[i] + u2[i], i < n (u0 the row on the output
     * row's side). */
    void (*up_v)(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, uint32_t *a, uint32_t *v, int n);
    /* Horizontal half, np output pairs: dst[2i] = floor((S_e + 96) / 192),
     * S_e = 11 a[i] + 28 a[i+1] + a[i+2] + v[i] + 3 v[i+1], and dst[2i+1]
     * the mirror (reads a, v [0 .. np+1]). Returns the OR of dst[0 .. 2np-1]. */
    uint32_t (*up_h)(const uint32_t *a, const uint32_t *v, uint32_t *dst, int np);
    const char *name;
} bloom_arm_kern_t;

extern const bloom_arm_kern_t bloom_arm_kern_c;
#if defined(BLOOM_SIMD_SSE2)
extern const bloom_arm_kern_t bloom_arm_kern_sse2;
#endif
#if defined(BLOOM_SIMD_AVX2)
extern const bloom_arm_kern_t bloom_arm_kern_avx2;
#endif
#if defined(BLOOM_SIMD_NEON)
extern const bloom_arm_kern_t bloom_arm_kern_neon;
#endif
/* The set for an engine's instruction set (the C one for BLOOM_ISA_C). */
const bloom_arm_kern_t *bloom_arm_kern(bloom_isa_t isa);

/* One output of the up filter from the five sums (q < 2^30 + 45). */
static inline uint32_t bloom_arm_div192(uint64_t s)
{
    const uint32_t q = (uint32_t)((s + 96u) >> 6);
    return (uint32_t)(((uint64_t)q * 0xAAAAAAABu) >> 33);
}

#endif
