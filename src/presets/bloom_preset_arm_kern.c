/* The arm preset's row kernels in C (bloom_preset_arm.h), the reference
 * its SIMD twins are held to, and the choice of a kernel set by the
 * engine's instruction set. */
#include "bloom_preset_arm.h"
#include "bloom_pixel.h"

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

static uint32_t max3_c(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, int n)
{
    uint32_t m = 0;
    for (int x = 0; x < n; x++) {
        const uint32_t a = u0[x] > u1[x] ? u0[x] : u1[x];
        m = a > m ? a : m;
        m = u2[x] > m ? u2[x] : m;
    }
    return m;
}

#if BLOOM_USE_S16
/* The vertical halves and the maximum on 16-bit rows (cfg.sample_bits = 16:
 * arm.md, "16-bit samples"), into the 32-bit column sums the horizontal
 * halves read; the up filter's sums widened by << sh on the way (sh = F - G
 * for the output's filter, 0 between levels). C only: they read what the
 * 32-bit kernels read and are a small part of the preset's work. */
void bloom_arm_down_v16(const uint16_t *s0, const uint16_t *s1, const uint16_t *s2, const uint16_t *s3,
                        uint32_t *c4, uint32_t *c2, int n)
{
    for (int i = 0; i < n; i++) {
        const uint32_t mid = (uint32_t)s1[i] + s2[i];
        c2[i] = mid;
        c4[i] = mid + s0[i] + s3[i];
    }
}

void bloom_arm_up_v16(const uint16_t *u0, const uint16_t *u1, const uint16_t *u2, uint32_t *a, uint32_t *v,
                      int n, int sh)
{
    for (int i = 0; i < n; i++) { /* 8 (2^16 - 1) << sh < 2^29 for sh <= 10 */
        a[i] = ((uint32_t)u0[i] + 3u * u1[i]) << sh;
        v[i] = (3u * u0[i] + 4u * u1[i] + u2[i]) << sh;
    }
}

uint32_t bloom_arm_max3_16(const uint16_t *u0, const uint16_t *u1, const uint16_t *u2, int n)
{
    uint32_t m = 0;
    for (int x = 0; x < n; x++) {
        const uint32_t a = u0[x] > u1[x] ? u0[x] : u1[x];
        m = a > m ? a : m;
        m = u2[x] > m ? u2[x] : m;
    }
    return m;
}
#endif

/* Y <= M: 64-bit products (Q24 weights x 2^28, their sum < 2^53). */
#define ARM_LUM8_LOOP(OP)                                                                                    \
    for (int x = 0; x < n; x++, p += step) {                                                                 \
        const uint32_t y = (uint32_t)((BLOOM_ARM_WR * (uint64_t)bloom_srgb_dec8[p[r]] +                      \
                                       BLOOM_ARM_WG * (uint64_t)bloom_srgb_dec8[p[1]] +                      \
                                       BLOOM_ARM_WB * (uint64_t)bloom_srgb_dec8[p[b]] + (1u << 23)) >>       \
                                      24);                                                                   \
        OP;                                                                                                  \
    }
static void lum8_c(const uint8_t *p, uint32_t *c4, uint32_t *c2, int n, bool x4, int i)
{
    const int step = x4 ? 4 : 3, r = x4 ? 2 : 0, b = x4 ? 0 : 2;
    switch (i) {
    case 0:
        ARM_LUM8_LOOP(c4[x] = y)
        break;
    case 1:
        ARM_LUM8_LOOP((c4[x] += y, c2[x] = y))
        break;
    case 2:
        ARM_LUM8_LOOP((c4[x] += y, c2[x] += y))
        break;
    default:
        ARM_LUM8_LOOP(c4[x] += y)
        break;
    }
}
#undef ARM_LUM8_LOOP

/* The code c itself where P <= max(A c, H0) (BLOOM_KEEP8, bloom_kernels.h:
 * the encoder gives c back), the table encoder (P clamped to 2^24, above
 * which both encoders give 255) otherwise. */
#if !BLOOM_SMALL /* (the table encoder of the fast output path: bloom_pixel.h) */
static void out8_c(const uint8_t *src, const uint32_t *b, const uint32_t f[3], uint8_t *dst, int n, bool x4)
{
    const int step = x4 ? 4 : 3, ch[3] = {x4 ? 2 : 0, 1, x4 ? 0 : 2}; /* byte q holds channel ch[q] */
    for (int x = 0; x < n; x++, src += step, dst += step) {
        const uint64_t bx = b[x];
        for (int q = 0; q < 3; q++) {
            const uint64_t p = (f[ch[q]] * bx + 32768u) >> 16;
            const uint32_t c = src[q],
                           lb = BLOOM_KEEP8_A * c > BLOOM_KEEP8_H0 ? BLOOM_KEEP8_A * c : BLOOM_KEEP8_H0;
            dst[q] =
                p <= lb
                    ? (uint8_t)c
                    : (uint8_t)BLOOM_FENC8(bloom_srgb_dec8[c] + (p < (1u << 24) ? (uint32_t)p : 1u << 24));
        }
        if (x4)
            dst[3] = 0xFF;
    }
}
#endif

const bloom_arm_kern_t bloom_arm_kern_c = {
    down_v_c, down_h_c, up_v_c, up_h_c, max3_c, lum8_c, BLOOM_ARM_OUT8(out8_c), "c"};

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
