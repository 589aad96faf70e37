/* bloom_cam --aux FILE: the one-channel plane of the presets that read one
 * (attenuation's depth plane, arm's mask or baked map), a static binary PGM
 * read once before streaming and given to the engine with every row.
 * No image library: P5 only, 8-bit or 16-bit (big-endian, as PGM stores it). */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cam.h"

static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    return -1;
}

/* The next header number (whitespace and # comments skipped); -1 if none. */
static long header_num(FILE *f)
{
    int ch = fgetc(f);
    for (;;) {
        if (ch == '#')
            while (ch != EOF && ch != '\n')
                ch = fgetc(f);
        else if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n')
            ch = fgetc(f);
        else
            break;
    }
    long v = 0;
    int digits = 0;
    while (ch >= '0' && ch <= '9' && v < 1000000) {
        v = v * 10 + (ch - '0');
        digits++;
        ch = fgetc(f);
    }
    if (!digits || !(ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n'))
        return -1; /* one whitespace byte ends each number (the last one before the data) */
    return v;
}

int cam_aux_load(const char *path, int w, int h, bloom_aux_format_t *fmt, uint8_t **data,
                 char *err, size_t errlen)
{
    *data = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fail(err, errlen, "--aux %s: %s", path, strerror(errno));
    char m[2];
    long pw = -1, ph = -1, mv = -1;
    if (fread(m, 1, 2, f) != 2 || m[0] != 'P' || m[1] != '5' || (pw = header_num(f)) < 1 ||
        (ph = header_num(f)) < 1 || (mv = header_num(f)) < 1 || mv > 65535) {
        fclose(f);
        return fail(err, errlen,
                    "--aux %s: not a binary PGM (P5, maxval 1..65535): bloom_cam reads the aux "
                    "plane as an 8-bit or 16-bit grey PGM",
                    path);
    }
    if (pw != w || ph != h) {
        fclose(f);
        return fail(err, errlen,
                    "--aux %s: the plane is %ldx%ld but the capture is %dx%d (the size the "
                    "driver set with VIDIOC_S_FMT); it must be the same",
                    path, pw, ph, w, h);
    }
    const int wide = mv > 255, in_bps = wide ? 2 : 1;
    const size_t n = (size_t)w * (size_t)h;
    uint8_t *raw = malloc(n * (size_t)in_bps), *out = malloc(n * (size_t)in_bps);
    if (!raw || !out) {
        free(raw);
        free(out);
        fclose(f);
        return fail(err, errlen, "--aux %s: out of memory", path);
    }
    size_t got = fread(raw, (size_t)in_bps, n, f);
    fclose(f);
    if (got != n) {
        free(raw);
        free(out);
        return fail(err, errlen, "--aux %s: truncated: %zu of %zu samples", path, got, n);
    }
    const uint32_t top = wide ? 65535u : 255u;
    for (size_t i = 0; i < n; i++) {
        uint32_t c = wide ? (uint32_t)raw[2 * i] << 8 | raw[2 * i + 1] : raw[i];
        if (c > (uint32_t)mv) {
            free(raw);
            free(out);
            return fail(err, errlen, "--aux %s: sample %zu is %u, above maxval %ld", path, i,
                        (unsigned)c, mv);
        }
        if ((uint32_t)mv != top)
            c = (c * top + (uint32_t)mv / 2u) / (uint32_t)mv; /* round half up */
        if (wide) {
            const uint16_t c16 = (uint16_t)c;
            memcpy(out + 2 * i, &c16, 2);
        } else {
            out[i] = (uint8_t)c;
        }
    }
    free(raw);
    *fmt = wide ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
    *data = out;
    return 0;
}
