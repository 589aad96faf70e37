/* The arm preset's down_v, up_v, up_h, max3 and (where the includer has a
 * deinterleaving load) down_h (bloom_preset_arm.h) on W lanes, written
 * once for the SSE2, AVX2 and NEON twins (bloom_preset_arm_{sse2,avx2,
 * neon}.c define these and include this file; nothing else does):
 *   VT            a vector of W uint32_t lanes, wrapping like uint32_t
 *   W             its lanes
 *   LDV(p), STV(p, v)  W words, unaligned
 *   ADDV(a, b), ANDV(a, b), ORV(a, b), SHLV(a, n), SHRV(a, n) (logical),
 *   DUPV(c)       lane-wise, and c on every lane
 *   MLAV(a, x, k) a + k x, for k = 3 and 4
 *   SUM5(x0, x1, x2, y0, y1)  11 x0 + 28 x1 + x2 + y0 + 3 y1
 *   DIV3(q)       floor(q / 3) on every lane, q < 2^31
 *   MAXV(a, b), MAX_LANES(v)  the lane-wise maximum of samples <= M, and
 *                 the largest lane as a uint32_t
 *   OR_LANES(v)   the OR of the lanes, as a uint32_t
 *   ST2V(p, e, o) 2 W words at p: e0 o0 e1 o1 ..
 *   VT2, LD2V(p)  optional: 2 W words at p as a VT2 of .val[0] = p[0],
 *                 p[2], .. and .val[1] = p[1], p[3], ..; without them no
 *                 down_h here
 *   ARM_TAIL      the kernel set the tails go to (bloom_preset_arm.h)
 *   ARM_FN(f)     the twin's name for the kernel f (f ## _sse2, ...)
 * Same bits as the C kernels (bloom_preset_arm_kern.c): the down sums and
 * the up filter's vertical sums are C's, below 2^32 (and wrapping like
 * C's uint32_t if they were not); the up filter's horizontal sums
 * S <= 192 M, which C forms in 64 bits, are formed exactly in 32-bit
 * lanes by splitting every input t as 64 h + l (l < 64): S + 96 =
 * 64 Sh + (Sl + 96), so q = (S + 96) >> 6 = Sh + ((Sl + 96) >> 6), with
 * Sh <= 3 M < 2^30 and Sl + 96 < 2^12, and DIV3 is the q / 3 of C's
 * bloom_arm_div192; every sample is <= M < 2^31, so MAXV may compare
 * signed (SSE2). max3 of fewer than W columns goes to the C kernel, every
 * other tail to ARM_TAIL. */

static void ARM_FN(down_v)(const uint32_t *s0, const uint32_t *s1, const uint32_t *s2, const uint32_t *s3,
                           uint32_t *c4, uint32_t *c2, int n)
{
    int i = 0;
    for (; i + W <= n; i += W) {
        const VT mid = ADDV(LDV(s1 + i), LDV(s2 + i));
        STV(c2 + i, mid);
        STV(c4 + i, ADDV(mid, ADDV(LDV(s0 + i), LDV(s3 + i))));
    }
    if (i < n)
        ARM_TAIL.down_v(s0 + i, s1 + i, s2 + i, s3 + i, c4 + i, c2 + i, n - i);
}

#if defined(LD2V)
static uint32_t ARM_FN(down_h)(const uint32_t *c4, const uint32_t *c2, uint32_t *dst, int n)
{
    const VT k7 = DUPV(7), k1 = DUPV(1);
    VT any = DUPV(0);
    int x = 0;
    for (; x + W <= n; x += W) { /* reads c4, c2 [2x .. 2x + 2W + 1] */
        const uint32_t *a = c4 + 2 * x, *b = c2 + 2 * x;
        const VT2 a0 = LD2V(a), a2 = LD2V(a + 2), b0 = LD2V(b), b2 = LD2V(b + 2);
        const VT s16 = ADDV(ADDV(a0.val[0], a0.val[1]), ADDV(a2.val[0], a2.val[1]));
        const VT cc = ADDV(b0.val[1], b2.val[0]);
        const VT y = ADDV(SHRV(s16, 1), SHLV(cc, 1));
        const VT t = ANDV(ORV(SHRV(y, 4), s16), k1);
        const VT d = SHRV(ADDV(ADDV(y, k7), t), 4);
        STV(dst + x, d);
        any = ORV(any, d);
    }
    uint32_t r = OR_LANES(any);
    if (x < n)
        r |= ARM_TAIL.down_h(c4 + 2 * x, c2 + 2 * x, dst + x, n - x);
    return r;
}
#endif

static void ARM_FN(up_v)(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, uint32_t *a, uint32_t *v,
                         int n)
{
    int i = 0;
    for (; i + W <= n; i += W) {
        const VT p = LDV(u0 + i), m = LDV(u1 + i), q = LDV(u2 + i);
        STV(a + i, MLAV(p, m, 3));
        STV(v + i, MLAV(MLAV(q, m, 4), p, 3));
    }
    if (i < n)
        ARM_TAIL.up_v(u0 + i, u1 + i, u2 + i, a + i, v + i, n - i);
}

static uint32_t ARM_FN(up_h)(const uint32_t *a, const uint32_t *v, uint32_t *dst, int np)
{
    const VT m63 = DUPV(63), k96 = DUPV(96);
    VT any = DUPV(0);
    int i = 0;
    for (; i + W <= np; i += W) { /* reads a, v [i .. i + W + 1] */
        const VT a0 = LDV(a + i), a1 = LDV(a + i + 1), a2 = LDV(a + i + 2);
        const VT v0 = LDV(v + i), v1 = LDV(v + i + 1), v2 = LDV(v + i + 2);
        const VT ah0 = SHRV(a0, 6), ah1 = SHRV(a1, 6), ah2 = SHRV(a2, 6);
        const VT vh0 = SHRV(v0, 6), vh1 = SHRV(v1, 6), vh2 = SHRV(v2, 6);
        const VT al0 = ANDV(a0, m63), al1 = ANDV(a1, m63), al2 = ANDV(a2, m63);
        const VT vl0 = ANDV(v0, m63), vl1 = ANDV(v1, m63), vl2 = ANDV(v2, m63);
        /* q = Sh + ((Sl + 96) >> 6), even and odd outputs */
        const VT e =
            DIV3(ADDV(SUM5(ah0, ah1, ah2, vh0, vh1), SHRV(ADDV(SUM5(al0, al1, al2, vl0, vl1), k96), 6)));
        const VT o =
            DIV3(ADDV(SUM5(ah2, ah1, ah0, vh2, vh1), SHRV(ADDV(SUM5(al2, al1, al0, vl2, vl1), k96), 6)));
        ST2V(dst + 2 * i, e, o);
        any = ORV(any, ORV(e, o));
    }
    uint32_t r = OR_LANES(any);
    if (i < np)
        r |= ARM_TAIL.up_h(a + i, v + i, dst + 2 * i, np - i);
    return r;
}

static uint32_t ARM_FN(max3)(const uint32_t *u0, const uint32_t *u1, const uint32_t *u2, int n)
{
    if (n < W)
        return bloom_arm_kern_c.max3(u0, u1, u2, n);
    VT m = DUPV(0);
    for (int i = 0;; i += W) {
        if (i + W > n) /* the last W again */
            i = n - W;
        m = MAXV(m, MAXV(LDV(u0 + i), MAXV(LDV(u1 + i), LDV(u2 + i))));
        if (i + W >= n)
            break;
    }
    return MAX_LANES(m);
}

/* the operation layer is the including file's: undone here, once */
#undef VT
#undef W
#undef LDV
#undef STV
#undef ADDV
#undef ANDV
#undef ORV
#undef SHLV
#undef SHRV
#undef DUPV
#undef MLAV
#undef SUM5
#undef DIV3
#undef MAXV
#undef MAX_LANES
#undef OR_LANES
#undef ST2V
#undef VT2
#undef LD2V
#undef ARM_TAIL
#undef ARM_FN
