/* xna_kawase_c on W lanes, written once for the SSE2, AVX2 and NEON twins
 * (bloom_preset_xna_{sse2,avx2,neon}.c define these and include this file;
 * nothing else does):
 *   VT            a vector of W uint32_t lanes, wrapping like uint32_t
 *   W             its lanes
 *   LDV(p), STV(p, v), ADDV(a, b), RNDV(s)  load, store (unaligned), add,
 *                 BLOOM_BOX_RND on every lane
 *   XNA_KAWASE    the function's name
 * Same bits as the C kernel: the column sums and the four-column sums are
 * the C code's sums in the same order (below 2^32: xna.md), RNDV is its
 * rounding; the edge columns and the tails go to the C helpers. */
void XNA_KAWASE(const uint32_t *const r[4], uint32_t *cs, uint32_t *dst, int w, int i, bool rnd)
{
    const int cnt = 3 * w;
    const uint32_t *r0 = r[0], *r1 = r[1], *r2 = r[2], *r3 = r[3];
    int j = 0;
    for (; j + W <= cnt; j += W)
        STV(cs + j, ADDV(ADDV(LDV(r0 + j), LDV(r1 + j)), ADDV(LDV(r2 + j), LDV(r3 + j))));
    for (; j < cnt; j++)
        cs[j] = r0[j] + r1[j] + r2[j] + r3[j];
    int xa, xb;
    xna_kawase_edges(cs, dst, w, i, &xa, &xb);
    if (rnd)
        xna_round_edges(dst, w, xa, xb);
    const int o1 = 3 * i + 3, o2 = 3 * i, end = 3 * xb;
    for (j = 3 * xa; j + W <= end; j += W) {
        const VT s = ADDV(ADDV(LDV(cs + j - o1), LDV(cs + j - o2)), ADDV(LDV(cs + j + o2), LDV(cs + j + o1)));
        STV(dst + j, rnd ? RNDV(s) : s);
    }
    for (; j < end; j++) {
        const uint32_t s = cs[j - o1] + cs[j - o2] + cs[j + o2] + cs[j + o1];
        dst[j] = rnd ? BLOOM_BOX_RND(s) : s;
    }
}
