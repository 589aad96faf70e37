/* Extreme and stiff inputs, run under the sanitizers: the worst case of every
 * intermediate (sim/docs/fixed-point.md), saturated and black frames, a hot
 * pixel at the largest representable value, degenerate sizes. The bit-true
 * model computes in exact arithmetic, so an overflow in the core shows up as
 * a difference from it. */
#include "conform.h"
#include "harness.h"

static void expect_bittrue(const char *what, const bloom_config_t *c, const frame_t *src)
{
    conform_t r = conform_run(c, src);
    CHECKF(r.ok && r.bittrue_diff == 0, "%s: %lld samples differ from bit-true", what, r.bittrue_diff);
    printf("%-44s L%-2d vs float: peak %d, exact %.3f%%\n", what, c->levels, r.vs_float.peak,
           errstat_exact_pct(&r.vs_float));
}

/* Every sample at the largest value, threshold 0, intensity 10, as deep as
 * the frame allows: U_1 = L * M, the tent sums at their largest. */
static void test_worst_case(void)
{
    bloom_config_t c;
    bloom_config_default(&c, 1024, 1024);
    c.levels = 16;
    c.in_fmt = BLOOM_FMT_RGBQ16;
    c.out_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = 0;
    c.soft_knee = 0;
    c.intensity = BLOOM_MAX_INTENSITY;
    bloom_info_t info;
    CHECK(bloom_query(&c, &info) == BLOOM_OK && info.levels == 9);
    frame_t src = frame_q16_fill(c.width, c.height, BLOOM_MAX_LINEAR);
    expect_bittrue("all at max, threshold 0, intensity 10", &c, &src);
    c.flags = BLOOM_FLAG_DEBUG_VIEW;
    expect_bittrue("all at max, bloom-only view", &c, &src);
    /* The same with an intensity small enough that I*B, with B at its
     * largest (9 levels of 256.0 = 2304.0), stays below the output ceiling:
     * any overflow in the sums would now show, not saturate away. */
    c.intensity = BLOOM_Q16(0.3);
    expect_bittrue("all at max, B unclamped (intensity 0.3)", &c, &src);
    frame_t unclamped = run_engine(&c, &src);
    CHECK(frame_get_q16(&unclamped, 512, 512) < BLOOM_MAX_LINEAR);
    CHECK(frame_get_q16(&unclamped, 512, 512) > (150u << 16)); /* 0.0732 * 2304 = 168.7 */
    frame_free(&unclamped);
    c.intensity = BLOOM_MAX_INTENSITY;
    /* the bloom-only value: I * L * M, clamped at the largest output */
    frame_t out = run_engine(&c, &src);
    CHECK(frame_get_q16(&out, 0, 0) == BLOOM_MAX_LINEAR &&
          frame_get_q16(&out, 517, 1023) == BLOOM_MAX_LINEAR);
    frame_free(&out);
    frame_free(&src);

    /* Words above the range read as the largest value. */
    bloom_config_default(&c, 70, 40);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    c.threshold = BLOOM_Q16(2.0);
    frame_t a = frame_q16_fill(c.width, c.height, 0xFFFFFFFFu);
    frame_t b = frame_q16_fill(c.width, c.height, BLOOM_MAX_LINEAR);
    frame_t oa = run_engine(&c, &a), ob = run_engine(&c, &b);
    CHECK(frame_equal(&oa, &ob));
    expect_bittrue("words above 2^24 clamp", &c, &a);
    frame_free(&a);
    frame_free(&b);
    frame_free(&oa);
    frame_free(&ob);
}

/* One hot pixel at the largest representable value, every level count:
 * box and tent weights sum to 1, so while the glow stays clear of the frame
 * edges the bloom-only image sums to L times the knee's output: the 4 level-1
 * pixels hold M/16 each and keep M/16 - T, i.e. L * (M - 16 T) in all. */
static void test_hot_pixel(void)
{
    double last_sum = 0;
    for (int lv = 1; lv <= 16; lv++) {
        bloom_config_t c;
        bloom_config_default(&c, 300, 260);
        c.levels = lv;
        c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
        c.threshold = BLOOM_Q16(1.0);
        c.soft_knee = BLOOM_Q16(0.5);
        c.flags = BLOOM_FLAG_DEBUG_VIEW;
        frame_t src = frame_q16_fill(c.width, c.height, 0);
        frame_set_q16(&src, 150, 130, BLOOM_MAX_LINEAR);
        conform_t r = conform_run(&c, &src);
        CHECKF(r.ok && r.bittrue_diff == 0, "hot pixel L%d: %lld differ", lv, r.bittrue_diff);
        frame_t out = run_engine(&c, &src);
        double sum = 0;
        for (int y = 0; y < c.height; y++)
            for (int x = 0; x < c.width; x++)
                sum += frame_get_q16(&out, x, y);
        bloom_info_t info;
        bloom_query(&c, &info);
        double want = info.levels * (double)(BLOOM_MAX_LINEAR - 16u * (1u << 16));
        if (info.levels <= 6) /* deeper, the glow reaches the edges of 300x260 */
            CHECKF(sum > 0.99 * want && sum < 1.01 * want, "L%d: energy %.0f want %.0f", lv, sum, want);
        else
            CHECKF(sum <= want && sum >= last_sum, "L%d: energy %.0f, want <= %.0f, >= %.0f", lv, sum, want,
                   last_sum);
        last_sum = sum;
        if (lv == 1 || lv == 5 || lv == 16)
            printf("hot pixel at 256.0, L%-2d: glow energy %.5f of L*(M-16T); vs float peak %d LSB\n",
                   info.levels, sum / want, r.vs_float.peak);
        frame_free(&out);
        frame_free(&src);
    }
}

/* Black, saturated and clamped frames; parameters at their limits. */
static void test_saturation(void)
{
    const bloom_format_t outs[] = {BLOOM_FMT_RGB888, BLOOM_FMT_RGB565, BLOOM_FMT_XRGB8888};
    for (size_t oi = 0; oi < 3; oi++) {
        bloom_config_t c;
        bloom_config_default(&c, 97, 53);
        c.out_fmt = outs[oi];
        c.threshold = 0;
        c.intensity = BLOOM_MAX_INTENSITY;
        /* every output clamped: white out everywhere */
        frame_t src = frame_alloc(c.width, c.height, c.in_fmt, 200);
        frame_t out = run_engine(&c, &src);
        frame_t white = frame_alloc(c.width, c.height, c.out_fmt, 255);
        CHECK(frame_equal(&out, &white));
        expect_bittrue("every output clamped", &c, &src);
        frame_free(&white);
        frame_free(&out);
        frame_free(&src);
    }
    /* all black: nothing blooms, the output is the input */
    bloom_config_t c;
    bloom_config_default(&c, 64, 64);
    c.threshold = 0;
    frame_t black = frame_alloc(c.width, c.height, c.in_fmt, 0);
    frame_t out = run_engine(&c, &black);
    CHECK(frame_equal(&out, &black));
    frame_free(&out);
    frame_free(&black);

    /* parameters at their limits, random content */
    const struct {
        const char *name;
        uint32_t t, s, i;
    } lim[] = {{"threshold 0, knee 0", 0, 0, BLOOM_Q16(1.0)},
               {"threshold 0, knee 1", 0, BLOOM_ONE, BLOOM_Q16(1.0)},
               {"hard knee at 0.5", BLOOM_Q16(0.5), 0, BLOOM_Q16(1.0)},
               {"knee 1 at 0.5", BLOOM_Q16(0.5), BLOOM_ONE, BLOOM_Q16(1.0)},
               {"intensity 0", BLOOM_Q16(0.2), BLOOM_Q16(0.5), 0},
               {"intensity 10", BLOOM_Q16(0.2), BLOOM_Q16(0.5), BLOOM_MAX_INTENSITY},
               /* the knee starts at t - t*s: only a hard knee at 256 stops everything */
               {"threshold above every input, hard knee", BLOOM_MAX_THRESHOLD, 0, BLOOM_MAX_INTENSITY},
               {"threshold 256, knee 1 (knee reaches 0)", BLOOM_MAX_THRESHOLD, BLOOM_ONE, BLOOM_Q16(1.0)}};
    for (size_t li = 0; li < sizeof lim / sizeof lim[0]; li++)
        for (int q16 = 0; q16 <= 1; q16++) {
            bloom_config_default(&c, 120, 90);
            c.threshold = lim[li].t;
            c.soft_knee = lim[li].s;
            c.intensity = lim[li].i;
            c.in_fmt = q16 ? BLOOM_FMT_RGBQ16 : BLOOM_FMT_RGB888;
            frame_t src = frame_random(&c, c.in_fmt, 7u + (uint32_t)li);
            if (q16) /* HDR content up to the largest value */
                for (int k = 0; k < 40; k++)
                    frame_set_q16(&src, (k * 37) % c.width, (k * 53) % c.height, BLOOM_MAX_LINEAR);
            expect_bittrue(lim[li].name, &c, &src);
            if (lim[li].i == 0 || (lim[li].t == BLOOM_MAX_THRESHOLD && lim[li].s == 0)) {
                /* nothing added: the output is the input, Q16 words too */
                c.out_fmt = c.in_fmt;
                frame_t o = run_engine(&c, &src);
                CHECK(frame_equal(&o, &src));
                frame_free(&o);
            }
            frame_free(&src);
        }
}

/* Degenerate sizes with every level count. */
static void test_sizes(void)
{
    const int sizes[][2] = {{1, 1}, {1, 2},    {2, 1},    {1, 1000}, {1000, 1}, {2, 2},
                            {3, 3}, {2, 1500}, {1500, 2}, {4, 700},  {700, 4}};
    long long differ = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
        for (int lv = 1; lv <= 16; lv++) {
            bloom_config_t c;
            bloom_config_default(&c, sizes[si][0], sizes[si][1]);
            c.levels = lv;
            c.threshold = BLOOM_Q16(0.3);
            frame_t src = frame_random(&c, c.in_fmt, 3u + (uint32_t)si);
            conform_t r = conform_run(&c, &src);
            CHECK(r.ok);
            differ += r.bittrue_diff;
            frame_free(&src);
        }
    CHECKF(differ == 0, "%lld samples differ", differ);
    printf("degenerate sizes (1x1 .. 1500x2, L 1..16): %lld samples differ from bit-true\n", differ);
}

int main(void)
{
    test_worst_case();
    test_hot_pixel();
    test_saturation();
    test_sizes();
    return harness_finish();
}
