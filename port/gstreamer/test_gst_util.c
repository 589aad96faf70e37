/* make test-gst: the helpers of test_gst.c (see test_gst.h). */
#include <stdio.h>
#include <string.h>

#include "test_gst.h"

const tg_fmt_t tg_fmts[TG_NFMTS] = {
    {GST_VIDEO_FORMAT_RGB, BLOOM_FMT_RGB888, 3, "RGB"},
    {GST_VIDEO_FORMAT_BGRx, BLOOM_FMT_XRGB8888, 4, "BGRx"},
    {GST_VIDEO_FORMAT_RGB16, BLOOM_FMT_RGB565, 2, "RGB16"},
};

guint8 *tg_frame(const tg_fmt_t *f, int w, int h, int stride, guint32 seed)
{
    GRand *r = g_rand_new_with_seed(seed);
    guint8 *p = g_malloc((gsize)stride * (gsize)h);
    memset(p, 0xA5, (gsize)stride * (gsize)h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const int dark = y < h / 3, spot = g_rand_int_range(r, 0, 100) < 3;
            for (int b = 0; b < f->bpp; b++)
                p[(gsize)y * (gsize)stride + (gsize)x * (gsize)f->bpp + (gsize)b] =
                    (guint8)(dark ? (spot ? 255 : g_rand_int_range(r, 0, 40)) : g_rand_int_range(r, 0, 256));
        }
    g_rand_free(r);
    return p;
}

void tg_config(bloom_config_t *c, bloom_preset_t p, int w, int h, bloom_format_t f)
{
    bloom_config_default(c, w, h);
    c->in_fmt = c->out_fmt = f;
    fail_unless(bloom_config_preset(c, p) == BLOOM_OK, "preset %d not in this build", (int)p);
}

guint8 *tg_engine(const bloom_config_t *cfg, const guint8 *src, int stride, const guint8 *aux, int aux_stride)
{
    bloom_info_t info;
    bloom_t *b;
    if (bloom_query(cfg, &info) != BLOOM_OK)
        return NULL;
    void *ws = g_malloc(info.workspace_bytes);
    guint8 *dst = g_malloc((gsize)stride * (gsize)cfg->height);
    memcpy(dst, src, (gsize)stride * (gsize)cfg->height); /* the padding as in the source */
    bloom_status_t st = bloom_init(&b, ws, info.workspace_bytes, cfg);
    if (st == BLOOM_OK && aux)
        st = bloom_set_aux(b, aux, aux_stride);
    if (st == BLOOM_OK)
        st = bloom_process(b, src, stride, dst, stride);
    g_free(ws);
    if (st != BLOOM_OK) {
        g_free(dst);
        return NULL;
    }
    return dst;
}

int tg_default_stride(const tg_fmt_t *f, int w, int h)
{
    GstVideoInfo info;
    gst_video_info_set_format(&info, f->vf, (guint)w, (guint)h);
    return GST_VIDEO_INFO_PLANE_STRIDE(&info, 0);
}

GstBuffer *tg_buffer(const tg_fmt_t *f, int w, int h, int stride, const guint8 *px, int px_stride)
{
    GstBuffer *b = gst_buffer_new_allocate(NULL, (gsize)stride * (gsize)h, NULL);
    GstMapInfo m;
    fail_unless(gst_buffer_map(b, &m, GST_MAP_WRITE));
    memset(m.data, 0xA5, m.size);
    for (int y = 0; y < h; y++)
        memcpy(m.data + (gsize)y * (gsize)stride, px + (gsize)y * (gsize)px_stride, (gsize)w * (gsize)f->bpp);
    gst_buffer_unmap(b, &m);
    if (stride != tg_default_stride(f, w, h)) {
        gsize offset[GST_VIDEO_MAX_PLANES] = {0};
        gint strides[GST_VIDEO_MAX_PLANES] = {stride};
        gst_buffer_add_video_meta_full(b, GST_VIDEO_FRAME_FLAG_NONE, f->vf, (guint)w, (guint)h, 1, offset,
                                       strides);
    }
    return b;
}

gboolean tg_same(GstBuffer *buf, const tg_fmt_t *f, int w, int h, const guint8 *exp, int exp_stride,
                 char **why)
{
    GstVideoInfo info;
    GstVideoFrame fr;
    *why = NULL;
    gst_video_info_set_format(&info, f->vf, (guint)w, (guint)h);
    if (!gst_video_frame_map(&fr, &info, buf, GST_MAP_READ)) {
        *why = g_strdup("cannot map the output as a video frame");
        return FALSE;
    }
    const guint8 *d = GST_VIDEO_FRAME_PLANE_DATA(&fr, 0);
    const int stride = GST_VIDEO_FRAME_PLANE_STRIDE(&fr, 0);
    for (int y = 0; y < h && !*why; y++)
        for (int x = 0; x < w * f->bpp; x++) {
            const guint8 a = d[(gsize)y * (gsize)stride + (gsize)x],
                         e = exp[(gsize)y * (gsize)exp_stride + (gsize)x];
            if (a != e) {
                *why = g_strdup_printf("%s %dx%d: row %d byte %d is %u, the engine's %u", f->name, w, h, y, x,
                                       a, e);
                break;
            }
        }
    gst_video_frame_unmap(&fr);
    return *why == NULL;
}

char *tg_caps(const tg_fmt_t *f, int w, int h)
{
    return g_strdup_printf("video/x-raw,format=%s,width=%d,height=%d,framerate=25/1", f->name, w, h);
}

void tg_pipe_new(tg_pipe_t *p, const tg_fmt_t *f, int w, int h)
{
    GError *err = NULL;
    char *caps = tg_caps(f, w, h);
    char *desc = g_strdup_printf("appsrc name=src format=time caps=\"%s\" ! bloom name=bloom ! "
                                 "appsink name=sink sync=false",
                                 caps);
    memset(p, 0, sizeof *p);
    p->pipe = gst_parse_launch(desc, &err);
    fail_unless(p->pipe && !err, "gst_parse_launch(%s): %s", desc, err ? err->message : "?");
    g_free(desc);
    g_free(caps);
    p->src = gst_bin_get_by_name(GST_BIN(p->pipe), "src");
    p->bloom = gst_bin_get_by_name(GST_BIN(p->pipe), "bloom");
    p->sink = gst_bin_get_by_name(GST_BIN(p->pipe), "sink");
    p->bus = gst_element_get_bus(p->pipe);
}

gboolean tg_pipe_play(tg_pipe_t *p)
{
    return gst_element_set_state(p->pipe, GST_STATE_PLAYING) != GST_STATE_CHANGE_FAILURE;
}

GstBuffer *tg_pipe_run(tg_pipe_t *p, const tg_fmt_t *f, int w, int h, const guint8 *px, int stride)
{
    GstBuffer *in = tg_buffer(f, w, h, stride, px, stride);
    GST_BUFFER_PTS(in) = (GstClockTime)p->frames * (GST_SECOND / 25);
    GST_BUFFER_DURATION(in) = GST_SECOND / 25;
    p->frames++;
    if (gst_app_src_push_buffer(GST_APP_SRC(p->src), in) != GST_FLOW_OK)
        return NULL;
    GstSample *s = gst_app_sink_try_pull_sample(GST_APP_SINK(p->sink), 20 * GST_SECOND);
    if (!s)
        return NULL;
    GstBuffer *out = gst_buffer_ref(gst_sample_get_buffer(s));
    gst_sample_unref(s);
    return out;
}

char *tg_bus_text(GstBus *bus, GstMessageType type, GstClockTime timeout)
{
    GstMessage *m = gst_bus_timed_pop_filtered(bus, timeout, type);
    if (!m)
        return NULL;
    GError *e = NULL;
    gchar *dbg = NULL;
    if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ERROR)
        gst_message_parse_error(m, &e, &dbg);
    else if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_WARNING)
        gst_message_parse_warning(m, &e, &dbg);
    char *t = g_strdup_printf("%s%s%s", e ? e->message : gst_message_type_get_name(GST_MESSAGE_TYPE(m)),
                              dbg ? " | " : "", dbg ? dbg : "");
    if (e)
        g_error_free(e);
    g_free(dbg);
    gst_message_unref(m);
    return t;
}

void tg_pipe_free(tg_pipe_t *p)
{
    if (!p->pipe)
        return;
    gst_element_set_state(p->pipe, GST_STATE_NULL);
    gst_object_unref(p->src);
    gst_object_unref(p->bloom);
    gst_object_unref(p->sink);
    gst_object_unref(p->bus);
    gst_object_unref(p->pipe);
    memset(p, 0, sizeof *p);
}

/* ---- files ------------------------------------------------------------------ */

static long pnm_num(const guint8 *b, gsize len, gsize *at)
{
    while (*at < len && (g_ascii_isspace(b[*at]) || b[*at] == '#')) {
        if (b[*at] == '#')
            while (*at < len && b[*at] != '\n')
                (*at)++;
        (*at)++;
    }
    long v = -1;
    for (; *at < len && g_ascii_isdigit(b[*at]); (*at)++)
        v = (v < 0 ? 0 : v * 10) + (b[*at] - '0');
    return v;
}

guint8 *tg_read_pnm(const char *path, int *w, int *h, int *channels)
{
    gchar *raw;
    gsize len, at = 2;
    if (!g_file_get_contents(path, &raw, &len, NULL))
        return NULL;
    const guint8 *b = (const guint8 *)raw;
    *channels = len > 2 && b[0] == 'P' && b[1] == '6' ? 3 : len > 2 && b[0] == 'P' && b[1] == '5' ? 1 : 0;
    const long pw = pnm_num(b, len, &at), ph = pnm_num(b, len, &at), mv = pnm_num(b, len, &at);
    at++;
    const gsize n = (gsize)(pw > 0 ? pw : 0) * (gsize)(ph > 0 ? ph : 0) * (gsize)*channels;
    if (!*channels || pw < 1 || ph < 1 || mv < 1 || mv > 255 || len < at || len - at < n) {
        g_free(raw);
        return NULL;
    }
    guint8 *px = g_memdup2(b + at, n);
    g_free(raw);
    *w = (int)pw;
    *h = (int)ph;
    return px;
}

gboolean tg_write_pgm(const char *path, int w, int h, int wide, const guint8 *data)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return FALSE;
    fprintf(f, "P5\n# bloom test plane\n%d %d\n%d\n", w, h, wide ? 65535 : 255);
    for (gsize i = 0; i < (gsize)w * (gsize)h; i++) {
        if (wide) {
            guint16 v;
            memcpy(&v, data + 2 * i, 2);
            fputc(v >> 8, f);
            fputc(v & 0xff, f);
        } else {
            fputc(data[i], f);
        }
    }
    return fclose(f) == 0;
}

const char *tg_tmp(void)
{
    const char *d = g_getenv("BLOOM_GST_TMP");
    if (!d)
        d = "build/gst/tmp";
    g_mkdir_with_parents(d, 0755);
    return d;
}

gpointer tg_race(gpointer data)
{
    tg_racer_t *r = data;
    while (!g_atomic_int_get(&r->stop)) {
        g_object_set(r->bloom, r->prop, r->vals[r->flips % r->nvals], NULL);
        r->flips++;
        g_usleep((gulong)r->pause_us);
    }
    return NULL;
}
