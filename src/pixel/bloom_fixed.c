/* Integer helpers: a 64-by-32 division that needs no runtime library, and
 * the sRGB curve for the intensity parameter (setup only, correctly
 * rounded by an exact multi-word comparison). */
#include "bloom_pixel.h"

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

#if UINTPTR_MAX <= 0xFFFFFFFFu
uint32_t bloom_div_u64_u32(uint64_t n, uint32_t d)
{
    return bloom_div_u64_u32_loop(n, d);
}
#endif

/* x (n little-endian 32-bit limbs) *= m; returns the new limb count. */
static int mp_mul(uint32_t *x, int n, uint32_t m)
{
    uint64_t c = 0;
    for (int j = 0; j < n; j++) {
        c += (uint64_t)x[j] * m;
        x[j] = (uint32_t)c;
        c >>= 32;
    }
    if (c)
        x[n++] = (uint32_t)c;
    return n;
}

/* Whether (2q - 1)^5 * 1055^12 * 2^71 <= m^12, exactly (both below 2^320:
 * m < 2^27, 2q - 1 < 2^25). */
static bool q_fits(uint32_t q, uint32_t m)
{
    uint32_t l[11] = {0, 0, 1}, r[11] = {1}; /* l starts at 2^64: times 2^7 below gives 2^71 */
    int nl = 3, nr = 1;
    for (int k = 0; k < 12; k++) {
        nl = mp_mul(l + 2, nl - 2, 1055u) + 2;
        nr = mp_mul(r, nr, m);
    }
    for (int k = 0; k < 5; k++)
        nl = mp_mul(l + 2, nl - 2, 2u * q - 1u) + 2;
    nl = mp_mul(l + 2, nl - 2, 128u) + 2;
    if (nl != nr)
        return nl < nr;
    for (int j = nl - 1; j >= 0; j--)
        if (l[j] != r[j])
            return l[j] < r[j];
    return true;
}

uint32_t bloom_srgb_to_linear_q16(uint32_t i)
{
    /* 0.04045 * 65536 = 2650.9: the linear segment is i <= 2650. */
    if (i <= 2650u)
        return (i * 100u + 646u) / 1292u; /* round(i / 12.92); never a tie */
    /* Above it, v = a^2.4 with a = (i/65536 + 0.055) / 1.055 = m / (1055 * 2^13),
     * m = 125 i + 450560. The result is the largest q with q - 1/2 <= 65536 v,
     * i.e. ((2q - 1) / 2^17)^5 <= a^12, which in integers is
     * (2q - 1)^5 * 1055^12 * 2^71 <= m^12: decided exactly (q_fits), q found
     * by bisection. So I_q = round(srgb_to_linear(i) * 65536) exactly (no
     * value lies within 1e-6 of a tie, tests/test_fixed.c checks every i). */
    const uint32_t m = 125u * i + 450560u;
    uint32_t lo = 1, hi = 1u << 24; /* q_fits(lo), !q_fits(hi): v <= 223.9 */
    while (hi - lo > 1) {
        const uint32_t q = lo + (hi - lo) / 2;
        if (q_fits(q, m))
            lo = q;
        else
            hi = q;
    }
    return lo;
}
