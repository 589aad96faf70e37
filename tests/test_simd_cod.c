/* The cod preset's SIMD twins (bloom_preset_cod_avx2.c, _avx2_up.c where
 * the CPU has AVX2; bloom_preset_cod_neon.c on aarch64) against their C
 * kernels (bloom_preset_cod_kern.c), bit for bit: the fused level-1 decode
 * and sums, the Karis 13-tap and its divisions, the 13-tap, the tent blends
 * of the up pass and of the output, the RGB888 decode and encode (NEON:
 * the 13-tap and the blends; the rest of its set is C); widths 1 .. 1921,
 * unaligned pointers, worst-case values (every sample at its largest, sums
 * at the bounds the twins test and past them, equal Karis weights, encoder
 * thresholds) and random ones. On a target without twins it compares the C
 * kernels with themselves (and says so). */
#include "bloom_preset_cod.h"
#include "bloom_pixel.h"
#include "harness.h"

#include <stdlib.h>
#include <string.h>

#define MAXW 1921
#define WORDS (6 * MAXW + 64)

static uint32_t rng = 0x2545F491u;
static uint32_t rnd32(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

/* n words of kind: 0 random below lim, 1 all lim - 1, 2 small (0 .. 40),
 * 3 one value (equal Karis weights), 4 random 32-bit. */
static void fill(uint32_t *p, int n, int kind, uint32_t lim)
{
    const uint32_t one = rnd32() % lim;
    for (int j = 0; j < n; j++) {
        const uint32_t r = rnd32();
        p[j] = kind == 0 ? r % lim : kind == 1 ? lim - 1u : kind == 2 ? r % 41u : kind == 3 ? one : r;
    }
}

typedef struct {
    const char *name;
    cod_kernels_t k;
} twin_t;

static uint8_t b6[6][3 * MAXW + 64];
static uint32_t ta[3][WORDS], tb[3][WORDS], oa[WORDS], ob[WORDS];

/* The sums of six rows, every width, rows at unaligned offsets: source
 * bytes (vsum6: all 255 or random) or decoded samples (vsum6w: at their
 * largest, 2^28, or random). */
static void test_vsum(const twin_t *t, bool wide)
{
    static uint32_t in[6][3 * MAXW + 16];
    const char *what = wide ? "vsum6w" : "vsum6";
    int bad = 0;
    for (int w = 1; w <= MAXW; w++) {
        const int n = 3 * w, off = w % 8, top = w % 5 == 0;
        const uint8_t *s8[6];
        const uint32_t *s32[6];
        for (int r = 0; r < 6; r++) {
            if (wide)
                fill(in[r] + off, n, top, BLOOM_LIN_MAX + 1u);
            else
                for (int j = 0; j < n; j++)
                    b6[r][off + j] = (uint8_t)(top ? 255u : rnd32());
            s8[r] = b6[r] + off;
            s32[r] = in[r] + off;
        }
        memset(ta, 0xA5, sizeof ta);
        memset(tb, 0xA5, sizeof tb);
        if (wide) {
            cod_vsum6w_c(s32, ta[0] + 1, ta[1] + 1, ta[2] + 1, n);
            t->k.vsum6w(s32, tb[0] + 1, tb[1] + 1, tb[2] + 1, n);
        } else {
            cod_vsum6_c(s8, ta[0] + 1, ta[1] + 1, ta[2] + 1, n);
            t->k.vsum6(s8, tb[0] + 1, tb[1] + 1, tb[2] + 1, n);
        }
        if (memcmp(ta, tb, sizeof ta) && bad++ < 5)
            fprintf(stderr, "%s %s w %d differs\n", t->name, what, w);
    }
    CHECKF(bad == 0, "%s: %d %s widths differ", t->name, bad, what);
}

/* Padded column sums of four rows: each word <= 4 LIN_MAX (kind 1 at
 * 4 2^20: every box 2^24, the 8-bit worst case; lim 2^30: boxes past the
 * twin's 2^25, the C path). */
static void test_karis(const twin_t *t)
{
    int bad = 0, cases = 0;
    const uint32_t lims[4] = {4u << 20, 4u * BLOOM_LIN_MAX + 1u, 1u << 22, 2u << 20};
    for (int w = 1; w <= MAXW; w++)
        for (int li = 0; li < 4; li++) {
            if (li >= 2 && w % 7)
                continue;
            const int n = 6 * w + 12, off = (w + li) % 8;
            const int kind = li == 1       ? (w % 3 ? 0 : 1)
                             : w % 11 == 0 ? 3
                             : w % 13 == 0 ? 2
                             : w % 4 == 1  ? 1
                                           : 0;
            for (int r = 0; r < 3; r++) {
                fill(ta[r] + off, n, kind, lims[li]);
                if (w % 17 == 0) /* a hot spot: unequal weights around it */
                    ta[r][off + (int)(rnd32() % (uint32_t)n)] = lims[li] - 1u;
                memcpy(tb[r], ta[r], sizeof ta[r]);
            }
            memset(oa, 0x5A, sizeof oa);
            memset(ob, 0x5A, sizeof ob);
            const uint32_t xa = cod_karis_c(ta[0] + off, ta[1] + off, ta[2] + off, oa + 1, w);
            const uint32_t xb = t->k.karis(tb[0] + off, tb[1] + off, tb[2] + off, ob + 1, w);
            cases++;
            if ((xa != xb || memcmp(oa, ob, sizeof oa)) && bad++ < 5)
                fprintf(stderr, "%s karis w %d lim %u differs\n", t->name, w, lims[li]);
        }
    CHECKF(bad == 0, "%s: %d of %d Karis cases differ", t->name, bad, cases);
}

static uint32_t rows[6][3 * 2 * MAXW + 64];

static void test_down13(const twin_t *t)
{
    int bad = 0, cases = 0;
    const uint32_t lims[3] = {1u << 20, BLOOM_LIN_MAX + 1u, 1u << 23};
    for (int w = 1; w <= MAXW; w++)
        for (int li = 0; li < 3; li++) {
            if (li == 2 && w % 5)
                continue;
            const int sw = 2 * w - (w & 1), off = (w + li) % 8;
            const int kind = w % 9 == 0 ? 1 : w % 13 == 0 ? 2 : 0;
            const uint32_t *rp[6];
            for (int r = 0; r < 6; r++) {
                fill(rows[r] + off + r, 3 * sw, kind, lims[li]);
                rp[r] = rows[r] + off + r;
            }
            memset(oa, 0x5A, sizeof oa);
            memset(ob, 0x5A, sizeof ob);
            const uint32_t xa = cod_down13_c(rp, ta[0], ta[1], oa + 1, w, sw);
            const uint32_t xb = t->k.down13(rp, tb[0] + off, tb[1] + 1, ob + 1, w, sw);
            cases++;
            if ((xa != xb || memcmp(oa, ob, sizeof oa)) && bad++ < 5)
                fprintf(stderr, "%s down13 w %d lim %u differs\n", t->name, w, lims[li]);
        }
    CHECKF(bad == 0, "%s: %d of %d 13-tap cases differ", t->name, bad, cases);
}

static uint64_t scr_a[2 * (3 * 2 * MAXW + 16) / 2 + 64], scr_b[2 * (3 * 2 * MAXW + 16) / 2 + 64];
static uint32_t dd[3 * 2 * MAXW + 64];

/* The blends: w = 2 sw or 2 sw - 1, rows below 2^20 (the 8-bit case),
 * up to LIN_MAX, at 2^24 - 1 (the twin's bound) and at 2^24 (past it);
 * both parities; a and c (f) random, at their ends and additive. */
static void test_blend(const twin_t *t, bool mix)
{
    int bad = 0, cases = 0;
    const uint32_t lims[4] = {1u << 20, BLOOM_LIN_MAX + 1u, 1u << 24, (1u << 24) + 1u};
    for (int sw = 1; sw <= (MAXW + 1) / 2; sw++)
        for (int li = 0; li < 4; li++) {
            if (li >= 2 && sw % 3)
                continue;
            const int w = 2 * sw - (sw & 1), off = (sw + li) % 8, odd = (sw >> 1) & 1;
            const int kind = li == 2 || li == 3 ? (sw % 2 ? 1 : 0) : sw % 7 == 0 ? 1 : sw % 11 == 0 ? 2 : 0;
            const uint32_t *u[4];
            for (int r = 0; r < 4; r++) {
                fill(rows[r] + off + r, 3 * sw, kind, lims[li]);
                u[r] = rows[r] + off + r;
            }
            fill(dd + off, 3 * w, sw % 5 == 0 ? 4 : 0, mix ? (1u << 20) + 1u : BLOOM_LIN_MAX + 1u);
            const uint32_t c = sw % 4 == 0 ? 65536u : sw % 4 == 1 ? 0u : rnd32() % 65537u;
            const uint32_t a = sw % 3 == 0 ? 1u << 24 : mix && sw % 5 == 1 ? 0u : (65536u - c) << 8;
            const uint32_t f[3] = {c, rnd32() % 65537u, sw % 2 ? 65536u : 0u};
            memset(oa, 0x5A, sizeof oa);
            memset(ob, 0x5A, sizeof ob);
            if (mix) {
                cod_mix_c(u, odd, dd + off, oa + 1, w, sw, a, f, (uint32_t *)scr_a);
                t->k.mix(u, odd, dd + off, ob + 1, w, sw, a, f, (uint32_t *)scr_b);
            } else {
                cod_blend_c(u, odd, dd + off, oa + 1, w, sw, a, c, (uint32_t *)scr_a);
                t->k.blend(u, odd, dd + off, ob + 1, w, sw, a, c, (uint32_t *)scr_b);
            }
            cases++;
            if (memcmp(oa, ob, sizeof oa) && bad++ < 5)
                fprintf(stderr, "%s %s sw %d lim %u differs\n", t->name, mix ? "mix" : "blend", sw, lims[li]);
        }
    CHECKF(bad == 0, "%s: %d of %d %s cases differ", t->name, bad, cases, mix ? "mix" : "blend");
}

static uint8_t ca[3 * MAXW + 64], cb[3 * MAXW + 64];

static void test_codec(const twin_t *t)
{
    int bad = 0;
    for (int w = 1; w <= MAXW; w++) {
        const int n = 3 * w, off = w % 8;
        for (int j = 0; j < n; j++)
            b6[0][off + j] = (uint8_t)rnd32();
        memset(oa, 0x5A, sizeof oa);
        memset(ob, 0x5A, sizeof ob);
        bloom_decode_row(BLOOM_FMT_RGB888, w % 9 == 0, b6[0] + off, oa + 1, w);
        t->k.dec(BLOOM_FMT_RGB888, w % 9 == 0, b6[0] + off, ob + 1, w);
        if (memcmp(oa, ob, sizeof oa) && bad++ < 5)
            fprintf(stderr, "%s dec w %d differs\n", t->name, w);
        /* the encoder: random words, the thresholds and their neighbours */
        for (int j = 0; j < n; j++) {
            const uint32_t r = rnd32(), c = r % 256u;
            const uint32_t th = c ? bloom_srgb_enc8[c] : 0u;
            dd[off + j] = w % 3 == 0 ? r : w % 3 == 1 ? th + (r >> 8) % 3u - 1u : r % ((1u << 21) + 1u);
        }
        memset(ca, 0x5A, sizeof ca);
        memset(cb, 0x5A, sizeof cb);
        bloom_encode_row(BLOOM_FMT_RGB888, w % 7 == 0, dd + off, ca + 1, w);
        t->k.enc(BLOOM_FMT_RGB888, w % 7 == 0, dd + off, cb + 1, w);
        if (memcmp(ca, cb, sizeof ca) && bad++ < 5)
            fprintf(stderr, "%s enc w %d differs\n", t->name, w);
    }
    CHECKF(bad == 0, "%s: %d decode/encode widths differ", t->name, bad);
}

#if defined(BLOOM_SIMD_AVX2)
/* The Karis twin's divisions: floor(2^48 / d) for every d of its domain
 * 699051 .. 3 2^20 - 1 (the weights' divisors are 2^20 .. 3 2^20 - 1, the
 * quotient's reciprocal takes (W >> 10) + 1 >= 699051); floor(n / W) for W
 * at the ends of 715827880 .. 2^31 and random, n at multiples of W, one
 * below them and at the largest numerator 2^52 + 2^30 - 1. */
static uint32_t dv[1024], qv[1024], wv[1024];
static uint64_t nv[1024];
static void test_divisions(void)
{
    int bad = 0;
    long cases = 0;
    const uint32_t lo = 699051u, hi = 3u << 20;
    for (uint32_t d0 = lo; d0 < hi; d0 += 1024u) {
        for (int i = 0; i < 1024; i++)
            dv[i] = d0 + (uint32_t)i < hi ? d0 + (uint32_t)i : hi - 1u;
        cod_recip48_avx2(dv, qv, 1024);
        for (int i = 0; i < 1024; i++, cases++)
            if (qv[i] != (uint32_t)((1ull << 48) / dv[i]) && bad++ < 5)
                fprintf(stderr, "recip48 %u: %u\n", dv[i], qv[i]);
    }
    CHECKF(bad == 0, "%d of %ld reciprocals differ", bad, cases);
    bad = 0;
    cases = 0;
    const uint64_t nmax = (1ull << 52) + (1ull << 30) - 1u;
    for (int round = 0; round < 4000; round++) {
        for (int i = 0; i < 1024; i++) {
            const uint32_t r = rnd32();
            uint32_t w = 715827880u + r % (2147483648u - 715827880u + 1u);
            if (i % 16 < 3)
                w = i % 16 == 0 ? 715827880u : i % 16 == 1 ? 2147483648u : 715827880u + (uint32_t)round;
            const uint64_t k = ((uint64_t)rnd32() << 32 | rnd32()) % (nmax / w + 1u);
            uint64_t n = k * w + (uint64_t)(i % 3) - 1u; /* one below, at, one above a multiple */
            if (k == 0 && i % 3 == 0)
                n = 0;
            if (i % 64 == 5)
                n = nmax;
            if (n > nmax)
                n = nmax;
            wv[i] = w;
            nv[i] = n;
        }
        cod_qdiv_avx2(wv, nv, qv, 1024);
        for (int i = 0; i < 1024; i++, cases++)
            if (qv[i] != (uint32_t)(nv[i] / wv[i]) && bad++ < 5)
                fprintf(stderr, "qdiv %llu / %u: %u\n", (unsigned long long)nv[i], wv[i], qv[i]);
    }
    CHECKF(bad == 0, "%d of %ld quotients differ", bad, cases);
}
#endif

int main(void)
{
    twin_t twins[3];
    int nt = 0;
#if defined(BLOOM_SIMD_AVX2)
    if (bloom_cpu_avx2()) {
        test_divisions();
        twins[nt].name = "avx2";
        cod_kernels(BLOOM_ISA_AVX2, &twins[nt++].k);
    } else
        SKIP("cpu avx2: the CPU or the OS lacks AVX2");
#endif
#if defined(BLOOM_SIMD_NEON)
    twins[nt].name = "neon";
    cod_kernels(BLOOM_ISA_NEON, &twins[nt++].k);
#endif
    if (!nt) {
        printf("no cod SIMD twins on this target: the C kernels against themselves\n");
        twins[nt].name = "c";
        cod_kernels(BLOOM_ISA_C, &twins[nt++].k);
    }
    for (int k = 0; k < nt; k++) {
        test_vsum(&twins[k], false);
        test_vsum(&twins[k], true);
        test_karis(&twins[k]);
        test_down13(&twins[k]);
        test_blend(&twins[k], false);
        test_blend(&twins[k], true);
        test_codec(&twins[k]);
    }
    /* the preset picks each twin by the kernel set's instruction set */
    cod_kernels_t kc;
    cod_kernels(BLOOM_ISA_C, &kc);
    CHECK(kc.karis == cod_karis_c && kc.blend == cod_blend_c && kc.enc == bloom_encode_row);
    cod_kernels(BLOOM_ISA_SSE2, &kc);
    CHECK(kc.karis == cod_karis_c && kc.mix == cod_mix_c);
#if defined(BLOOM_SIMD_NEON)
    cod_kernels(BLOOM_ISA_NEON, &kc);
    CHECK(kc.down13 == cod_down13_neon && kc.blend == cod_blend_neon && kc.mix == cod_mix_neon &&
          kc.karis == cod_karis_c);
#endif
#if defined(BLOOM_SIMD_AVX2)
    cod_kernels(BLOOM_ISA_AVX2, &kc);
    CHECK(kc.karis == cod_karis_avx2 && kc.down13 == cod_down13_avx2 && kc.blend == cod_blend_avx2 &&
          kc.mix == cod_mix_avx2 && kc.vsum6 == cod_vsum6_avx2 && kc.vsum6w == cod_vsum6w_avx2 &&
          kc.dec == cod_dec_avx2 && kc.enc == cod_enc_avx2);
#endif
    return harness_finish();
}
