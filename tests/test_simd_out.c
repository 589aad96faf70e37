/* The output kernels against their references, bit for bit: the sRGB
 * encoder without its bound test (every value), the fused composite and
 * encode of the fast output path (k->eo), and the output row kernel with the
 * SIMD kernels (SSE2, AVX2 where the CPU has it, NEON on aarch64) and with
 * the C ones. The other kernels: test_simd.c. */
#include "bloom_kernels.h"
#include "bloom_pixel.h"
#include "simd_rows.h"

#if !BLOOM_SMALL
/* The encoder without the bound test against the reference, every value. */
static void test_enc_fast(void)
{
    int bad = 0;
    CHECK(bloom_srgb_bkt8[bloom_srgb_enc8[255] >> (BLOOM_LIN_BITS - 12)] < 255);
    CHECK(bloom_srgb_bkt6[bloom_srgb_enc6[63] >> (BLOOM_LIN_BITS - 10)] < 63);
    CHECK(bloom_srgb_bkt5[bloom_srgb_enc5[31] >> (BLOOM_LIN_BITS - 9)] < 31);
    for (int bits = 5; bits <= 8; bits++) {
        if (bits == 7)
            continue;
        for (uint32_t v = 0; v <= BLOOM_LIN_ONE + 4096u; v++)
            bad += bloom_enc_srgb_fast(v, bits) != bloom_enc_srgb_ref(v, bits);
        for (int i = 0; i < 100000; i++) {
            const uint32_t v = rng_next(&seed);
            bad += bloom_enc_srgb_fast(v, bits) != bloom_enc_srgb_ref(v, bits);
        }
        bad += bloom_enc_srgb_fast(0xFFFFFFFFu, bits) != bloom_enc_srgb_ref(0xFFFFFFFFu, bits);
    }
    CHECKF(bad == 0, "%d values encode differently", bad);
    /* The SIMD encoders' wide buckets: every v a decoded code plus a bloom
     * clamped to the top threshold can make (and the table's last entry). */
    int wide = 0;
    const uint32_t vmax = BLOOM_LIN_ONE + bloom_srgb_enc8[255];
    CHECK((vmax >> (BLOOM_LIN_BITS - 12)) < sizeof bloom_srgb_bkt8w);
    for (uint32_t v = 0; v <= vmax; v++)
        wide += bloom_fenc8w(v) != bloom_enc_srgb_ref(v, 8);
    CHECKF(wide == 0, "%d values encode differently through the wide buckets", wide);
}

/* The fused composite + encode of the fast output path (k->eo: the AVX2
 * twin where the CPU has it) against bloom_encode_eo, for every format
 * pair, with and without the debug view, bloom samples at the encoder's
 * thresholds and up to the largest the path allows (P + S < 2^32), even
 * and odd columns in one buffer (as bloom_row_out_k has them, either order)
 * and in two. */
static void test_eo(const bloom_kernels_t *ks)
{
    static const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565};
#if defined(BLOOM_SIMD_AVX2)
    /* the AVX2 encoder copies the code where b <= max(A c, H0) */
    int loose = 0;
    for (uint32_t c = 0; c < 255; c++) {
        const uint32_t lb = BLOOM_KEEP8_A * c > BLOOM_KEEP8_H0 ? BLOOM_KEEP8_A * c : BLOOM_KEEP8_H0;
        loose += lb + bloom_srgb_dec8[c] >= bloom_srgb_enc8[c + 1];
    }
    CHECKF(loose == 0, "%d codes where the keep bound of the AVX2 encoder is too large", loose);
#endif
    int bad = 0, cases = 0;
    for (int wi = 0; wi < NWIDTHS; wi++) {
        const int n = widths[wi], ns = 3 * ((n + 1) / 2);
        for (int fi = 0; fi < 3; fi++)
            for (int fo = 0; fo < 3; fo++)
                for (int var = 0; var < 6; var++) {
                    const int ib = bloom_format_bpp(fmts[fi]), ob = bloom_format_bpp(fmts[fo]);
                    if (ib == 0 || ob == 0)
                        continue;
                    const bool dbg = var == 5;
                    row_t buf = row_new((size_t)(2 * ns + 8), var & 3, 0), e2 = row_new((size_t)ns, 1, 0);
                    uint32_t *e = buf.p, *o = buf.p + ns + var % 3;
                    if (var == 3) { /* odd columns first */
                        o = buf.p;
                        e = buf.p + ns + 2;
                    }
                    if (var == 4)
                        e = e2.p;
                    for (int i = 0; i < ns; i++)
                        for (int h = 0; h < 2; h++) {
                            const uint32_t r = rng_next(&seed);
                            /* var 0, 1: mostly small (around the AVX2 encoder's keep bound) */
                            const int mode = var < 2 && (r & 0x800u) ? 4 : (int)((r >> 28) % 4u);
                            const uint32_t v = mode == 0   ? r % (2u << BLOOM_LIN_BITS)
                                               : mode == 1 ? r >> 1
                                               /* (thresholds 1 .. 255: entry 0 is unused, and
                                                  0 - 1 would break P + S < 2^32) */
                                               : mode == 2
                                                   ? bloom_srgb_enc8[1u + (r >> 8) % 255u] + (r & 3u) - 1u
                                               : mode == 3 ? ((r & 1u) ? 0xFFFFFFFFu - BLOOM_LIN_ONE : 0u)
                                                           : (r >> 12) % 4000u;
                            (h ? o : e)[i] = v;
                        }
                    uint8_t *src = (uint8_t *)xmalloc((size_t)n * (size_t)ib + 1u);
                    for (int i = 0; i < n * ib + 1; i++)
                        src[i] = (uint8_t)rng_next(&seed);
                    const size_t nb = (size_t)n * (size_t)ob;
                    uint8_t *d1 = (uint8_t *)xmalloc(nb + 9u), *d2 = (uint8_t *)xmalloc(nb + 9u);
                    memset(d1, 0x5A, nb + 9u);
                    memset(d2, 0x5A, nb + 9u);
                    ks->eo(fmts[fi], fmts[fo], dbg, src + 1, e, o, d1 + 1, n);
                    bloom_encode_eo(fmts[fi], fmts[fo], dbg, src + 1, e, o, d2 + 1, n);
                    cases++;
                    if (memcmp(d1, d2, nb + 9u) != 0) {
                        bad++;
                        fprintf(stderr, "eo (%s): n %d in %d out %d var %d differs\n", ks->name, n,
                                (int)fmts[fi], (int)fmts[fo], var);
                    }
                    free(d1);
                    free(d2);
                    free(src);
                    free(buf.base);
                    free(e2.base);
                }
    }
    CHECKF(bad == 0, "%d of %d encoded rows differ", bad, cases);
}

/* The output row kernel: bloom_row_out_k (fast path where it applies) with
 * the SIMD and the C kernels against bloom_row_out_c, U at the bound of the
 * default pipeline (16 * 2^F) and below; and from an even column on. */
static void test_out(const bloom_kernels_t *ks, const bloom_kernels_t *kc)
{
    static const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    static const uint32_t Is[] = {65536u, 14707629u, 98304u, 0u, 1u};
    int bad = 0, cases = 0;
    for (int wi = 0; wi < NWIDTHS; wi++) {
        const int w = widths[wi], sw = (w + 1) / 2;
        for (int fi = 0; fi < 4; fi++)
            for (int fo = 0; fo < 4; fo++) {
                const int ib = bloom_format_bpp(fmts[fi]), ob = bloom_format_bpp(fmts[fo]);
                if (ib == 0 || ob == 0)
                    continue;
                for (int var = 0; var < 8; var++) {
                    const int mode = var % 3;
                    bloom_out_t o;
                    o.in_fmt = fmts[fi];
                    o.out_fmt = fmts[fo];
                    o.linear = var == 4;
                    o.debug = var == 5 || var == 7;
                    o.intensity = Is[var % 5];
                    row_t u[3];
                    const uint32_t *up[3];
                    for (int i = 0; i < 3; i++) {
                        u[i] = row_new((size_t)sw * 3u, (var + i) & 3, 0);
                        fill(u[i].p, (size_t)sw * 3u, mode,
                             fmts[fi] == BLOOM_FMT_RGBQ16 ? 0xFFFFFFFFu : 16u << BLOOM_LIN_BITS);
                        if (var >= 6) /* mostly zero: whole chunks of B = 0 */
                            for (int j = 0; j < sw * 3; j++)
                                if ((j / 3 + i) % 50 != 7)
                                    u[i].p[j] = 0;
                        up[i] = u[i].p;
                    }
                    uint8_t *src = (uint8_t *)xmalloc((size_t)w * (size_t)ib + 1u);
                    for (int i = 0; i < w * ib; i++)
                        src[i] = (uint8_t)rng_next(&seed);
                    if (fmts[fi] == BLOOM_FMT_RGBQ16)
                        for (int i = 0; i < w * 3; i++) {
                            const uint32_t q = rng_next(&seed) % (1u << 25);
                            memcpy(src + 4 * i, &q, 4);
                        }
                    uint8_t *d[3];
                    for (int j = 0; j < 3; j++) {
                        d[j] = (uint8_t *)xmalloc((size_t)w * (size_t)ob + 1u + 8u);
                        memset(d[j], 0x5A, (size_t)w * (size_t)ob + 8u);
                        d[j] += 1; /* unaligned */
                    }
                    for (int odd = 0; odd < 2; odd++) {
                        bloom_row_out_k(ks, up, odd, src, d[0], 0, w, sw, &o);
                        bloom_row_out_k(kc, up, odd, src, d[1], 0, w, sw, &o);
                        bloom_row_out_c(up, odd, src, d[2], w, sw, &o);
                        cases++;
                        const size_t nb = (size_t)w * (size_t)ob;
                        int ok = memcmp(d[0], d[2], nb) == 0 && memcmp(d[1], d[2], nb) == 0;
                        for (int j = 0; j < 3; j++)
                            for (int g = 0; g < 7; g++)
                                ok = ok && d[j][nb + (size_t)g] == 0x5A;
                        /* from an even column x0 on (a tile's row in place):
                         * the same columns, none before x0 written */
                        const int x0 = (w / 3) & ~1;
                        const size_t nx0 = (size_t)x0 * (size_t)ob;
                        memset(d[0], 0x5A, nb);
                        bloom_row_out_k(ks, up, odd, src + (size_t)x0 * (size_t)ib, d[0] + nx0, x0, w, sw,
                                        &o);
                        ok = ok && memcmp(d[0] + nx0, d[2] + nx0, nb - nx0) == 0;
                        for (size_t i = 0; i < nx0; i++)
                            ok = ok && d[0][i] == 0x5A;
                        if (!ok) {
                            bad++;
                            fprintf(stderr, "out: w %d in %d out %d var %d odd %d differs\n", w,
                                    (int)fmts[fi], (int)fmts[fo], var, odd);
                        }
                    }
                    for (int j = 0; j < 3; j++)
                        free(d[j] - 1);
                    free(src);
                    for (int i = 0; i < 3; i++)
                        free(u[i].base);
                }
            }
    }
    CHECKF(bad == 0, "%d of %d output rows differ", bad, cases);
}
#endif

int main(void)
{
#if BLOOM_SMALL
    SKIP("BLOOM_SMALL: the fast encoder and the fused output path are compiled out");
#else
    bloom_kernels_t ks, k2, kc;
    bloom_kernels_select(&ks, 0);
    bloom_kernels_select(&k2, BLOOM_FLAG_NO_AVX2);
    bloom_kernels_select(&kc, BLOOM_FLAG_NO_SIMD);
    test_enc_fast();
    printf("output kernels: %s against the references\n", ks.name);
    test_eo(&ks);
    test_out(&ks, &kc);
    if (strcmp(ks.name, k2.name) != 0) {
        printf("output kernels: %s against the references\n", k2.name);
        test_eo(&k2);
        test_out(&k2, &kc);
    }
#endif
    return harness_finish();
}
