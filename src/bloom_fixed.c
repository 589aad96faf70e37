/* Integer helpers: a 64-by-32 division that needs no runtime library, and
 * the sRGB curve for the intensity parameter (setup only). */
#include "bloom_internal.h"

uint32_t bloom_div_u64_u32_loop(uint64_t n, uint32_t d)
{
    uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n, q = 0;
    if (hi == 0)
        return lo / d;
    /* Restoring division; the quotient fits in 32 bits, so hi < d. */
    for (int i = 0; i < 32; i++) {
        uint32_t carry = hi >> 31;
        hi = (hi << 1) | (lo >> 31);
        lo <<= 1;
        q <<= 1;
        if (carry || hi >= d) {
            hi -= d;
            q |= 1u;
        }
    }
    return q;
}

uint32_t bloom_div_u64_u32(uint64_t n, uint32_t d)
{
#if UINTPTR_MAX > 0xFFFFFFFFu
    return (uint32_t)(n / d); /* native 64-bit divide */
#else
    return bloom_div_u64_u32_loop(n, d); /* no __aeabi_uldivmod on Cortex-M */
#endif
}

#define Q28 (1ull << 28)

/* (a * b) >> 28 for Q4.28 values whose product stays below 2^64. */
static uint64_t mul28(uint64_t a, uint64_t b)
{
    return (a * b) >> 28;
}

uint32_t bloom_srgb_to_linear_q16(uint32_t i)
{
    /* 0.04045 * 65536 = 2650.9: the linear segment is i <= 2650. */
    if (i <= 2650u)
        return (i * 100u + 646u) / 1292u; /* round(i / 12.92) */
    /* a = (i + 0.055) / 1.055 in Q4.28 (i <= 10.0, so a < 9.54) */
    const uint64_t c055 = 14763950ull;    /* round(0.055 * 2^28) */
    const uint64_t r1055 = 254441191ull;  /* round(2^28 / 1.055) */
    uint64_t a = mul28(((uint64_t)i << 12) + c055, r1055);
    uint64_t a2 = mul28(a, a); /* < 91 * 2^28 */
    /* z = a2^(1/5) by bisection: largest z with z^5 <= a2 (z < 2.5). */
    uint64_t lo = 0, hi = 5ull * Q28 / 2u;
    while (hi - lo > 1) {
        uint64_t z = (lo + hi) / 2, p = z;
        for (int k = 0; k < 4; k++)
            p = mul28(p, z);
        if (p <= a2)
            lo = z;
        else
            hi = z;
    }
    /* a^2.4 = a2 * z; Q28 * Q28 -> Q16 with rounding. */
    return (uint32_t)((a2 * lo + (1ull << 39)) >> 40);
}
