/* bloom_sim pixel rules: decoded images to frames, frames to engine formats,
 * engine output to display codes, BT.601 Y'CbCr. The rules are documented in
 * sim/docs/simulator.md; every integer rounding is round half up. Also the
 * readers' shared guards on what a header may cost (sizes, pipes, rows
 * that grow with the data). */
#include "sim.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "bloom_model.h"

int sim_errf(char *err, size_t errlen, const char *fmt, ...)
{
    if (err && errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

int sim_frame_alloc(sim_frame_t *f, int w, int h)
{
    size_t n = (size_t)w * (size_t)h * 3u;
    if (w < 1 || h < 1)
        return -1;
    if (f->px && (size_t)f->w * (size_t)f->h * 3u >= n) {
        f->w = w;
        f->h = h;
        memset(f->px, 0, n * sizeof *f->px);
        return 0;
    }
    uint32_t *px = calloc(n, sizeof *px);
    if (!px)
        return -1;
    free(f->px);
    f->px = px;
    f->w = w;
    f->h = h;
    return 0;
}

void sim_frame_free(sim_frame_t *f)
{
    if (f) {
        free(f->px);
        memset(f, 0, sizeof *f);
    }
}

/* ---- what a header may cost ------------------------------------------- */

long long sim_stream_left(FILE *f)
{
    struct stat st;
    off_t pos = ftello(f), end;
    if (pos < 0)
        return -1;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode))
        return st.st_size > pos ? (long long)(st.st_size - pos) : 0;
    /* not a file descriptor (fmemopen): seekable streams tell their end */
    if (fseeko(f, 0, SEEK_END) != 0 || (end = ftello(f)) < 0 || fseeko(f, pos, SEEK_SET) != 0)
        return -1;
    return end > pos ? (long long)(end - pos) : 0;
}

FILE *sim_spool(FILE *f, char *err, size_t errlen)
{
    FILE *t = tmpfile();
    char buf[16384];
    size_t n;
    if (!t) {
        sim_errf(err, errlen, "cannot create a temporary file: %s", strerror(errno));
        return NULL;
    }
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        if (fwrite(buf, 1, n, t) != n) {
            sim_errf(err, errlen, "cannot write a temporary file: %s", strerror(errno));
            fclose(t);
            return NULL;
        }
    if (ferror(f) || fflush(t) != 0 || fseeko(t, 0, SEEK_SET) != 0) {
        sim_errf(err, errlen, "read error: %s", strerror(errno));
        fclose(t);
        return NULL;
    }
    return t;
}

int sim_img_rows(img_t *img, int rows, int *cap)
{
    if (rows <= *cap)
        return 0;
    if (rows > img->height)
        return -1;
    const size_t row =
        (size_t)img->width * (size_t)img->channels * (img->maxval ? sizeof(uint16_t) : sizeof(float));
    int n = *cap < 16 ? 16 : *cap;
    while (n < rows)
        n = n > img->height / 2 ? img->height : 2 * n;
    if (n > img->height)
        n = img->height;
    void *p = realloc(img->maxval ? (void *)img->u16 : (void *)img->f32, row * (size_t)n);
    if (!p)
        return -1;
    memset((char *)p + row * (size_t)*cap, 0, row * (size_t)(n - *cap));
    if (img->maxval)
        img->u16 = p;
    else
        img->f32 = p;
    *cap = n;
    return 0;
}

/* ---- one sample between ranges ---------------------------------------- */

static uint32_t round_unit(double v, unsigned n) /* v in [0, 1] -> round(v * n) */
{
    return (uint32_t)floor(v * (double)n + 0.5);
}

/* c of range m (0 = Q16.16, SIM_F32 = the bits of a linear float) to
 * range n (the same). A float goes through Q16.16 (img_float_to_q16) to
 * any other range; a float made from a code is its Q16.16 value. */
static uint32_t convert(uint32_t c, unsigned m, unsigned n, int linear)
{
    if (m == n)
        return c;
    if (m == SIM_F32) {
        float v;
        memcpy(&v, &c, sizeof v);
        c = img_float_to_q16(v);
        m = 0;
        if (n == 0)
            return c;
    }
    if (n == SIM_F32) {
        const float v = (float)(convert(c, m, 0, linear) / 65536.0);
        uint32_t b;
        memcpy(&b, &v, sizeof b);
        return b;
    }
    if (m && n) /* code to code: round half up of c * n / m */
        return (uint32_t)(((uint64_t)c * n + m / 2u) / m);
    if (m) /* code to linear Q16.16: what the engine's decoder computes */
        return linear ? (uint32_t)(((uint64_t)c * 65536u + m / 2u) / m)
                      : round_unit(bloom_srgb_to_linear((double)c / m), 65536u);
    /* linear Q16.16 to code: the engine's encoder rule, clipped at 1.0 */
    uint32_t v = c > 65536u ? 65536u : c;
    return linear ? (uint32_t)(((uint64_t)v * n + 32768u) >> 16)
                  : round_unit(bloom_linear_to_srgb(v / 65536.0), n);
}

int sim_frame_from_img(const img_t *im, int decode16_srgb, sim_frame_t *f)
{
    if (sim_frame_alloc(f, im->width, im->height))
        return -1;
    const size_t n = (size_t)im->width * (size_t)im->height;
    const int ch = im->channels;
    const unsigned m = (unsigned)im->maxval;
    const int wide = !im->f32 && m > 255u;
    for (int c = 0; c < 3; c++)
        f->max[c] = im->f32 ? (int)SIM_F32 : wide ? 0 : 255;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            size_t s = i * (size_t)ch + (size_t)(ch == 3 ? c : 0);
            uint32_t v;
            if (im->f32) /* the float itself (RGBF32); to words where needed */
                memcpy(&v, &im->f32[s], sizeof v);
            else if (!wide)
                v = convert(im->u16[s], m, 255u, 0);
            else if (decode16_srgb)
                v = convert(im->u16[s], m, 0u, 0);
            else
                v = convert(im->u16[s], m, 0u, 1);
            f->px[3 * i + (size_t)c] = v;
        }
    return 0;
}

/* ---- Y'CbCr (BT.601, BT.709) ----------------------------------------------
 * Coefficients in Q16 (round(x * 65536)): limited range scales Y' by
 * 255/219 and chroma by 255/224; BT.601 Kr = 0.299, Kb = 0.114, BT.709
 * Kr = 0.2126, Kb = 0.0722. */

static uint32_t clamp_q16(int32_t t) /* Q16 value plus 1/2 -> 0..255 */
{
    if (t < 0)
        return 0;
    t >>= 16;
    return t > 255 ? 255u : (uint32_t)t;
}

void sim_ycbcr_to_rgb(int y, int cb, int cr, int how, uint32_t rgb[3])
{
    /* [how]: Y' scale, R' from v, G' from u and v, B' from u */
    static const int32_t k[4][5] = {{76309, 104597, 25675, 53279, 132201},
                                    {65536, 91881, 22553, 46802, 116130},
                                    {76309, 117489, 13975, 34925, 138438},
                                    {65536, 103206, 12276, 30679, 121609}};
    const int32_t *c = k[how & 3], u = cb - 128, v = cr - 128;
    const int32_t yy = c[0] * (y - ((how & SIM_YCC_FULL) ? 0 : 16)) + 32768;
    rgb[0] = clamp_q16(yy + c[1] * v);
    rgb[1] = clamp_q16(yy - c[2] * u - c[3] * v);
    rgb[2] = clamp_q16(yy + c[4] * u);
}

void sim_rgb8_to_yuv420(const uint8_t *rgb, int w, int h, uint8_t *out)
{
    const int cw = (w + 1) / 2, chh = (h + 1) / 2;
    uint8_t *yp = out, *up = out + (size_t)w * (size_t)h, *vp = up + (size_t)cw * (size_t)chh;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint8_t *p = rgb + 3 * ((size_t)y * (size_t)w + (size_t)x);
            int32_t t = 16829 * p[0] + 33039 * p[1] + 6416 * p[2] + (16 << 16) + 32768;
            yp[(size_t)y * (size_t)w + (size_t)x] = (uint8_t)(t >> 16);
        }
    for (int by = 0; by < chh; by++)
        for (int bx = 0; bx < cw; bx++) {
            int32_t su = 0, sv = 0, cnt = 0;
            for (int y = 2 * by; y < 2 * by + 2 && y < h; y++)
                for (int x = 2 * bx; x < 2 * bx + 2 && x < w; x++) {
                    const uint8_t *p = rgb + 3 * ((size_t)y * (size_t)w + (size_t)x);
                    su += -9714 * p[0] - 19070 * p[1] + 28784 * p[2];
                    sv += 28784 * p[0] - 24103 * p[1] - 4681 * p[2];
                    cnt++;
                }
            /* 128 + round(sum / (cnt * 65536)); the biased sums are positive */
            const int32_t one = cnt * 65536;
            up[(size_t)by * (size_t)cw + (size_t)bx] = (uint8_t)((su + 128 * one + one / 2) / one);
            vp[(size_t)by * (size_t)cw + (size_t)bx] = (uint8_t)((sv + 128 * one + one / 2) / one);
        }
}

/* ---- engine formats ----------------------------------------------------- */

static const struct {
    const char *name;
    bloom_format_t fmt;
} fmt_names[] = {
    {"rgb888", BLOOM_FMT_RGB888}, {"xrgb8888", BLOOM_FMT_XRGB8888}, {"rgb565", BLOOM_FMT_RGB565},
    {"rgbq16", BLOOM_FMT_RGBQ16}, {"rgbf32", BLOOM_FMT_RGBF32},
};

int sim_fmt_parse(const char *s, bloom_format_t *fmt)
{
    for (size_t i = 0; i < sizeof fmt_names / sizeof fmt_names[0]; i++)
        if (!strcasecmp(s, fmt_names[i].name)) {
            *fmt = fmt_names[i].fmt;
            return 0;
        }
    return -1;
}

const char *sim_fmt_name(bloom_format_t fmt)
{
    for (size_t i = 0; i < sizeof fmt_names / sizeof fmt_names[0]; i++)
        if (fmt_names[i].fmt == fmt)
            return fmt_names[i].name;
    return "?";
}

void sim_fmt_max(bloom_format_t fmt, int max[3])
{
    max[0] = max[1] = max[2] = 255;
    if (fmt == BLOOM_FMT_RGB565) {
        max[0] = max[2] = 31;
        max[1] = 63;
    } else if (fmt == BLOOM_FMT_RGBQ16) {
        max[0] = max[1] = max[2] = 0;
    } else if (fmt == BLOOM_FMT_RGBF32) {
        max[0] = max[1] = max[2] = (int)SIM_F32;
    }
}

void sim_to_engine(const sim_frame_t *f, bloom_format_t fmt, int linear, uint8_t *buf)
{
    int tmax[3];
    sim_fmt_max(fmt, tmax);
    const size_t n = (size_t)f->w * (size_t)f->h;
    for (size_t i = 0; i < n; i++) {
        uint32_t v[3];
        for (int c = 0; c < 3; c++)
            v[c] = convert(f->px[3 * i + (size_t)c], (unsigned)f->max[c], (unsigned)tmax[c], linear);
        switch (fmt) {
        case BLOOM_FMT_RGB888:
            for (int c = 0; c < 3; c++)
                buf[3 * i + (size_t)c] = (uint8_t)v[c];
            break;
        case BLOOM_FMT_XRGB8888:
            buf[4 * i] = (uint8_t)v[2];
            buf[4 * i + 1] = (uint8_t)v[1];
            buf[4 * i + 2] = (uint8_t)v[0];
            buf[4 * i + 3] = 0xFF;
            break;
        case BLOOM_FMT_RGB565: {
            uint32_t wd = v[0] << 11 | v[1] << 5 | v[2];
            buf[2 * i] = (uint8_t)wd;
            buf[2 * i + 1] = (uint8_t)(wd >> 8);
            break;
        }
        case BLOOM_FMT_RGBQ16:
        case BLOOM_FMT_RGBF32:
            memcpy(buf + 12 * i, v, 12);
            break;
        }
    }
}

void sim_from_engine(const uint8_t *buf, bloom_format_t fmt, size_t npix, uint32_t *codes)
{
    for (size_t i = 0; i < npix; i++) {
        uint32_t *o = codes + 3 * i;
        switch (fmt) {
        case BLOOM_FMT_RGB888:
            o[0] = buf[3 * i];
            o[1] = buf[3 * i + 1];
            o[2] = buf[3 * i + 2];
            break;
        case BLOOM_FMT_XRGB8888:
            o[0] = buf[4 * i + 2];
            o[1] = buf[4 * i + 1];
            o[2] = buf[4 * i];
            break;
        case BLOOM_FMT_RGB565: {
            uint32_t wd = (uint32_t)buf[2 * i] | (uint32_t)buf[2 * i + 1] << 8;
            o[0] = wd >> 11;
            o[1] = (wd >> 5) & 63u;
            o[2] = wd & 31u;
            break;
        }
        case BLOOM_FMT_RGBQ16:
        case BLOOM_FMT_RGBF32:
            memcpy(o, buf + 12 * i, 12);
            break;
        }
    }
}

void sim_codes_to_rgb8(const uint32_t *codes, const int max[3], size_t npix, int linear, uint8_t *rgb)
{
    for (size_t i = 0; i < 3 * npix; i++)
        rgb[i] = (uint8_t)convert(codes[i], (unsigned)max[i % 3], 255u, linear);
}

void sim_codes_to_float(const uint32_t *codes, const int max[3], size_t npix, int linear, float *out)
{
    for (size_t i = 0; i < 3 * npix; i++) {
        const int m = max[i % 3];
        float f;
        memcpy(&f, &codes[i], sizeof f);
        double v = m == (int)SIM_F32 ? (f > 0.0f ? (double)f : 0.0)
                   : m == 0          ? codes[i] / 65536.0
                   : linear          ? (double)codes[i] / m
                                     : bloom_srgb_to_linear((double)codes[i] / m);
        out[i] = (float)v;
    }
}
