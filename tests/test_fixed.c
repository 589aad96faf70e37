/* Fixed-point helpers and pixel formats: the 64/32 division, the integer
 * sRGB curve for the intensity, the knee factor's formula, the quantized
 * parameters of every preset against the model's own computation, the
 * decode/encode tables against double. */
#include <math.h>
#include <string.h>

#include "bloom_kernels.h"
#include "bloom_model.h"
#include "harness.h"

static double s2l(double x)
{
    return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}

static double l2s(double x)
{
    return x <= 0.0031308 ? x * 12.92 : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

static void test_div(void)
{
    uint32_t s = 12345;
    int ok = 1;
    for (int i = 0; i < 200000; i++) {
        s ^= s << 13, s ^= s >> 17, s ^= s << 5;
        uint32_t d = s | 1u;
        s ^= s << 13, s ^= s >> 17, s ^= s << 5;
        uint32_t qwant = s >> (i % 32);
        uint64_t n = (uint64_t)qwant * d + (i & 1 ? d - 1 : (uint64_t)(s % d));
        ok &= bloom_div_u64_u32_loop(n, d) == (uint32_t)(n / d);
        ok &= bloom_div_u64_u32(n, d) == (uint32_t)(n / d);
    }
    CHECK(ok);
    CHECK(bloom_div_u64_u32_loop(0xFFFFFFFEull * 0xFFFFFFFFull + 0xFFFFFFFEull, 0xFFFFFFFFu) == 0xFFFFFFFEu);
    CHECK(bloom_div_u64_u32_loop(1ull << 40, 1u << 16) == 1u << 24);
}

/* srgb_to_linear_q16 is the correctly rounded curve for every input. */
static void test_intensity(void)
{
    int bad = 0, first = -1;
    double tie = 1.0;
    for (uint32_t i = 0; i <= BLOOM_MAX_INTENSITY; i++) {
        const double v = s2l(i / 65536.0) * 65536.0, want = floor(v + 0.5);
        tie = fmin(tie, fabs(v - floor(v) - 0.5));
        if ((double)bloom_srgb_to_linear_q16(i) != want && bad++ == 0)
            first = (int)i;
    }
    CHECKF(bad == 0, "%d intensities differ from round(srgb_to_linear(i) * 65536), first %d", bad, first);
    CHECK(bloom_srgb_to_linear_q16(0) == 0);
    CHECK(bloom_srgb_to_linear_q16(65536) == 65536);
    CHECK(bloom_srgb_to_linear_q16(BLOOM_MAX_INTENSITY) == 14668679u); /* 223.83 */
    printf(
        "srgb_to_linear_q16: correctly rounded for all %u intensities 0..10.0 (closest to a tie: %.2g LSB)\n",
        BLOOM_MAX_INTENSITY + 1, tie);
}

/* The knee of fixed-point.md step 3, written out here from the document in
 * 64-bit integers, against the row kernel, pixel by pixel: thresholds and
 * knees at their extremes, pixels on either side of every branch. */
static uint32_t knee_doc(uint32_t c, uint32_t bmax, uint64_t T, uint64_t K)
{
    const int64_t x0 = (int64_t)bmax - (int64_t)T + (int64_t)K;
    const int64_t x = x0 < 0 ? 0 : x0 > 2 * (int64_t)K ? 2 * (int64_t)K : x0;
    /* soft = x^2 / (4K + 0.00004) as 2x^2 / (8K + E8), E8 = round(0.00008 * 2^F) */
    const uint64_t e8 = ((1ull << (BLOOM_LIN_BITS + 3)) + 50000u) / 100000u, den = 8 * K + e8;
    const uint64_t soft = K == 0 ? 0 : (2 * (uint64_t)(x * x) + den / 2) / den;
    const int64_t over = (int64_t)bmax - (int64_t)T;
    const uint64_t num = over > (int64_t)soft ? (uint64_t)over : soft;
    if (num == 0 || bmax == 0)
        return 0;
    /* num / max(bmax, 0.00001), Q24 */
    const uint64_t f = (uint64_t)bmax * 100000u < (1ull << BLOOM_LIN_BITS)
                           ? num * (100000u << (24 - BLOOM_LIN_BITS))
                           : ((num << 24) + bmax / 2) / bmax;
    return (uint32_t)(((uint64_t)c * f + (1u << 23)) >> 24);
}

static void test_knee_formula(void)
{
    const uint32_t ts[] = {0, 1, 1000, 1u << 20, 3u << 19, 1u << 28}; /* Q12.20: 0 .. 256.0 */
    const uint32_t ss[] = {0, 1, 32768, 65535, 65536};
    uint32_t rng = 99;
    long n = 0, bad = 0, active = 0;
    for (size_t ti = 0; ti < sizeof ts / sizeof ts[0]; ti++)
        for (size_t si = 0; si < sizeof ss / sizeof ss[0]; si++) {
            bloom_knee_t kn = {ts[ti], (uint32_t)(((uint64_t)ts[ti] * ss[si] + 32768u) >> 16)};
            uint32_t row[3 * 256], in[3 * 256];
            for (int rep = 0; rep < 40; rep++) {
                for (int i = 0; i < 3 * 256; i++) {
                    rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
                    /* around the knee's edges, and anywhere up to the largest sample */
                    const uint32_t edge[5] = {kn.t - kn.k, kn.t, kn.t + kn.k, BLOOM_LIN_MAX, 0};
                    uint32_t v = rep & 1 ? rng % (BLOOM_LIN_MAX + 1u)
                                         : edge[rng % 5] + (rng >> 8) % 64u - 32u; /* 0 +- 32: tiny b */
                    in[i] = row[i] = v > BLOOM_LIN_MAX ? BLOOM_LIN_MAX : v;
                }
                bloom_row_knee_c(row, 256, &kn);
                for (int x = 0; x < 256; x++) {
                    const uint32_t *p = in + 3 * x;
                    const uint32_t bmax =
                        p[0] > p[1] ? (p[0] > p[2] ? p[0] : p[2]) : (p[1] > p[2] ? p[1] : p[2]);
                    for (int c = 0; c < 3; c++, n++) {
                        const uint32_t want = knee_doc(p[c], bmax, kn.t, kn.k);
                        active += want != 0;
                        bad += row[3 * x + c] != want;
                    }
                }
            }
        }
    CHECKF(bad == 0, "%ld of %ld knee outputs differ from fixed-point.md step 3", bad, n);
    CHECK(active > n / 4); /* the formula's active branches were reached, not only the zeroes */
    printf("knee: %ld samples equal to the formula of fixed-point.md step 3 (%ld non-zero)\n", n, active);
}

/* bloom_query's quantized threshold, knee and intensity equal the model's
 * own computation (bloom_model_quantize) for every preset, at the
 * parameter extremes and at odd values in between. */
static void test_quantized_params(void)
{
    const uint32_t ts[] = {0, 1, 0x8000, BLOOM_ONE, 0x1234567, BLOOM_MAX_THRESHOLD - 1, BLOOM_MAX_THRESHOLD};
    const uint32_t ks[] = {0, 1, 0x7FFF, 0x8000, 0xFFFF, BLOOM_ONE};
    const uint32_t is[] = {0, 1, 2650, 2651, 0x8000, BLOOM_ONE, 0x9A3C5, BLOOM_MAX_INTENSITY};
    int runs = 0, bad = 0;
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++) {
        if (!bloom_preset_available((bloom_preset_t)p))
            continue;
        for (size_t a = 0; a < sizeof ts / sizeof ts[0]; a++)
            for (size_t b = 0; b < sizeof ks / sizeof ks[0]; b++)
                for (size_t c = 0; c < sizeof is / sizeof is[0]; c++) {
                    bloom_config_t cfg;
                    bloom_config_default(&cfg, 64, 48);
                    bloom_config_preset(&cfg, (bloom_preset_t)p);
                    if (bloom_preset_params((bloom_preset_t)p) & BLOOM_PARAM_AUX)
                        cfg.aux_fmt = BLOOM_AUX_U8;
                    cfg.threshold = ts[a];
                    cfg.soft_knee = ks[b];
                    cfg.intensity = is[c];
                    if (p == BLOOM_PRESET_GAMEDEV)
                        cfg.p.strength = is[c] > (16u << 16) ? 16u << 16 : is[c];
                    bloom_info_t info;
                    if (bloom_query(&cfg, &info) != BLOOM_OK)
                        continue; /* a preset's own limits (xna: T < 1) */
                    uint32_t t, k, i;
                    bloom_model_quantize(&cfg, BLOOM_LIN_BITS, &t, &k, &i);
                    runs++;
                    if (t != info.threshold_q || k != info.knee_q || i != info.intensity_q) {
                        if (bad++ < 5)
                            fprintf(stderr, "preset %d t %u s %u i %u: engine %u %u %u, model %u %u %u\n", p,
                                    ts[a], ks[b], is[c], info.threshold_q, info.knee_q, info.intensity_q, t,
                                    k, i);
                    }
                }
    }
    CHECKF(bad == 0, "%d of %d configurations quantized differently by engine and model", bad, runs);
    CHECK(runs > 1000);
    printf("quantized parameters: engine = model in %d configurations (every preset, extremes)\n", runs);
}

/* Decode then encode gives back every code, in every format and curve. */
static void test_roundtrip(void)
{
    const bloom_format_t fmts[] = {BLOOM_FMT_RGB888, BLOOM_FMT_XRGB8888, BLOOM_FMT_RGB565};
    for (size_t f = 0; f < 3; f++)
        for (int lin = 0; lin <= 1; lin++) {
            int ok = 1;
            for (uint32_t v = 0; v < 65536; v += (fmts[f] == BLOOM_FMT_RGB565 ? 1 : 0x10101)) {
                uint8_t px[4] = {(uint8_t)v, (uint8_t)(v >> 8), (uint8_t)(v >> 16), 0xFF};
                uint8_t back[4] = {0, 0, 0, 0};
                uint32_t q[3];
                bloom_pixel_decode(fmts[f], lin, px, q);
                bloom_pixel_encode(fmts[f], lin, q, back);
                ok &= memcmp(px, back, (size_t)bloom_format_bpp(fmts[f])) == 0;
                if (fmts[f] != BLOOM_FMT_RGB565 && v == 0xFFFFFF)
                    break;
            }
            CHECKF(ok, "format %d linear %d", (int)fmts[f], lin);
        }
}

/* The tables are round(curve * 65536), and the encoder is round-half-up of
 * linear_to_srgb for every Q12.20 value up to 1.0 and beyond. */
static void test_tables(void)
{
    int ok = 1;
    for (int c = 0; c < 256; c++)
        ok &= bloom_srgb_dec8[c] == (uint32_t)floor(s2l(c / 255.0) * 1048576.0 + 0.5);
    for (int c = 0; c < 64; c++)
        ok &= bloom_srgb_dec6[c] == (uint32_t)floor(s2l(c / 63.0) * 1048576.0 + 0.5);
    CHECK(ok);
    ok = 1;
    int lin_ok = 1;
    for (uint32_t v = 0; v <= 1100000; v++) {
        uint32_t q[3] = {v, v, v};
        uint8_t px[3], p565[2];
        bloom_pixel_encode(BLOOM_FMT_RGB888, false, q, px);
        double e = v >= 1048576 ? 1.0 : l2s(v / 1048576.0);
        ok &= px[0] == (uint8_t)floor(e * 255.0 + 0.5);
        bloom_pixel_encode(BLOOM_FMT_RGB565, false, q, p565);
        uint32_t w = (uint32_t)p565[0] | ((uint32_t)p565[1] << 8);
        ok &= (w & 31u) == (uint32_t)floor(e * 31.0 + 0.5);
        ok &= ((w >> 5) & 63u) == (uint32_t)floor(e * 63.0 + 0.5);
        bloom_pixel_encode(BLOOM_FMT_RGB888, true, q, px);
        double l = v >= 1048576 ? 1.0 : v / 1048576.0;
        lin_ok &= px[0] == (uint8_t)floor(l * 255.0 + 0.5);
    }
    CHECK(ok);
    CHECK(lin_ok);
    /* RGBQ16 clamps at the largest linear value, both ways. */
    uint32_t big[3] = {0xFFFFFFFFu, BLOOM_MAX_LINEAR + 1u, 7u}, q[3];
    bloom_pixel_decode(BLOOM_FMT_RGBQ16, false, (const uint8_t *)big, q);
    CHECK(q[0] == BLOOM_LIN_MAX && q[1] == BLOOM_LIN_MAX && q[2] == 7u * 16u);
    uint32_t back[3];
    bloom_pixel_encode(BLOOM_FMT_RGBQ16, false, q, (uint8_t *)back);
    CHECK(back[0] == BLOOM_MAX_LINEAR && back[2] == 7u);
}

/* RGBF32 decode: the integer conversion of the float's bits against
 * double arithmetic (v * 2^F rounded half to even by rint, clamped), over
 * a stride through all 2^32 bit patterns, the ties k + 1/2 LSB (to even),
 * and the special values. */
static uint32_t f32_ref(float f)
{
    if (!(f > 0.0f))
        return 0;
    const double v = rint((double)f * (double)BLOOM_LIN_ONE);
    return v >= (double)BLOOM_LIN_MAX ? BLOOM_LIN_MAX : (uint32_t)v;
}
static uint32_t f32_dec(uint32_t bits)
{
    uint32_t w[3] = {bits, 0, 0}, q[3];
    bloom_pixel_decode(BLOOM_FMT_RGBF32, false, (const uint8_t *)w, q);
    return q[0];
}
static void test_f32_decode(void)
{
    long bad = 0, n = 0;
    for (uint64_t b = 0; b <= 0xFFFFFFFFu; b += 4093u, n++) {
        float f;
        const uint32_t bits = (uint32_t)b;
        memcpy(&f, &bits, 4);
        bad += f32_dec(bits) != f32_ref(f);
    }
    CHECKF(bad == 0, "%ld of %ld bit patterns decode unlike rint(v * 2^F)", bad, n);
    bad = 0;
    for (uint32_t k = 0; k < 4096; k++) { /* (k + 1/2) / 2^F: a tie, to the even neighbour */
        const float f = (float)((k + 0.5) / (double)BLOOM_LIN_ONE);
        uint32_t bits;
        memcpy(&bits, &f, 4);
        bad += f32_dec(bits) != k + (k & 1u);
    }
    CHECKF(bad == 0, "%ld ties not rounded to even", bad);
    const float sp[] = {-0.0f, -1.0f, 256.0f, 1e30f, 255.99998f, 1e-40f, 0x1p-21f, 0x1.000002p-21f, 1.0f};
    const uint32_t want[] = {0, 0, BLOOM_LIN_MAX, BLOOM_LIN_MAX, BLOOM_LIN_MAX, 0, 0, 1, BLOOM_LIN_ONE};
    for (size_t i = 0; i < sizeof sp / sizeof sp[0]; i++) {
        uint32_t bits;
        memcpy(&bits, &sp[i], 4);
        CHECKF(f32_dec(bits) == want[i], "%g decodes to %u, not %u", (double)sp[i], f32_dec(bits), want[i]);
    }
    CHECK(f32_dec(0x7F800000u) == BLOOM_LIN_MAX && f32_dec(0x7FC00000u) == 0 && f32_dec(0xFFC00000u) == 0);
    /* an input-only format: refused as the output, with the reason */
    bloom_config_t c;
    bloom_config_default(&c, 8, 8);
    c.in_fmt = BLOOM_FMT_RGBF32;
    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK);
    c.out_fmt = BLOOM_FMT_RGBF32;
    CHECK(bloom_query(&c, &info) == BLOOM_E_FORMAT);
}

int main(void)
{
    test_f32_decode();
    test_div();
    test_intensity();
    test_knee_formula();
    test_quantized_params();
    test_roundtrip();
    test_tables();
    return harness_finish();
}
