/* Model of the arm preset (sim/docs/presets/arm.md): dual filtering on a
 * one-channel luminance plane with a mask, or the baked map.
 *
 * Float mode is the recipe taken literally: the down filter as Bjorge's
 * five bilinear taps (centre x4, diagonals at +-1 source texel, /8), the up
 * filter as his eight bilinear taps (axis at +-2 halfpixel weight 1,
 * diagonals at +-halfpixel weight 2, /12), in pixel indices with the exact
 * 2x mapping and clamped reads. Bit-true mode applies the 4x4 and 3x3
 * integer kernels those taps reduce to, directly in 2-D, with the integer
 * roundings of src/presets/bloom_preset_arm.c (plain floor divisions, not the
 * engine's separable sums and multiply-by-inverse). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"

#if BLOOM_USE_ARM

typedef struct {
    int w, h;
    double *v;
} plane_t;

static int plane_new(plane_t *p, int w, int h)
{
    p->w = w;
    p->h = h;
    p->v = calloc((size_t)w * (size_t)h, sizeof *p->v);
    return p->v ? 0 : -1;
}

static int ci(int v, int hi)
{
    return v < 0 ? 0 : v > hi ? hi : v;
}

static double at(const plane_t *p, int x, int y)
{
    return p->v[(size_t)ci(y, p->h - 1) * (size_t)p->w + (size_t)ci(x, p->w - 1)];
}

/* Bilinear sample at (px, py) in texel units (pixel i spans [i, i+1]). */
static double samp(const plane_t *p, double px, double py)
{
    const double fx = px - 0.5, fy = py - 0.5;
    const int x0 = (int)floor(fx), y0 = (int)floor(fy);
    const double ax = fx - x0, ay = fy - y0;
    return (1 - ay) * ((1 - ax) * at(p, x0, y0) + ax * at(p, x0 + 1, y0)) +
           ay * ((1 - ax) * at(p, x0, y0 + 1) + ax * at(p, x0 + 1, y0 + 1));
}

static const double K4[4][4] = {{1, 1, 1, 1}, {1, 5, 5, 1}, {1, 5, 5, 1}, {1, 1, 1, 1}};
/* Up kernel for an even column and an even row: rows m-1..m+1, columns
 * n-1..n+1 of the lower level (m = y >> 1, n = x >> 1); odd parities mirror. */
static const double K3[3][3] = {{14, 37, 1}, {37, 96, 3}, {1, 3, 0}};

static int down(const plane_t *s, plane_t *d, int bt)
{
    if (plane_new(d, (s->w + 1) / 2, (s->h + 1) / 2))
        return -1;
    for (int y = 0; y < d->h; y++)
        for (int x = 0; x < d->w; x++) {
            double r;
            if (bt) {
                double sum = 0;
                for (int i = 0; i < 4; i++)
                    for (int j = 0; j < 4; j++)
                        sum += K4[i][j] * at(s, 2 * x - 1 + j, 2 * y - 1 + i);
                const double q = bloom_model_fdiv(sum, 32), rem = sum - 32 * q; /* half to even */
                r = q + (rem > 16 || (rem == 16 && fmod(q, 2.0) == 1.0));
            } else {
                const double cx = 2 * x + 1, cy = 2 * y + 1; /* destination centre, source texels */
                r = (4 * samp(s, cx, cy) + samp(s, cx - 1, cy - 1) + samp(s, cx + 1, cy - 1) +
                     samp(s, cx - 1, cy + 1) + samp(s, cx + 1, cy + 1)) /
                    8;
            }
            d->v[(size_t)y * (size_t)d->w + (size_t)x] = r;
        }
    return 0;
}

static int up(const plane_t *s, plane_t *d, int w, int h, int bt)
{
    if (plane_new(d, w, h))
        return -1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double r;
            if (bt) {
                double sum = 0;
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                        sum += K3[(y & 1) ? 2 - i : i][(x & 1) ? 2 - j : j] *
                               at(s, (x >> 1) - 1 + j, (y >> 1) - 1 + i);
                r = bloom_model_fdiv(sum + 96, 192);
            } else {
                /* halfpixel = half a destination texel = 1/4 source texel */
                const double cx = (x + 0.5) / 2, cy = (y + 0.5) / 2, hp = 0.25;
                r = (samp(s, cx - 2 * hp, cy) + samp(s, cx + 2 * hp, cy) + samp(s, cx, cy - 2 * hp) +
                     samp(s, cx, cy + 2 * hp) +
                     2 * (samp(s, cx - hp, cy - hp) + samp(s, cx + hp, cy - hp) + samp(s, cx - hp, cy + hp) +
                          samp(s, cx + hp, cy + hp))) /
                    12;
            }
            d->v[(size_t)y * (size_t)w + (size_t)x] = r;
        }
    return 0;
}

/* The knee on one channel: b * contribution (float, epsilons included),
 * max(soft, b - T, 0) with soft = 2x^2 / (8K + E8), rounded (bit-true). */
static double knee1(const bloom_model_params_t *p, double b)
{
    if (!p->bittrue) {
        const double t = p->threshold, k = p->threshold * p->soft_knee;
        double soft = fmin(fmax(b - t + k, 0.0), 2 * k);
        soft = soft * soft * 0.25 / (k + 0.00001);
        return b * (fmax(soft, b - t) / fmax(b, 0.00001));
    }
    const double t = p->threshold_q, k = p->knee_q, one = ldexp(1.0, p->lin_bits);
    const double x = fmin(fmax(b - t + k, 0.0), 2 * k);
    double soft = 0;
    if (k > 0) { /* 2x^2 / (8K + round(0.00008 * 2^F)), rounded; x^2 < 2^58: integers */
        const uint64_t xi = (uint64_t)x, den = 8u * (uint64_t)k + (uint64_t)floor(one * 0.00008 + 0.5);
        soft = (double)((2u * xi * xi + den / 2u) / den);
    }
    const double v = fmax(fmax(soft, b - t), 0.0);
    if (b * 100000.0 < one) /* max(b, 0.00001) = 0.00001: v * b / 0.00001, rounded */
        return floor((v * b * 100000.0 + one / 2) / one);
    return v;
}

/* Q24 value of a mask or map code (bit-true: c * 2^24 / max rounded, max
 * odd so no tie), c / max (float). */
static double auxv(const bloom_model_preset_args_t *a, uint32_t c)
{
    if (!a->bittrue)
        return (double)c / a->aux_max;
    return floor((c * 16777216.0 + (a->aux_max - 1) / 2) / a->aux_max);
}

int bloom_model_arm(const bloom_model_preset_args_t *a)
{
    bloom_model_params_t p;
    if (bloom_model_params_from(a, &p))
        return -1;
    const bloom_config_t *c = a->cfg;
    const int bt = a->bittrue, baked = (c->flags & BLOOM_FLAG_BAKED) != 0;
    const int has_aux = c->aux_fmt != BLOOM_AUX_NONE;
    if (has_aux && (!a->aux || a->aux_max != (c->aux_fmt == BLOOM_AUX_U16 ? 65535 : 255)))
        return -1;
    const int w = c->width, h = c->height, F = p.lin_bits;
    const size_t np = (size_t)w * (size_t)h;
    const double one = ldexp(1.0, F), top = 4294967295.0;
    /* 16-bit samples (bit-true; arm.md, "16-bit samples"): D_1 narrowed to
     * G fraction bits (every value is at most the knee's peak: one "level"
     * of it), the chain in those units, U_1 widened for B */
    const int s16 = bt && c->sample_bits == 16;
    const double step = s16 ? ldexp(1.0, F - bloom_model_s16_frac(&p, 1)) : 1.0;
    double *S = malloc(np * 3 * sizeof *S), *V = malloc(np * 3 * sizeof *V);
    plane_t lev[BLOOM_MODEL_MAX_LEVELS + 1], U;
    memset(lev, 0, sizeof lev);
    memset(&U, 0, sizeof U);
    int L = bloom_model_levels(w, h, c->levels), ret = -1;
    if (!S || !V || L < 1)
        goto out;
    for (size_t i = 0; i < np * 3; i++)
        S[i] = bloom_model_decode(bt, p.linear, a->src[i], a->src_max[i % 3], F);

    if (baked) {
        const double st = c->p.strength, dbg = p.debug_view;
        for (size_t i = 0; i < np; i++) {
            const double m = auxv(a, a->aux[i]);
            for (int ch = 0; ch < 3; ch++) {
                const double s = S[3 * i + ch];
                if (!bt) {
                    V[3 * i + ch] = (dbg ? 0.0 : s) + s * m * (st / 65536.0);
                } else {
                    /* Q24: s (2^24 + f) reaches 2^56, so in 64-bit integers */
                    const uint64_t f = (uint64_t)floor((m * st + 32768.0) / 65536.0);
                    const uint64_t v = ((uint64_t)s * ((dbg ? 0u : 1u << 24) + f) + (1u << 23)) >> 24;
                    V[3 * i + ch] = fmin((double)v, top);
                }
            }
        }
    } else {
        /* P = Y * mask, full resolution */
        if (plane_new(&lev[0], w, h))
            goto out;
        for (size_t i = 0; i < np; i++) {
            const double *s = S + 3 * i;
            double y;
            if (!bt) {
                y = 0.2126 * s[0] + 0.7152 * s[1] + 0.0722 * s[2];
                if (has_aux)
                    y *= auxv(a, a->aux[i]);
            } else {
                /* Q24 weights summing to 2^24; sums below 2^53 */
                y = floor((3566836.0 * s[0] + 11999065.0 * s[1] + 1211315.0 * s[2] + 8388608.0) / 16777216.0);
                if (has_aux)
                    y = floor((y * auxv(a, a->aux[i]) + 8388608.0) / 16777216.0);
            }
            lev[0].v[i] = y;
        }
        for (int k = 1; k <= L; k++) {
            if (down(&lev[k - 1], &lev[k], bt))
                goto out;
            if (k == 1)
                for (size_t i = 0; i < (size_t)lev[1].w * (size_t)lev[1].h; i++) {
                    lev[1].v[i] = knee1(&p, lev[1].v[i]);
                    if (s16) /* narrowed to v / 2^-15, half to even */
                        lev[1].v[i] = bloom_model_round_even(lev[1].v[i], step);
                }
        }
        /* up: U_L = D_L, U_k = up(U_k+1), B = up(U_1) at level 0 */
        plane_t cur = lev[L];
        for (int k = L - 1; k >= 0; k--) {
            plane_t nxt;
            if (k == 0 && s16) { /* U_1 widened for B (exact) */
                plane_t wide;
                const int fail = plane_new(&wide, cur.w, cur.h);
                for (size_t i = 0; !fail && i < (size_t)cur.w * (size_t)cur.h; i++)
                    wide.v[i] = cur.v[i] * step;
                if (cur.v != lev[L].v)
                    free(cur.v);
                if (fail)
                    goto out;
                cur = wide;
            }
            if (up(&cur, &nxt, lev[k].w, lev[k].h, bt)) {
                if (cur.v != lev[L].v)
                    free(cur.v);
                goto out;
            }
            if (cur.v != lev[L].v)
                free(cur.v);
            cur = nxt;
        }
        U = cur; /* B */
        const double I = bt ? (double)p.intensity_q : bloom_srgb_to_linear(p.intensity);
        for (size_t i = 0; i < np; i++)
            for (int ch = 0; ch < 3; ch++) {
                const double b = U.v[i], s = p.debug_view ? 0.0 : S[3 * i + ch];
                if (!bt) {
                    V[3 * i + ch] = s + I * (c->p.tint[ch] / 65536.0) * b;
                } else {
                    const double g = floor((I * c->p.tint[ch] + 32768.0) / 65536.0);
                    V[3 * i + ch] = fmin(s + floor((g * b + 32768.0) / 65536.0), top);
                }
            }
    }
    for (size_t i = 0; i < np * 3; i++) {
        if (a->dst_codes)
            a->dst_codes[i] = bloom_model_encode(bt, p.linear, V[i], a->dst_max[i % 3], F);
        if (a->dst_value)
            a->dst_value[i] = bt ? V[i] / one : V[i];
    }
    ret = L;
out:
    for (int k = 0; k <= BLOOM_MODEL_MAX_LEVELS; k++)
        free(lev[k].v);
    free(U.v);
    free(S);
    free(V);
    return ret;
}

#else
typedef int bloom_model_arm_unused_t;
#endif
