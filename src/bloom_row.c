/* Row kernels: one row of output from a few rows of input, rounding written
 * out in full (sim/docs/fixed-point.md steps 2-7). Samples are interleaved
 * R, G, B uint32_t, Q16.16. The frame-level code only schedules these. */
#include "bloom_internal.h"

static inline int imin(int a, int b)
{
    return a < b ? a : b;
}

/* Column sum of four rows at column c (three channels). */
static inline void colsum4(const uint32_t *const s[4], int c, uint32_t out[3])
{
    const size_t i = (size_t)c * 3u;
    for (int ch = 0; ch < 3; ch++)
        out[ch] = s[0][i + ch] + s[1][i + ch] + s[2][i + ch] + s[3][i + ch];
}

void bloom_row_box_c(const uint32_t *const s[4], uint32_t *dst, int dw, int sw)
{
    uint32_t a[3], b[3], c[3], d[3];
    colsum4(s, 0, a); /* column 2x-1 = -1 clamps to 0 */
    colsum4(s, 0, b);
    for (int x = 0; x < dw; x++) {
        colsum4(s, imin(2 * x + 1, sw - 1), c);
        colsum4(s, imin(2 * x + 2, sw - 1), d);
        for (int ch = 0; ch < 3; ch++) {
            dst[3 * x + ch] = (a[ch] + b[ch] + c[ch] + d[ch] + 8u) >> 4;
            a[ch] = c[ch];
            b[ch] = d[ch];
        }
    }
}

static inline void colsum4_src(const uint8_t *const s[4], bloom_format_t fmt, bool linear, int bpp,
                               int c, uint32_t out[3])
{
    uint32_t px[3];
    out[0] = out[1] = out[2] = 0;
    for (int r = 0; r < 4; r++) {
        bloom_pixel_decode(fmt, linear, s[r] + (size_t)c * (size_t)bpp, px);
        out[0] += px[0];
        out[1] += px[1];
        out[2] += px[2];
    }
}

void bloom_row_box_src_c(const uint8_t *const s[4], bloom_format_t fmt, bool linear,
                         uint32_t *dst, int dw, int sw)
{
    const int bpp = bloom_format_bpp(fmt);
    uint32_t a[3], b[3], c[3], d[3];
    colsum4_src(s, fmt, linear, bpp, 0, a);
    b[0] = a[0];
    b[1] = a[1];
    b[2] = a[2];
    for (int x = 0; x < dw; x++) {
        colsum4_src(s, fmt, linear, bpp, imin(2 * x + 1, sw - 1), c);
        colsum4_src(s, fmt, linear, bpp, imin(2 * x + 2, sw - 1), d);
        for (int ch = 0; ch < 3; ch++) {
            dst[3 * x + ch] = (a[ch] + b[ch] + c[ch] + d[ch] + 8u) >> 4;
            a[ch] = c[ch];
            b[ch] = d[ch];
        }
    }
}

void bloom_row_knee_c(uint32_t *row, int w, const bloom_knee_t *kn)
{
    const int64_t t = kn->t, k = kn->k;
    /* Below t - k nothing passes: the common case costs three compares. */
    const uint32_t cut = kn->t > kn->k ? kn->t - kn->k : 0u;
    for (int x = 0; x < w; x++) {
        uint32_t *p = row + 3 * x;
        uint32_t bmax = p[0] > p[1] ? p[0] : p[1];
        bmax = bmax > p[2] ? bmax : p[2];
        if (bmax <= cut || bmax == 0) {
            p[0] = p[1] = p[2] = 0;
            continue;
        }
        int64_t xs = (int64_t)bmax - t + k; /* > 0 here */
        if (xs > 2 * k)
            xs = 2 * k;
        uint32_t soft = 0;
        if (k > 0)
            soft = bloom_div_u64_u32((uint64_t)(xs * xs) + (uint64_t)(2 * k), (uint32_t)(4 * k));
        int64_t over = (int64_t)bmax - t;
        uint64_t num = over > (int64_t)soft ? (uint64_t)over : soft;
        if (num == 0) {
            p[0] = p[1] = p[2] = 0;
            continue;
        }
        uint32_t f = bloom_div_u64_u32((num << 16) + (bmax >> 1), bmax);
        for (int ch = 0; ch < 3; ch++)
            p[ch] = (uint32_t)(((uint64_t)p[ch] * f + 32768u) >> 16);
    }
}

/* Vertical tent of one column: weights (3,4,1) even, (1,4,3) odd. U is
 * below 2^32, so the weighted sums need 64 bits (one UMLAL per tap on
 * Cortex-M); the results fit in 32 again. */
static inline void vtent(const uint32_t *const u[3], int odd, int c, uint32_t v[3])
{
    const size_t i = (size_t)c * 3u;
    const uint64_t wa = odd ? 1u : 3u, wc = odd ? 3u : 1u;
    for (int ch = 0; ch < 3; ch++)
        v[ch] = (uint32_t)((wa * u[0][i + ch] + 4u * (uint64_t)u[1][i + ch] +
                            wc * u[2][i + ch] + 4u) >> 3);
}

void bloom_row_tent_c(const uint32_t *const u[3], int odd, const uint32_t *add, uint32_t *dst,
                      int x0, int n, int sw)
{
    int x = x0, end = x0 + n;
    int m = x >> 1;
    uint32_t vp[3], vc[3], vn[3];
    vtent(u, odd, m > 0 ? m - 1 : 0, vp);
    vtent(u, odd, m, vc);
    while (x < end) {
        vtent(u, odd, imin(m + 1, sw - 1), vn);
        if (!(x & 1)) { /* even column: (3, 4, 1) */
            for (int ch = 0; ch < 3; ch++) {
                uint32_t t = (uint32_t)((3u * (uint64_t)vp[ch] + 4u * (uint64_t)vc[ch] + vn[ch] + 4u) >> 3);
                dst[3 * (x - x0) + ch] = t + (add ? add[3 * (x - x0) + ch] : 0u);
            }
            x++;
        }
        if (x < end) { /* odd column: (1, 4, 3) */
            for (int ch = 0; ch < 3; ch++) {
                uint32_t t = (uint32_t)(((uint64_t)vp[ch] + 4u * (uint64_t)vc[ch] + 3u * (uint64_t)vn[ch] + 4u) >> 3);
                dst[3 * (x - x0) + ch] = t + (add ? add[3 * (x - x0) + ch] : 0u);
            }
            x++;
        }
        for (int ch = 0; ch < 3; ch++) {
            vp[ch] = vc[ch];
            vc[ch] = vn[ch];
        }
        m++;
    }
}

void bloom_row_out_c(const uint32_t *const u[3], int odd, const uint8_t *src, uint8_t *dst, int w,
                     int sw, const bloom_out_t *o)
{
    const int ibpp = bloom_format_bpp(o->in_fmt), obpp = bloom_format_bpp(o->out_fmt);
    uint32_t bl[3 * BLOOM_OUT_CHUNK];
    for (int x0 = 0; x0 < w; x0 += BLOOM_OUT_CHUNK) {
        const int n = imin(BLOOM_OUT_CHUNK, w - x0);
        bloom_row_tent_c(u, odd, NULL, bl, x0, n, sw);
        for (int i = 0; i < n; i++) {
            const size_t x = (size_t)(x0 + i);
            uint32_t s[3], v[3];
            if (!o->debug)
                bloom_pixel_decode(o->in_fmt, o->linear, src + x * (size_t)ibpp, s);
            for (int ch = 0; ch < 3; ch++) {
                uint64_t p = ((uint64_t)o->intensity * bl[3 * i + ch] + 32768u) >> 16;
                if (!o->debug)
                    p += s[ch];
                v[ch] = p > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)p;
            }
            bloom_pixel_encode(o->out_fmt, o->linear, v, dst + x * (size_t)obpp);
        }
    }
}
