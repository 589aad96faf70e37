/* The arm preset's row kernels in C (bloom_preset_arm.h), the reference
 * its SIMD twins are held to, and the choice of a kernel set by the
 * engine's instruction set. */
#include "bloom_preset_arm.h"

#if BLOOM_USE_ARM

static void down_v_c(const uint32_t *s0, const uint32_t *s1, const uint32_t *s2, const uint32_t *s3,
                     uint32_t *c4, uint32_t *c2, int n)
{
    for (int i = 0; i < n; i++) {
        const uint32_t mid = s1[i] + s2[i];
        c2[i] = mid;
        c4[i] = mid + s0[i] + s3[i];
    }
}

/* (S16 + 4 C4) / 32 half to even on the halved sum y = (S16 >> 1) + 2 C4
 * (below 2^32): up when y mod 16 > 8, or = 8 with S16 odd (past the half)
 * or with y >> 4 odd (arm.md, down). */
static uint32_t down_h_c(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n)
{
    uint32_t any = 0;
    for (int x = 0; x < n; x++) {
        const uint32_t *a = c4 + 2 * x, *b = c2 + 2 * x;
        const uint32_t s16 = a[0] + a[1] + a[2] + a[3], cc = b[1] + b[2];
        const uint32_t y = (s16 >> 1) + 2u * cc;
        dst[x] = (y + 7u + (((y >> 4) | s16) & 1u)) >> 4;
        any |= dst[x];
    }
    return any;
}

static void up_v_c(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, uint32_t *a, uint32_t *v,
                   int n)
{
    for (int i = 0; i < n; i++) {
        a[i] = u0[i] + 3u * u1[i];
        v[i] = 3u * u0[i] + 4u * u1[i] + u2[i];
    }
}

/* The sums S <= 192M are formed in 64 bits (arm.md, overflow). */
static uint32_t up_h_c(const uint32_t *a, const uint32_t *v, uint32_t *dst, int np)
{
    uint32_t any = 0;
    for (int i = 0; i < np; i++) {
        const uint64_t a0 = a[i], a1 = a[i + 1], a2 = a[i + 2], v0 = v[i], v1 = v[i + 1], v2 = v[i + 2];
        dst[2 * i] = bloom_arm_div192(11u * a0 + 28u * a1 + a2 + v0 + 3u * v1);
        dst[2 * i + 1] = bloom_arm_div192(a0 + 28u * a1 + 11u * a2 + 3u * v1 + v2);
        any |= dst[2 * i] | dst[2 * i + 1];
    }
    return any;
}

const bloom_arm_kern_t bloom_arm_kern_c = {down_v_c, down_h_c, up_v_c, up_h_c, "c"};

const bloom_arm_kern_t *bloom_arm_kern(bloom_isa_t isa)
{
    switch (isa) {
#if defined(BLOOM_SIMD_SSE2)
    case BLOOM_ISA_SSE2:
        return &bloom_arm_kern_sse2;
#endif
#if defined(BLOOM_SIMD_AVX2)
    case BLOOM_ISA_AVX2:
        return &bloom_arm_kern_avx2;
#endif
#if defined(BLOOM_SIMD_NEON)
    case BLOOM_ISA_NEON:
        return &bloom_arm_kern_neon;
#endif
    default:
        return &bloom_arm_kern_c;
    }
}

#else
typedef int bloom_preset_arm_kern_unused_t;
#endif
