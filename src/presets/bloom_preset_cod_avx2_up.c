/* AVX2 twins of the cod preset's up-pass and output kernels
 * (bloom_preset_cod.h): the tent blends of the up pass and of the output,
 * the RGB888 decode and encode. Compiled for AVX2 by a target pragma,
 * picked when the engine's kernel set is AVX2 (ctx->kern.isa); same bits as
 * the C kernels (tests/test_simd_cod.c). The level-1 and down-pass twins:
 * bloom_preset_cod_avx2.c. */
#include "bloom_preset_cod.h"
#include "bloom_pixel.h"

#if BLOOM_USE_COD && defined(BLOOM_SIMD_AVX2)

#include "bloom_avx2.h" /* from here on compiled for AVX2 */

/* The tent's two halves in 32-bit lanes when every sample of the four rows
 * is below 2^24 (V < 2^28, T4 < 2^32; else false: the C kernel):
 * V = wa a + wb b + wc c + wd d at scr + 6 (padded 2 columns each side),
 * then E[j] = V[j-6] + 5 V[j-3] + 7 V[j] + 3 V[j+3] (even columns) and
 * O[j] = 3 V[j-3] + 7 V[j] + 5 V[j+3] + V[j+6] (odd) for j < 3 ceil(w / 2). */
static bool tent32(const uint32_t *const u[4], int odd, int w, int sw, uint32_t *scr, uint32_t **e,
                   uint32_t **o)
{
    uint32_t *v = scr + 6, *ev = v + 3 * sw + 6, *ov = ev + 3 * sw;
    const uint32_t wa = odd ? 3u : 1u, wb = odd ? 7u : 5u, wc = odd ? 5u : 7u, wd = odd ? 1u : 3u;
    const __m256i ka = _mm256_set1_epi32((int)wa), kb = _mm256_set1_epi32((int)wb),
                  kc = _mm256_set1_epi32((int)wc), kd = _mm256_set1_epi32((int)wd);
    const int n = 3 * sw;
    __m256i bor = _mm256_setzero_si256();
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256i a = LD8(u[0] + i), b = LD8(u[1] + i), c = LD8(u[2] + i), d = LD8(u[3] + i);
        bor = _mm256_or_si256(bor, _mm256_or_si256(_mm256_or_si256(a, b), _mm256_or_si256(c, d)));
        ST8(v + i, _mm256_add_epi32(_mm256_add_epi32(_mm256_mullo_epi32(ka, a), _mm256_mullo_epi32(kb, b)),
                                    _mm256_add_epi32(_mm256_mullo_epi32(kc, c), _mm256_mullo_epi32(kd, d))));
    }
    uint32_t sor = or_lanes8(bor);
    for (; i < n; i++) {
        sor |= u[0][i] | u[1][i] | u[2][i] | u[3][i];
        v[i] = wa * u[0][i] + wb * u[1][i] + wc * u[2][i] + wd * u[3][i];
    }
    if (sor >> 24)
        return false;
    for (int ch = 0; ch < 3; ch++) {
        v[ch - 6] = v[ch - 3] = v[ch];
        v[n + ch] = v[n + 3 + ch] = v[n - 3 + ch];
    }
    const int m = 3 * ((w + 1) >> 1);
    const __m256i k3 = _mm256_set1_epi32(3), k5 = _mm256_set1_epi32(5), k7 = _mm256_set1_epi32(7);
    int j = 0;
    for (; j + 8 <= m; j += 8) {
        const __m256i vm2 = LD8(v + j - 6), vm1 = LD8(v + j - 3), v0 = LD8(v + j), v1 = LD8(v + j + 3),
                      v2 = LD8(v + j + 6);
        ST8(ev + j,
            _mm256_add_epi32(_mm256_add_epi32(vm2, _mm256_mullo_epi32(k5, vm1)),
                             _mm256_add_epi32(_mm256_mullo_epi32(k7, v0), _mm256_mullo_epi32(k3, v1))));
        ST8(ov + j,
            _mm256_add_epi32(_mm256_add_epi32(_mm256_mullo_epi32(k3, vm1), _mm256_mullo_epi32(k7, v0)),
                             _mm256_add_epi32(_mm256_mullo_epi32(k5, v1), v2)));
    }
    for (; j < m; j++) {
        ev[j] = v[j - 6] + 5u * v[j - 3] + 7u * v[j] + 3u * v[j + 3];
        ov[j] = 3u * v[j - 3] + 7u * v[j] + 5u * v[j + 3] + v[j + 6];
    }
    *e = ev;
    *o = ov;
    return true;
}

/* (a d + c t + 2^23) >> 24 in 64-bit lanes (even and odd 32-bit lanes
 * apart): the even and odd results, each in the low half of its lane. */
static inline void mac24(__m256i d, __m256i t, __m256i a, __m256i c, __m256i *qe, __m256i *qo)
{
    const __m256i rnd = _mm256_set1_epi64x(1ll << 23);
    *qe = _mm256_srli_epi64(
        _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epu32(d, a), _mm256_mul_epu32(t, c)), rnd), 24);
    *qo = _mm256_srli_epi64(_mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(d, 32), a),
                                                              _mm256_mul_epu32(_mm256_srli_epi64(t, 32),
                                                                               _mm256_srli_epi64(c, 32))),
                                             rnd),
                            24);
}

void cod_blend_avx2(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                    uint32_t a, uint32_t c, uint32_t *scr)
{
    uint32_t *ev, *ov;
    if (w < 8 || !tent32(u, odd, w, sw, scr, &ev, &ov)) {
        cod_blend_c(u, odd, d, o, w, sw, a, c, scr);
        return;
    }
    const __m256i av = _mm256_set1_epi32((int)a), cv = _mm256_set1_epi32((int)c);
    int x = 0;
    for (; x + 8 <= w; x += 8) {
        __m256i t[3];
        il24(ev + 3 * (x >> 1), ov + 3 * (x >> 1), t);
        for (int k = 0; k < 3; k++) {
            __m256i qe, qo;
            mac24(LD8(d + 3 * x + 8 * k), t[k], av, cv, &qe, &qo);
            ST8(o + 3 * x + 8 * k, _mm256_blend_epi32(qe, _mm256_slli_epi64(qo, 32), 0xAA));
        }
    }
    for (; x < w; x++) {
        const uint32_t *t = ((x & 1) ? ov : ev) + 3 * (x >> 1);
        for (int ch = 0; ch < 3; ch++)
            o[3 * x + ch] =
                (uint32_t)(((uint64_t)a * d[3 * x + ch] + (uint64_t)c * t[ch] + (1u << 23)) >> 24);
    }
}

/* min(q, 2^32 - 1) of a 64-bit lane, in its low half */
static inline __m256i sat32(__m256i q)
{
    const __m256i big = _mm256_cmpeq_epi64(_mm256_srli_epi64(q, 32), _mm256_setzero_si256());
    return _mm256_or_si256(q, _mm256_andnot_si256(big, _mm256_set1_epi32(-1)));
}

void cod_mix_avx2(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                  uint32_t a, const uint32_t f[3], uint32_t *scr)
{
    uint32_t *ev, *ov;
    if (w < 8 || !tent32(u, odd, w, sw, scr, &ev, &ov)) {
        cod_mix_c(u, odd, d, o, w, sw, a, f, scr);
        return;
    }
    const int f0 = (int)f[0], f1 = (int)f[1], f2 = (int)f[2];
    const __m256i av = _mm256_set1_epi32((int)a);
    const __m256i fv[3] = {SET8(f0, f1, f2, f0, f1, f2, f0, f1), SET8(f2, f0, f1, f2, f0, f1, f2, f0),
                           SET8(f1, f2, f0, f1, f2, f0, f1, f2)};
    int x = 0;
    for (; x + 8 <= w; x += 8) {
        __m256i t[3];
        il24(ev + 3 * (x >> 1), ov + 3 * (x >> 1), t);
        const __m256i d0 = LD8(d + 3 * x), d1 = LD8(d + 3 * x + 8), d2 = LD8(d + 3 * x + 16);
        /* every d below 2^31: q < d + 2^24 + 1 < 2^32, no clamp */
        const bool small = _mm256_testz_si256(_mm256_or_si256(_mm256_or_si256(d0, d1), d2),
                                              _mm256_set1_epi32((int)0x80000000u));
        const __m256i dv[3] = {d0, d1, d2};
        for (int k = 0; k < 3; k++) {
            __m256i qe, qo;
            mac24(dv[k], t[k], av, fv[k], &qe, &qo);
            if (!small) {
                qe = sat32(qe);
                qo = sat32(qo);
            }
            ST8(o + 3 * x + 8 * k, _mm256_blend_epi32(qe, _mm256_slli_epi64(qo, 32), 0xAA));
        }
    }
    for (; x < w; x++) {
        const uint32_t *t = ((x & 1) ? ov : ev) + 3 * (x >> 1);
        for (int ch = 0; ch < 3; ch++) {
            const uint64_t q = ((uint64_t)a * d[3 * x + ch] + (uint64_t)f[ch] * t[ch] + (1u << 23)) >> 24;
            o[3 * x + ch] = q > UINT32_MAX ? UINT32_MAX : (uint32_t)q;
        }
    }
}

/* RGB888 sRGB decode by table loads (dec8x8), encode by the wide bucket
 * table of bloom_pixel.h (bloom_fenc8w, scalar loads after a clamp to
 * t[255] in lanes); other formats and curves go to the C rows. */
void cod_dec_avx2(bloom_format_t fmt, bool linear, const uint8_t *src, uint32_t *dst, int n)
{
#if BLOOM_USE_RGB888
    if (fmt == BLOOM_FMT_RGB888 && !linear) {
        const int m = 3 * n;
        int i = 0;
        for (; i + 8 <= m; i += 8)
            ST8(dst + i, dec8x8(src + i));
        for (; i < m; i++)
            dst[i] = bloom_srgb_dec8[src[i]];
        return;
    }
#endif
    bloom_decode_row(fmt, linear, src, dst, n);
}

void cod_enc_avx2(bloom_format_t fmt, bool linear, const uint32_t *v, uint8_t *dst, int n)
{
#if BLOOM_USE_RGB888 && BLOOM_LIN_BITS == 20
    if (fmt == BLOOM_FMT_RGB888 && !linear) {
        const __m256i top = _mm256_set1_epi32((int)bloom_srgb_enc8[255]);
        const int m = 3 * n;
        int i = 0;
        uint32_t x[8];
        for (; i + 8 <= m; i += 8) {
            ST8(x, _mm256_min_epu32(LD8(v + i), top));
            for (int k = 0; k < 8; k++)
                dst[i + k] = (uint8_t)bloom_fenc8w(x[k]);
        }
        for (; i < m; i++)
            dst[i] = (uint8_t)BLOOM_FENC8(v[i]);
        return;
    }
#endif
    bloom_encode_row(fmt, linear, v, dst, n);
}

#include "bloom_avx2_end.h"

#else
typedef int bloom_preset_cod_avx2_up_unused_t;
#endif
