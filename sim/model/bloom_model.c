/* Reference model of the bloom engine. Read with sim/docs/bloom-model.md (the
 * maths) and sim/docs/fixed-point.md (the integer pipeline).
 *
 * One set of loops serves both modes. In float mode every value is real
 * linear light and nothing is rounded. In bit-true mode every value is the
 * core's integer (linear samples Q12.20) held in a double, and each rounding
 * point of fixed-point.md steps 1-7 is written out where it happens. Values
 * stay below 2^53, so the doubles are exact; the two products that can go
 * beyond (the knee's x^2 and the composite's I*B) are done in uint64_t. */
#include "bloom_model.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define MAX_LINEAR 16777215.0 /* BLOOM_MAX_LINEAR = 2^24 - 1, Q16.16 */
#define Q_ONE 65536.0         /* 1.0 in Q16.16 (factors, intensity, RGBQ16) */
#define KNEE_ONE 16777216.0   /* 1.0 in the knee factor's Q24 */

/* The pipeline's parameters in the units of the mode. */
typedef struct {
    int bt;     /* bit-true */
    double t;   /* threshold: real, or T_q */
    double k;   /* knee = t*s: real, or K_q */
    double i;   /* linear intensity: real, or I_q */
    double one; /* bit-true: 1.0 in internal units, 2^F */
    double q16; /* bit-true: 2^(F-16), Q16.16 -> internal */
} model_t;

/* ---- curves --------------------------------------------------------- */

double bloom_srgb_to_linear(double x)
{
    return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}

/* Inverse of the branch srgb_to_linear takes. The standard sRGB pieces do
 * not meet exactly at 0.04045 (the power piece is ~1.4e-7 lower there), so
 * the breakpoint is the linear piece's image, 0.04045/12.92: then
 * srgb_to_linear(linear_to_srgb(x)) == x for all x >= 0 and the curve is
 * monotone. No Q16.16 value falls in the ~1.4e-7 gap, so the bit-true encode
 * does not depend on this choice. */
double bloom_linear_to_srgb(double x)
{
    return x <= 0.04045 / 12.92 ? x * 12.92 : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

/* ---- small helpers -------------------------------------------------- */

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* floor(a / b) for non-negative integers a < 2^53, b >= 1 held in doubles:
 * the integer division of fixed-point.md. The division rounds once; the
 * fix-ups make the result exact even if that rounding reached an integer. */
static double fdiv(double a, double b)
{
    double q = floor(a / b);
    if (q * b > a)
        q -= 1;
    else if ((q + 1) * b <= a)
        q += 1;
    return q;
}

/* Normalising a kernel sum by its power-of-two weight total: exact real
 * division in float mode; in bit-true mode the rounding fixed-point.md
 * names for that point ("Rounding without bias"): half up, half down or
 * half to even. */
enum { RND_UP, RND_DOWN, RND_EVEN };
static double norm(int bt, double sum, double den, int rnd)
{
    if (!bt)
        return sum / den;
    if (rnd == RND_UP)
        return fdiv(sum + den / 2, den);
    if (rnd == RND_DOWN)
        return fdiv(sum + den / 2 - 1, den);
    const double q = fdiv(sum, den), r = sum - q * den; /* half to even */
    return q + (r > den / 2 || (r == den / 2 && fmod(q, 2.0) == 1.0));
}

double bloom_model_round_even(double v, double den)
{
    return norm(1, v, den, RND_EVEN);
}

/* ---- images --------------------------------------------------------- */

static int image_alloc(bloom_model_image_t *im, int w, int h)
{
    im->w = w;
    im->h = h;
    im->px = NULL;
    if (w < 1 || h < 1 || (size_t)w > SIZE_MAX / 3 / sizeof(double) / (size_t)h)
        return -1;
    im->px = calloc((size_t)w * (size_t)h * 3, sizeof(double));
    return im->px ? 0 : -1;
}

void bloom_model_image_free(bloom_model_image_t *im)
{
    if (!im)
        return;
    free(im->px);
    im->px = NULL;
    im->w = im->h = 0;
}

static double *px(const bloom_model_image_t *im, int x, int y)
{
    return im->px + ((size_t)y * (size_t)im->w + (size_t)x) * 3;
}

/* Edge rule: reads outside the image replicate the nearest edge pixel. */
static double at(const bloom_model_image_t *im, int x, int y, int c)
{
    return px(im, clampi(x, 0, im->w - 1), clampi(y, 0, im->h - 1))[c];
}

/* ---- level count ---------------------------------------------------- */

int bloom_model_levels(int w, int h, int requested)
{
    int k = 1;
    if (w < 1 || h < 1 || requested < 1 || requested > BLOOM_MODEL_MAX_LEVELS)
        return -1;
    w = (w + 1) / 2; /* level 1 always exists */
    h = (h + 1) / 2;
    /* level k+1 exists while k+1 <= N and both its sides are >= 2 */
    while (k + 1 <= requested) {
        int w2 = (w + 1) / 2, h2 = (h + 1) / 2;
        if (w2 < 2 || h2 < 2)
            break;
        w = w2;
        h = h2;
        k++;
    }
    return k;
}

/* ---- step 1: decode; step 7: encode ---------------------------------- */

static double decode(const model_t *m, int linear, uint32_t word, int n)
{
    if (n == 0) /* RGBQ16: a linear Q16.16 word, clamped, to Q12.20 */
        return m->bt ? fmin((double)word, MAX_LINEAR) * m->q16 : word / Q_ONE;
    if (n == BLOOM_MODEL_F32) { /* RGBF32: the bits of a linear binary32 value */
        float f;
        memcpy(&f, &word, sizeof f);
        if (!(f > 0.0f)) /* negative, zero, NaN */
            return 0.0;
        if (!m->bt)
            return (double)f;
        /* round half to even of f * 2^F (exact in double: a power of two
         * times a 24-bit mantissa; rint rounds ties to even), clamped to
         * the largest sample (2^24 - 1) * 2^(F - 16) */
        return fmin(rint((double)f * m->one), MAX_LINEAR * m->q16);
    }
    if (!m->bt)
        return linear ? (double)word / n : bloom_srgb_to_linear((double)word / n);
    if (linear) /* (c*2^20 + (n-1)/2) / n, integer division */
        return fdiv(word * m->one + (double)((n - 1) / 2), n);
    /* the table value: round(srgb_to_linear(c/n) * 2^20) */
    return floor(bloom_srgb_to_linear((double)word / n) * m->one + 0.5);
}

static uint32_t encode(const model_t *m, int linear, double v, int n)
{
    double e;
    if (m->bt) {
        if (n == 0) /* Q12.20 -> Q16.16, round half to even, clamp */
            return (uint32_t)fmin(m->q16 == 1.0 ? v : norm(1, v, m->q16, RND_EVEN), MAX_LINEAR);
        if (linear) /* (min(v, 2^20)*n + 2^19) >> 20 */
            return (uint32_t)fdiv(fmin(v, m->one) * n + m->one / 2, m->one);
        /* equals counting the table thresholds E_n[c] (fixed-point.md step 7) */
        e = floor(bloom_linear_to_srgb(v / m->one) * n + 0.5);
        return (uint32_t)clampd(e, 0.0, n);
    }
    if (n == 0)
        return (uint32_t)clampd(floor(v * Q_ONE + 0.5), 0.0, MAX_LINEAR);
    v = clampd(v, 0.0, 1.0);
    e = linear ? v : bloom_linear_to_srgb(v);
    return (uint32_t)floor(e * n + 0.5);
}

double bloom_model_fdiv(double a, double b)
{
    return fdiv(a, b);
}

static void model_units(model_t *m, int bittrue, int lin_bits)
{
    memset(m, 0, sizeof *m);
    m->bt = bittrue != 0;
    m->one = ldexp(1.0, lin_bits ? lin_bits : 20);
    m->q16 = m->one / Q_ONE;
}

double bloom_model_decode(int bittrue, int linear, uint32_t code, int n, int lin_bits)
{
    model_t m;
    model_units(&m, bittrue, lin_bits);
    return decode(&m, linear, code, n);
}

uint32_t bloom_model_encode(int bittrue, int linear, double v, int n, int lin_bits)
{
    model_t m;
    model_units(&m, bittrue, lin_bits);
    return encode(&m, linear, v, n);
}

/* ---- step 3: the knee (prefilter) ------------------------------------ */

/* Bit-true: the knee's numerator max(soft, b - T, 0) at brightness b. */
static double knee_num(const model_t *m, double b)
{
    double soft;
    const double x = clampd(b - m->t + m->k, 0.0, 2.0 * m->k); /* signed before the clamp */
    if (m->k == 0) {                                           /* then x = 0 */
        soft = 0.0;
    } else {
        const uint64_t xi = (uint64_t)x, den = 8u * (uint64_t)m->k + (uint64_t)floor(m->one * 0.00008 + 0.5);
        soft = (double)((2u * xi * xi + den / 2u) / den);
    }
    return fmax(fmax(soft, b - m->t), 0.0);
}

static void knee(const model_t *m, double rgb[3])
{
    double b = fmax(rgb[0], fmax(rgb[1], rgb[2])); /* brightness */
    double num, f;
    int c;

    if (!m->bt) { /* bloom-model.md, epsilons included */
        double contribution, soft;
        soft = clampd(b - m->t + m->k, 0.0, 2.0 * m->k);
        soft = soft * soft * 0.25 / (m->k + 0.00001);
        contribution = fmax(soft, b - m->t) / fmax(b, 0.00001);
        for (c = 0; c < 3; c++)
            rgb[c] *= contribution;
        return;
    }
    /* Integer form, the epsilons in internal units (fixed-point.md step 3):
     * soft = 2x^2 / (8K + E8), rounded, E8 = round(0.00008 * 2^F); the
     * factor num / max(b, 2^F / 100000) in Q16. x^2 reaches 2^58: integers. */
    num = knee_num(m, b);
    if (num == 0 || b == 0) {
        rgb[0] = rgb[1] = rgb[2] = 0.0;
        return;
    }
    /* the Q24 factor: num * 2^24 reaches 2^53, so the quotient in integers */
    if (b * 100000.0 < m->one) /* max(b, 0.00001) = 0.00001: exact */
        f = num * KNEE_ONE * 100000.0 / m->one;
    else
        f = (double)((((uint64_t)num << 24) + (uint64_t)floor(b / 2)) / (uint64_t)b);
    for (c = 0; c < 3; c++)
        rgb[c] = fdiv(rgb[c] * f + KNEE_ONE / 2, KNEE_ONE); /* (c*f + 2^23) >> 24, c*f < 2^53 */
}

void bloom_model_knee(const bloom_model_params_t *p, double rgb[3])
{
    model_t m;
    model_units(&m, p->bittrue, p->lin_bits);
    m.t = m.bt ? p->threshold_q : p->threshold;
    m.k = m.bt ? p->knee_q : p->threshold * p->soft_knee;
    m.i = 0.0;
    knee(&m, rgb);
}

/* ---- step 2: box down ------------------------------------------------ */

int bloom_model_box_down(const bloom_model_image_t *src, bloom_model_image_t *dst, int bittrue)
{
    int x, y, c, i, j;
    if (image_alloc(dst, (src->w + 1) / 2, (src->h + 1) / 2))
        return -1;
    for (y = 0; y < dst->h; y++)
        for (x = 0; x < dst->w; x++)
            for (c = 0; c < 3; c++) {
                /* the 4x4 source block 2x-1..2x+2 by 2y-1..2y+2, weight 1/16 */
                double sum = 0.0;
                for (i = 0; i < 4; i++)
                    for (j = 0; j < 4; j++)
                        sum += at(src, 2 * x - 1 + j, 2 * y - 1 + i, c);
                px(dst, x, y)[c] = norm(bittrue, sum, 16.0, RND_EVEN); /* sum / 16, half to even */
            }
    return 0;
}

/* ---- step 4: tent up -------------------------------------------------- */

/* Weights of taps m-1, m, m+1 (m = d >> 1) for destination index d. */
static const double tent_w[2][3] = {{3.0, 4.0, 1.0}, {1.0, 4.0, 3.0}};

int bloom_model_tent_up(const bloom_model_image_t *low, int w, int h, bloom_model_image_t *dst, int bittrue)
{
    bloom_model_image_t v; /* vertical pass: low->w columns by h rows */
    int x, y, c, i;

    dst->px = NULL;
    if (w < 1 || h < 1 || (w + 1) / 2 != low->w || (h + 1) / 2 != low->h)
        return -1;
    if (image_alloc(&v, low->w, h))
        return -1;
    if (image_alloc(dst, w, h)) {
        bloom_model_image_free(&v);
        return -1;
    }
    /* vertical first, rounded half up ... */
    for (y = 0; y < h; y++)
        for (x = 0; x < low->w; x++)
            for (c = 0; c < 3; c++) {
                double sum = 0.0;
                for (i = 0; i < 3; i++)
                    sum += tent_w[y & 1][i] * at(low, x, (y >> 1) - 1 + i, c);
                px(&v, x, y)[c] = norm(bittrue, sum, 8.0, RND_UP); /* (sum + 4) >> 3 */
            }
    /* ... then horizontal, rounded half down (the two passes' ties cancel) */
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            for (c = 0; c < 3; c++) {
                double sum = 0.0;
                for (i = 0; i < 3; i++)
                    sum += tent_w[x & 1][i] * at(&v, (x >> 1) - 1 + i, y, c);
                px(dst, x, y)[c] = norm(bittrue, sum, 8.0, RND_DOWN); /* (sum + 3) >> 3 */
            }
    bloom_model_image_free(&v);
    return 0;
}

/* ---- argument checks --------------------------------------------------- */

static int bad_max(const int n[3], int input)
{
    int c;
    for (c = 0; c < 3; c++)
        if (n[c] < (input ? BLOOM_MODEL_F32 : 0) || n[c] > 65535)
            return 1;
    return 0;
}

static int bad_args(const bloom_model_params_t *p, const uint32_t *src, const int src_max[3])
{
    size_t i, count;
    if (!p || !src || !src_max || bad_max(src_max, 1))
        return 1;
    if (bloom_model_levels(p->width, p->height, p->levels) < 0)
        return 1;
    if (p->bittrue) {
        /* these bounds keep every intermediate below 2^53 (fixed-point.md) */
        if (p->threshold_q > (1u << 28) || p->knee_q > p->threshold_q || p->intensity_q > (1u << 24))
            return 1;
        /* 16-bit samples carry codes' decodes (up to 1.0), not linear words */
        if (p->sample_bits != 0 && p->sample_bits != 32 &&
            (p->sample_bits != 16 || src_max[0] <= 0 || src_max[1] <= 0 || src_max[2] <= 0))
            return 1;
    } else {
        if (!(p->threshold >= 0 && isfinite(p->threshold)) || !(p->soft_knee >= 0 && p->soft_knee <= 1) ||
            !(p->intensity >= 0 && isfinite(p->intensity)))
            return 1;
    }
    if ((size_t)p->width > SIZE_MAX / 3 / sizeof(double) / (size_t)p->height)
        return 1;
    count = (size_t)p->width * (size_t)p->height * 3;
    for (i = 0; i < count; i++)
        if (src_max[i % 3] > 0 && src[i] > (uint32_t)src_max[i % 3])
            return 1;
    return 0;
}

static void setup(const bloom_model_params_t *p, model_t *m)
{
    m->bt = p->bittrue != 0;
    m->one = ldexp(1.0, p->lin_bits ? p->lin_bits : 20);
    m->q16 = m->one / Q_ONE;
    if (m->bt) {
        m->t = p->threshold_q;
        m->k = p->knee_q;
        m->i = p->intensity_q;
    } else {
        m->t = p->threshold;
        m->k = p->threshold * p->soft_knee;
        /* intensity is given in gamma space whatever the linear flag says */
        m->i = bloom_srgb_to_linear(p->intensity);
    }
}

/* ---- the pipeline -------------------------------------------------------- */

static double knee_num(const model_t *m, double b);
/* G, the fraction bits of 16-bit samples (fixed-point.md, "16-bit
 * samples"): the largest G below F with L * round(P / 2^(F-G)) < 2^16,
 * P = num(1.0) + 1 the knee's peak on codes' input. */
static int s16_frac(const model_t *m, int L)
{
    const double peak = knee_num(m, m->one) + 1.0;
    const int F = (int)log2(m->one);
    int g = F - 1;
    while (g > 1 && L * fdiv(peak + ldexp(1.0, F - g - 1), ldexp(1.0, F - g)) > 65535.0)
        g--;
    return g;
}

int bloom_model_s16_frac(const bloom_model_params_t *p, int L)
{
    model_t m;
    setup(p, &m);
    return s16_frac(&m, L);
}

void bloom_model_pyramid_free(bloom_model_pyramid_t *pyr)
{
    int k;
    if (!pyr)
        return;
    bloom_model_image_free(&pyr->S);
    for (k = 0; k <= BLOOM_MODEL_MAX_LEVELS; k++) {
        bloom_model_image_free(&pyr->D[k]);
        bloom_model_image_free(&pyr->U[k]);
    }
    bloom_model_image_free(&pyr->B);
    pyr->levels = 0;
}

/* Every sample of im times f (a power of two), narrowed (rounded half to
 * even) when f < 1 and `round`. */
static void scale(bloom_model_image_t *im, double f, int round)
{
    const size_t n = (size_t)im->w * (size_t)im->h * 3;
    for (size_t i = 0; i < n; i++)
        im->px[i] = round ? norm(1, im->px[i], 1.0 / f, RND_EVEN) : im->px[i] * f;
}

int bloom_model_pyramid(const bloom_model_params_t *p, const uint32_t *src, const int src_max[3],
                        bloom_model_pyramid_t *out)
{
    model_t m;
    bloom_model_image_t t;
    size_t i, count;
    int L, k, st;

    if (!out)
        return -1;
    memset(out, 0, sizeof *out);
    if (bad_args(p, src, src_max))
        return -1;
    setup(p, &m);
    L = bloom_model_levels(p->width, p->height, p->levels);

    /* 1. decode the source into S */
    if (image_alloc(&out->S, p->width, p->height))
        goto fail;
    count = (size_t)p->width * (size_t)p->height * 3;
    for (i = 0; i < count; i++)
        out->S.px[i] = decode(&m, p->linear, src[i], src_max[i % 3]);

    /* 2-3. D1 = knee(boxdown(S)); Dk+1 = boxdown(Dk) */
    if (bloom_model_box_down(&out->S, &out->D[1], m.bt))
        goto fail;
    for (i = 0; i < (size_t)out->D[1].w * (size_t)out->D[1].h; i++) {
        double *v = out->D[1].px + 3 * i;
        knee(&m, v);
        if (p->d1_scale)
            for (k = 0; k < 3; k++)
                v[k] = m.bt ? fdiv(v[k] * p->d1_scale[i] + KNEE_ONE / 2, KNEE_ONE) : v[k] * p->d1_scale[i];
    }
    /* 16-bit samples: levels 1 .. top in G units (D_1 narrowed half to
     * even); the deeper levels keep the internal units; the box into level
     * top + 1 reads D_top widened, the tent out of it is narrowed half to
     * even; U_1 is widened for B (exact) */
    const int s16 = m.bt && p->sample_bits == 16, top = s16 ? (p->s16_levels ? p->s16_levels : 16) : 0;
    const double step = s16 ? m.one / ldexp(1.0, s16_frac(&m, L)) : 1.0;
    if (s16)
        scale(&out->D[1], 1.0 / step, 1);
    for (k = 1; k < L; k++) {
        if (k == top)
            scale(&out->D[k], step, 0);
        st = bloom_model_box_down(&out->D[k], &out->D[k + 1], m.bt);
        if (k == top)
            scale(&out->D[k], 1.0 / step, 0);
        if (st)
            goto fail;
    }

    /* 4-5. UL = DL; Uk = Dk + tentup(Uk+1) (an exact add); B = tentup(U1) */
    if (image_alloc(&out->U[L], out->D[L].w, out->D[L].h))
        goto fail;
    memcpy(out->U[L].px, out->D[L].px, (size_t)out->D[L].w * (size_t)out->D[L].h * 3 * sizeof(double));
    for (k = L - 1; k >= 1; k--) {
        if (bloom_model_tent_up(&out->U[k + 1], out->D[k].w, out->D[k].h, &t, m.bt))
            goto fail;
        if (k == top)
            scale(&t, 1.0 / step, 1);
        out->U[k] = t;
        for (i = 0; i < (size_t)t.w * (size_t)t.h * 3; i++)
            out->U[k].px[i] += out->D[k].px[i];
    }
    if (s16)
        scale(&out->U[1], step, 0);
    st = bloom_model_tent_up(&out->U[1], p->width, p->height, &out->B, m.bt);
    if (s16)
        scale(&out->U[1], 1.0 / step, 0);
    if (st)
        goto fail;
    out->levels = L;
    return L;

fail:
    bloom_model_pyramid_free(out);
    return -1;
}

int bloom_model_run(const bloom_model_params_t *p, const uint32_t *src, const int src_max[3],
                    uint32_t *dst_codes, const int dst_max[3], double *dst_value)
{
    bloom_model_pyramid_t pyr;
    model_t m;
    size_t i, count;
    int L;

    if (dst_codes && (!dst_max || bad_max(dst_max, 0)))
        return -1;
    L = bloom_model_pyramid(p, src, src_max, &pyr);
    if (L < 0)
        return -1;
    setup(p, &m);
    count = (size_t)p->width * (size_t)p->height * 3;
    for (i = 0; i < count; i++) {
        /* 6. composite: P = (I_q*B + 2^15) >> 16 in bit-true mode (Q16 x Q20
         * -> Q20; the product reaches 2^56, so in integers) */
        double P =
            m.bt ? (double)(((uint64_t)m.i * (uint64_t)pyr.B.px[i] + 32768u) >> 16) : m.i * pyr.B.px[i];
        double v = p->debug_view ? P : pyr.S.px[i] + P;
        if (dst_value)
            dst_value[i] = m.bt ? v / m.one : v;
        /* 7. encode */
        if (dst_codes)
            dst_codes[i] = encode(&m, p->linear, v, dst_max[i % 3]);
    }
    bloom_model_pyramid_free(&pyr);
    return L;
}
