/* Model of the xna preset (sim/docs/presets/xna.md): the XNA Bloom sample
 * with Kawase passes, full frame.
 *
 * Float mode: the maths in double precision with the parameters as the real
 * values they stand for (t = threshold / 2^16, I = srgb_to_linear(i)); the
 * working range [0, LIN_MAX] is enforced where the engine enforces it.
 * Bit-true mode: every integer rounding of src/presets/bloom_preset_xna.c, written
 * out per pixel (integers held in doubles, uint64_t where a product can
 * pass 2^53). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"

#if BLOOM_USE_XNA

typedef struct {
    int bt;
    double one;     /* 1.0 in model units: 2^F (bit-true) or 1.0 */
    double lin_max; /* the working range's top: (2^24 - 1) 2^(F-16), or its real value */
} xna_units_t;

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static double *pix(const bloom_model_image_t *im, int x, int y)
{
    return im->px + ((size_t)y * (size_t)im->w + (size_t)x) * 3;
}

static double at(const bloom_model_image_t *im, int x, int y, int c)
{
    return pix(im, clampi(x, 0, im->w - 1), clampi(y, 0, im->h - 1))[c];
}

/* Kawase pass i of src into dst (same size): per axis pixels x-i-1, x-i,
 * x+i, x+i+1 (edge rule), weight 1/16 in all; scaled by f on the first pass
 * and by I on the last; optionally clamped to 1.0. */
static int kawase(const xna_units_t *u, const bloom_model_image_t *src, bloom_model_image_t *dst, int i,
                  int first, int last, int sat, uint64_t f_q, double f_real, uint32_t I_q, double I_real,
                  double widen, double one)
{
    dst->w = src->w;
    dst->h = src->h;
    dst->px = calloc((size_t)src->w * (size_t)src->h * 3u, sizeof(double));
    if (!dst->px)
        return -1;
    const int off[4] = {-i - 1, -i, i, i + 1};
    for (int y = 0; y < src->h; y++)
        for (int x = 0; x < src->w; x++)
            for (int c = 0; c < 3; c++) {
                double sum = 0.0;
                for (int a = 0; a < 4; a++)
                    for (int b = 0; b < 4; b++)
                        sum += at(src, x + off[b], y + off[a], c);
                sum *= widen; /* 16-bit samples: the last pass's sums in internal units */
                double v;
                if (u->bt) {
                    if (first &&
                        f_q !=
                            1u << 24) { /* sum f / 2^28 split at bit 16 (f Q24); f = 1: as the other passes */
                        const uint64_t sh = (uint64_t)sum >> 16, sl = (uint64_t)sum & 0xFFFFu;
                        const uint64_t p = (sh * f_q + ((sl * f_q) >> 16) + (1u << 11)) >> 12;
                        v = p > (uint64_t)u->lin_max ? u->lin_max : (double)p;
                    } else {
                        { /* sum / 16, half to even */
                            const double q = bloom_model_fdiv(sum, 16.0), r = sum - 16.0 * q;
                            v = q + (r > 8.0 || (r == 8.0 && fmod(q, 2.0) == 1.0));
                        }
                    }
                    if (last) {
                        const uint64_t p = ((uint64_t)v * I_q + 32768u) >> 16;
                        v = p > (uint64_t)u->lin_max ? u->lin_max : (double)p;
                    }
                } else {
                    v = sum / 16.0;
                    if (first)
                        v = fmin(v * f_real, u->lin_max);
                    if (last)
                        v = fmin(v * I_real, u->lin_max);
                }
                if (sat)
                    v = fmin(v, one);
                pix(dst, x, y)[c] = v;
            }
    return 0;
}

int bloom_model_xna(const bloom_model_preset_args_t *a)
{
    bloom_model_params_t p;
    if (bloom_model_params_from(a, &p) || a->cfg->preset != BLOOM_PRESET_XNA || !a->src)
        return -1;
    const bloom_config_t *c = a->cfg;
    const int w = c->width, h = c->height, P = c->p.passes, sat = (c->flags & BLOOM_FLAG_SATURATE) != 0;
    const int F = p.lin_bits;
    xna_units_t u;
    u.bt = a->bittrue != 0;
    u.one = u.bt ? ldexp(1.0, F) : 1.0;
    u.lin_max = u.bt ? (double)((1u << 24) - 1u) * ldexp(1.0, F - 16) : ((1u << 24) - 1u) / 65536.0;
    const double t = u.bt ? (double)p.threshold_q : c->threshold / 65536.0;
    /* range restore: f = round(2^40 / (2^16 - threshold)) in Q24 (bit-true), 1 / (1 - t) (float) */
    const uint64_t d = 65536u - c->threshold;
    const uint64_t f_q = ((1ull << 40) + d / 2u) / d;
    const double f_real = 1.0 / (1.0 - c->threshold / 65536.0);
    const double I_real = bloom_srgb_to_linear(c->intensity / 65536.0);

    bloom_model_image_t S = {w, h, NULL}, H = {0, 0, NULL}, Q = {0, 0, NULL},
                        K[2] = {{0, 0, NULL}, {0, 0, NULL}};
    bloom_model_image_t Bh = {0, 0, NULL}, B = {0, 0, NULL};
    int ret = -1;
    S.px = malloc((size_t)w * (size_t)h * 3u * sizeof(double));
    if (!S.px)
        goto out;
    for (size_t i = 0; i < (size_t)w * (size_t)h * 3u; i++)
        S.px[i] = bloom_model_decode(u.bt, p.linear, a->src[i], a->src_max[i % 3], F);
    /* half, then quarter with the threshold subtraction */
    /* 16-bit samples (bit-true; xna.md, "16-bit samples"): H, Q and the
     * passes but the last narrowed to G = 15 fraction bits, half to even; Q
     * is made from H widened, the last pass from its sums widened */
    const int s16 = u.bt && c->sample_bits == 16;
    const double step = s16 ? ldexp(1.0, F - 15) : 1.0;
    if (bloom_model_box_down(&S, &H, u.bt))
        goto out;
    for (size_t i = 0; s16 && i < (size_t)H.w * (size_t)H.h * 3u; i++)
        H.px[i] = bloom_model_round_even(H.px[i], step) * step;
    if (bloom_model_box_down(&H, &Q, u.bt))
        goto out;
    for (size_t i = 0; i < (size_t)Q.w * (size_t)Q.h * 3u; i++) {
        double v = fmax(Q.px[i] - t, 0.0);
        v = sat ? fmin(v, u.one) : v;
        Q.px[i] = s16 ? bloom_model_round_even(v, step) : v;
    }
    /* Kawase passes at quarter resolution */
    const bloom_model_image_t *prev = &Q;
    for (int i = 0; i < P; i++) {
        bloom_model_image_t *next = &K[i & 1];
        bloom_model_image_free(next);
        if (kawase(&u, prev, next, i, i == 0, i == P - 1, sat, f_q, f_real, p.intensity_q, I_real,
                   i == P - 1 ? step : 1.0, i == P - 1 ? u.one : u.one / step))
            goto out;
        prev = next;
    }
    /* back to full resolution: tent to half, tent to full */
    if (bloom_model_tent_up(prev, H.w, H.h, &Bh, u.bt) || bloom_model_tent_up(&Bh, w, h, &B, u.bt))
        goto out;
    for (size_t i = 0; i < (size_t)w * (size_t)h * 3u; i++) {
        double v = B.px[i];
        if (!p.debug_view) { /* screen: b + S (1 - b), b = min(B, 1) */
            const double b = fmin(v, u.one);
            v = u.bt ? b + bloom_model_fdiv(S.px[i] * (u.one - b) + u.one / 2.0, u.one)
                     : b + S.px[i] * (1.0 - b);
        }
        if (a->dst_value)
            a->dst_value[i] = u.bt ? v / u.one : v;
        if (a->dst_codes)
            a->dst_codes[i] = bloom_model_encode(u.bt, p.linear, v, a->dst_max[i % 3], F);
    }
    ret = 2;
out:
    bloom_model_image_free(&S);
    bloom_model_image_free(&H);
    bloom_model_image_free(&Q);
    bloom_model_image_free(&K[0]);
    bloom_model_image_free(&K[1]);
    bloom_model_image_free(&Bh);
    bloom_model_image_free(&B);
    return ret;
}

#else
typedef int bloom_model_xna_unused_t;
#endif
