/* The cod preset's row kernels in C (bloom_preset_cod.h): the reference
 * its AVX2 twins are tested against (tests/test_simd_cod.c), and the pick
 * of the twins by instruction set. The maths: bloom_preset_cod.c and
 * sim/docs/presets/cod.md. */
#include "bloom_preset_cod.h"
#include "bloom_pixel.h"

#if BLOOM_USE_COD

/* Rec.709 luma coefficients in Q16 (sum 65536). */
#define COD_KR 13933u
#define COD_KG 46871u
#define COD_KB 4732u

void cod_vsum6_c(const uint8_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n)
{
    const uint32_t *d = bloom_srgb_dec8;
    for (int i = 0; i < n; i++) {
        const uint32_t v1 = d[s[1][i]], mid = d[s[2][i]] + d[s[3][i]], v4 = d[s[4][i]];
        t[i] = d[s[0][i]] + v1 + mid;
        c[i] = v1 + mid + v4;
        b[i] = mid + v4 + d[s[5][i]];
    }
}

void cod_vsum6w_c(const uint32_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n)
{
    for (int i = 0; i < n; i++) {
        const uint32_t v1 = s[1][i], mid = s[2][i] + s[3][i], v4 = s[4][i];
        t[i] = s[0][i] + v1 + mid;
        c[i] = v1 + mid + v4;
        b[i] = mid + v4 + s[5][i];
    }
}

/* The five 4x4 box sums per channel, the Karis weights
 *   d_i = 2^F + floor(Y_i / 2^20), Y_i = 13933 R_i + 46871 G_i + 4732 B_i
 *   w_i = floor(2^(F+28) / d_i) (<= 2^28), g_i w_i with g = 1, 1, 1, 1, 4
 *   D = floor(floor((sum_i g_i w_i Box_i + 8 W) / 16) / W), W = sum g_i w_i;
 * equal d_i give equal weights, and then D is exactly
 * (sum_i g_i Box_i + 64) >> 7 (nested floors): no division. */
uint32_t cod_karis_c(uint32_t *vt, uint32_t *vc, uint32_t *vb, uint32_t *o, int w)
{
    uint32_t any = 0;
    const uint64_t wnum = 1ull << (BLOOM_LIN_BITS + 28);
    for (int x = 0; x < w; x++) {
        /* padded column 2x - 2 + i is at 3 (2x + i) */
        const uint32_t *t = vt + 6 * x, *c = vc + 6 * x, *b = vb + 6 * x;
        uint32_t box[5][3]; /* TL, TR, BL, BR, C */
        for (int ch = 0; ch < 3; ch++) {
            const uint32_t t01 = t[ch] + t[3 + ch], t23 = t[6 + ch] + t[9 + ch],
                           t45 = t[12 + ch] + t[15 + ch];
            const uint32_t b01 = b[ch] + b[3 + ch], b23 = b[6 + ch] + b[9 + ch],
                           b45 = b[12 + ch] + b[15 + ch];
            box[0][ch] = t01 + t23;
            box[1][ch] = t23 + t45;
            box[2][ch] = b01 + b23;
            box[3][ch] = b23 + b45;
            box[4][ch] = c[3 + ch] + c[6 + ch] + c[9 + ch] + c[12 + ch];
        }
        uint32_t d[5];
        bool same = true;
        for (int i = 0; i < 5; i++) {
            const uint64_t y =
                (uint64_t)COD_KR * box[i][0] + (uint64_t)COD_KG * box[i][1] + (uint64_t)COD_KB * box[i][2];
            d[i] = BLOOM_LIN_ONE + (uint32_t)(y >> 20);
            same = same && d[i] == d[0];
        }
        uint32_t *p = o + 3 * x;
        if (same) {
            for (int ch = 0; ch < 3; ch++)
                p[ch] = (uint32_t)(((uint64_t)box[0][ch] + box[1][ch] + box[2][ch] + box[3][ch] +
                                    4u * (uint64_t)box[4][ch] + 64u) >>
                                   7);
            any |= p[0] | p[1] | p[2];
            continue;
        }
        uint32_t gw[5], wsum = 0;
        for (int i = 0; i < 5; i++) {
            gw[i] = bloom_div_u64_u32(wnum, d[i]) << (i == 4 ? 2 : 0);
            wsum += gw[i];
        }
        for (int ch = 0; ch < 3; ch++) {
            uint64_t num = 8u * (uint64_t)wsum;
            for (int i = 0; i < 5; i++)
                num += (uint64_t)gw[i] * box[i][ch];
            p[ch] = bloom_div_u64_u32(num >> 4, wsum);
        }
        any |= p[0] | p[1] | p[2];
    }
    return any;
}

/* Per column vO = r0 + r1 + 2 (r2 + r3) + r4 + r5 (<= 8 M) and
 * vI = r1 + .. + r4; per pixel sO = the same weights across vO (<= 64 M,
 * 64-bit), sI across vI columns 1..4; D = (sO + 4 sI + 64) >> 7. */
uint32_t cod_down13_c(const uint32_t *const r[6], uint32_t *vo, uint32_t *vi, uint32_t *o, int w, int sw)
{
    const int nw = 3 * sw;
    const uint32_t *r0 = r[0], *r1 = r[1], *r2 = r[2], *r3 = r[3], *r4 = r[4], *r5 = r[5];
    for (int i = 0; i < nw; i++) {
        const uint32_t mid = r2[i] + r3[i];
        vi[COD_PAD + i] = r1[i] + mid + r4[i];
        vo[COD_PAD + i] = r0[i] + r1[i] + 2u * mid + r4[i] + r5[i];
    }
    cod_pad_edges(vo, sw);
    cod_pad_edges(vi, sw);
    uint32_t any = 0;
    for (int x = 0; x < w; x++) {
        const uint32_t *a = vo + 6 * x, *b = vi + 6 * x;
        for (int ch = 0; ch < 3; ch++) {
            const uint64_t so = (uint64_t)a[ch] + a[3 + ch] + 2u * ((uint64_t)a[6 + ch] + a[9 + ch]) +
                                a[12 + ch] + a[15 + ch];
            const uint32_t si = b[3 + ch] + b[6 + ch] + b[9 + ch] + b[12 + ch];
            o[3 * x + ch] = (uint32_t)((so + 4u * (uint64_t)si + 64u) >> 7);
            any |= o[3 * x + ch];
        }
    }
    return any;
}

/* The vertical half of the tent: V[j] = the four rows' weighted samples at
 * low-resolution column j, each <= 16 * 2^32, 64-bit, padded (2 columns
 * left, 2 right). Returns column 0. */
static const uint64_t *vtent64(const uint32_t *const u[4], int odd, int sw, uint32_t *scr)
{
    uint64_t *v = (uint64_t *)(void *)scr + 6;
    const uint32_t *a = u[0], *b = u[1], *c = u[2], *d = u[3];
    const uint32_t wa = odd ? 3u : 1u, wb = odd ? 7u : 5u, wc = odd ? 5u : 7u, wd = odd ? 1u : 3u;
    for (int i = 0; i < 3 * sw; i++)
        v[i] = (uint64_t)wa * a[i] + (uint64_t)wb * b[i] + (uint64_t)wc * c[i] + (uint64_t)wd * d[i];
    for (int ch = 0; ch < 3; ch++) {
        v[ch - 6] = v[ch - 3] = v[ch];
        v[3 * sw + ch] = v[3 * sw + 3 + ch] = v[3 * (sw - 1) + ch];
    }
    return v;
}

/* The horizontal half for x = 2m (weights 1, 5, 7, 3 over m-2 .. m+1) and
 * 2m + 1 (3, 7, 5, 1 over m-1 .. m+2): the exact 2-D tent sums (<= 2^40). */
#define TENT_EVEN(p, ch) ((p)[(ch)-6] + 5u * (p)[(ch)-3] + 7u * (p)[(ch)] + 3u * (p)[(ch) + 3])
#define TENT_ODD(p, ch) (3u * (p)[(ch)-3] + 7u * (p)[(ch)] + 5u * (p)[(ch) + 3] + (p)[(ch) + 6])

void cod_blend_c(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                 uint32_t a, uint32_t c, uint32_t *scr)
{
    const uint64_t *v = vtent64(u, odd, sw, scr);
    for (int x = 0; x < w; x++) {
        const uint64_t *p = v + 3 * (x >> 1);
        for (int ch = 0; ch < 3; ch++) {
            const uint64_t t = (x & 1) ? TENT_ODD(p, ch) : TENT_EVEN(p, ch);
            o[3 * x + ch] = (uint32_t)(((uint64_t)a * d[3 * x + ch] + (uint64_t)c * t + (1u << 23)) >> 24);
        }
    }
}

void cod_mix_c(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw, uint32_t a,
               const uint32_t f[3], uint32_t *scr)
{
    const uint64_t *v = vtent64(u, odd, sw, scr);
    for (int x = 0; x < w; x++) {
        const uint64_t *p = v + 3 * (x >> 1);
        for (int ch = 0; ch < 3; ch++) {
            const uint64_t t = (x & 1) ? TENT_ODD(p, ch) : TENT_EVEN(p, ch);
            const uint64_t q = ((uint64_t)a * d[3 * x + ch] + (uint64_t)f[ch] * t + (1u << 23)) >> 24;
            o[3 * x + ch] = q > UINT32_MAX ? UINT32_MAX : (uint32_t)q;
        }
    }
}

void cod_kernels(bloom_isa_t isa, cod_kernels_t *k)
{
    *k = (cod_kernels_t){cod_vsum6_c, cod_vsum6w_c, cod_karis_c,      cod_down13_c,
                         cod_blend_c, cod_mix_c,    bloom_decode_row, bloom_encode_row};
#if defined(BLOOM_SIMD_AVX2)
    if (isa == BLOOM_ISA_AVX2)
        *k = (cod_kernels_t){cod_vsum6_avx2, cod_vsum6w_avx2, cod_karis_avx2, cod_down13_avx2,
                             cod_blend_avx2, cod_mix_avx2,    cod_dec_avx2,   cod_enc_avx2};
#endif
#if defined(BLOOM_SIMD_NEON)
    if (isa == BLOOM_ISA_NEON) {
        k->down13 = cod_down13_neon;
        k->blend = cod_blend_neon;
        k->mix = cod_mix_neon;
    }
#endif
    (void)isa;
}

#else
typedef int bloom_preset_cod_kern_unused_t;
#endif
