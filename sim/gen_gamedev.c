/* Generator of src/presets/bloom_preset_gamedev_tables.c: the output thresholds of
 * the gamedev preset (sim/docs/presets/gamedev.md, "Output").
 *
 * The preset's output code of a composite c (linear, Q12.20 integer) is
 *   gamma:  k = floor((c / (c + 1))^(1/2.2) * n + 1/2), clamped to 0 .. n
 *   linear: k = floor( c / (c + 1)          * n + 1/2)  (BLOOM_FLAG_LINEAR)
 * (Reinhard, then gamma 1/2.2 or none). Both are monotone in c, so the code
 * is the number of thresholds T[1..n] with c >= T[k], T[k] the smallest
 * integer c whose code is at least k. This program prints T for n = 255,
 * 63, 31 in Q12.20 (T[0] = 0 heads each table, T[n+1] = 2^32 - 1 ends it).
 * For speed (not in BLOOM_SMALL builds) a bucket table per T: v's bucket
 * key is v itself below 64, else 64 + 32 (e - 6) + the 5 bits after the
 * leading one (e = its position), 896 buckets; the bucket holds the code
 * of its smallest v, and the generator checks that no bucket holds more
 * than two thresholds above that, so two compares finish the search. For F < 20 fraction bits the
 * core compares c << (20 - F) with the same table, exact because
 * ceil(ceil(x) / m) = ceil(x / m).
 *
 * Checks (exit 1 on failure): at every threshold and every F = 16..20 the
 * double formula of the bit-true model (sim/model/model_gamedev.c) gives k at T
 * and k - 1 just below; the exact linear thresholds agree with the formula.
 *
 *   make gamedev-tables        regenerate
 *   make check-gamedev-tables  fail if the committed file is stale */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* The bit-true model's formula (sim/model/model_gamedev.c), c an integer in a
 * double, one = 2^F. */
static double code_of(double c, double one, int n, int linear)
{
    const double r = c / (c + one);
    const double e = floor((linear ? r : pow(r, 1.0 / 2.2)) * n + 0.5);
    return e > n ? n : e;
}

static int failures;

#define NKEYS 896

/* The core's bucket key (src/presets/bloom_preset_gamedev.c) and its inverse. */
static uint32_t key_of(uint32_t v)
{
    if (v < 64)
        return v;
    int e = 31;
    while (!(v >> e))
        e--;
    return 64u + 32u * (uint32_t)(e - 6) + ((v >> (e - 5)) & 31u);
}
static uint64_t key_lo(uint32_t key)
{
    if (key < 64)
        return key;
    const uint32_t e = 6 + (key - 64) / 32, m = (key - 64) % 32;
    return (uint64_t)(32 + m) << (e - 5);
}

static void table(const char *name, int n, int linear)
{
    const double one = 1048576.0;
    uint32_t t[257];
    t[0] = 0;
    for (int k = 1; k <= n; k++) {
        double c;
        if (linear) {
            /* c / (c + 1) >= (k - 1/2) / n  <=>  c >= (2k - 1) / (2n - 2k + 1), exactly */
            const uint64_t num = (uint64_t)(2 * k - 1) << 20, den = (uint64_t)(2 * n - 2 * k + 1);
            c = (double)((num + den - 1) / den);
        } else {
            const double y = pow((k - 0.5) / n, 2.2);
            c = ceil(y / (1.0 - y) * one);
            while (c > 0 && code_of(c - 1, one, n, 0) >= k)
                c -= 1;
            while (code_of(c, one, n, 0) < k)
                c += 1;
        }
        if (c >= 4294967296.0) {
            fprintf(stderr, "gen_gamedev: %s[%d] does not fit in 32 bits\n", name, k);
            failures++;
        }
        t[k] = (uint32_t)c;
        for (int f = 16; f <= 20; f++) { /* the table as the core uses it at F bits */
            const uint32_t m = 1u << (20 - f);
            const double tf = (double)((t[k] + m - 1) / m), onef = ldexp(1.0, f);
            if (code_of(tf, onef, n, linear) < k || (tf > 0 && code_of(tf - 1, onef, n, linear) >= k)) {
                fprintf(stderr, "gen_gamedev: %s[%d] inconsistent at F = %d\n", name, k, f);
                failures++;
            }
        }
        if (k > 1 && t[k] <= t[k - 1]) {
            fprintf(stderr, "gen_gamedev: %s not increasing at %d\n", name, k);
            failures++;
        }
    }
    t[n + 1] = 0xFFFFFFFFu;
    printf("const uint32_t %s[%d] = {", name, n + 2);
    for (int k = 0; k <= n + 1; k++)
        printf("%s%u%s", k % 8 ? " " : "\n    ", t[k], k < n + 1 ? "," : "");
    printf("\n};\n");
    /* buckets */
    printf("#if !BLOOM_SMALL\nconst uint8_t %s_bk[%d] = {", name, NKEYS);
    for (uint32_t key = 0; key < NKEYS; key++) {
        const uint64_t lo = key_lo(key), hi = key + 1 < NKEYS ? key_lo(key + 1) - 1 : 0xFFFFFFFFu;
        if (key_of((uint32_t)lo) != key || key_of((uint32_t)hi) != key) {
            fprintf(stderr, "gen_gamedev: bucket %u bounds wrong\n", key);
            failures++;
        }
        int k = 0, inside = 0;
        while (k < n && t[k + 1] <= lo)
            k++;
        for (int j = k + 1; j <= n; j++)
            inside += t[j] > lo && t[j] <= hi;
        if (inside > 2) {
            fprintf(stderr, "gen_gamedev: %s bucket %u holds %d thresholds\n", name, key, inside);
            failures++;
        }
        printf("%s%d%s", key % 16 ? " " : "\n    ", k, key + 1 < NKEYS ? "," : "");
    }
    printf("\n};\n#endif\n");
}

int main(void)
{
    printf("/* Generated by sim/gen_gamedev.c (make gamedev-tables): do not edit.\n"
           " * Output thresholds of the gamedev preset, Q12.20: code k of n is the\n"
           " * number of T[1..n] at or below the composite c (Reinhard, then gamma\n"
           " * 1/2.2, or linear). sim/docs/presets/gamedev.md, \"Output\". */\n"
           "/* clang-format off */\n"
           "#include \"bloom_preset_gamedev.h\"\n\n#if BLOOM_USE_GAMEDEV\n\n");
    table("bloom_gd_gamma8", 255, 0);
    table("bloom_gd_gamma6", 63, 0);
    table("bloom_gd_gamma5", 31, 0);
    table("bloom_gd_lin8", 255, 1);
    table("bloom_gd_lin6", 63, 1);
    table("bloom_gd_lin5", 31, 1);
    printf("\n#else\ntypedef int bloom_preset_gamedev_tables_unused_t;\n#endif\n");
    if (failures) {
        fprintf(stderr, "gen_gamedev: %d failures\n", failures);
        return 1;
    }
    return 0;
}
