/* bloom_cam --aux FILE: the one-channel plane of the presets that read one
 * (attenuation's depth plane, arm's mask or baked map), a static binary PGM
 * read once before streaming and given to the engine with every row.
 * No image library: P5 only, 8-bit or 16-bit (big-endian, as PGM stores it). */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "cam.h"

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/* The next header number, by the rules of the simulator's reader
 * (sim/imgio.c), so that both tools take the same files: whitespace and
 * '#' comments (to CR or LF) before it; after it one whitespace byte, or a
 * comment unless it is the last (maxval: the samples follow one
 * whitespace byte). -1 if none. */
static long header_num(FILE *f, int last)
{
    int ch = fgetc(f);
    while (is_space(ch) || ch == '#') {
        if (ch == '#')
            while (ch != EOF && ch != '\n' && ch != '\r')
                ch = fgetc(f);
        ch = ch == EOF ? EOF : fgetc(f);
    }
    long v = 0;
    int digits = 0;
    for (; ch >= '0' && ch <= '9'; ch = fgetc(f), digits++)
        if ((v = v * 10 + (ch - '0')) > 1000000)
            v = 1000000; /* saturate: larger than any size or maxval taken */
    if (ch == '#' && !last && digits)
        ungetc(ch, f);
    else if (!digits || !is_space(ch))
        return -1;
    return v;
}

int cam_aux_load(const char *path, int w, int h, bloom_aux_format_t *fmt, uint8_t **data, char *err,
                 size_t errlen)
{
    *data = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return cam_errf(err, errlen, "--aux %s: %s", path, strerror(errno));
    char m[2];
    long pw = -1, ph = -1, mv = -1;
    /* the magic, then whitespace or a comment */
    int ok = fread(m, 1, 2, f) == 2 && m[0] == 'P' && m[1] == '5';
    if (ok) {
        const int c = fgetc(f);
        ok = is_space(c) || (c == '#' && ungetc(c, f) != EOF);
    }
    ok = ok && (pw = header_num(f, 0)) >= 1 && (ph = header_num(f, 0)) >= 1 && (mv = header_num(f, 1)) >= 1 &&
         mv <= 65535;
    if (!ok) {
        fclose(f);
        return cam_errf(err, errlen,
                        "--aux %s: not a binary PGM (P5, maxval 1..65535): bloom_cam reads the aux "
                        "plane as an 8-bit or 16-bit grey PGM",
                        path);
    }
    if (pw != w || ph != h) {
        fclose(f);
        return cam_errf(err, errlen,
                        "--aux %s: the plane is %ldx%ld but the capture is %dx%d (the size the "
                        "driver set with VIDIOC_S_FMT); it must be the same",
                        path, pw, ph, w, h);
    }
    const int wide = mv > 255, in_bps = wide ? 2 : 1;
    const size_t n = (size_t)w * (size_t)h;
    /* a regular file too short for the plane is refused before allocating it */
    struct stat st;
    const off_t at = ftello(f);
    const unsigned long long need = (unsigned long long)n * (unsigned)in_bps;
    if (at >= 0 && fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) &&
        (st.st_size < at || (unsigned long long)(st.st_size - at) < need)) {
        const unsigned long long have =
            st.st_size > at ? (unsigned long long)(st.st_size - at) / (unsigned)in_bps : 0;
        fclose(f);
        return cam_errf(err, errlen, "--aux %s: truncated: %llu of %zu samples", path, have, n);
    }
    uint8_t *raw = malloc(n * (size_t)in_bps), *out = malloc(n * (size_t)in_bps);
    if (!raw || !out) {
        free(raw);
        free(out);
        fclose(f);
        return cam_errf(err, errlen, "--aux %s: out of memory", path);
    }
    size_t got = fread(raw, (size_t)in_bps, n, f);
    fclose(f);
    if (got != n) {
        free(raw);
        free(out);
        return cam_errf(err, errlen, "--aux %s: truncated: %zu of %zu samples", path, got, n);
    }
    const uint32_t top = wide ? 65535u : 255u;
    for (size_t i = 0; i < n; i++) {
        uint32_t c = wide ? (uint32_t)raw[2 * i] << 8 | raw[2 * i + 1] : raw[i];
        if (c > (uint32_t)mv) {
            free(raw);
            free(out);
            return cam_errf(err, errlen, "--aux %s: sample %zu is %u, above maxval %ld", path, i, (unsigned)c,
                            mv);
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
