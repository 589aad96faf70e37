/* gd_bright, gd_gauss_v and gd_gauss_h on W lanes, written once for the
 * SSE2, AVX2 and NEON twins (bloom_preset_gamedev_{sse2,avx2,neon}.c
 * define these and include this file; nothing else does):
 *   VT            a vector of W uint32_t lanes, wrapping like uint32_t
 *   VB            the same register as 4 W uint8_t lanes
 *   W             its 32-bit lanes
 *   LDV(p), STV(p, v)  W words, unaligned;  LDB(p), STB(p, v)  4 W bytes
 *   ADDV(a, b)    lane-wise add (32-bit lanes)
 *   GAUSSV(c, p1, p2, p3, p4)  (W0 c + W1 p1 + W2 p2 + W3 p3 + W4 p4 +
 *                 2^23) >> 24 on every lane, the products and their sum
 *                 in 64 bits, the low 32 bits of the result kept
 *   DUPB(c), MAXB(a, b), SUBSB(a, b)  a byte on every lane, the unsigned
 *                 byte maximum, the unsigned byte difference saturated at 0
 *   GD_FN(f)      the twin's name for the C kernel f (f ## _sse2, ...)
 * Same bits as the C kernels (bloom_preset_gamedev_kern.c): the byte
 * maximum minus the dark code saturated at 0 is gd_bright_c's; the
 * Gaussian adds the symmetric pairs in 32-bit lanes (< 2^29, as C does)
 * and GAUSSV forms C's 64-bit sum of the same products; the tails go to
 * the C kernels. The per-code table (gd_lut8) is no twin of this: the
 * AVX2 byte shuffles and the NEON table lookups stay in their files. */

void GD_FN(gd_bright)(const uint8_t *const s[4], uint8_t *b, int n, uint32_t c)
{
    const VB cv = DUPB((uint8_t)(c > 255u ? 255u : c));
    int i = 0;
    for (; i + 4 * W <= n; i += 4 * W) {
        const VB m = MAXB(MAXB(LDB(s[0] + i), LDB(s[1] + i)), MAXB(LDB(s[2] + i), LDB(s[3] + i)));
        STB(b + i, SUBSB(m, cv));
    }
    if (i < n) {
        const uint8_t *const t[4] = {s[0] + i, s[1] + i, s[2] + i, s[3] + i};
        gd_bright_c(t, b + i, n - i, c);
    }
}

void GD_FN(gd_gauss_v)(const uint32_t *const a[9], uint32_t *dst, int m)
{
    const uint32_t *a0 = a[0], *a1 = a[1], *a2 = a[2], *a3 = a[3], *a4 = a[4], *a5 = a[5], *a6 = a[6],
                   *a7 = a[7], *a8 = a[8];
    int i = 0;
    for (; i + W <= m; i += W)
        STV(dst + i, GAUSSV(LDV(a4 + i), ADDV(LDV(a3 + i), LDV(a5 + i)), ADDV(LDV(a2 + i), LDV(a6 + i)),
                            ADDV(LDV(a1 + i), LDV(a7 + i)), ADDV(LDV(a0 + i), LDV(a8 + i))));
    if (i < m) {
        const uint32_t *const t[9] = {a0 + i, a1 + i, a2 + i, a3 + i, a4 + i, a5 + i, a6 + i, a7 + i, a8 + i};
        gd_gauss_v_c(t, dst + i, m - i);
    }
}

void GD_FN(gd_gauss_h)(const uint32_t *v, uint32_t *dst, int i0, int i1)
{
    int i = i0;
    for (; i + W <= i1; i += W) {
        const uint32_t *p = v + i;
        STV(dst + i, GAUSSV(LDV(p), ADDV(LDV(p - 3), LDV(p + 3)), ADDV(LDV(p - 6), LDV(p + 6)),
                            ADDV(LDV(p - 9), LDV(p + 9)), ADDV(LDV(p - 12), LDV(p + 12))));
    }
    if (i < i1)
        gd_gauss_h_c(v, dst, i, i1);
}

/* the operation layer is the including file's: undone here, once */
#undef VT
#undef VB
#undef W
#undef LDV
#undef STV
#undef LDB
#undef STB
#undef ADDV
#undef GAUSSV
#undef DUPB
#undef MAXB
#undef SUBSB
#undef GD_FN
