/* bloom_sim outputs: file-name patterns, temp files renamed into place, the
 * PPM/PNG/PFM per-frame writers and the Y4M stream writer. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* mkstemp, fchmod, fsync, sigaction */
#endif

#include "sim.h"

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* ---- temp files, removed on a fatal signal ------------------------------ */

#define TMP_SLOTS 8
static char *volatile tmp_reg[TMP_SLOTS];

static void on_signal(int sig)
{
    for (int i = 0; i < TMP_SLOTS; i++)
        if (tmp_reg[i])
            unlink(tmp_reg[i]); /* async-signal-safe */
    raise(sig);                 /* SA_RESETHAND: the default action now */
}

static void tmp_register(char *tmp)
{
    static int installed;
    if (!installed) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sa.sa_flags = (int)SA_RESETHAND;
        sigemptyset(&sa.sa_mask);
        const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
        for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
            struct sigaction old;
            /* leave a signal the caller ignores (nohup) ignored */
            if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
                sigaction(sigs[i], &sa, NULL);
        }
        installed = 1;
    }
    for (int i = 0; i < TMP_SLOTS; i++)
        if (!tmp_reg[i]) {
            tmp_reg[i] = tmp;
            return;
        }
}

static void tmp_unregister(const char *tmp)
{
    for (int i = 0; i < TMP_SLOTS; i++)
        if (tmp_reg[i] == tmp)
            tmp_reg[i] = NULL;
}

FILE *sim_tmp_open(const char *path, char **tmp, char *err, size_t errlen)
{
    static const char suffix[] = ".tmp-XXXXXX";
    size_t n = strlen(path);
    if (!(*tmp = malloc(n + sizeof suffix))) {
        sim_errf(err, errlen, "%s: out of memory", path);
        return NULL;
    }
    memcpy(*tmp, path, n);
    memcpy(*tmp + n, suffix, sizeof suffix);
    int fd = mkstemp(*tmp);
    if (fd < 0) {
        sim_errf(err, errlen, "%s: cannot create temporary file %s: %s", path, *tmp, strerror(errno));
        free(*tmp);
        *tmp = NULL;
        return NULL;
    }
    tmp_register(*tmp);
    mode_t mask = umask(0); /* mkstemp makes 0600: give the mode fopen would */
    umask(mask);
    FILE *f = NULL;
    if (fchmod(fd, 0666 & ~mask) != 0 || !(f = fdopen(fd, "wb"))) {
        sim_errf(err, errlen, "%s: cannot set up temporary file %s: %s", path, *tmp, strerror(errno));
        close(fd);
        tmp_unregister(*tmp);
        remove(*tmp);
        free(*tmp);
        *tmp = NULL;
    }
    return f;
}

int sim_tmp_commit(FILE *f, char *tmp, const char *path, int ok, char *err, size_t errlen)
{
    if (ok && (fflush(f) != 0 || ferror(f) || fsync(fileno(f)) != 0)) {
        sim_errf(err, errlen, "%s: write failed: %s", path, errno ? strerror(errno) : "I/O error");
        ok = 0;
    }
    if (fclose(f) != 0 && ok) {
        sim_errf(err, errlen, "%s: write failed on close: %s", path, strerror(errno));
        ok = 0;
    }
    if (ok && rename(tmp, path) != 0) {
        sim_errf(err, errlen, "%s: cannot rename %s over it: %s", path, tmp, strerror(errno));
        ok = 0;
    }
    if (!ok)
        remove(tmp);
    tmp_unregister(tmp);
    free(tmp);
    return ok ? 0 : -1;
}

/* ---- patterns ----------------------------------------------------------- */

struct sim_out {
    sim_out_kind_t kind;
    char *pattern;
    char *prefix, *suffix; /* around the %d, %% already turned into % */
    int has_conv, zero, width;
    long count;
    int fps_num, fps_den;
    /* Y4M stream */
    FILE *f;
    char *tmp;
    int w, h;
    uint8_t *yuv;
};

/* Copies s[0..n) turning "%%" into "%". */
static char *unescape(const char *s, size_t n)
{
    char *o = malloc(n + 1), *p = o;
    if (!o)
        return NULL;
    for (size_t i = 0; i < n; i++) {
        *p++ = s[i];
        if (s[i] == '%')
            i++;
    }
    *p = '\0';
    return o;
}

static int parse_pattern(sim_out_t *o, const char *pat, char *err, size_t errlen)
{
    const char *conv = NULL, *conv_end = NULL;
    for (const char *p = pat; *p; p++) {
        if (*p != '%')
            continue;
        if (p[1] == '%') {
            p++;
            continue;
        }
        const char *q = p + 1;
        int zero = *q == '0', width = 0;
        q += zero;
        while (*q >= '0' && *q <= '9' && width < 100)
            width = width * 10 + (*q++ - '0');
        if (*q != 'd' || conv || width > 20)
            return sim_errf(err, errlen,
                            "output pattern '%s': only one %%d conversion (optionally with a 0 "
                            "flag and a width up to 20, e.g. %%04d) and %%%% are allowed",
                            pat);
        conv = p;
        conv_end = q + 1;
        o->zero = zero;
        o->width = width;
        p = q;
    }
    o->has_conv = conv != NULL;
    size_t len = strlen(pat);
    o->prefix = unescape(pat, conv ? (size_t)(conv - pat) : len);
    o->suffix = conv ? unescape(conv_end, strlen(conv_end)) : unescape("", 0);
    if (!o->prefix || !o->suffix)
        return sim_errf(err, errlen, "out of memory");
    return 0;
}

static char *frame_path(const sim_out_t *o, long n)
{
    char num[32] = "";
    if (o->has_conv)
        snprintf(num, sizeof num, o->zero ? "%0*ld" : "%*ld", o->width, n);
    size_t len = strlen(o->prefix) + strlen(num) + strlen(o->suffix) + 1;
    char *p = malloc(len);
    if (p)
        snprintf(p, len, "%s%s%s", o->prefix, num, o->suffix);
    return p;
}

int sim_out_open(sim_out_t **out, const char *pattern, int fps_num, int fps_den, char *err, size_t errlen)
{
    *out = NULL;
    sim_out_t *o = calloc(1, sizeof *o);
    if (!o)
        return sim_errf(err, errlen, "out of memory");
    o->fps_num = fps_num;
    o->fps_den = fps_den;
    o->pattern = strdup(pattern);
    if (!o->pattern || parse_pattern(o, pattern, err, errlen)) {
        if (!o->pattern)
            sim_errf(err, errlen, "out of memory");
        sim_out_abort(o);
        return -1;
    }
    const char *name = o->has_conv ? o->suffix : o->prefix;
    const char *slash = strrchr(name, '/'), *dot = strrchr(name, '.');
    static const struct {
        const char *ext;
        sim_out_kind_t kind;
    } kinds[] = {{".ppm", SIM_OUT_PPM}, {".png", SIM_OUT_PNG}, {".pfm", SIM_OUT_PFM}, {".y4m", SIM_OUT_Y4M}};
    int found = 0;
    for (size_t i = 0; dot && (!slash || dot > slash) && i < sizeof kinds / sizeof kinds[0]; i++)
        if (!strcasecmp(dot, kinds[i].ext)) {
            o->kind = kinds[i].kind;
            found = 1;
        }
    if (!found) {
        sim_errf(err, errlen,
                 "output '%s': the name must end in .ppm, .png, .pfm (one file per frame) or "
                 ".y4m (one stream)",
                 pattern);
        sim_out_abort(o);
        return -1;
    }
    if (o->kind == SIM_OUT_Y4M && o->has_conv) {
        sim_errf(err, errlen, "output '%s': a .y4m output is one stream; its name takes no %%d", pattern);
        sim_out_abort(o);
        return -1;
    }
    /* the directory must exist: found now, not after the first frame */
    char *first = frame_path(o, 0);
    char *slash2 = first ? strrchr(first, '/') : NULL;
    struct stat st;
    if (slash2 && slash2 != first) {
        *slash2 = '\0';
        if (stat(first, &st) != 0 || !S_ISDIR(st.st_mode)) {
            sim_errf(err, errlen, "output '%s': directory '%s' does not exist", pattern, first);
            free(first);
            sim_out_abort(o);
            return -1;
        }
    }
    free(first);
    *out = o;
    return 0;
}

sim_out_kind_t sim_out_kind(const sim_out_t *o)
{
    return o->kind;
}
int sim_out_has_number(const sim_out_t *o)
{
    return o->has_conv || o->kind == SIM_OUT_Y4M;
}
const char *sim_out_pattern(const sim_out_t *o)
{
    return o->pattern;
}
long sim_out_count(const sim_out_t *o)
{
    return o->count;
}

/* ---- writers -------------------------------------------------------------- */

/* P6 8-bit, or little-endian PF (rows bottom to top), through a temp file. */
static int write_pnm(const char *path, int w, int h, const uint8_t *rgb, const float *lin, char *err,
                     size_t errlen)
{
    char *tmp;
    FILE *f = sim_tmp_open(path, &tmp, err, errlen);
    if (!f)
        return -1;
    int ok;
    const size_t row = (size_t)w * 3u;
    if (rgb) {
        ok =
            fprintf(f, "P6\n%d %d\n255\n", w, h) > 0 && fwrite(rgb, 1, row * (size_t)h, f) == row * (size_t)h;
    } else {
        ok = fprintf(f, "PF\n%d %d\n-1.0\n", w, h) > 0;
        unsigned char b[4];
        for (int y = h - 1; ok && y >= 0; y--)
            for (size_t i = 0; ok && i < row; i++) {
                uint32_t u;
                memcpy(&u, &lin[(size_t)y * row + i], 4);
                for (int k = 0; k < 4; k++)
                    b[k] = (unsigned char)(u >> (8 * k));
                ok = fwrite(b, 1, 4, f) == 4;
            }
    }
    if (!ok)
        sim_errf(err, errlen, "%s: write failed: %s", path, strerror(errno));
    return sim_tmp_commit(f, tmp, path, ok, err, errlen);
}

static int write_png(const char *path, int w, int h, const uint8_t *rgb, char *err, size_t errlen)
{
    char *tmp;
    FILE *f = sim_tmp_open(path, &tmp, err, errlen);
    if (!f)
        return -1;
    char why[SIM_ERRLEN];
    int ok = sim_png_write_rgb8(f, rgb, w, h, why, sizeof why) == 0;
    if (!ok)
        sim_errf(err, errlen, "%s: %s", path, why);
    return sim_tmp_commit(f, tmp, path, ok, err, errlen);
}

static int y4m_write(sim_out_t *o, long n, int w, int h, const uint8_t *rgb, char *err, size_t errlen)
{
    const char *path = o->prefix;
    if (!o->f) {
        size_t bytes = (size_t)w * (size_t)h + 2u * (size_t)((w + 1) / 2) * (size_t)((h + 1) / 2);
        if (!(o->yuv = malloc(bytes)))
            return sim_errf(err, errlen, "%s: out of memory", path);
        if (!(o->f = sim_tmp_open(path, &o->tmp, err, errlen)))
            return -1;
        o->w = w;
        o->h = h;
        fprintf(o->f, "YUV4MPEG2 W%d H%d F%d:%d Ip A1:1 C420jpeg XYSCSS=420JPEG XCOLORRANGE=LIMITED\n", w, h,
                o->fps_num, o->fps_den);
    } else if (w != o->w || h != o->h) {
        return sim_errf(err, errlen, "%s: frame %ld is %dx%d but the Y4M stream is %dx%d", path, n, w, h,
                        o->w, o->h);
    }
    size_t bytes = (size_t)w * (size_t)h + 2u * (size_t)((w + 1) / 2) * (size_t)((h + 1) / 2);
    sim_rgb8_to_yuv420(rgb, w, h, o->yuv);
    if (fputs("FRAME\n", o->f) < 0 || fwrite(o->yuv, 1, bytes, o->f) != bytes)
        return sim_errf(err, errlen, "%s: write failed: %s", path, strerror(errno));
    return 0;
}

int sim_out_write(sim_out_t *o, long n, int w, int h, const uint8_t *rgb, const float *lin, char *err,
                  size_t errlen)
{
    int rc;
    if (o->kind == SIM_OUT_Y4M) {
        rc = y4m_write(o, n, w, h, rgb, err, errlen);
    } else {
        if (!o->has_conv && o->count > 0)
            return sim_errf(err, errlen,
                            "output '%s' names one file but there is more than one frame: add a "
                            "frame number, e.g. out_%%04d%s",
                            o->pattern,
                            o->kind == SIM_OUT_PNG   ? ".png"
                            : o->kind == SIM_OUT_PFM ? ".pfm"
                                                     : ".ppm");
        char *path = frame_path(o, n);
        if (!path)
            return sim_errf(err, errlen, "out of memory");
        rc = o->kind == SIM_OUT_PNG
                 ? write_png(path, w, h, rgb, err, errlen)
                 : write_pnm(path, w, h, o->kind == SIM_OUT_PPM ? rgb : NULL, lin, err, errlen);
        free(path);
    }
    if (rc == 0)
        o->count++;
    return rc;
}

static void out_free(sim_out_t *o)
{
    free(o->pattern);
    free(o->prefix);
    free(o->suffix);
    free(o->yuv);
    free(o);
}

int sim_out_finish(sim_out_t *o, char *err, size_t errlen)
{
    int rc = 0;
    if (o->f)
        rc = sim_tmp_commit(o->f, o->tmp, o->prefix, 1, err, errlen);
    out_free(o);
    return rc;
}

void sim_out_abort(sim_out_t *o)
{
    if (!o)
        return;
    if (o->f)
        sim_tmp_commit(o->f, o->tmp, o->prefix, 0, NULL, 0);
    out_free(o);
}
