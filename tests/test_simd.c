/* The SIMD row kernels (SSE2 and, where the CPU has it, AVX2 on x86-64;
 * NEON on aarch64) against their C twins, bit for bit: every kernel at many
 * widths, unaligned pointers, random and extreme inputs (the output kernels:
 * test_simd_out.c); then whole frames through bloom_process with and without
 * BLOOM_FLAG_NO_SIMD. On a target without SIMD kernels it
 * compares the C kernels with themselves (and says so). */
#include "bloom_kernels.h"
#include "bloom_pixel.h"
#include "harness.h"
#include "testutil.h"

#include "simd_rows.h"

static void test_box(const bloom_kernels_t *ks, const bloom_kernels_t *kc)
{
    int bad = 0;
    /* every width to 300 (the AVX2 box's blocks of 8 and chunks of 128
     * pixels start and end everywhere), then the long rows */
    for (int wi = 0; wi < 300 + NWIDTHS; wi++) {
        const int sw = wi < 300 ? wi + 1 : widths[wi - 300], dw = (sw + 1) / 2;
        for (int mode = 0; mode < 4; mode++)
            for (int off = 0; off < 4; off++) {
                row_t s[4];
                const uint32_t *sp[4];
                for (int i = 0; i < 4; i++) {
                    s[i] = row_new((size_t)sw * 3u, (off + i) & 3, 0);
                    fill(s[i].p, (size_t)sw * 3u, mode, SMAX);
                    sp[i] = s[i].p;
                }
                row_t a = row_new((size_t)dw * 3u, off, 1), c = row_new((size_t)dw * 3u, 3 - off, 1);
                ks->box(sp, a.p, dw, sw);
                kc->box(sp, c.p, dw, sw);
                const int same = memcmp(a.p, c.p, (size_t)dw * 3u * sizeof(uint32_t)) == 0;
                if (!same || !row_guard_ok(&a) || !row_guard_ok(&c)) {
                    bad++;
                    fprintf(stderr, "box: width %d mode %d offset %d: %s\n", sw, mode, off,
                            same ? "guard overwritten" : "differs");
                }
                free(a.base);
                free(c.base);
                for (int i = 0; i < 4; i++)
                    free(s[i].base);
            }
    }
    CHECKF(bad == 0, "%d box cases differ", bad);
}

/* One tent call of each kernel set on columns x0 .. x0+n-1 of a row of
 * width w; add: 0 none, 1 separate, 2 in place (add == dst). */
static int tent_case(const bloom_kernels_t *ks, const bloom_kernels_t *kc, const uint32_t *const u[3],
                     int odd, int addmode, const uint32_t *addsrc, int x0, int n, int sw, int off)
{
    row_t a = row_new((size_t)n * 3u, off, 1), c = row_new((size_t)n * 3u, (off + 2) & 3, 1);
    row_t ad = row_new((size_t)n * 3u, (off + 1) & 3, 0);
    memcpy(ad.p, addsrc, (size_t)n * 3u * sizeof(uint32_t));
    const uint32_t *add_s = NULL, *add_c = NULL;
    if (addmode == 1) {
        add_s = add_c = ad.p;
    } else if (addmode == 2) {
        memcpy(a.p, addsrc, (size_t)n * 3u * sizeof(uint32_t));
        memcpy(c.p, addsrc, (size_t)n * 3u * sizeof(uint32_t));
        add_s = a.p;
        add_c = c.p;
    }
    ks->tent(u, odd, add_s, a.p, x0, n, sw);
    kc->tent(u, odd, add_c, c.p, x0, n, sw);
    const int ok = memcmp(a.p, c.p, (size_t)n * 3u * sizeof(uint32_t)) == 0 && row_guard_ok(&a) &&
                   row_guard_ok(&c) && memcmp(ad.p, addsrc, (size_t)n * 3u * sizeof(uint32_t)) == 0;
    free(a.base);
    free(c.base);
    free(ad.base);
    return ok;
}

static void test_tent(const bloom_kernels_t *ks, const bloom_kernels_t *kc)
{
    int bad = 0, cases = 0;
    for (int wi = 0; wi < NWIDTHS; wi++) {
        const int sw = widths[wi];
        for (int mode = 0; mode < 7; mode++)
            for (int off = 0; off < 4; off++) {
                row_t u[3];
                const uint32_t *up[3];
                for (int i = 0; i < 3; i++) {
                    u[i] = row_new((size_t)sw * 3u, (off + i + 1) & 3, 0);
                    /* U sums: anything below 2^32; modes 3..6 below 2^29
                     * (the SIMD kernels' path without the split), but
                     * mode 6 has one sample above (one chunk of the AVX2
                     * tent takes the exact path) */
                    fill(u[i].p, (size_t)sw * 3u, mode % 3, mode < 3 ? 0xFFFFFFFFu : (1u << 29) - 1u);
                    if (mode == 6 && i == 1)
                        u[i].p[rng_next(&seed) % ((uint32_t)sw * 3u)] = 0xF0000000u + (rng_next(&seed) >> 4);
                    up[i] = u[i].p;
                }
                for (int w = 2 * sw - 1; w <= 2 * sw; w++) {
                    if (w < 1)
                        continue;
                    uint32_t *addsrc = (uint32_t *)xmalloc((size_t)w * 3u * sizeof(uint32_t));
                    fill(addsrc, (size_t)w * 3u, mode % 4, mode == 3 ? 0xFFFFFFFFu : SMAX);
                    for (int odd = 0; odd < 2; odd++)
                        for (int addmode = 0; addmode < 3; addmode++) {
                            /* the whole row, the output kernel's chunks, random ranges */
                            int ranges[12][2], nr = 0;
                            ranges[nr][0] = 0;
                            ranges[nr++][1] = w;
                            for (int x0 = 0; x0 < w && nr < 6; x0 += BLOOM_OUT_CHUNK) {
                                ranges[nr][0] = x0;
                                ranges[nr++][1] = w - x0 < BLOOM_OUT_CHUNK ? w - x0 : BLOOM_OUT_CHUNK;
                            }
                            if (w > BLOOM_OUT_CHUNK) { /* the last chunk */
                                const int x0 = (w - 1) / BLOOM_OUT_CHUNK * BLOOM_OUT_CHUNK;
                                ranges[nr][0] = x0;
                                ranges[nr++][1] = w - x0;
                            }
                            while (nr < 12) {
                                const int x0 = (int)(rng_next(&seed) % (uint32_t)w);
                                ranges[nr][0] = x0;
                                ranges[nr++][1] = 1 + (int)(rng_next(&seed) % (uint32_t)(w - x0));
                            }
                            for (int r = 0; r < nr; r++) {
                                const int x0 = ranges[r][0], n = ranges[r][1];
                                cases++;
                                if (!tent_case(ks, kc, up, odd, addmode, addsrc + (size_t)x0 * 3u, x0, n, sw,
                                               (off + r) & 3)) {
                                    bad++;
                                    fprintf(stderr,
                                            "tent: sw %d w %d mode %d odd %d add %d x0 %d n %d differs\n", sw,
                                            w, mode, odd, addmode, x0, n);
                                }
                            }
                        }
                    free(addsrc);
                }
                for (int i = 0; i < 3; i++)
                    free(u[i].base);
            }
    }
    CHECKF(bad == 0, "%d of %d tent cases differ", bad, cases);
}

static void test_composite(const bloom_kernels_t *ks, const bloom_kernels_t *kc)
{
    static const uint32_t Is[] = {0u, 1u, 65536u, 14707629u, 0xFFFFFFFFu, 12345678u};
    int bad = 0;
    for (int wi = 0; wi < NWIDTHS; wi++) {
        const size_t n = (size_t)widths[wi] * 3u;
        for (int mode = 0; mode < 4; mode++)
            for (int ii = 0; ii < (int)(sizeof Is / sizeof Is[0]) + 2; ii++) {
                const uint32_t I =
                    ii < (int)(sizeof Is / sizeof Is[0]) ? Is[ii] : rng_next(&seed) % 14707630u;
                const int off = ii & 3;
                row_t sv = row_new(n, off, 0), a = row_new(n, (off + 1) & 3, 1), c = row_new(n, 3 - off, 1);
                fill(sv.p, n, mode == 3 ? 0 : mode, SMAX);
                fill(a.p, n, mode == 3 ? 3 : mode, 0xFFFFFFFFu);
                memcpy(c.p, a.p, n * sizeof(uint32_t));
                ks->composite(a.p, sv.p, (int)n, I);
                kc->composite(c.p, sv.p, (int)n, I);
                /* and against the formula itself */
                int ok = memcmp(a.p, c.p, n * sizeof(uint32_t)) == 0 && row_guard_ok(&a) && row_guard_ok(&c);
                if (!ok) {
                    bad++;
                    fprintf(stderr, "composite: n %zu mode %d I %u differs\n", n, mode, (unsigned)I);
                }
                free(sv.base);
                free(a.base);
                free(c.base);
            }
    }
    CHECKF(bad == 0, "%d composite cases differ", bad);
}

/* The composite of the C kernel against the formula written out. */
static void test_composite_formula(const bloom_kernels_t *ks)
{
    uint32_t bl[8] = {0u, 1u, 0xFFFFFFFFu, 0x80000000u, 123456789u, 0xFFFFFFFEu, 65535u, 65536u};
    uint32_t sv[8] = {0u, SMAX, SMAX, 1u, 0u, 7u, SMAX, 3u};
    const uint32_t I = 14707629u;
    uint32_t r[8];
    memcpy(r, bl, sizeof r);
    ks->composite(r, sv, 8, I);
    int bad = 0;
    for (int i = 0; i < 8; i++) {
        const uint64_t v = (((uint64_t)I * bl[i] + 32768u) >> 16) + sv[i];
        bad += r[i] != (v > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)v);
    }
    CHECK(bad == 0);
}

#if !BLOOM_SMALL
/* The flat kernels of the fast output path: any 32-bit inputs (both wrap
 * the same way), unaligned, every width. */
static void test_flat(const bloom_kernels_t *ks, const bloom_kernels_t *kc)
{
    static const uint32_t Is[] = {0u, 1u, 65535u, 65536u, 98304u, 14707629u, 0xFFFFFFFFu};
    int bad = 0;
    for (int wi = 0; wi < NWIDTHS; wi++) {
        const int n = widths[wi] * 3; /* samples */
        for (int mode = 0; mode < 4; mode++)
            for (int off = 0; off < 4; off++) {
                const uint32_t max = mode == 3 ? 0xFFFFFFFFu : 16u << BLOOM_LIN_BITS;
                /* vtent */
                row_t in[3];
                for (int i = 0; i < 3; i++) {
                    in[i] = row_new((size_t)n, (off + i) & 3, 0);
                    fill(in[i].p, (size_t)n, mode, max);
                }
                row_t a = row_new((size_t)n, off, 1), c = row_new((size_t)n, 3 - off, 1);
                const uint32_t va = ks->vtent(in[0].p, in[1].p, in[2].p, a.p, n);
                const uint32_t vc = kc->vtent(in[0].p, in[1].p, in[2].p, c.p, n);
                int ok =
                    va == vc && memcmp(a.p, c.p, (size_t)n * 4u) == 0 && row_guard_ok(&a) && row_guard_ok(&c);
                for (int i = 0; i < n && ok && mode != 3; i++)
                    ok = c.p[i] == (uint32_t)((3ull * in[0].p[i] + 4ull * in[1].p[i] + in[2].p[i] + 4u) >> 3);
                if (!ok) {
                    bad++;
                    fprintf(stderr, "vtent: n %d mode %d offset %d differs\n", n, mode, off);
                }
                free(a.base);
                free(c.base);
                /* htent_eo: v[-3 .. n+2] */
                row_t v = row_new((size_t)n + 6u, off, 0);
                fill(v.p, (size_t)n + 6u, mode, max);
                row_t e1 = row_new((size_t)n, (off + 1) & 3, 1), o1 = row_new((size_t)n, (off + 2) & 3, 1);
                row_t e2 = row_new((size_t)n, (off + 3) & 3, 1), o2 = row_new((size_t)n, off, 1);
                const uint32_t any1 = ks->htent_eo(v.p + 3, e1.p, o1.p, n);
                const uint32_t any2 = kc->htent_eo(v.p + 3, e2.p, o2.p, n);
                ok = any1 == any2 && memcmp(e1.p, e2.p, (size_t)n * 4u) == 0 &&
                     memcmp(o1.p, o2.p, (size_t)n * 4u) == 0 && row_guard_ok(&e1) && row_guard_ok(&o1) &&
                     row_guard_ok(&e2) && row_guard_ok(&o2);
                for (int i = 0; i < n && ok && mode != 3; i++) {
                    const uint64_t pv = v.p[i], cv = v.p[i + 3], qv = v.p[i + 6];
                    /* the horizontal pass rounds half down (fixed-point.md) */
                    ok = e2.p[i] == (uint32_t)((3u * pv + 4u * cv + qv + 3u) >> 3) &&
                         o2.p[i] == (uint32_t)((pv + 4u * cv + 3u * qv + 3u) >> 3);
                }
                if (!ok) {
                    bad++;
                    fprintf(stderr, "htent_eo: n %d mode %d offset %d differs\n", n, mode, off);
                }
                free(v.base);
                free(e1.base);
                free(o1.base);
                free(e2.base);
                free(o2.base);
                /* scale */
                for (int ii = 0; ii < (int)(sizeof Is / sizeof Is[0]); ii++) {
                    row_t x1 = row_new((size_t)n, (off + ii) & 3, 1),
                          x2 = row_new((size_t)n, (off + ii + 1) & 3, 1);
                    fill(x1.p, (size_t)n, mode, max);
                    memcpy(x2.p, x1.p, (size_t)n * 4u);
                    ks->scale(x1.p, n, Is[ii]);
                    kc->scale(x2.p, n, Is[ii]);
                    if (memcmp(x1.p, x2.p, (size_t)n * 4u) != 0 || !row_guard_ok(&x1) || !row_guard_ok(&x2)) {
                        bad++;
                        fprintf(stderr, "scale: n %d mode %d I %u differs\n", n, mode, (unsigned)Is[ii]);
                    }
                    free(x1.base);
                    free(x2.base);
                }
                for (int i = 0; i < 3; i++)
                    free(in[i].base);
            }
    }
    CHECKF(bad == 0, "%d flat kernel cases differ", bad);
}

/* The level-1 kernel (box from the source, knee) against box + knee in C:
 * rows mostly darker than the dark code with bright spots, every format,
 * the exact dark codes of the engine and a smaller one. */
static uint32_t dark_code(uint32_t cut, bool lin, const uint32_t *table, uint32_t n)
{
    uint32_t c = 0;
    while (c < n) {
        const uint32_t next = lin ? ((c + 1u) * BLOOM_LIN_ONE + (n - 1u) / 2u) / n : table[c + 1];
        if (next > cut)
            break;
        c++;
    }
    return c;
}

static void test_d1(const bloom_kernels_t *ks, const bloom_kernels_t *kc)
{
    static const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    static const double ths[] = {0.6, 1.0, 0.05, 0.0};
    int bad = 0, cases = 0;
    for (int wi = 0; wi < NWIDTHS; wi++) {
        const int sw = widths[wi], dw = (sw + 1) / 2;
        for (int fi = 0; fi < 4; fi++) {
            const int bpp = bloom_format_bpp(fmts[fi]);
            if (bpp == 0)
                continue;
            for (int var = 0; var < 8; var++) {
                const bool lin = var & 1;
                bloom_knee_t kn;
                kn.t = (uint32_t)(ths[var >> 1] * BLOOM_LIN_ONE);
                kn.k = var >= 6 ? 0u : kn.t / 2u;
                const uint32_t cut = kn.t > kn.k ? kn.t - kn.k : 0u;
                bloom_dark_t dk;
                dk.c8 = dark_code(cut, lin, bloom_srgb_dec8, 255);
                dk.c6 = dark_code(cut, lin, bloom_srgb_dec6, 63);
                dk.c5 = dark_code(cut, lin, bloom_srgb_dec5, 31);
                dk.q16 = 0;
                for (int dv = 0; dv < 3; dv++) { /* dv 2: every code random (long bright runs) */
                    if (dv == 1) {               /* a smaller dark code only skips less */
                        dk.c8 /= 2u;
                        dk.c6 /= 2u;
                        dk.c5 /= 2u;
                    }
                    row_t rows[4];
                    const uint8_t *sp[4];
                    for (int r = 0; r < 4; r++) {
                        const size_t nb = (size_t)sw * (size_t)bpp;
                        rows[r] = row_new((nb + 3u) / 4u, (var + r) & 3, 0);
                        uint8_t *b = (uint8_t *)rows[r].p;
                        for (size_t i = 0; i < nb; i++) {
                            const uint32_t x = rng_next(&seed);
                            /* below or at the dark code, or a bright spot now and then */
                            b[i] = (uint8_t)(dv == 2 || (x >> 8) % 97u == 0u
                                                 ? x & 255u
                                                 : (dk.c8 ? (x & 255u) % (dk.c8 + 1u) : 0u));
                        }
                        if (fmts[fi] == BLOOM_FMT_RGB565 &&
                            dv < 2) /* fields at most their dark codes, bright now and then */
                            for (int i = 0; i < sw; i++) {
                                const uint32_t x = rng_next(&seed);
                                uint32_t w = ((x % (dk.c5 + 1u)) << 11) | (((x >> 8) % (dk.c6 + 1u)) << 5) |
                                             ((x >> 16) % (dk.c5 + 1u));
                                if ((x >> 24) % 53u == 0u)
                                    w ^= 1u << ((x >> 20) & 15u);
                                b[2 * i] = (uint8_t)w;
                                b[2 * i + 1] = (uint8_t)(w >> 8);
                            }
                        sp[r] = b;
                    }
                    row_t a = row_new((size_t)dw * 3u, var & 3, 1),
                          c = row_new((size_t)dw * 3u, (var + 1) & 3, 1);
                    /* the box over a range against the whole row's */
                    const int xa = (int)(rng_next(&seed) % (uint32_t)dw);
                    const int xb = xa + (int)(rng_next(&seed) % (uint32_t)(dw - xa + 1));
                    bloom_row_box_src_c(sp, fmts[fi], lin, c.p, dw, sw);
                    memset(a.p, 0, (size_t)dw * 12u);
                    bloom_row_box_src_range_c(sp, fmts[fi], lin, a.p, xa, xb, sw);
                    if (memcmp(a.p + 3 * xa, c.p + 3 * xa, (size_t)(xb - xa) * 12u) != 0 ||
                        !row_guard_ok(&a)) {
                        bad++;
                        fprintf(stderr, "box_src_range: sw %d fmt %d %d..%d differs\n", sw, (int)fmts[fi], xa,
                                xb);
                    }
                    memset(a.p, 0, (size_t)dw * 12u); /* the twin's box from the source, same range */
                    ks->box_src(sp, fmts[fi], lin, a.p, xa, xb, sw);
                    if (memcmp(a.p + 3 * xa, c.p + 3 * xa, (size_t)(xb - xa) * 12u) != 0 ||
                        !row_guard_ok(&a)) {
                        bad++;
                        fprintf(stderr, "box_src (%s): sw %d fmt %d %d..%d differs\n", ks->name, sw,
                                (int)fmts[fi], xa, xb);
                    }
                    const bool ra = ks->d1(sp, fmts[fi], lin, a.p, dw, sw, &kn, &dk, NULL);
                    const bool rc = kc->d1(sp, fmts[fi], lin, c.p, dw, sw, &kn, &dk, NULL);
                    cases++;
                    if (ra != rc || memcmp(a.p, c.p, (size_t)dw * 12u) != 0 || !row_guard_ok(&a) ||
                        !row_guard_ok(&c)) {
                        bad++;
                        fprintf(stderr, "d1: sw %d fmt %d var %d dark %u differs\n", sw, (int)fmts[fi], var,
                                (unsigned)dk.c8);
                    }
                    /* the sums kept for the next row (bloom_d1_keep_t): row 7
                     * with nothing kept, then row 8, whose upper rows are row
                     * 7's lower ones, with what row 7 kept; each kernel set
                     * against the same rows with nothing kept */
                    for (int set = 0; set < 2; set++) {
                        const bloom_kernels_t *kk = set ? kc : ks;
                        bloom_d1_keep_t kp;
                        kp.sum = (uint32_t *)xmalloc((size_t)(dw + 1) * 12u);
                        kp.tag = (int32_t *)xmalloc((size_t)(dw + 1) * 4u);
                        memset(kp.tag, 0xFF, (size_t)(dw + 1) * 4u);
                        const uint8_t *sn[4] = {sp[2], sp[3], sp[0], sp[1]};
                        for (int y = 7; y <= 8; y++) {
                            const uint8_t *const *sy = y == 7 ? sp : sn;
                            kp.y = y;
                            const bool rk = kk->d1(sy, fmts[fi], lin, a.p, dw, sw, &kn, &dk, &kp);
                            const bool rn = kc->d1(sy, fmts[fi], lin, c.p, dw, sw, &kn, &dk, NULL);
                            cases++;
                            if (rk != rn || memcmp(a.p, c.p, (size_t)dw * 12u) != 0 || !row_guard_ok(&a)) {
                                bad++;
                                fprintf(stderr,
                                        "d1 (%s) with kept sums, row %d: sw %d fmt %d var %d differs\n",
                                        kk->name, y, sw, (int)fmts[fi], var);
                            }
                        }
                        free(kp.sum);
                        free(kp.tag);
                    }
                    free(a.base);
                    free(c.base);
                    for (int r = 0; r < 4; r++)
                        free(rows[r].base);
                }
            }
        }
    }
    CHECKF(bad == 0, "%d of %d level-1 rows differ", bad, cases);
}

#endif

/* Whole frames: SIMD engine against the NO_SIMD engine. */
static void test_frames(void)
{
    static const int sizes[][2] = {{1, 1},   {2, 2},   {3, 5},    {17, 9},
                                   {33, 31}, {64, 48}, {101, 37}, {257, 130}};
    static const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    static const uint32_t flagsets[] = {0u, BLOOM_FLAG_LINEAR, BLOOM_FLAG_DEBUG_VIEW, BLOOM_FLAG_NO_SKIP,
                                        BLOOM_FLAG_COPY_SOURCE | BLOOM_FLAG_LINEAR};
    int bad = 0, frames = 0;
    for (int si = 0; si < (int)(sizeof sizes / sizeof sizes[0]); si++)
        for (int fi = 0; fi < 4; fi++)
            for (int gi = 0; gi < 5; gi++) {
                if (bloom_format_bpp(fmts[fi]) == 0)
                    continue;
                bloom_config_t c;
                bloom_config_default(&c, sizes[si][0], sizes[si][1]);
                c.in_fmt = fmts[fi];
                c.out_fmt = fmts[(fi + gi) % 4];
                if (bloom_format_bpp(c.out_fmt) == 0)
                    c.out_fmt = c.in_fmt;
                c.flags = flagsets[gi];
                c.levels = 1 + (si + gi) % 9;
                c.threshold = BLOOM_Q16(gi == 4 ? 0.0 : 0.3);
                c.soft_knee = BLOOM_Q16(gi == 1 ? 0.0 : 0.5);
                c.intensity = BLOOM_Q16(gi == 2 ? 10.0 : 1.5);
                frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(si * 31 + fi * 7 + gi));
                frame_t a = run_engine(&c, &src);
                bloom_config_t cc = c;
                cc.flags |= BLOOM_FLAG_NO_SIMD;
                frame_t b = run_engine(&cc, &src);
                cc.flags = c.flags | BLOOM_FLAG_NO_AVX2;
                frame_t b2 = run_engine(&cc, &src);
                frames++;
                if (!frame_equal(&a, &b) || !frame_equal(&b2, &b) || !frame_intact(&a) || !frame_intact(&b)) {
                    bad++;
                    fprintf(stderr, "frame %dx%d in %d out %d flags %u levels %d: SIMD differs\n", c.width,
                            c.height, (int)c.in_fmt, (int)c.out_fmt, (unsigned)c.flags, c.levels);
                }
                frame_free(&a);
                frame_free(&b);
                frame_free(&b2);
                frame_free(&src);
            }
    /* The worst case: every sample at the maximum, threshold 0, intensity 10. */
    if (BLOOM_USE_RGBQ16) {
        for (int lv = 5; lv <= 9; lv += 4) {
            bloom_config_t c;
            bloom_config_default(&c, 300, 260);
            c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
            c.levels = lv;
            c.threshold = 0;
            c.intensity = BLOOM_MAX_INTENSITY;
            c.flags = lv == 9 ? BLOOM_FLAG_DEBUG_VIEW : 0u;
            frame_t src = frame_alloc(c.width, c.height, c.in_fmt, (int)BLOOM_MAX_LINEAR);
            frame_t a = run_engine(&c, &src);
            bloom_config_t cc = c;
            cc.flags |= BLOOM_FLAG_NO_SIMD;
            frame_t b = run_engine(&cc, &src);
            frames++;
            if (!frame_equal(&a, &b)) {
                bad++;
                fprintf(stderr, "extreme frame, %d levels: SIMD differs\n", lv);
            }
            frame_free(&a);
            frame_free(&b);
            frame_free(&src);
        }
    }
    CHECKF(bad == 0, "%d of %d frames differ", bad, frames);
    printf("frames: %d configurations, SIMD and NO_SIMD %s\n", frames, bad ? "DIFFER" : "identical");
}

/* Every test of one SIMD kernel set against the C kernels. */
static void test_set(const bloom_kernels_t *ks, const bloom_kernels_t *kc)
{
    if (bloom_kernels_simd(ks))
        printf("SIMD kernels: %s (box, tent, composite, d1, box_src, vtent, htent_eo, scale) against C\n",
               ks->name);
    else
        printf("no SIMD kernels on this target (or BLOOM_NO_SIMD): comparing C with C\n");
    test_box(ks, kc);
    test_tent(ks, kc);
    test_composite(ks, kc);
    test_composite_formula(ks);
#if !BLOOM_SMALL
    test_flat(ks, kc);
    test_d1(ks, kc);
#endif
}

int main(void)
{
    bloom_kernels_t ks, k2, kc;
    bloom_kernels_select(&ks, 0);
    bloom_kernels_select(&k2, BLOOM_FLAG_NO_AVX2);
    bloom_kernels_select(&kc, BLOOM_FLAG_NO_SIMD);
    CHECK(!bloom_kernels_simd(&kc) && kc.box == bloom_row_box_c && kc.tent == bloom_row_tent_c);
    CHECK(strcmp(k2.name, "avx2") != 0);

    /* the flags are accepted; the next bit is not */
    bloom_config_t c;
    bloom_config_default(&c, 16, 16);
    c.flags = BLOOM_FLAG_NO_SIMD | BLOOM_FLAG_NO_AVX2;
    CHECK(bloom_query(&c, NULL) == BLOOM_OK);
    c.flags = BLOOM_FLAG_NO_AVX2 << 1;
    CHECK(bloom_query(&c, NULL) == BLOOM_E_FLAGS);

    test_set(&ks, &kc);
    if (strcmp(ks.name, k2.name) != 0)
        test_set(&k2, &kc);
    else if (strcmp(ks.name, "sse2") == 0) {
#if defined(BLOOM_SIMD_AVX2)
        SKIP("cpu without AVX2: the AVX2 kernels against C (SSE2 tested)");
#else
        SKIP("AVX2 kernels: compiled out (BLOOM_NO_AVX2=1; SSE2 tested)");
#endif
    }
    test_composite_formula(&kc);
    test_frames();
    return harness_finish();
}
