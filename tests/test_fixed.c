/* Fixed-point helpers and pixel formats: the 64/32 division, the integer
 * sRGB curve for the intensity, the decode/encode tables against double. */
#include <math.h>
#include <string.h>

#include "bloom_internal.h"
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
    CHECK(bloom_div_u64_u32_loop(0xFFFFFFFEull * 0xFFFFFFFFull + 0xFFFFFFFEull, 0xFFFFFFFFu) ==
          0xFFFFFFFEu);
    CHECK(bloom_div_u64_u32_loop(1ull << 40, 1u << 16) == 1u << 24);
}

/* srgb_to_linear_q16 within 1 LSB of the double curve for every input. */
static void test_intensity(void)
{
    int worst = 0;
    for (uint32_t i = 0; i <= BLOOM_MAX_INTENSITY; i++) {
        double want = floor(s2l(i / 65536.0) * 65536.0 + 0.5);
        int d = (int)((double)bloom_srgb_to_linear_q16(i) - want);
        if (d < 0)
            d = -d;
        if (d > worst)
            worst = d;
    }
    CHECKF(worst <= 1, "worst %d LSB", worst);
    CHECK(bloom_srgb_to_linear_q16(0) == 0);
    CHECK(bloom_srgb_to_linear_q16(65536) == 65536);
    printf("srgb_to_linear_q16: worst error %d LSB over 0..10.0\n", worst);
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

int main(void)
{
    test_div();
    test_intensity();
    test_roundtrip();
    test_tables();
    return harness_finish();
}
