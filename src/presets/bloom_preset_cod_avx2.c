/* AVX2 twins of the cod preset's level-1 and down-pass kernels
 * (bloom_preset_cod.h; the up pass and output: _avx2_up.c), compiled
 * for AVX2 by a target pragma (the rest of the core stays baseline
 * x86-64), picked when the engine's kernel set is AVX2 (ctx->kern.isa). Same
 * bits as the C kernels (tests/test_simd_cod.c); the bounds each twin
 * relies on are tested on every chunk, which goes to the C kernel when
 * they fail (sim/docs/presets/cod.md, "SIMD twins"). */
#include "bloom_preset_cod.h"
#include "bloom_pixel.h"

#if BLOOM_USE_COD && defined(BLOOM_SIMD_AVX2)
#include <string.h>

#include "bloom_avx2.h" /* from here on compiled for AVX2 */

#if BLOOM_USE_RGB888
void cod_vsum6_avx2(const uint8_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n)
{
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i v1 = dec8x8(s[1] + i), v4 = dec8x8(s[4] + i);
        const __m256i mid = _mm256_add_epi32(dec8x8(s[2] + i), dec8x8(s[3] + i));
        const __m256i m14 = _mm256_add_epi32(mid, _mm256_add_epi32(v1, v4));
        ST8(c + i, m14);
        ST8(t + i, _mm256_add_epi32(_mm256_add_epi32(dec8x8(s[0] + i), v1), mid));
        ST8(b + i, _mm256_add_epi32(_mm256_add_epi32(dec8x8(s[5] + i), v4), mid));
    }
    if (i < n) {
        const uint8_t *const r[6] = {s[0] + i, s[1] + i, s[2] + i, s[3] + i, s[4] + i, s[5] + i};
        cod_vsum6_c(r, t + i, c + i, b + i, n - i);
    }
}
#else
void cod_vsum6_avx2(const uint8_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n)
{
    cod_vsum6_c(s, t, c, b, n);
}
#endif

void cod_vsum6w_avx2(const uint32_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n)
{
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i v1 = LD8(s[1] + i), v4 = LD8(s[4] + i),
                      mid = _mm256_add_epi32(LD8(s[2] + i), LD8(s[3] + i));
        ST8(c + i, _mm256_add_epi32(mid, _mm256_add_epi32(v1, v4)));
        ST8(t + i, _mm256_add_epi32(_mm256_add_epi32(LD8(s[0] + i), v1), mid));
        ST8(b + i, _mm256_add_epi32(_mm256_add_epi32(LD8(s[5] + i), v4), mid));
    }
    if (i < n) {
        const uint32_t *const r[6] = {s[0] + i, s[1] + i, s[2] + i, s[3] + i, s[4] + i, s[5] + i};
        cod_vsum6w_c(r, t + i, c + i, b + i, n - i);
    }
}

/* In place, p[j] = p[j] + p[j + 3] + p[j + 6] + p[j + 9] for j < m (reads
 * p[0 .. m + 8]): the 4-column sums of a padded row. */
static void quad3(uint32_t *p, int m)
{
    int j = 0;
    for (; j + 8 <= m; j += 8)
        ST8(p + j, _mm256_add_epi32(_mm256_add_epi32(LD8(p + j), LD8(p + j + 3)),
                                    _mm256_add_epi32(LD8(p + j + 6), LD8(p + j + 9))));
    for (; j < m; j++)
        p[j] = p[j] + p[j + 3] + p[j + 6] + p[j + 9];
}

/* The first three words of each of 8 pixels 6 words apart (p[6l + ch],
 * l = 0 .. 7, ch = 0 .. 2) as three vectors: 128-bit loads (reading
 * p[0 .. 45]) and a 4x4 transpose in each half. Contiguous loads and
 * shuffles: cheaper than gathers on the CPU measured here. */
static inline void rgb6(const uint32_t *p, __m256i v[3])
{
#define LD4X2(a, b)                                                                                          \
    _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_loadu_si128((const __m128i *)(const void *)(a))),     \
                            _mm_loadu_si128((const __m128i *)(const void *)(b)), 1)
    const __m256i a0 = LD4X2(p, p + 24), a1 = LD4X2(p + 6, p + 30), a2 = LD4X2(p + 12, p + 36),
                  a3 = LD4X2(p + 18, p + 42);
#undef LD4X2
    const __m256i t0 = _mm256_unpacklo_epi32(a0, a1), t1 = _mm256_unpacklo_epi32(a2, a3);
    const __m256i t2 = _mm256_unpackhi_epi32(a0, a1), t3 = _mm256_unpackhi_epi32(a2, a3);
    v[0] = _mm256_unpacklo_epi64(t0, t1);
    v[1] = _mm256_unpackhi_epi64(t0, t1);
    v[2] = _mm256_unpacklo_epi64(t2, t3);
}

/* R, G, B vectors of 8 pixels into 24 samples in pixel order. */
static inline void il3(__m256i r, __m256i g, __m256i b, uint32_t *o)
{
    ST8(o, _mm256_blend_epi32(
               _mm256_blend_epi32(PERM(r, 0, 0, 0, 1, 0, 0, 2, 0), PERM(g, 0, 0, 0, 0, 1, 0, 0, 2), 0x92),
               PERM(b, 0, 0, 0, 0, 0, 1, 0, 0), 0x24));
    ST8(o + 8, _mm256_blend_epi32(
                   _mm256_blend_epi32(PERM(r, 0, 3, 0, 0, 4, 0, 0, 5), PERM(g, 0, 0, 3, 0, 0, 4, 0, 0), 0x24),
                   PERM(b, 2, 0, 0, 3, 0, 0, 4, 0), 0x49));
    ST8(o + 16, _mm256_blend_epi32(_mm256_blend_epi32(PERM(r, 0, 0, 6, 0, 0, 7, 0, 0),
                                                      PERM(g, 5, 0, 0, 6, 0, 0, 7, 0), 0x49),
                                   PERM(b, 0, 5, 0, 0, 6, 0, 0, 7), 0x92));
}

/* floor(2^48 / (j 2^11)) for j = 256 .. 1536 (the grid points of the
 * divisors 2^19 .. 3 2^20), compile-time constants; stored as the pair
 * (T_j, T_j - T_(j+1)) in one word for j < 1536, so that one 64-bit load
 * per lane fetches both ends of the chord (loads, not gathers: on the CPU
 * measured here a gather was slower than its eight loads). */
#define RCP(j) (uint32_t)((1ull << 48) / (((uint64_t)(j) + 256u) << 11))
#define RCP2(j) ((uint64_t)RCP(j) | (uint64_t)(RCP(j) - RCP((j) + 1)) << 32)
#define RCP4(j) RCP2(j), RCP2((j) + 1), RCP2((j) + 2), RCP2((j) + 3)
#define RCP16(j) RCP4(j), RCP4((j) + 4), RCP4((j) + 8), RCP4((j) + 12)
#define RCP64(j) RCP16(j), RCP16((j) + 16), RCP16((j) + 32), RCP16((j) + 48)
#define RCP256(j) RCP64(j), RCP64((j) + 64), RCP64((j) + 128), RCP64((j) + 192)
static const uint64_t rcp_tab[1280] = {RCP256(0), RCP256(256), RCP256(512), RCP256(768), RCP256(1024)};

/* T_j and T_j - T_(j+1) for the 8 lanes of j (each < 1280). */
static inline void rcp_pairs(__m256i j, __m256i *t0, __m256i *dt)
{
    uint32_t ix[8];
    ST8(ix, j);
    __m128i q[4];
    for (int k = 0; k < 4; k++)
        q[k] = _mm_insert_epi64(_mm_loadl_epi64((const __m128i *)(const void *)(rcp_tab + ix[2 * k])),
                                (long long)rcp_tab[ix[2 * k + 1]], 1);
    /* lanes 0-3 and 4-7, each T then T - T' per 64 bits: the T into the low
     * 128 bits, the differences into the high */
    const __m256i sep = SET8(0, 2, 4, 6, 1, 3, 5, 7);
    const __m256i a = _mm256_permutevar8x32_epi32(
                      _mm256_inserti128_si256(_mm256_castsi128_si256(q[0]), q[1], 1), sep),
                  b = _mm256_permutevar8x32_epi32(
                      _mm256_inserti128_si256(_mm256_castsi128_si256(q[2]), q[3], 1), sep);
    *t0 = _mm256_permute2x128_si256(a, b, 0x20);
    *dt = _mm256_permute2x128_si256(a, b, 0x31);
}

/* Two 64-bit-lane halves (even, odd 32-bit lanes) back into 8 lanes: the
 * low 32 bits of each. */
static inline __m256i join(__m256i e, __m256i o)
{
    return _mm256_blend_epi32(e, _mm256_slli_epi64(o, 32), 0xAA);
}

/* floor(2^48 / d), exact for 699051 <= d < 3 2^20 (cod.md "SIMD twins", tested
 * for every such d). r0: the chord between the grid points around d
 * (1 / x is convex: the chord is above it, by at most 2^68 / d^3 <= 864,
 * and the integer chord within 2 of the exact one) less 900, so
 * 0 <= q - r0 <= 903; then e1 = 2^48 - d r0 < 904 d < 2^32 is exact as the
 * low 32 bits of -d r0, a Newton step r1 = r0 + (e1 r0 >> 48) keeps
 * r1 <= q (the step is at most e1 / d) and leaves a gap of at most
 * 1 + 904 e1 / 2^48 < 2, and one last +1 where e2 = 2^48 - d r1 >= d. */
static inline __m256i recip48(__m256i d)
{
    const __m256i j = _mm256_sub_epi32(_mm256_srli_epi32(d, 11), _mm256_set1_epi32(256));
    __m256i t0, dt;
    rcp_pairs(j, &t0, &dt);
    const __m256i fr = _mm256_and_si256(d, _mm256_set1_epi32(2047));
    const __m256i r0 = _mm256_sub_epi32(
        _mm256_sub_epi32(t0, _mm256_srli_epi32(_mm256_mullo_epi32(dt, fr), 11)), _mm256_set1_epi32(900));
    const __m256i e1 = _mm256_sub_epi32(_mm256_setzero_si256(), _mm256_mullo_epi32(d, r0));
    const __m256i r1 = _mm256_add_epi32(
        r0,
        join(_mm256_srli_epi64(_mm256_mul_epu32(e1, r0), 48),
             _mm256_srli_epi64(_mm256_mul_epu32(_mm256_srli_epi64(e1, 32), _mm256_srli_epi64(r0, 32)), 48)));
    const __m256i e2 = _mm256_sub_epi32(_mm256_setzero_si256(), _mm256_mullo_epi32(d, r1));
    return _mm256_sub_epi32(r1, _mm256_cmpeq_epi32(_mm256_max_epu32(e2, d), e2));
}

/* floor(n / W) in the 4 lanes of one half, W (low 32 bits of each lane)
 * in 715827880 .. 2^31, n < 2^52 + 2^30, r = R'' <= 2^58 / W within 1.003:
 * q0 = floor(n r / 2^58) (n split at bit 26, exact) is q or q - 1, and
 * the remainder n - q0 W decides (wm1 = W - 1 in 64-bit lanes). */
/* W - 1 of the low 32 bits of each 64-bit lane */
static inline __m256i wm1e(__m256i w)
{
    return _mm256_sub_epi64(_mm256_and_si256(w, _mm256_set1_epi64x(0xFFFFFFFFll)), _mm256_set1_epi64x(1));
}

static inline __m256i qdiv(__m256i n, __m256i w, __m256i wm1, __m256i r)
{
    const __m256i nh = _mm256_srli_epi64(n, 26),
                  nl = _mm256_and_si256(n, _mm256_set1_epi64x((1ll << 26) - 1));
    const __m256i q0 = _mm256_srli_epi64(
        _mm256_add_epi64(_mm256_mul_epu32(nh, r), _mm256_srli_epi64(_mm256_mul_epu32(nl, r), 26)), 32);
    const __m256i rem = _mm256_sub_epi64(n, _mm256_mul_epu32(q0, w));
    return _mm256_sub_epi64(q0, _mm256_cmpgt_epi64(rem, wm1));
}

/* R'' for W in 8 lanes: a Newton step from R' = recip48((W >> 10) + 1),
 * R' <= 2^58 / W within 591; R'' = R' + ((e >> 9) R') >> 49 with
 * e = 2^58 - W R' >= 0 (< 2^40.3) is at most 2^58 / W, within 1.003. */
static inline __m256i recip58(__m256i w)
{
    const __m256i r1 = recip48(_mm256_add_epi32(_mm256_srli_epi32(w, 10), _mm256_set1_epi32(1)));
    const __m256i two58 = _mm256_set1_epi64x(1ll << 58);
    const __m256i w_o = _mm256_srli_epi64(w, 32), r1_o = _mm256_srli_epi64(r1, 32);
    const __m256i ee = _mm256_srli_epi64(_mm256_sub_epi64(two58, _mm256_mul_epu32(w, r1)), 9);
    const __m256i eo = _mm256_srli_epi64(_mm256_sub_epi64(two58, _mm256_mul_epu32(w_o, r1_o)), 9);
    return _mm256_add_epi32(r1, join(_mm256_srli_epi64(_mm256_mul_epu32(ee, r1), 49),
                                     _mm256_srli_epi64(_mm256_mul_epu32(eo, r1_o), 49)));
}

/* Test hooks (tests/test_simd_cod.c): recip48 on n divisors, and the
 * quotients floor(num[i] / w[i]) through recip58 and qdiv; n a multiple of 8. */
void cod_recip48_avx2(const uint32_t *d, uint32_t *q, int n)
{
    for (int i = 0; i + 8 <= n; i += 8)
        ST8(q + i, recip48(LD8(d + i)));
}
void cod_qdiv_avx2(const uint32_t *w, const uint64_t *num, uint32_t *q, int n)
{
    for (int i = 0; i + 8 <= n; i += 8) {
        const __m256i wv = LD8(w + i), r = recip58(wv);
        uint64_t e4[4], o4[4]; /* the even lanes' and the odd lanes' numerators */
        for (int k = 0; k < 4; k++) {
            e4[k] = num[i + 2 * k];
            o4[k] = num[i + 2 * k + 1];
        }
        ST8(q + i, join(qdiv(LD8(e4), wv, wm1e(wv), r),
                        qdiv(LD8(o4), _mm256_srli_epi64(wv, 32), wm1e(_mm256_srli_epi64(wv, 32)),
                             _mm256_srli_epi64(r, 32))));
    }
}

/* The Karis average of 8 pixels in lanes: the box sums are the 4-column
 * sums (TL, TR at top columns 2x, 2x + 2; BL, BR at the bottom; C at the
 * centre's 2x + 1), de-interleaved by rgb6, all below 2^25 (else false: the C kernel). The
 * luma in 32-bit lanes: with R = 2^12 R_h + R_l, Y = 2^12 A + B_l (A = sum
 * of K R_h < 2^29, B_l = sum of K R_l < 2^28) and floor(Y / 2^20) =
 * (A + (B_l >> 12)) >> 8; so d < 3 2^20. Every lane through the divisions
 * (equal d give the equal-weight result anyway), unless all 8 lanes have
 * equal weights: then (sum g_i Box_i + 64) >> 7. The numerators
 * 8 W + sum g_i w_i Box_i (< 2^56 + 2^34) in 64-bit lanes; the weights by
 * recip48, the quotients by qdiv with R'' = a Newton step from
 * recip48((W >> 10) + 1). */
static bool karis8(const uint32_t *pt, const uint32_t *pc, const uint32_t *pb, uint32_t *o, uint32_t *any)
{
    const __m256i kr = _mm256_set1_epi32(13933), kg = _mm256_set1_epi32(46871), kb = _mm256_set1_epi32(4732);
    const __m256i lo12 = _mm256_set1_epi32(4095), one = _mm256_set1_epi32((int)BLOOM_LIN_ONE);
    __m256i box[5][3], d[5], same = _mm256_set1_epi32(-1), bor = _mm256_setzero_si256();
    rgb6(pt, box[0]);
    rgb6(pt + 6, box[1]);
    rgb6(pb, box[2]);
    rgb6(pb + 6, box[3]);
    rgb6(pc + 3, box[4]);
    BLOOM_UNROLL
    for (int i = 0; i < 5; i++) {
        const __m256i x0 = box[i][0], x1 = box[i][1], x2 = box[i][2];
        bor = _mm256_or_si256(bor, _mm256_or_si256(_mm256_or_si256(x0, x1), x2));
        const __m256i ah =
            _mm256_add_epi32(_mm256_add_epi32(_mm256_mullo_epi32(kr, _mm256_srli_epi32(x0, 12)),
                                              _mm256_mullo_epi32(kg, _mm256_srli_epi32(x1, 12))),
                             _mm256_mullo_epi32(kb, _mm256_srli_epi32(x2, 12)));
        const __m256i bl =
            _mm256_add_epi32(_mm256_add_epi32(_mm256_mullo_epi32(kr, _mm256_and_si256(x0, lo12)),
                                              _mm256_mullo_epi32(kg, _mm256_and_si256(x1, lo12))),
                             _mm256_mullo_epi32(kb, _mm256_and_si256(x2, lo12)));
        d[i] = _mm256_add_epi32(one, _mm256_srli_epi32(_mm256_add_epi32(ah, _mm256_srli_epi32(bl, 12)), 8));
        if (i)
            same = _mm256_and_si256(same, _mm256_cmpeq_epi32(d[i], d[0]));
    }
    if (or_lanes8(bor) >> 25)
        return false;
    __m256i res[3];
    if (_mm256_movemask_epi8(same) == -1) { /* equal weights: (sum g_i Box_i + 64) >> 7 */
        BLOOM_UNROLL
        for (int ch = 0; ch < 3; ch++) {
            const __m256i s4 = _mm256_add_epi32(_mm256_add_epi32(box[0][ch], box[1][ch]),
                                                _mm256_add_epi32(box[2][ch], box[3][ch]));
            res[ch] =
                _mm256_srli_epi32(_mm256_add_epi32(_mm256_add_epi32(s4, _mm256_slli_epi32(box[4][ch], 2)),
                                                   _mm256_set1_epi32(64)),
                                  7);
        }
    } else {
        __m256i g[5], wsum = _mm256_setzero_si256();
        BLOOM_UNROLL
        for (int i = 0; i < 5; i++) {
            g[i] = recip48(d[i]);
            if (i == 4)
                g[i] = _mm256_slli_epi32(g[i], 2);
            wsum = _mm256_add_epi32(wsum, g[i]);
        }
        const __m256i rr = recip58(wsum), w_o = _mm256_srli_epi64(wsum, 32);
        const __m256i we = _mm256_slli_epi64(_mm256_and_si256(wsum, _mm256_set1_epi64x(0xFFFFFFFFll)), 3);
        const __m256i wo = _mm256_slli_epi64(w_o, 3), rr_o = _mm256_srli_epi64(rr, 32);
        const __m256i wm_e = wm1e(wsum), wm_o = wm1e(w_o);
        BLOOM_UNROLL
        for (int ch = 0; ch < 3; ch++) {
            __m256i ne = we, no = wo;
            BLOOM_UNROLL
            for (int i = 0; i < 5; i++) {
                const __m256i x = box[i][ch];
                ne = _mm256_add_epi64(ne, _mm256_mul_epu32(g[i], x));
                no = _mm256_add_epi64(
                    no, _mm256_mul_epu32(_mm256_srli_epi64(g[i], 32), _mm256_srli_epi64(x, 32)));
            }
            res[ch] = join(qdiv(_mm256_srli_epi64(ne, 4), wsum, wm_e, rr),
                           qdiv(_mm256_srli_epi64(no, 4), w_o, wm_o, rr_o));
        }
    }
    *any |= or_lanes8(_mm256_or_si256(_mm256_or_si256(res[0], res[1]), res[2]));
    il3(res[0], res[1], res[2], o);
    return true;
}

uint32_t cod_karis_avx2(uint32_t *vt, uint32_t *vc, uint32_t *vb, uint32_t *o, int w)
{
    /* 4-column sums at words 0 .. 6 w + 2 (reads to 6 w + 11 < 3 (2 w + 4)) */
    const int m = 6 * w + 3;
    uint32_t any = 0;
    if (w < 8 || BLOOM_LIN_BITS != 20) /* the divisions' domains are for F = 20 */
        return cod_karis_c(vt, vc, vb, o, w);
    quad3(vt, m);
    quad3(vc, m);
    quad3(vb, m);
    int x = 0;
    for (; x + 8 <= w; x += 8)
        if (!karis8(vt + 6 * x, vc + 6 * x, vb + 6 * x, o + 3 * x, &any))
            break;
    /* the rest (a box of 2^25 or more: HDR input; the last w % 8 pixels) by
     * the C kernel on the 4-column sums, placed so that its sums of four
     * words pick one: TL = q[0] at word 0, TR = q[6] at 12, C = q[3] at 3
     * (zeros elsewhere) */
    for (; x < w; x++) {
        uint32_t t1[18], c1[18], b1[18];
        memset(t1, 0, sizeof t1);
        memset(c1, 0, sizeof c1);
        memset(b1, 0, sizeof b1);
        for (int ch = 0; ch < 3; ch++) {
            t1[ch] = vt[6 * x + ch];
            t1[12 + ch] = vt[6 * x + 6 + ch];
            b1[ch] = vb[6 * x + ch];
            b1[12 + ch] = vb[6 * x + 6 + ch];
            c1[3 + ch] = vc[6 * x + 3 + ch];
        }
        any |= cod_karis_c(t1, c1, b1, o + 3 * x, 1);
    }
    return any;
}

/* Output sample i = 3 x + ch of a row decimated by 2 comes from word
 * 6 x + ch = 2 i - ch of the full-width flat row: for i = 24 k + 8 v + l
 * the word is 48 k + DEC2[v][l]. */
static const int dec2[3][8] = {
    {0, 1, 2, 6, 7, 8, 12, 13}, {14, 18, 19, 20, 24, 25, 26, 30}, {31, 32, 36, 37, 38, 42, 43, 44}};

/* The vertical sums in 32-bit lanes (exact: samples <= 2^28, vo < 2^31),
 * then per pixel h = (sO + 4 sI + 64) >> 7 on every word j = 6x + ch of
 * the flat row, in place in vo, when every vo is below 2^26 (so sO < 2^29,
 * 4 sI < 2^30: no wrap), picked by gathers; else the C kernel. */
uint32_t cod_down13_avx2(const uint32_t *const r[6], uint32_t *vo, uint32_t *vi, uint32_t *o, int w, int sw)
{
    const int nw = 3 * sw;
    if (w < 8)
        return cod_down13_c(r, vo, vi, o, w, sw);
    __m256i vor = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= nw; i += 8) {
        const __m256i a1 = LD8(r[1] + i), a4 = LD8(r[4] + i),
                      mid = _mm256_add_epi32(LD8(r[2] + i), LD8(r[3] + i));
        const __m256i vin = _mm256_add_epi32(_mm256_add_epi32(a1, a4), mid);
        const __m256i von =
            _mm256_add_epi32(_mm256_add_epi32(vin, mid), _mm256_add_epi32(LD8(r[0] + i), LD8(r[5] + i)));
        ST8(vi + COD_PAD + i, vin);
        ST8(vo + COD_PAD + i, von);
        vor = _mm256_or_si256(vor, von);
    }
    uint32_t bor = or_lanes8(vor);
    for (; i < nw; i++) {
        const uint32_t mid = r[2][i] + r[3][i];
        vi[COD_PAD + i] = r[1][i] + mid + r[4][i];
        vo[COD_PAD + i] = r[0][i] + r[1][i] + 2u * mid + r[4][i] + r[5][i];
        bor |= vo[COD_PAD + i];
    }
    if (bor >> 26)
        return cod_down13_c(r, vo, vi, o, w, sw);
    cod_pad_edges(vo, sw);
    cod_pad_edges(vi, sw);
    /* h at words j < 6 w - 3 (reads vo to j + 15 <= 6 w + 11 < 3 (sw + 5)) */
    const int m = 6 * w - 3;
    const __m256i r64 = _mm256_set1_epi32(64);
    int j = 0;
    for (; j + 8 <= m; j += 8) {
        const __m256i so =
            _mm256_add_epi32(_mm256_add_epi32(_mm256_add_epi32(LD8(vo + j), LD8(vo + j + 3)),
                                              _mm256_add_epi32(LD8(vo + j + 12), LD8(vo + j + 15))),
                             _mm256_slli_epi32(_mm256_add_epi32(LD8(vo + j + 6), LD8(vo + j + 9)), 1));
        const __m256i si = _mm256_add_epi32(_mm256_add_epi32(LD8(vi + j + 3), LD8(vi + j + 6)),
                                            _mm256_add_epi32(LD8(vi + j + 9), LD8(vi + j + 12)));
        ST8(vo + j,
            _mm256_srli_epi32(_mm256_add_epi32(_mm256_add_epi32(so, _mm256_slli_epi32(si, 2)), r64), 7));
    }
    for (; j < m; j++) {
        const uint32_t so = vo[j] + vo[j + 3] + 2u * (vo[j + 6] + vo[j + 9]) + vo[j + 12] + vo[j + 15];
        const uint32_t si = vi[j + 3] + vi[j + 6] + vi[j + 9] + vi[j + 12];
        vo[j] = (so + 4u * si + 64u) >> 7;
    }
    const int n = 3 * w;
    const __m256i ix[3] = {LD8(dec2[0]), LD8(dec2[1]), LD8(dec2[2])};
    __m256i any = _mm256_setzero_si256();
    int k = 0;
    for (; k + 24 <= n; k += 24)
        for (int v = 0; v < 3; v++) {
            const __m256i h = GATHER(vo + 2 * k, ix[v]);
            ST8(o + k + 8 * v, h);
            any = _mm256_or_si256(any, h);
        }
    uint32_t an = or_lanes8(any);
    for (; k < n; k++)
        an |= o[k] = vo[2 * k - k % 3];
    return an;
}

#include "bloom_avx2_end.h"

#else
typedef int bloom_preset_cod_avx2_unused_t;
#endif
