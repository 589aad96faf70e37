/* Model of the gamedev preset (sim/docs/presets/gamedev.md), full frame.
 *
 * Float mode: the recipe in double precision with the parameters as real
 * values: Rec.709 luminance 0.2126/0.7152/0.0722, contribution
 * max(0, L - t) / max(L, 1e-4), the article's Gaussian weights
 * (0.227027, 0.194595, 0.121622, 0.054054, 0.016216) divided by their
 * printed sum 1.000001 so that they sum to one,
 * real box and tent averages, c = S + strength * B, Reinhard, gamma 1/2.2.
 *
 * Bit-true mode: every integer rounding of the core's preset, written out
 * per image: exact integer luminance (10000 L), Q24 Gaussian weights, round-half-up
 * after each pass, the Q32 contribution factor, the rounded strength product, and the
 * output code from the real Reinhard/gamma formula at the integer c (the
 * generator sim/gen_gamedev.c checks that this formula and the core's
 * threshold tables agree at every threshold). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom_model.h"

typedef bloom_model_image_t image_t;

static int img_new(image_t *im, int w, int h)
{
    im->w = w;
    im->h = h;
    im->px = calloc((size_t)w * (size_t)h * 3u, sizeof(double));
    return im->px ? 0 : -1;
}

static double *pix(const image_t *im, int x, int y)
{
    x = x < 0 ? 0 : x >= im->w ? im->w - 1 : x;
    y = y < 0 ? 0 : y >= im->h ? im->h - 1 : y;
    return im->px + ((size_t)y * (size_t)im->w + (size_t)x) * 3u;
}

/* The luminance threshold on every pixel of d in place. Bit-true: 10000 L
 * exactly in integers, the Q32 factor from the divisor and numerator
 * shifted until the divisor fits in 32 bits. */
static void threshold(image_t *d, int bt, double t, uint32_t t_q, int lin_bits)
{
    const uint64_t one = 1ull << lin_bits, tx = (uint64_t)t_q * 10000u;
    for (int y = 0; y < d->h; y++)
        for (int x = 0; x < d->w; x++) {
            double *p = pix(d, x, y);
            if (!bt) {
                const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
                const double f = fmax(0.0, l - t) / fmax(l, 1e-4);
                for (int c = 0; c < 3; c++)
                    p[c] *= f;
                continue;
            }
            const uint64_t r = (uint64_t)p[0], g = (uint64_t)p[1], b = (uint64_t)p[2];
            const uint64_t lx = 2126u * r + 7152u * g + 722u * b;
            if (lx <= tx) {
                p[0] = p[1] = p[2] = 0.0;
                continue;
            }
            uint64_t den = lx > one ? lx : one, num = lx - tx;
            while (den > 0xFFFFFFFFu) {
                den >>= 1;
                num >>= 1;
            }
            if (num >= den)
                continue;                                      /* factor exactly 1 */
            const uint64_t f = ((num << 32) + den / 2u) / den; /* Q32 */
            for (int c = 0; c < 3; c++)
                p[c] = (double)((((uint64_t)p[c]) * f + 0x80000000u) >> 32);
        }
}

/* The separable 9-tap Gaussian: vertical pass, then horizontal. Float: the
 * article's weights divided by their sum (1.000001); bit-true: their Q24
 * integers, each pass rounded half up. */
static int gauss(const image_t *s, image_t *o, int bt)
{
    static const double wa[5] = {0.227027, 0.194595, 0.121622, 0.054054, 0.016216};
    static const uint64_t wq[5] = {3808876, 3264759, 2040477, 906875, 272059}; /* Q24 */
    const double sum = wa[0] + 2.0 * (wa[1] + wa[2] + wa[3] + wa[4]);          /* 1.000001 */
    image_t v;
    if (img_new(&v, s->w, s->h))
        return -1;
    if (img_new(o, s->w, s->h)) {
        free(v.px);
        return -1;
    }
    for (int pass = 0; pass < 2; pass++) {
        const image_t *from = pass ? &v : s;
        image_t *to = pass ? o : &v;
        for (int y = 0; y < s->h; y++)
            for (int x = 0; x < s->w; x++)
                for (int c = 0; c < 3; c++) {
                    double sf = 0.0;
                    uint64_t sq = 1u << 23;
                    for (int j = -4; j <= 4; j++) {
                        const double a = pass ? pix(from, x + j, y)[c] : pix(from, x, y + j)[c];
                        const int k = j < 0 ? -j : j;
                        if (bt)
                            sq += wq[k] * (uint64_t)a;
                        else
                            sf += wa[k] / sum * a;
                    }
                    pix(to, x, y)[c] = bt ? (double)(sq >> 24) : sf;
                }
    }
    free(v.px);
    return 0;
}

/* Output code of c: Reinhard, gamma 1/2.2 (or none when linear), to n; n = 0:
 * the tone-mapped value in Q16.16. one = 2^F (bit-true) or 1 (float). */
static uint32_t encode(int bt, int linear, double c, int n, double one)
{
    if (bt) {
        const uint64_t ci = (uint64_t)c, o = (uint64_t)one;
        if (n == 0) /* floor((2^17 c + d) / 2d), d = c + 2^F */
            return (uint32_t)(((ci << 17) + ci + o) / (2u * (ci + o)));
        if (linear) { /* floor(n r + 1/2), r = c / (c + 2^F), exactly */
            const uint64_t k = (2u * (uint64_t)n * ci + ci + o) / (2u * (ci + o));
            return (uint32_t)(k > (uint64_t)n ? (uint64_t)n : k);
        }
    }
    const double r = c / (c + one);
    if (n == 0)
        return (uint32_t)floor(r * 65536.0 + 0.5);
    const double e = floor((linear ? r : pow(r, 1.0 / 2.2)) * n + 0.5);
    return (uint32_t)(e > n ? n : e);
}

int bloom_model_gamedev(const bloom_model_preset_args_t *a)
{
    bloom_model_params_t p;
    if (bloom_model_params_from(a, &p) || a->cfg->preset != BLOOM_PRESET_GAMEDEV || !a->src)
        return -1;
    const bloom_config_t *cfg = a->cfg;
    const int w = cfg->width, h = cfg->height, bt = a->bittrue, F = p.lin_bits;
    const int L = bloom_model_levels(w, h, 3);
    const double one = bt ? ldexp(1.0, F) : 1.0;
    const double t = cfg->threshold / 65536.0, strength = cfg->p.strength / 65536.0;
    for (int c = 0; c < 3; c++)
        if (a->src_max[c] < BLOOM_MODEL_F32 || a->src_max[c] > 65535 || a->dst_max[c] < 0 ||
            a->dst_max[c] > 65535)
            return -1;
    image_t S, D[4], G[4], U[4], B, T;
    memset(D, 0, sizeof D);
    memset(G, 0, sizeof G);
    memset(U, 0, sizeof U);
    memset(&B, 0, sizeof B);
    int ok = img_new(&S, w, h) == 0;
    for (int y = 0; ok && y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) {
                const uint32_t code = a->src[((size_t)y * (size_t)w + (size_t)x) * 3u + (size_t)c];
                pix(&S, x, y)[c] = bloom_model_decode(bt, p.linear, code, a->src_max[c], F);
            }
    /* down: D1 = threshold(box(S)), Dk = box(Dk-1) */
    for (int k = 1; ok && k <= L; k++) {
        ok = bloom_model_box_down(k == 1 ? &S : &D[k - 1], &D[k], bt) == 0;
        if (ok && k == 1)
            threshold(&D[1], bt, t, p.threshold_q, F);
    }
    /* G_k = gauss(D_k); U_L = G_L, U_k = G_k + tent(U_k+1); B = tent(U_1) */
    for (int k = L; ok && k >= 1; k--) {
        ok = gauss(&D[k], &G[k], bt) == 0;
        if (!ok)
            break;
        if (k == L) {
            U[k] = G[k];
            G[k].px = NULL;
            continue;
        }
        ok = bloom_model_tent_up(&U[k + 1], D[k].w, D[k].h, &T, bt) == 0;
        if (!ok)
            break;
        for (size_t i = 0; i < (size_t)D[k].w * (size_t)D[k].h * 3u; i++)
            T.px[i] += G[k].px[i];
        U[k] = T;
    }
    if (ok)
        ok = bloom_model_tent_up(&U[1], w, h, &B, bt) == 0;
    /* composite and output */
    for (int y = 0; ok && y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) {
                const size_t i = ((size_t)y * (size_t)w + (size_t)x) * 3u + (size_t)c;
                const double s = p.debug_view ? 0.0 : S.px[i];
                double v;
                if (bt) /* P = (strength_q * B + 2^15) >> 16, S + P */
                    v = s + (double)(((uint64_t)cfg->p.strength * (uint64_t)B.px[i] + 32768u) >> 16);
                else
                    v = s + strength * B.px[i];
                if (a->dst_value)
                    a->dst_value[i] = v;
                if (a->dst_codes)
                    a->dst_codes[i] = encode(bt, p.linear, v, a->dst_max[c], one);
            }
    free(S.px);
    free(B.px);
    for (int k = 0; k <= 3; k++) {
        free(D[k].px);
        free(G[k].px);
        free(U[k].px);
    }
    return ok ? L : -1;
}
