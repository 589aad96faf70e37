/* bloom element: the properties' settings to an engine configuration, the
 * "R,G,B" lists, and the aux plane (a binary PGM read as bloom_cam --aux
 * reads it, port/linux/cam_aux.c). No GObject here: plain data. */
#include <string.h>

#include "gstbloom.h"

void gst_bloom_settings_init(GstBloomSettings *s)
{
    memset(s, 0, sizeof *s);
    s->preset = BLOOM_PRESET_UNITY;
    s->threshold = 1.0;
    s->knee = 0.5;
    s->intensity = 1.0;
    s->levels = 5;
    s->strength = 1.0;
    s->attenuation = 0.75;
    s->max_reduction = 0.25;
    s->tint[0] = s->tint[1] = s->tint[2] = 1.0;
    s->passes = 3;
    s->sample_bits = 32;
}

void gst_bloom_settings_copy(GstBloomSettings *dst, const GstBloomSettings *src)
{
    if (dst == src)
        return;
    GstBloomAux *old = dst->aux;
    *dst = *src;
    if (dst->aux)
        gst_bloom_aux_ref(dst->aux);
    if (old)
        gst_bloom_aux_unref(old);
}

void gst_bloom_settings_clear(GstBloomSettings *s)
{
    if (s->aux)
        gst_bloom_aux_unref(s->aux);
    s->aux = NULL;
}

static uint32_t q16(double v)
{
    return BLOOM_Q16(v); /* the properties' ranges keep v in 0 .. 256 */
}

/* "unity, gamedev, ...": the presets this build carries. */
static char *available(void)
{
    GString *s = g_string_new(NULL);
    for (int p = 0; p < BLOOM_PRESET_COUNT; p++)
        if (bloom_preset_available((bloom_preset_t)p))
            g_string_append_printf(s, "%s%s", s->len ? ", " : "", bloom_preset_name((bloom_preset_t)p));
    return g_string_free(s, FALSE);
}

bloom_status_t gst_bloom_settings_config(const GstBloomSettings *s, int w, int h, bloom_format_t fmt,
                                         bloom_config_t *cfg, bloom_info_t *info, char **why)
{
    const uint32_t reads = bloom_preset_params(s->preset);
    const char *pn = bloom_preset_name(s->preset) ? bloom_preset_name(s->preset) : "?";
    *why = NULL;
    bloom_config_default(cfg, w, h);
    cfg->in_fmt = cfg->out_fmt = fmt;
    cfg->levels = s->levels; /* before the preset: cod's default weights follow it */
    if ((reads & BLOOM_PARAM_RADIUS) && s->radius > 0)
        cfg->levels = bloom_levels_for_radius(s->radius);
    cfg->flags = (s->linear ? (uint32_t)BLOOM_FLAG_LINEAR : 0u) |
                 (s->bloom_only ? (uint32_t)BLOOM_FLAG_DEBUG_VIEW : 0u);
    bloom_status_t st = bloom_config_preset(cfg, s->preset);
    if (st != BLOOM_OK) {
        char *list = available();
        *why = g_strdup_printf("preset %s: %s (this build has: %s)", pn, bloom_status_str(st), list);
        g_free(list);
        return st;
    }
    if (s->given & GB_GIVEN_THRESHOLD)
        cfg->threshold = q16(s->threshold);
    if (s->given & GB_GIVEN_KNEE)
        cfg->soft_knee = q16(s->knee);
    if (s->given & GB_GIVEN_INTENSITY)
        cfg->intensity = q16(s->intensity);
    /* a preset ignores the parameters it does not read (bloom_preset_params) */
    if ((reads & BLOOM_PARAM_STRENGTH) && (s->given & GB_GIVEN_STRENGTH))
        cfg->p.strength = q16(s->strength);
    if ((reads & BLOOM_PARAM_PASSES) && (s->given & GB_GIVEN_PASSES))
        cfg->p.passes = s->passes;
    if ((reads & BLOOM_PARAM_ATTENUATION) && (s->given & GB_GIVEN_ATTENUATION))
        cfg->p.attenuation = q16(s->attenuation);
    if ((reads & BLOOM_PARAM_MAX_REDUCTION) && (s->given & GB_GIVEN_MAX_REDUCTION))
        cfg->p.max_reduction = q16(s->max_reduction);
    if ((reads & BLOOM_PARAM_TINT) && (s->given & GB_GIVEN_TINT))
        for (int c = 0; c < 3; c++)
            cfg->p.tint[c] = q16(s->tint[c]);
    if ((reads & BLOOM_PARAM_WEIGHTS) && (s->given & GB_GIVEN_WEIGHTS))
        for (int k = 0; k < s->nweights; k++)
            cfg->p.level_weight[k] = q16(s->weights[k]);
    if ((reads & BLOOM_PARAM_SATURATE) && s->saturate)
        cfg->flags |= BLOOM_FLAG_SATURATE;
    if ((reads & BLOOM_PARAM_ADDITIVE) && s->additive)
        cfg->flags |= BLOOM_FLAG_ADDITIVE;
    if ((reads & BLOOM_PARAM_BAKED) && s->baked)
        cfg->flags |= BLOOM_FLAG_BAKED;
    cfg->aux_fmt = BLOOM_AUX_NONE;
    if ((reads & BLOOM_PARAM_AUX) && s->aux) {
        if (s->aux->width != w || s->aux->height != h) {
            *why = g_strdup_printf("preset %s: the aux plane %s is %dx%d but the video is %dx%d "
                                   "(it must be the same size)",
                                   pn, s->aux->path, s->aux->width, s->aux->height, w, h);
            return BLOOM_E_AUX;
        }
        cfg->aux_fmt = s->aux->fmt;
    }
    cfg->sample_bits = s->sample_bits;
    st = bloom_query(cfg, info);
    if (st == BLOOM_OK)
        return st;
    const char *hint = "";
    if (st == BLOOM_E_THRESHOLD && s->preset == BLOOM_PRESET_XNA)
        hint = " (xna divides by 1 - threshold: give a threshold below 1.0)";
    else if (st == BLOOM_E_AUX && s->preset == BLOOM_PRESET_ATTENUATION)
        hint = " (attenuation reads a depth plane: set aux-location to an 8- or 16-bit binary "
               "PGM of the video's size)";
    else if (st == BLOOM_E_AUX && s->preset == BLOOM_PRESET_ARM)
        hint = " (arm with baked=true reads its baked bloom map: set aux-location to an 8- or "
               "16-bit binary PGM of the video's size)";
    else if (st == BLOOM_E_SIZE)
        hint = " (the engine's BLOOM_MAX_DIM)";
    *why = g_strdup_printf("preset %s at %dx%d: %s%s", pn, w, h, bloom_status_str(st), hint);
    return st;
}

int gst_bloom_parse_list01(const char *str, double *out, int max)
{
    int n = 0;
    if (!str)
        return -1;
    for (;;) {
        char *end;
        while (*str == ' ')
            str++;
        const double v = g_ascii_strtod(str, &end);
        if (end == str || n == max || !(v >= 0.0 && v <= 1.0))
            return -1;
        while (*end == ' ')
            end++;
        if (*end && *end != ',')
            return -1;
        out[n++] = v;
        if (!*end)
            return n;
        str = end + 1;
    }
}

char *gst_bloom_format_list(const double *v, int n)
{
    GString *s = g_string_new(NULL);
    for (int i = 0; i < n; i++) {
        char buf[G_ASCII_DTOSTR_BUF_SIZE];
        g_string_append_printf(s, "%s%s", i ? "," : "", g_ascii_formatd(buf, sizeof buf, "%g", v[i]));
    }
    return g_string_free(s, FALSE);
}

/* ---- the aux plane ------------------------------------------------------ */

static void aux_clear(gpointer p)
{
    GstBloomAux *a = p;
    g_free(a->path);
    g_free(a->data);
}

GstBloomAux *gst_bloom_aux_ref(GstBloomAux *a)
{
    return g_rc_box_acquire(a);
}

void gst_bloom_aux_unref(GstBloomAux *a)
{
    g_rc_box_release_full(a, aux_clear);
}

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/* The next header number by the simulator's rules (sim/imgio.c): blanks and
 * '#' comments before it; after it one blank, or a comment unless it is the
 * last (maxval: the samples follow one blank byte). -1 if none. */
static long header_num(const guint8 *b, gsize len, gsize *at, int last)
{
    gsize i = *at;
    while (i < len && (is_space(b[i]) || b[i] == '#')) {
        if (b[i] == '#')
            while (i < len && b[i] != '\n' && b[i] != '\r')
                i++;
        if (i < len)
            i++;
    }
    long v = 0;
    int digits = 0;
    for (; i < len && b[i] >= '0' && b[i] <= '9'; i++, digits++)
        if ((v = v * 10 + (b[i] - '0')) > 1000000)
            v = 1000000;
    if (!digits || i >= len)
        return -1;
    if (b[i] == '#' && !last) {
        *at = i;
        return v;
    }
    if (!is_space(b[i]))
        return -1;
    *at = i + 1;
    return v;
}

GstBloomAux *gst_bloom_aux_load(const char *path, char **err)
{
    gchar *raw = NULL;
    gsize len = 0;
    GError *gerr = NULL;
    *err = NULL;
    if (!g_file_get_contents(path, &raw, &len, &gerr)) {
        *err = g_strdup_printf("aux-location %s: %s", path, gerr->message);
        g_error_free(gerr);
        return NULL;
    }
    const guint8 *b = (const guint8 *)raw;
    gsize at = 2;
    long w = -1, h = -1, mv = -1;
    int ok = len > 3 && b[0] == 'P' && b[1] == '5' && (is_space(b[2]) || b[2] == '#');
    ok = ok && (w = header_num(b, len, &at, 0)) >= 1 && w <= BLOOM_MAX_DIM &&
         (h = header_num(b, len, &at, 0)) >= 1 && h <= BLOOM_MAX_DIM &&
         (mv = header_num(b, len, &at, 1)) >= 1 && mv <= 65535;
    if (!ok) {
        g_free(raw);
        *err = g_strdup_printf("aux-location %s: not a binary PGM (P5, 1..%d x 1..%d, maxval "
                               "1..65535): the aux plane is an 8- or 16-bit grey PGM",
                               path, BLOOM_MAX_DIM, BLOOM_MAX_DIM);
        return NULL;
    }
    const int wide = mv > 255, bps = wide ? 2 : 1;
    const size_t n = (size_t)w * (size_t)h;
    if (len - at < n * (size_t)bps) {
        *err = g_strdup_printf("aux-location %s: truncated: %zu of %zu samples", path,
                               (size_t)(len - at) / (size_t)bps, n);
        g_free(raw);
        return NULL;
    }
    guint8 *data = g_malloc(n * (size_t)bps);
    const uint32_t top = wide ? 65535u : 255u;
    for (size_t i = 0; i < n; i++) {
        const guint8 *p = b + at + i * (size_t)bps;
        uint32_t c = wide ? (uint32_t)p[0] << 8 | p[1] : p[0];
        if (c > (uint32_t)mv) {
            *err = g_strdup_printf("aux-location %s: sample %zu is %u, above maxval %ld", path, i,
                                   (unsigned)c, mv);
            g_free(data);
            g_free(raw);
            return NULL;
        }
        if ((uint32_t)mv != top)
            c = (c * top + (uint32_t)mv / 2u) / (uint32_t)mv; /* round half up */
        if (wide) {
            const guint16 c16 = (guint16)c;
            memcpy(data + 2 * i, &c16, 2);
        } else {
            data[i] = (guint8)c;
        }
    }
    g_free(raw);
    GstBloomAux *a = g_rc_box_new0(GstBloomAux);
    a->path = g_strdup(path);
    a->width = (int)w;
    a->height = (int)h;
    a->fmt = wide ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
    a->stride = (size_t)w * (size_t)bps;
    a->data = data;
    return a;
}
