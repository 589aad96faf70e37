/* The dark-row test of every kernel set (kern.dark: bloom_row_dark and
 * its SSE2, AVX2 and NEON twins in src/kernels/) against the C test, which
 * the scheduler runs on every pushed source row (a row it calls dark makes
 * zeros without being computed, so a wrong "dark" would lose bloom).
 * Widths 1 .. 1921, each buffer at offsets 0 .. 3 bytes, RGB888 and
 * XRGB8888 (the X byte bright: it must not count) and RGB565 and RGBQ16
 * (passed to the C test): every byte at or below the dark code, then one
 * colour byte one above it at a random place, at the first and at the last
 * byte; dark codes 0, 254, 255 and random. The test that copies the row
 * as it reads it (kern.dark_copy, the frame call's dark rows) the same
 * way: its answer the C test's, a dark row copied whole, no byte written
 * outside the row. */
#include <string.h>

#include "bloom_kernels.h"
#include "harness.h"
#include "testutil.h"

#define NMAX 1921

#if !BLOOM_SMALL
static uint32_t seed = 4242u;

/* n pixels of fmt at p, every colour code at most c (X bytes 0xFF). */
static void fill_dark(uint8_t *p, int n, int bpp, uint32_t c)
{
    for (int i = 0; i < n * bpp; i++)
        p[i] = (uint8_t)(c == 0 ? 0u : rng_next(&seed) % (c + 1u));
    if (bpp == 4)
        for (int i = 0; i < n; i++)
            p[4 * i + 3] = 0xFF;
}

/* Index of colour byte k of the row (X bytes skipped). */
static int colour_byte(int k, int bpp)
{
    return bpp == 4 ? k / 3 * 4 + k % 3 : k;
}

/* k's dark test that copies (kern.dark_copy) on the n pixels at p: the
 * same answer as the C test, the row's bytes copied whole when dark, and
 * nothing written past the row either way. Returns 1 when it differs. */
static int copy_differs(const bloom_kernels_t *k, bloom_format_t fmt, const uint8_t *p, int n, int bpp,
                        const bloom_dark_t *d)
{
    static uint8_t out[12 * NMAX + 64];
    const size_t nb = (size_t)n * (size_t)bpp;
    memset(out, 0xA5, nb + 64);
    const bool dark = k->dark_copy(fmt, p, n, d, out + 1);
    if (dark != bloom_row_dark(fmt, p, n, d) || out[0] != 0xA5 || out[nb + 1] != 0xA5)
        return 1;
    return dark && memcmp(out + 1, p, nb) != 0;
}

static int check_set(const bloom_kernels_t *k)
{
    static uint8_t buf[12 * NMAX + 64];
    static const uint32_t codes[] = {0, 254, 255, 17, 100};
    const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565, BLOOM_FMT_RGBQ16,
                                   BLOOM_FMT_RGBF32};
    const int bpps[] = {3, 4, 2, 12, 12};
    int bad = 0;
    for (int f = 0; f < 5; f++)
        for (int n = 1; n <= NMAX; n++) {
            if (f >= 2 && n % 97 != 1) /* passed through: a few widths */
                continue;
            for (int off = 0; off < 4; off++) {
                uint8_t *p = buf + off;
                for (size_t ci = 0; ci < sizeof codes / sizeof codes[0]; ci++) {
                    /* (q16 holds a float's bits for RGBF32 input) */
                    bloom_dark_t d = {codes[ci], codes[ci] >> 2, codes[ci] >> 3,
                                      codes[ci] << (f == 4 ? 23 : 12)};
                    const int bpp = bpps[f], cb = bpp == 4 ? 3 * n : n * bpp;
                    fill_dark(p, n, bpp, d.c8);
                    bad += bloom_row_dark(fmts[f], p, n, &d) != k->dark(fmts[f], p, n, &d);
                    bad += copy_differs(k, fmts[f], p, n, bpp, &d);
                    if (d.c8 == 255 || f >= 2)
                        continue;
                    const int at[3] = {0, cb - 1, (int)(rng_next(&seed) % (uint32_t)cb)};
                    for (int a = 0; a < 3; a++) { /* one colour byte one above: not dark */
                        const int i = colour_byte(at[a], bpp);
                        const uint8_t keep = p[i];
                        p[i] = (uint8_t)(d.c8 + 1u);
                        bad += k->dark(fmts[f], p, n, &d) != false;
                        bad += copy_differs(k, fmts[f], p, n, bpp, &d);
                        p[i] = keep;
                    }
                }
            }
        }
    return bad;
}

static void run(const bloom_kernels_t *k)
{
    const int bad = check_set(k);
    CHECKF(bad == 0,
           "%s dark-row test (and the one that copies) = C over widths 1 .. %d, offsets 0 .. 3 (%d cases "
           "differ)",
           k->name, NMAX, bad);
    printf("%s: dark-row test and its copying twin bit-identical to C (bright bytes found, dark rows copied "
           "whole, nothing written past a row), widths 1 .. %d\n",
           k->name, NMAX);
}
#endif

int main(void)
{
#if BLOOM_SMALL
    SKIP("dark-row twins: BLOOM_SMALL builds have none (bloom_row_dark only)");
#else
    bloom_kernels_t ks, k2, kc;
    bloom_kernels_select(&ks, 0);
    bloom_kernels_select(&k2, BLOOM_FLAG_NO_AVX2);
    bloom_kernels_select(&kc, BLOOM_FLAG_NO_SIMD);
    CHECK(kc.dark == bloom_row_dark);
    run(&kc);
    if (bloom_kernels_simd(&ks))
        run(&ks);
    else
        SKIP("cpu without SIMD twins for the dark-row test (this target has none: C tested)");
    if (strcmp(ks.name, k2.name) != 0)
        run(&k2);
#endif
    return harness_finish();
}
