/* bloom_sim --aux FILE: the one-channel plane of the presets that read one
 * (the depth plane of attenuation, the mask or baked map of arm), read once
 * and used for every frame.
 *
 * Accepted: a grey PGM (P5) or grey PNG, 8-bit (maxval <= 255: the engine's
 * BLOOM_AUX_U8, codes rescaled to 0..255 as round(c * 255 / maxval) when
 * maxval < 255) or 16-bit (maxval > 255: BLOOM_AUX_U16, V4L2 Z16 style,
 * rescaled to 0..65535 as round(c * 65535 / maxval) when maxval < 65535).
 * Anything else (RGB, PFM, JPEG, ...) is refused with the file's name. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* fseeko */
#endif

#include "sim.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

void sim_aux_free(sim_aux_t *a)
{
    free(a->data);
    free(a->codes);
    memset(a, 0, sizeof *a);
}

int sim_aux_load(sim_aux_t *a, const char *path, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return sim_errf(err, errlen, "%s: --aux: cannot open: %s", path, strerror(errno));
    char why[SIM_ERRLEN];
    /* the magic is looked at and then read again: a pipe is spooled first */
    if (sim_stream_left(fp) < 0) {
        FILE *t = sim_spool(fp, why, sizeof why);
        fclose(fp);
        if (!t)
            return sim_errf(err, errlen, "%s: --aux: %s", path, why);
        fp = t;
    }
    unsigned char m[8];
    size_t n = fread(m, 1, sizeof m, fp);
    img_t im;
    int rc;
    memset(&im, 0, sizeof im);
    if (fseeko(fp, 0, SEEK_SET) != 0) {
        fclose(fp);
        return sim_errf(err, errlen, "%s: --aux: cannot read: %s", path, strerror(errno));
    }
    if (n >= 2 && m[0] == 'P' && (m[1] == '5' || m[1] == '6' || m[1] == 'f' || m[1] == 'F')) {
        rc = img_fread(fp, path, &im, BLOOM_MAX_DIM, why, sizeof why);
        fclose(fp);
        size_t pl = strlen(path); /* imgio names the path itself: keep what is wrong */
        if (rc && !strncmp(why, path, pl) && !strncmp(why + pl, ": ", 2))
            memmove(why, why + pl + 2, strlen(why + pl + 2) + 1);
    } else if (n == 8 && !memcmp(m, "\x89PNG\r\n\x1a\n", 8)) {
        rc = sim_png_read(fp, &im, why, sizeof why);
        fclose(fp);
    } else {
        fclose(fp);
        return sim_errf(err, errlen,
                        "%s: --aux: not a PGM or PNG image (the aux plane is one channel: an "
                        "8-bit or 16-bit grey PGM or PNG)",
                        path);
    }
    if (rc)
        return sim_errf(err, errlen, "%s: --aux: %s", path, why);
    if (!im.u16 || im.channels != 1) {
        sim_errf(err, errlen,
                 "%s: --aux: %s image; the aux plane is one channel (an 8-bit or 16-bit grey PGM "
                 "or PNG)",
                 path, im.f32 ? "a float (PFM)" : "an RGB");
        img_free(&im);
        return -1;
    }
    const size_t np = (size_t)im.width * (size_t)im.height;
    const int wide = im.maxval > 255;
    const uint32_t top = wide ? 65535u : 255u, mv = (uint32_t)im.maxval;
    a->w = im.width;
    a->h = im.height;
    a->max = (int)top;
    a->fmt = wide ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
    a->data = malloc(np * (wide ? 2 : 1));
    a->codes = malloc(np * sizeof *a->codes);
    if (!a->data || !a->codes) {
        img_free(&im);
        sim_aux_free(a);
        return sim_errf(err, errlen, "%s: --aux: out of memory", path);
    }
    for (size_t i = 0; i < np; i++) {
        uint32_t c = im.u16[i];
        if (mv != top)
            c = (c * top + mv / 2u) / mv; /* round half up */
        a->codes[i] = c;
        if (wide) {
            const uint16_t c16 = (uint16_t)c; /* native byte order, as the engine reads it */
            memcpy(a->data + 2 * i, &c16, 2);
        } else {
            a->data[i] = (uint8_t)c;
        }
    }
    snprintf(a->desc, sizeof a->desc, "%s %dx%d %d-bit grey", n == 8 && m[0] == 0x89 ? "PNG" : "PGM",
             im.width, im.height, wide ? 16 : 8);
    img_free(&im);
    return 0;
}
