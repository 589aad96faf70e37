/* The cod preset's model (sim/docs/presets/cod.md), full frame.
 *
 * Float mode: the recipe in double precision, parameters as real values
 * (q / 65536): Karis-weighted 13-tap mean with luma 0.2126 R + 0.7152 G +
 * 0.0722 B of each box mean, the soft knee (only when the threshold is above
 * 0, as Bevy), the plain 13-tap, the 3x3 tent as bilinear taps, the blends.
 * Bit-true mode: every integer rounding of src/presets/bloom_preset_cod.c, written
 * from the box sums and 2-D weights directly (no separable passes, no fast
 * paths): exact sums in double (all below 2^53), products that can pass
 * 2^53 in uint64_t. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model_cod.h"

const bloom_cod_bevy_t bloom_cod_natural = {0.15, 0.7, 0.95, 1.0, 0};
const bloom_cod_bevy_t bloom_cod_old_school = {0.05, 0.7, 0.95, 1.0, 1};
const bloom_cod_bevy_t bloom_cod_screen_blur = {1.0, 0.0, 0.0, 1.0 / 3.0, 0};

/* Bevy's curve at x = mip / max_mip in [0, 1]. */
static double blend_at(const bloom_cod_bevy_t *s, double x)
{
    double lf = (1.0 - pow(1.0 - x, 1.0 / (1.0 - s->low_frequency_boost_curvature))) * s->low_frequency_boost;
    double hp = (x - s->high_pass_frequency) / s->high_pass_frequency;
    hp = 1.0 - (hp < 0.0 ? 0.0 : hp > 1.0 ? 1.0 : hp);
    lf *= s->additive ? 1.0 : 1.0 - s->intensity;
    return (s->intensity + lf) * hp;
}

double bloom_cod_blend_factor(const bloom_cod_bevy_t *s, int mip, int max_mip)
{
    return blend_at(s, max_mip > 0 ? (double)mip / (double)max_mip : 0.0);
}

void bloom_cod_weights(const bloom_cod_bevy_t *s, int L, uint32_t w[BLOOM_MAX_LEVELS])
{
    for (int k = 0; k < BLOOM_MAX_LEVELS; k++) {
        double c = k < L ? bloom_cod_blend_factor(s, k, L - 1) : blend_at(s, 1.0);
        c = c < 0.0 || c != c ? 0.0 : c > 1.0 ? 1.0 : c;
        w[k] = (uint32_t)floor(c * 65536.0 + 0.5);
    }
}

typedef bloom_model_image_t img_t;

static int img_new(img_t *im, int w, int h)
{
    im->w = w;
    im->h = h;
    im->px = calloc((size_t)w * (size_t)h * 3u, sizeof *im->px);
    return im->px ? 0 : -1;
}

static double at(const img_t *im, int x, int y, int c)
{
    x = x < 0 ? 0 : x >= im->w ? im->w - 1 : x;
    y = y < 0 ? 0 : y >= im->h ? im->h - 1 : y;
    return im->px[((size_t)y * (size_t)im->w + (size_t)x) * 3u + (size_t)c];
}

static double *pix(img_t *im, int x, int y)
{
    return im->px + ((size_t)y * (size_t)im->w + (size_t)x) * 3u;
}

/* Sum of the 4x4 block with top-left (x0, y0), edge rule. */
static double box4(const img_t *im, int x0, int y0, int c)
{
    double s = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            s += at(im, x0 + j, y0 + i, c);
    return s;
}

/* The 13-tap down of src into dst (half size); level 1 with the Karis
 * average when karis. Boxes: TL, TR, BL, BR (weight 1/8), centre (1/2). */
static void down13(const img_t *src, img_t *dst, int bt, int karis)
{
    static const int ox[5] = {-2, 0, -2, 0, -1}, oy[5] = {-2, -2, 0, 0, -1};
    static const double g[5] = {1, 1, 1, 1, 4};
    const int F = BLOOM_LIN_BITS;
    for (int y = 0; y < dst->h; y++)
        for (int x = 0; x < dst->w; x++) {
            double box[5][3];
            for (int i = 0; i < 5; i++)
                for (int c = 0; c < 3; c++)
                    box[i][c] = box4(src, 2 * x + ox[i], 2 * y + oy[i], c);
            double *o = pix(dst, x, y);
            if (!bt) {
                double wgt[5], ws = 0.0;
                for (int i = 0; i < 5; i++) {
                    const double l = (0.2126 * box[i][0] + 0.7152 * box[i][1] + 0.0722 * box[i][2]) / 16.0;
                    wgt[i] = karis ? g[i] / (1.0 + l) : g[i];
                    ws += wgt[i];
                }
                for (int c = 0; c < 3; c++) {
                    double s = 0.0;
                    for (int i = 0; i < 5; i++)
                        s += wgt[i] * box[i][c] / 16.0;
                    o[c] = s / ws;
                }
            } else if (!karis) {
                for (int c = 0; c < 3; c++) {
                    double s = 64.0;
                    for (int i = 0; i < 5; i++)
                        s += g[i] * box[i][c];
                    o[c] = floor(s / 128.0);
                }
            } else {
                /* d = 2^F + floor(Y / 2^20), w = floor(2^(F+28) / d), weights g w */
                uint64_t gw[5], W = 0;
                for (int i = 0; i < 5; i++) {
                    const double Y = 13933.0 * box[i][0] + 46871.0 * box[i][1] + 4732.0 * box[i][2];
                    const uint64_t d = ((uint64_t)1 << F) + (uint64_t)floor(Y / 1048576.0);
                    gw[i] = (((uint64_t)1 << (F + 28)) / d) * (uint64_t)g[i];
                    W += gw[i];
                }
                for (int c = 0; c < 3; c++) {
                    uint64_t N = 8u * W;
                    for (int i = 0; i < 5; i++)
                        N += gw[i] * (uint64_t)box[i][c];
                    o[c] = (double)((N / 16u) / W);
                }
            }
        }
}

/* The tent taps of output coordinate x onto a low-resolution axis of n
 * pixels: 4 indices (edge rule) and weights in sixteenths. */
static void taps(int x, int n, int idx[4], double wt[4])
{
    static const double we[4] = {1, 5, 7, 3}, wo[4] = {3, 7, 5, 1};
    const int m = x >> 1, first = (x & 1) ? m - 1 : m - 2;
    for (int i = 0; i < 4; i++) {
        const int j = first + i;
        idx[i] = j < 0 ? 0 : j >= n ? n - 1 : j;
        wt[i] = (x & 1) ? wo[i] : we[i];
    }
}

/* 256 x the tent of low at output pixel (x, y), channel c: exact (< 2^41). */
static double tent256(const img_t *low, int x, int y, int c)
{
    int ix[4], iy[4];
    double wx[4], wy[4], s = 0.0;
    taps(x, low->w, ix, wx);
    taps(y, low->h, iy, wy);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            s += wy[i] * wx[j] * at(low, ix[j], iy[i], c);
    return s;
}

/* floor((a * s + b * t + 2^23) / 2^24) in 64 bits (a, b <= 2^24, s, t < 2^41). */
static double blend_bt(uint64_t a, double s, uint64_t b, double t)
{
    const uint64_t v = (a * (uint64_t)s + b * (uint64_t)t + (1u << 23)) >> 24;
    return (double)(v > UINT32_MAX ? UINT32_MAX : v);
}

int bloom_model_cod_ex(const bloom_model_preset_args_t *a, int karis)
{
    bloom_model_params_t p;
    if (bloom_model_params_from(a, &p) || a->cfg->preset != BLOOM_PRESET_COD || !a->src)
        return -1;
    const bloom_config_t *cfg = a->cfg;
    const int bt = a->bittrue != 0, F = BLOOM_LIN_BITS, lin = p.linear;
    const int add = (cfg->flags & BLOOM_FLAG_ADDITIVE) != 0, dbg = p.debug_view;
    const int L = bloom_model_levels(cfg->width, cfg->height, cfg->levels);
    img_t S, D[BLOOM_MAX_LEVELS + 1], U[BLOOM_MAX_LEVELS + 1];
    memset(D, 0, sizeof D);
    memset(U, 0, sizeof U);
    int fail = img_new(&S, cfg->width, cfg->height);
    for (int y = 0; !fail && y < S.h; y++)
        for (int x = 0; x < S.w; x++)
            for (int c = 0; c < 3; c++)
                pix(&S, x, y)[c] = bloom_model_decode(
                    bt, lin, a->src[((size_t)y * (size_t)S.w + (size_t)x) * 3u + (size_t)c], a->src_max[c],
                    F);
    /* down chain */
    for (int k = 1; !fail && k <= L; k++) {
        const img_t *src = k == 1 ? &S : &D[k - 1];
        fail = img_new(&D[k], (src->w + 1) / 2, (src->h + 1) / 2);
        if (fail)
            break;
        down13(src, &D[k], bt, k == 1 && karis);
        if (k == 1 && cfg->threshold > 0)
            for (size_t i = 0; i < (size_t)D[1].w * (size_t)D[1].h; i++)
                bloom_model_knee(&p, D[1].px + 3 * i);
    }
    /* up chain: U_L = D_L, U_k = blend(D_k, tent(U_k+1), c_k) */
    for (int k = L - 1; !fail && k >= 1; k--) {
        const img_t *low = k == L - 1 ? &D[L] : &U[k + 1];
        fail = img_new(&U[k], D[k].w, D[k].h);
        if (fail)
            break;
        const uint32_t cq = cfg->p.level_weight[k];
        const double c = cq / 65536.0;
        for (int y = 0; y < U[k].h; y++)
            for (int x = 0; x < U[k].w; x++)
                for (int ch = 0; ch < 3; ch++) {
                    const double d = pix(&D[k], x, y)[ch], t = tent256(low, x, y, ch);
                    double *o = &pix(&U[k], x, y)[ch];
                    if (!bt)
                        *o = add ? d + c * t / 256.0 : (1.0 - c) * d + c * t / 256.0;
                    else
                        *o = blend_bt(add ? 65536u * 256u : (65536u - cq) * 256u, d, cq, t);
                }
    }
    /* composite */
    const img_t *u1 = L == 1 ? &D[1] : &U[1];
    const uint32_t c0 = cfg->p.level_weight[0];
    for (int y = 0; !fail && y < S.h; y++)
        for (int x = 0; x < S.w; x++)
            for (int ch = 0; ch < 3; ch++) {
                const size_t i = ((size_t)y * (size_t)S.w + (size_t)x) * 3u + (size_t)ch;
                const double s = S.px[i], t = tent256(u1, x, y, ch);
                double v;
                if (!bt) {
                    const double f = c0 / 65536.0 * (cfg->p.tint[ch] / 65536.0);
                    v = (dbg ? 0.0 : add ? s : (1.0 - c0 / 65536.0) * s) + f * t / 256.0;
                } else {
                    const uint64_t f = ((uint64_t)c0 * cfg->p.tint[ch] + 32768u) >> 16;
                    v = blend_bt(dbg ? 0u : add ? 65536u * 256u : (65536u - c0) * 256u, s, f, t);
                }
                if (a->dst_codes)
                    a->dst_codes[i] = bloom_model_encode(bt, lin, v, a->dst_max[ch], F);
                if (a->dst_value)
                    a->dst_value[i] = bt ? v / (double)(1u << F) : v;
            }
    free(S.px);
    for (int k = 0; k <= BLOOM_MAX_LEVELS; k++) {
        free(D[k].px);
        free(U[k].px);
    }
    return fail ? -1 : L;
}

int bloom_model_cod(const bloom_model_preset_args_t *a)
{
    return bloom_model_cod_ex(a, 1);
}
