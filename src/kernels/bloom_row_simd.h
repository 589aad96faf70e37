/* The SIMD row kernels, written once over a few vector operations that
 * bloom_row_sse2.c and bloom_row_neon.c define before including this file
 * (nothing else includes it). One vector holds one pixel: lanes 0..2 are
 * R, G, B, lane 3 is the next sample (read, computed on, never stored), so
 * every load stays inside the row by construction: the `_any` wrappers give
 * the SIMD loops only the interior columns and leave the edges (where
 * columns clamp) and the tails to the C kernels.
 *
 * Operations the includer defines, on VT (4 x uint32_t lanes, wrapping):
 *   LD4(p), ST4(p, v)  four samples, unaligned
 *   LD2(p), ST2(p, v)  two samples in lanes 0, 1
 *   ADD(a, b), AND(a, b), OR(a, b), SHL(a, n), SHR(a, n) (logical), DUP(c)
 *   OR_LANES(v)        the OR of the four lanes, as a uint32_t
 *   ADD_SHR3(acc, v)   acc + (v >> 3)
 *   PACK_LO(e, o)      [e0 e1 e2 o0]     PACK_HI(o)  [o1 o2 . .]
 *
 * Bit-identical to the C kernels: the box sums stay below 2^32 (as in C,
 * and wrap exactly like C's uint32_t if they did not), and the tent's
 * (3a + 4b + c + 4) >> 3 of 32-bit a, b, c, which C forms in 64 bits, is
 * formed exactly in 32-bit lanes by splitting every input as 8h + l:
 * 3a + 4b + c + 4 = 8(3ha + 4hb + hc) + (3la + 4lb + lc + 4), so the
 * result is (3ha + 4hb + hc) + ((3la + 4lb + lc + 4) >> 3); the first term
 * is at most 8(2^29 - 1) and the second at most 7, so neither wraps. */

static inline int simd_imin(int a, int b)
{
    return a < b ? a : b;
}
static inline int simd_imax(int a, int b)
{
    return a > b ? a : b;
}

/* ---- box down: 4x4 of four rows, sum / 16 half to even ------------------ */

/* Column sum of the four rows at sample index i (lane 3: the next sample). */
#define COL4(s0, s1, s2, s3, i)                                                                              \
    ADD(ADD(LD4((s0) + (i)), LD4((s1) + (i))), ADD(LD4((s2) + (i)), LD4((s3) + (i))))

/* Destination pixels xa .. xa + 2 np - 1 (xa >= 1) in pairs; reads source
 * columns 2 xa - 1 .. 2 (xa + 2 np - 2) + 4 and one sample past them. */
static void box_pairs(const uint32_t *const s[4], uint32_t *dst, int xa, int np)
{
    const uint32_t *s0 = s[0], *s1 = s[1], *s2 = s[2], *s3 = s[3];
    size_t c = (size_t)(2 * xa - 1) * 3u;
    uint32_t *d = dst + (size_t)xa * 3u;
    VT a = ADD(COL4(s0, s1, s2, s3, c), COL4(s0, s1, s2, s3, c + 3u)); /* columns 2x-1, 2x */
    for (int i = 0; i < np; i++, c += 12u, d += 6u) {
        const VT b = ADD(COL4(s0, s1, s2, s3, c + 6u), COL4(s0, s1, s2, s3, c + 9u));
        const VT e = bloom_box_rnd4(ADD(a, b));
        a = ADD(COL4(s0, s1, s2, s3, c + 12u), COL4(s0, s1, s2, s3, c + 15u));
        const VT o = bloom_box_rnd4(ADD(b, a));
        ST4(d, PACK_LO(e, o));
        ST2(d + 4, PACK_HI(o));
    }
}

static void box_any(const uint32_t *const s[4], uint32_t *dst, int dw, int sw)
{
    /* SIMD pairs start at x = 1 (column 2x - 1 = 1 needs no clamp); the
     * pair starting at x reads up to sample 3 (2x + 4) + 3 < 3 sw. */
    const int xa = 1;
    int np = 0;
    if (sw >= 8 && dw >= 3) {
        const int xlast = (sw - 6) / 2; /* largest first pixel of a pair */
        np = simd_imin((xlast - xa) / 2 + 1, (dw - xa) / 2);
        if (np < 0)
            np = 0;
    }
    if (np == 0) {
        bloom_row_box_range_c(s, dst, 0, dw, sw);
        return;
    }
    bloom_row_box_range_c(s, dst, 0, xa, sw);
    box_pairs(s, dst, xa, np);
    bloom_row_box_range_c(s, dst, xa + 2 * np, dw, sw);
}

/* ---- tent up ------------------------------------------------------------- */

/* (3a + 4b + c + 4) >> 3 exactly (see the top of the file): the vertical
 * pass, half up. */
static inline VT tent3(VT a, VT b, VT c)
{
    const VT k7 = DUP(7u), k4 = DUP(BLOOM_VT_RND);
    const VT ha = SHR(a, 3), hb = SHR(b, 3), hc = SHR(c, 3);
    const VT la = AND(a, k7), lb = AND(b, k7), lc = AND(c, k7);
    const VT hi = ADD(ADD(ADD(ha, SHL(ha, 1)), SHL(hb, 2)), hc);
    const VT lo = ADD(ADD(ADD(la, SHL(la, 1)), SHL(lb, 2)), ADD(lc, k4));
    return ADD_SHR3(hi, lo);
}

/* Output columns 2 ma .. 2 (ma + np) - 1 in pairs (ma >= 1); dst and add
 * point at column 2 ma. Reads low-resolution columns ma - 1 .. ma + np and
 * one sample past them. Odd rows weigh (1, 4, 3) = (3, 4, 1) on the rows
 * in reverse, odd columns likewise. */
static void tent_pairs(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int ma,
                       int np)
{
    const uint32_t *a = odd ? u[2] : u[0], *b = u[1], *c = odd ? u[0] : u[2];
    const VT k7 = DUP(7u), kh = DUP(BLOOM_HT_RND);
    size_t i = (size_t)(ma - 1) * 3u;
    const VT vp = tent3(LD4(a + i), LD4(b + i), LD4(c + i));
    i += 3u;
    const VT vc = tent3(LD4(a + i), LD4(b + i), LD4(c + i));
    VT hp = SHR(vp, 3), lp = AND(vp, k7), hc = SHR(vc, 3), lc = AND(vc, k7);
    for (int j = 0; j < np; j++, dst += 6) {
        i += 3u;
        const VT vn = tent3(LD4(a + i), LD4(b + i), LD4(c + i));
        const VT hn = SHR(vn, 3), ln = AND(vn, k7);
        /* even: 3 vp + 4 vc + vn; odd: vp + 4 vc + 3 vn; split as in tent3 */
        const VT q = ADD(SHL(hc, 2), ADD(hp, hn));
        const VT ql = ADD(ADD(SHL(lc, 2), ADD(lp, ln)), kh); /* horizontal: half down */
        const VT e = ADD_SHR3(ADD(q, SHL(hp, 1)), ADD(ql, SHL(lp, 1)));
        const VT o = ADD_SHR3(ADD(q, SHL(hn, 1)), ADD(ql, SHL(ln, 1)));
        VT lo4 = PACK_LO(e, o), hi2 = PACK_HI(o);
        if (add) {
            lo4 = ADD(lo4, LD4(add));
            hi2 = ADD(hi2, LD2(add + 4));
            add += 6;
        }
        ST4(dst, lo4);
        ST2(dst + 4, hi2);
        hp = hc;
        lp = lc;
        hc = hn;
        lc = ln;
    }
}

/* The same pairs when every u value read is below 2^29: then
 * 3a + 4b + c + 4 < 2^32 and the sums need no split (same bits). */
static void tent_pairs_small(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int ma,
                             int np)
{
    const uint32_t *a = odd ? u[2] : u[0], *b = u[1], *c = odd ? u[0] : u[2];
    const VT k4 = DUP(BLOOM_VT_RND), kh = DUP(BLOOM_HT_RND);
    size_t i = (size_t)(ma - 1) * 3u;
#define TENT3S(a_, b_, c_) SHR(ADD(ADD(ADD((a_), SHL((a_), 1)), SHL((b_), 2)), ADD((c_), k4)), 3)
    VT vp = TENT3S(LD4(a + i), LD4(b + i), LD4(c + i));
    i += 3u;
    VT vc = TENT3S(LD4(a + i), LD4(b + i), LD4(c + i));
    for (int j = 0; j < np; j++, dst += 6) {
        i += 3u;
        const VT vn = TENT3S(LD4(a + i), LD4(b + i), LD4(c + i));
        const VT q = ADD(ADD(SHL(vc, 2), kh), ADD(vp, vn));
        const VT e = SHR(ADD(q, SHL(vp, 1)), 3), o = SHR(ADD(q, SHL(vn, 1)), 3);
        VT lo4 = PACK_LO(e, o), hi2 = PACK_HI(o);
        if (add) {
            lo4 = ADD(lo4, LD4(add));
            hi2 = ADD(hi2, LD2(add + 4));
            add += 6;
        }
        ST4(dst, lo4);
        ST2(dst + 4, hi2);
        vp = vc;
        vc = vn;
    }
#undef TENT3S
}

/* Whether samples i0 .. i1-1 (i1 - i0 >= 4) of the three rows are all
 * below 2^29 (the OR of them all, shifted). */
static int tent_small_ok(const uint32_t *const u[3], size_t i0, size_t i1)
{
    VT any = DUP(0u);
    for (int r = 0; r < 3; r++) {
        const uint32_t *p = u[r];
        size_t i = i0;
        for (; i + 4 <= i1; i += 4)
            any = OR(any, LD4(p + i));
        if (i < i1)
            any = OR(any, LD4(p + i1 - 4)); /* the last four again */
    }
    return (OR_LANES(any) >> 29) == 0;
}

static void tent_any(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst, int x0, int n,
                     int sw)
{
    /* Pairs (2m, 2m + 1) inside [x0, x0 + n) with 1 <= m and m + 1 <= sw - 2
     * (column m + 1 is read with one sample past it). */
    const int end = x0 + n;
    const int ma = simd_imax((x0 + 1) >> 1, 1);
    const int mb = end >= 2 ? simd_imin((end - 2) >> 1, sw - 3) : -1;
    const int np = mb >= ma ? mb - ma + 1 : 0;
    if (np < 2) {
        bloom_row_tent_c(u, odd, add, dst, x0, n, sw);
        return;
    }
    const int xa = 2 * ma, xb = 2 * (ma + np);
    if (xa > x0)
        bloom_row_tent_c(u, odd, add, dst, x0, xa - x0, sw);
    /* the pairs read columns ma - 1 .. ma + np and one sample past them */
    if (tent_small_ok(u, (size_t)(ma - 1) * 3u, (size_t)(ma + np) * 3u + 4u))
        tent_pairs_small(u, odd, add ? add + (size_t)(xa - x0) * 3u : NULL, dst + (size_t)(xa - x0) * 3u, ma,
                         np);
    else
        tent_pairs(u, odd, add ? add + (size_t)(xa - x0) * 3u : NULL, dst + (size_t)(xa - x0) * 3u, ma, np);
    if (end > xb)
        bloom_row_tent_c(u, odd, add ? add + (size_t)(xb - x0) * 3u : NULL, dst + (size_t)(xb - x0) * 3u, xb,
                         end - xb, sw);
}

#if !BLOOM_SMALL
/* ---- flat kernels of the fast output path --------------------------------- */

/* dst[i] = (3 a[i] + 4 b[i] + c[i] + 4) >> 3, 32-bit lanes (as the C twin). */
static uint32_t vtent_flat(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    const VT k4 = DUP(BLOOM_VT_RND);
    VT any = DUP(0u);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const VT va = LD4(a + i);
        const VT s = SHR(ADD(ADD(ADD(va, SHL(va, 1)), SHL(LD4(b + i), 2)), ADD(LD4(c + i), k4)), 3);
        ST4(dst + i, s);
        any = OR(any, s);
    }
    uint32_t r = OR_LANES(any);
    if (i < n && n >= 4) { /* the last four again (dst is not an input) */
        i = n - 4;
        const VT va = LD4(a + i);
        const VT s = SHR(ADD(ADD(ADD(va, SHL(va, 1)), SHL(LD4(b + i), 2)), ADD(LD4(c + i), k4)), 3);
        ST4(dst + i, s);
        r |= OR_LANES(s);
    } else if (i < n) {
        r |= bloom_row_vtent_c(a + i, b + i, c + i, dst + i, n - i);
    }
    return r;
}

/* e[i] = (3 v[i-3] + 4 v[i] + v[i+3] + 3) >> 3, o[i] = (v[i-3] + 4 v[i] + 3 v[i+3] + 3) >> 3,
 * samples i .. i + 3: their OR. */
static inline VT htent_eo4(const uint32_t *v, uint32_t *e, uint32_t *o, int i)
{
    const VT p = LD4(v + i - 3), q = LD4(v + i + 3);
    const VT m = ADD(ADD(SHL(LD4(v + i), 2), DUP(BLOOM_HT_RND)), ADD(p, q));
    const VT ev = SHR(ADD(m, SHL(p, 1)), 3), ov = SHR(ADD(m, SHL(q, 1)), 3);
    ST4(e + i, ev);
    ST4(o + i, ov);
    return OR(ev, ov);
}

static uint32_t htent_eo_flat(const uint32_t *v, uint32_t *e, uint32_t *o, int n)
{
    VT any = DUP(0u);
    int i = 0;
    for (; i + 4 <= n; i += 4)
        any = OR(any, htent_eo4(v, e, o, i));
    if (i < n && n >= 4) /* the tail: a block overlapping the last (e, o are not v) */
        any = OR(any, htent_eo4(v, e, o, n - 4));
    else if (i < n)
        return bloom_row_htent_eo_c(v + i, e + i, o + i, n - i);
    return OR_LANES(any);
}
#endif

#if !BLOOM_SMALL && (BLOOM_USE_RGB888 || BLOOM_USE_XRGB8888 || BLOOM_USE_RGB565)
/* ---- level-1 row: box from the source and knee, dark blocks skipped ------ */

/* Blocks of four level-1 pixels x .. x+3 (x >= 1) read source columns
 * 2x-1 .. 2x+8 of the four rows (10 pixels from byte (2x-1) bpp); when no
 * code there exceeds the dark code, every box value is at most
 * dec(c8) <= t - k and the knee makes the four pixels 0. Other blocks run
 * the C box and knee, in runs. The includer defines BRIGHT30(s, off, c8)
 * (RGB888: whether a byte of the 30 at s[r] + off, r = 0..3, exceeds c8;
 * reads 32), BRIGHT40X(s, off, c8) (XRGB8888: the same over 40 bytes,
 * X bytes left out; reads 48) and BRIGHT20_565(s, off, c5, c6) (RGB565:
 * whether a field of the ten pixels exceeds its dark code; reads 32). */
static bool d1_any(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw, int sw,
                   const bloom_knee_t *kn, const bloom_dark_t *dk, bloom_d1_keep_t *kp)
{
    const bool x8 = BLOOM_USE_XRGB8888 && fmt == BLOOM_FMT_XRGB8888;
    const bool h5 = BLOOM_USE_RGB565 && fmt == BLOOM_FMT_RGB565;
    if (!(BLOOM_USE_RGB888 && fmt == BLOOM_FMT_RGB888) && !x8 && !h5)
        return bloom_row_d1_c(s, fmt, linear, dst, dw, sw, kn, dk, kp);
    const size_t bpp = x8 ? 4u : h5 ? 2u : 3u, rd = x8 ? 48u : 32u, row = (size_t)sw * bpp;
    bool any = false;
    int run = 0; /* first pixel not written yet */
    int x = 1;
    for (; x + 4 <= dw && (size_t)(2 * x - 1) * bpp + rd <= row; x += 4) {
        const size_t off = (size_t)(2 * x - 1) * bpp;
        if (h5   ? BRIGHT20_565(s, off, dk->c5, dk->c6)
            : x8 ? BRIGHT40X(s, off, dk->c8)
                 : BRIGHT30(s, off, dk->c8))
            continue; /* computed with its run */
        if (run < x) {
            bloom_row_box_src_kept_c(s, fmt, linear, dst, run, x, sw, kp);
            any = bloom_row_knee_c(dst + (size_t)run * 3u, x - run, kn) || any;
        }
        memset(dst + (size_t)x * 3u, 0, 12u * sizeof *dst);
        run = x + 4;
    }
    if (run < dw) {
        bloom_row_box_src_kept_c(s, fmt, linear, dst, run, dw, sw, kp);
        any = bloom_row_knee_c(dst + (size_t)run * 3u, dw - run, kn) || any;
    }
    return any;
}
#endif
