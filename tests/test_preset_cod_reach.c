/* The reach of the cod preset's L levels (sim/docs/presets/cod.md), and
 * bloom_levels_for_radius against it: the RMS radius of the bloom of a
 * point light, measured through the engine. COD_REACH_MAX=L prints deeper
 * pyramids too (their frames grow as 8 * 2^L). */
#include <math.h>
#include <stdlib.h>

#include "harness.h"
#include "imgframe.h"
#include "model_cod.h"
#include "preset_conform.h"

#if BLOOM_USE_COD
/* Reach of L levels (cod.md): the RMS radius sqrt(sum r^2 b / sum b) of the
 * bloom term b (debug view, RGBQ16 out) of a point light (256.0) at the
 * centre of an n x n black frame, n = max(64, 8 * 2^L), Bevy's NATURAL
 * weights with c_0 = 1 (c_0 only scales the bloom term; 1 keeps more of its
 * faint tail above the output's LSB). From L = 6 on the "point" is a square
 * of 2^(L-5) pixels (a point's deepest tail falls below the LSB). Rows are
 * pushed one at a time (one black row, one row with the point), so large
 * frames cost no memory. In tenths of a pixel. */
static int reach_of(int L)
{
    const int n = (8 << L) < 64 ? 64 : 8 << L, cx = n / 2, cy = n / 2, sq = L > 5 ? 1 << (L - 5) : 1;
    const double off = sq % 2 ? 0.0 : 0.5;
    bloom_config_t c;
    bloom_config_default(&c, n, n);
    c.in_fmt = c.out_fmt = BLOOM_FMT_RGBQ16;
    bloom_config_preset(&c, BLOOM_PRESET_COD);
    c.levels = L;
    bloom_cod_weights(&bloom_cod_natural, L, c.p.level_weight);
    c.p.level_weight[0] = BLOOM_ONE;
    c.flags |= BLOOM_FLAG_DEBUG_VIEW;
    engine_t e = engine_new(&c);
    uint32_t *black = (uint32_t *)calloc((size_t)n * 3u, 4), *point = (uint32_t *)calloc((size_t)n * 3u, 4),
             *row = (uint32_t *)calloc((size_t)n * 3u, 4);
    for (int x = cx - sq / 2; x < cx - sq / 2 + sq; x++)
        point[3 * x] = point[3 * x + 1] = point[3 * x + 2] = BLOOM_MAX_LINEAR;
    bloom_begin(e.b);
    int y_in = 0;
    double sum = 0.0, r2 = 0.0;
    while (bloom_rows_out(e.b) < n) {
        if (y_in < n &&
            bloom_push_row(e.b, y_in >= cy - sq / 2 && y_in < cy - sq / 2 + sq ? point : black) == BLOOM_OK) {
            y_in++;
            continue;
        }
        while (bloom_rows_out(e.b) < n) {
            const int y = bloom_rows_out(e.b);
            if (bloom_pull_row(e.b, row) != BLOOM_OK)
                break;
            const double dy = y - cy + off;
            for (int x = 0; x < n; x++) {
                const double dx = x - cx + off, b = row[3 * x];
                sum += b;
                r2 += b * (dx * dx + dy * dy);
            }
        }
    }
    free(black);
    free(point);
    free(row);
    engine_free(&e);
    return (int)floor(10.0 * sqrt(r2 / sum) + 0.5);
}

static void reach(void)
{
    const char *env = getenv("COD_REACH_MAX");
    const int lmax = env ? atoi(env) : 5;
    int r[11] = {0};
    for (int L = 1; L <= lmax && L <= 10; L++) {
        r[L] = reach_of(L);
        printf("cod reach: L = %2d: %6.1f px (RMS radius of the bloom of a point)\n", L, r[L] / 10.0);
    }
    static const int radii[] = {2, 4, 10, 20, 30};
    for (size_t i = 0; i < sizeof radii / sizeof radii[0]; i++) {
        const int L = bloom_levels_for_radius(radii[i]);
        const int got = L <= lmax ? r[L] : reach_of(L);
        printf("cod: bloom_levels_for_radius(%d) = %d, measured reach %.1f px\n", radii[i], L, got / 10.0);
        CHECKF(got * 2 >= radii[i] * 10 && got <= 2 * radii[i] * 10,
               "radius %d: L = %d reaches %.1f px (within 2x)", radii[i], L, got / 10.0);
    }
    CHECK(bloom_levels_for_radius(0) == 1 && bloom_levels_for_radius(-5) == 1);
    CHECK(bloom_levels_for_radius(1000000) == 10);
}
#endif

int main(void)
{
    /* bloom_levels_for_radius exists in every build */
    CHECK(bloom_levels_for_radius(1) >= 1);
#if BLOOM_USE_COD
    reach();
#else
    SKIP("cod preset: compiled out (BLOOM_USE_COD=0)");
#endif
    return harness_finish();
}
