/* The gamedev preset's SIMD twins (bloom_preset_gamedev_{sse2,avx2,neon}.c)
 * against its C kernels, bit for bit: the Gaussian's vertical and horizontal
 * passes and the 8-bit tone curve at every width 1 .. 64 and 1900 .. 1921
 * and random widths between, unaligned pointers, random, extreme and any
 * 32-bit inputs; then whole frames with and without BLOOM_FLAG_NO_SIMD and
 * BLOOM_FLAG_NO_SKIP (dark bands: the zero-row shortcuts and the output's
 * per-code table), and a workspace reused by a second configuration. On a
 * target without twins it compares the C kernels with themselves (and says
 * so). sim/docs/presets/gamedev.md, "Kernels". */
#include "bloom_kernels.h"
#include "bloom_preset_gamedev_k.h"
#include "harness.h"
#include "testutil.h"

#if BLOOM_USE_GAMEDEV
#define GUARD 8u
#define GUARD_WORD 0xA5A5A5A5u
#define SMAX ((1u << 28) - 16u) /* largest linear sample */

static uint32_t seed = 271828u;

/* The widths: 1 .. 64, 1900 .. 1921 and 40 random ones in between. */
static int width_at(int i)
{
    if (i < 64)
        return i + 1;
    if (i < 86)
        return 1900 + (i - 64);
    return 65 + (int)(rng_next(&seed) % 1835u);
}
#define NW 126

/* mode 0: random up to SMAX; 1: all SMAX; 2: 0 / SMAX / SMAX - small /
 * small; 3: any 32-bit value (the sums wrap the same way). */
static uint32_t sample(int mode)
{
    const uint32_t r = rng_next(&seed);
    switch (mode) {
    case 0:
        return r % (SMAX + 1u);
    case 1:
        return SMAX;
    case 2: {
        const uint32_t k = r & 3u;
        return k == 0 ? 0u : k == 1 ? SMAX : k == 2 ? SMAX - (r >> 28) : (r >> 8) & 15u;
    }
    default:
        return r;
    }
}

/* n words at `off` words into a fresh block of off + n + GUARD: reads past
 * the end hit the sanitizer, writes past it the guard. */
static uint32_t *words(size_t n, int off, uint32_t **base)
{
    *base = (uint32_t *)xmalloc(((size_t)off + n + GUARD) * sizeof(uint32_t));
    for (size_t i = 0; i < (size_t)off + n + GUARD; i++)
        (*base)[i] = GUARD_WORD;
    return *base + off;
}

static int guard_ok(const uint32_t *p, size_t n)
{
    for (size_t i = 0; i < GUARD; i++)
        if (p[n + i] != GUARD_WORD)
            return 0;
    return 1;
}

static void test_gauss(const gd_kern_t *k, const gd_kern_t *kc)
{
    int bad_v = 0, bad_h = 0, bad_row = 0, runs = 0;
    for (int wi = 0; wi < NW; wi++) {
        const int w = width_at(wi), m = 3 * w;
        for (int mode = 0; mode < 4; mode++) {
            const int off = (wi + mode) % 8; /* word offsets 0 .. 7: every 32-byte alignment */
            uint32_t *rb[9], *rows[9], *b1, *b2, *b3, *b4;
            for (int j = 0; j < 9; j++) {
                rows[j] = words((size_t)m, (off + j) % 8, &rb[j]);
                for (int i = 0; i < m; i++)
                    rows[j][i] = sample(mode);
            }
            uint32_t *d1 = words((size_t)m, off, &b1), *d2 = words((size_t)m, (off + 3) % 8, &b2);
            uint32_t *h1 = words((size_t)m, (off + 5) % 8, &b3), *h2 = words((size_t)m, (off + 1) % 8, &b4);
            const uint32_t *const a[9] = {rows[0], rows[1], rows[2], rows[3], rows[4],
                                          rows[5], rows[6], rows[7], rows[8]};
            kc->gauss_v(a, d1, m);
            k->gauss_v(a, d2, m);
            bad_v += memcmp(d1, d2, (size_t)m * 4u) != 0 || !guard_ok(d2, (size_t)m);
            /* the interior kernel on every range the row allows, then whole rows */
            if (w > 8) {
                const int i0 = 12 + (int)(rng_next(&seed) % 4u), i1 = m - 12 - (int)(rng_next(&seed) % 4u);
                memset(h1, 0, (size_t)m * 4u);
                memset(h2, 0, (size_t)m * 4u);
                if (i1 > i0) {
                    kc->gauss_h(rows[0], h1, i0, i1);
                    k->gauss_h(rows[0], h2, i0, i1);
                }
                bad_h += memcmp(h1, h2, (size_t)m * 4u) != 0 || !guard_ok(h2, (size_t)m);
            }
            gd_gauss_h_row(kc, rows[1], h1, w);
            gd_gauss_h_row(k, rows[1], h2, w);
            bad_row += memcmp(h1, h2, (size_t)m * 4u) != 0 || !guard_ok(h2, (size_t)m);
            runs++;
            for (int j = 0; j < 9; j++)
                free(rb[j]);
            free(b1);
            free(b2);
            free(b3);
            free(b4);
        }
    }
    CHECKF(bad_v == 0, "gamedev %s gauss_v = C over %d rows (%d differ)", k->name, runs, bad_v);
    CHECKF(bad_h == 0, "gamedev %s gauss_h = C, interior ranges (%d differ)", k->name, bad_h);
    CHECKF(bad_row == 0, "gamedev %s gauss_h = C, whole rows with edges (%d differ)", k->name, bad_row);
}

#if !BLOOM_SMALL
/* The tone curve: bloom up to 2^32 - 1, strengths 0 .. 2^20, decoded
 * samples up to SMAX or sRGB codes decoded on the fly, both tables; the
 * output to its own row and in place over the bloom row. */
static void test_tone(const gd_kern_t *k, const gd_kern_t *kc)
{
    static const uint32_t strengths[] = {0, 1, 65536, 98304, 1u << 18, 1u << 20};
    int bad = 0, bad_alias = 0, runs = 0;
    for (int wi = 0; wi < NW; wi++) {
        const int n = 3 * width_at(wi);
        for (int mode = 0; mode < 4; mode++) {
            const int off = (wi + 2 * mode) % 8;
            const bool codes = (wi + mode) & 1, lin = (wi >> 1) & 1;
            const uint32_t s = strengths[(wi + mode) % 6];
            uint32_t *bb, *sb, *ab, *o1b, *o2b;
            uint32_t *bl = words((size_t)n, off, &bb), *sv = words((size_t)n, (off + 3) % 8, &sb);
            uint32_t *al = words((size_t)n, (off + 1) % 8, &ab);
            uint32_t *o1 = words((size_t)n / 4u + 1u, 0, &o1b), *o2 = words((size_t)n / 4u + 1u, 0, &o2b);
            uint8_t *sc = (uint8_t *)xmalloc((size_t)n + 1u);
            for (int i = 0; i < n; i++) {
                /* mode 3: any bloom word; else samples by mode, scaled down
                 * now and then to the codes' small end */
                const uint32_t r = rng_next(&seed);
                bl[i] = mode == 3 ? r : sample(mode) >> (r % 3u == 0 ? r % 29u : 0u);
                sv[i] = sample(mode == 3 ? 0 : mode) >> (r % 5u == 0 ? (r >> 8) % 29u : 0u);
                sc[i + 1] = (uint8_t)(r >> 24);
            }
            const uint32_t *t = lin ? bloom_gd_lin8 : bloom_gd_gamma8;
            const uint8_t *bk = lin ? bloom_gd_lin8_bk : bloom_gd_gamma8_bk;
            const uint8_t *scp = codes ? sc + 1 : NULL; /* odd address */
            uint8_t *c1 = (uint8_t *)o1 + (off & 3), *c2 = (uint8_t *)o2 + (off & 3);
            kc->tone8(bl, codes ? NULL : sv, scp, bloom_srgb_dec8, c1, n, s, t, bk);
            k->tone8(bl, codes ? NULL : sv, scp, bloom_srgb_dec8, c2, n, s, t, bk);
            bad += memcmp(c1, c2, (size_t)n) != 0;
            memcpy(al, bl, (size_t)n * 4u);
            k->tone8(al, codes ? NULL : sv, scp, bloom_srgb_dec8, (uint8_t *)al, n, s, t, bk);
            bad_alias += memcmp(c1, al, (size_t)n) != 0 || !guard_ok(al, (size_t)n);
            runs++;
            free(bb);
            free(sb);
            free(ab);
            free(o1b);
            free(o2b);
            free(sc);
        }
    }
    CHECKF(bad == 0, "gamedev %s tone8 = C over %d rows (%d differ)", k->name, runs, bad);
    CHECKF(bad_alias == 0, "gamedev %s tone8 in place over the bloom row = C (%d differ)", k->name,
           bad_alias);
}
#endif

/* The byte table of the rows without bloom: random tables, every byte
 * offset, to a row of its own and in place; runs of codes below 64, below
 * 128 and of any code (the twins' shortcuts for dark chunks). */
static void test_lut(const gd_kern_t *k, const gd_kern_t *kc)
{
    uint8_t tab[256];
    int bad = 0;
    for (int wi = 0; wi < NW; wi++) {
        const int n = 3 * width_at(wi), off = wi % 32;
        for (int i = 0; i < 256; i++)
            tab[i] = (uint8_t)(wi & 1 ? (uint32_t)i : rng_next(&seed) & 255u);
        uint8_t *s = (uint8_t *)xmalloc((size_t)n + 32u), *d1 = (uint8_t *)xmalloc((size_t)n + 32u + GUARD);
        uint8_t *d2 = (uint8_t *)xmalloc((size_t)n + 32u + GUARD);
        static const uint32_t masks[3] = {0x3F, 0x7F, 0xFF};
        for (int i = 0; i < n + 32; i++)
            s[i] = (uint8_t)(rng_next(&seed) & masks[(i / 29 + wi) % 3]);
        memset(d1, 0x5A, (size_t)n + 32u + GUARD);
        memset(d2, 0x5A, (size_t)n + 32u + GUARD);
        kc->lut8(s + off, tab, d1 + (31 - off), n);
        k->lut8(s + off, tab, d2 + (31 - off), n);
        bad += memcmp(d1, d2, (size_t)n + 32u + GUARD) != 0;
        k->lut8(s + off, tab, s + off, n); /* in place */
        bad += memcmp(s + off, d1 + (31 - off), (size_t)n) != 0;
        free(s);
        free(d1);
        free(d2);
    }
    CHECKF(bad == 0, "gamedev %s lut8 = C, in place too (%d differ)", k->name, bad);
}

/* Whole frames: the default kernels and skipping against C-only without
 * skipping, on frames with dark bands (rows and blocks below the
 * threshold, bright rows, bright spots). */
static void test_frames(void)
{
    static const int sizes[][2] = {{1, 1}, {5, 9}, {17, 40}, {80, 60}, {97, 131}, {333, 70}};
    static const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565,
                                          BLOOM_FMT_RGBQ16};
    static const uint32_t flags[] = {0, BLOOM_FLAG_LINEAR, BLOOM_FLAG_DEBUG_VIEW, BLOOM_FLAG_COPY_SOURCE};
    int differ = 0, runs = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
        for (int f = 0; f < 16; f++) {
            bloom_config_t c;
            bloom_config_default(&c, sizes[si][0], sizes[si][1]);
            bloom_config_preset(&c, BLOOM_PRESET_GAMEDEV);
            c.in_fmt = fmts[f / 4];
            c.out_fmt = fmts[f % 4];
            c.flags = flags[(si + (size_t)f) % 4];
            c.threshold = (si + (size_t)f) % 5 == 0 ? BLOOM_Q16(0.1) : BLOOM_Q16(0.75);
            c.p.strength = f % 3 == 0 ? (16u << 16) : BLOOM_ONE;
            frame_t src = frame_random(&c, c.in_fmt, (uint32_t)(si * 16 + (size_t)f + 1));
            /* dark bands: two thirds of the rows (in bands of 7) black or
             * dim, and a third of those dim rows with one bright pixel */
            for (int y = 0; y < c.height; y++) {
                uint8_t *row = src.p + (size_t)y * src.stride;
                if ((y / 7) % 3 == 2)
                    continue;
                for (size_t i = 0; i < (size_t)c.width * (size_t)src.bpp; i++)
                    row[i] = c.in_fmt == BLOOM_FMT_RGBQ16
                                 ? (uint8_t)(i % 4u == 1u ? rng_next(&seed) & 15u : 0u)
                                 : (uint8_t)((y / 7) % 3 ? rng_next(&seed) & 31u : 0u);
                if (y % 3 == 0 && (y / 7) % 3 == 1)
                    memset(row + (size_t)((y * 7) % c.width) * (size_t)src.bpp, 0x7F, (size_t)src.bpp);
            }
            frame_t a = run_engine(&c, &src);
            c.flags |= BLOOM_FLAG_NO_SIMD | BLOOM_FLAG_NO_SKIP;
            frame_t b = run_engine(&c, &src);
            c.flags &= ~BLOOM_FLAG_NO_SKIP;
            frame_t d = run_engine(&c, &src);
            differ += !frame_equal(&a, &b) + !frame_equal(&d, &b);
            runs += 2;
            frame_free(&a);
            frame_free(&b);
            frame_free(&d);
            frame_free(&src);
        }
    CHECKF(differ == 0, "gamedev frames: SIMD and skipping = C-only without skipping (%d of %d differ)",
           differ, runs);
}

/* One workspace, two configurations (linear, then gamma output): the
 * second engine's output equals a fresh one's (the output's per-code table
 * in the scratch row is never taken from an earlier engine or frame). The
 * first rows bloom (the second engine's row 0 decodes on the fly and does
 * not write the table's row), the rest of the frame is dim: its rows have
 * no bloom and use the table. */
static void test_reused_workspace(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 300, 200);
    bloom_config_preset(&c, BLOOM_PRESET_GAMEDEV);
    frame_t src = frame_alloc(300, 200, c.in_fmt, 0);
    for (size_t i = 0; i < src.stride * 200u; i++)
        src.p[i] = (uint8_t)(i < src.stride * 4u ? 255u : rng_next(&seed) % 90u);
    c.flags = BLOOM_FLAG_LINEAR;
    const size_t n = bloom_workspace_size(&c);
    guarded_t ws = guarded_alloc(n);
    frame_t out = frame_alloc(300, 200, c.out_fmt, 0), lin = frame_alloc(300, 200, c.out_fmt, 0);
    bloom_t *b;
    CHECK(bloom_init(&b, ws.p, n, &c) == BLOOM_OK);
    CHECK(bloom_process(b, src.p, (ptrdiff_t)src.stride, lin.p, (ptrdiff_t)lin.stride) == BLOOM_OK);
    c.flags = 0;
    CHECK(bloom_workspace_size(&c) <= n && bloom_init(&b, ws.p, n, &c) == BLOOM_OK);
    CHECK(bloom_process(b, src.p, (ptrdiff_t)src.stride, out.p, (ptrdiff_t)out.stride) == BLOOM_OK);
    frame_t fresh = run_engine(&c, &src);
    CHECKF(frame_equal(&out, &fresh) && !frame_equal(&out, &lin),
           "gamedev: a reused workspace gives a fresh engine's output");
    frame_free(&fresh);
    frame_free(&out);
    frame_free(&lin);
    frame_free(&src);
    guarded_free(&ws);
}

static void test_set(const gd_kern_t *k, const gd_kern_t *kc)
{
    test_gauss(k, kc);
    test_lut(k, kc);
#if !BLOOM_SMALL
    test_tone(k, kc);
#endif
}
#endif

int main(void)
{
#if BLOOM_USE_GAMEDEV
    bloom_kernels_t ks, k2;
    bloom_kernels_select(&ks, 0);
    bloom_kernels_select(&k2, BLOOM_FLAG_NO_AVX2);
    const gd_kern_t *kc = gd_kern_for(BLOOM_ISA_C), *g1 = gd_kern_for(ks.isa), *g2 = gd_kern_for(k2.isa);
    CHECK(gd_kern_for(BLOOM_ISA_C)->gauss_v == gd_gauss_v_c);
    if (g1 == kc)
        SKIP("cpu without SIMD twins for gamedev (%s): the C kernels against themselves", ks.name);
    test_set(g1, kc);
    if (g2 != g1 && g2 != kc)
        test_set(g2, kc);
    printf("gamedev twins tested: %s%s%s\n", g1->name, g2 != g1 && g2 != kc ? ", " : "",
           g2 != g1 && g2 != kc ? g2->name : "");
    test_frames();
    test_reused_workspace();
#else
    SKIP("gamedev preset: compiled out (BLOOM_USE_GAMEDEV=0)");
#endif
    return harness_finish();
}
