/* GStreamer element "bloom": the fixed-point bloom engine as a
 * GstVideoFilter (port/gstreamer/README.md).
 *
 * RGB, BGRx and RGB16 in, the same format and size out, frames of 1 ..
 * BLOOM_MAX_DIM each side, each frame through bloom_process with its own
 * plane stride. In place (transform_frame_ip) when the in-place property
 * allows it and the formats and strides match, which GstBaseTransform then
 * does on the input buffer when it is writable (a copy of it otherwise);
 * out of place (transform_frame) into a new buffer otherwise.
 *
 * Properties only touch the settings, under the object lock; the streaming
 * thread re-configures the engine from them before the next frame (still
 * under the lock) and allocates only when the workspace must grow: no
 * allocation per frame. A configuration the engine refuses is reported on
 * the bus (a warning while playing, an error at negotiation) with
 * bloom_status_str's text, and the previous one is kept. */
#include "gstbloom.h"

GST_DEBUG_CATEGORY_STATIC(gst_bloom_debug);
#define GST_CAT_DEFAULT gst_bloom_debug

#ifndef GST_BLOOM_VERSION
#define GST_BLOOM_VERSION "1.0.0"
#endif
#define PACKAGE "bloom" /* GstPluginDesc.source (GST_PLUGIN_DEFINE reads it) */

/* RGB16 is native-endian in GStreamer, the engine's RGB565 little-endian. */
#if G_BYTE_ORDER == G_LITTLE_ENDIAN
#define GB_FORMATS "{ RGB, BGRx, RGB16 }"
#else
#define GB_FORMATS "{ RGB, BGRx }"
#endif

static GstStaticPadTemplate sink_template = GST_STATIC_PAD_TEMPLATE(
    "sink", GST_PAD_SINK, GST_PAD_ALWAYS, GST_STATIC_CAPS(GST_VIDEO_CAPS_MAKE(GB_FORMATS)));
static GstStaticPadTemplate src_template = GST_STATIC_PAD_TEMPLATE(
    "src", GST_PAD_SRC, GST_PAD_ALWAYS, GST_STATIC_CAPS(GST_VIDEO_CAPS_MAKE(GB_FORMATS)));

G_DEFINE_TYPE(GstBloom, gst_bloom, GST_TYPE_VIDEO_FILTER)

static bloom_format_t engine_format(GstVideoFormat f)
{
    switch (f) {
    case GST_VIDEO_FORMAT_RGB:
        return BLOOM_FMT_RGB888; /* bytes R, G, B */
    case GST_VIDEO_FORMAT_BGRx:
        return BLOOM_FMT_XRGB8888; /* bytes B, G, R, x */
#if G_BYTE_ORDER == G_LITTLE_ENDIAN
    case GST_VIDEO_FORMAT_RGB16:
        return BLOOM_FMT_RGB565; /* LE word RRRRRGGG GGGBBBBB */
#endif
    default:
        return (bloom_format_t)0;
    }
}

/* ---- configuration -------------------------------------------------------- */

/* Configure the engine from self->settings for the negotiated size (object
 * lock held). A refused configuration: *warn says why and the previous
 * settings are restored and used; when there are none, or they fail too,
 * *err says why and the engine is gone. Allocates only when the workspace
 * must grow (or shrink below a quarter). */
static void configure_locked(GstBloom *self, char **warn, char **err)
{
    bloom_config_t cfg;
    bloom_info_t info;
    char *why = NULL;
    *warn = *err = NULL;
    self->dirty = FALSE;
    bloom_status_t st =
        gst_bloom_settings_config(&self->settings, self->width, self->height, self->fmt, &cfg, &info, &why);
    if (st != BLOOM_OK && self->have_applied) {
        *warn = g_strdup_printf("%s: the previous configuration is kept", why);
        g_free(why);
        gst_bloom_settings_copy(&self->settings, &self->applied);
        st = gst_bloom_settings_config(&self->settings, self->width, self->height, self->fmt, &cfg, &info,
                                       &why);
    }
    if (st != BLOOM_OK) {
        self->engine = NULL;
        *err = why;
        return;
    }
    void *ws = self->ws;
    size_t cap = self->ws_bytes;
    if (!ws || info.workspace_bytes > cap || info.workspace_bytes < cap / 4) {
        cap = info.workspace_bytes;
        ws = g_try_malloc(cap);
        if (!ws) {
            self->engine = NULL;
            *err = g_strdup_printf("cannot allocate the engine's workspace (%zu bytes)", cap);
            return;
        }
    }
    bloom_t *b = NULL;
    st = bloom_init(&b, ws, cap, &cfg);
    if (st != BLOOM_OK) {
        if (ws != self->ws)
            g_free(ws);
        else
            self->engine = NULL; /* the shared workspace is spoilt */
        *err = g_strdup_printf("bloom_init: %s", bloom_status_str(st));
        return;
    }
    if (ws != self->ws) {
        g_free(self->ws);
        self->ws = ws;
        self->ws_bytes = cap;
    }
    self->engine = b;
    self->cfg = cfg;
    self->info = info;
    gst_bloom_settings_copy(&self->applied, &self->settings);
    self->have_applied = TRUE;
    self->engine_aux = cfg.aux_fmt != BLOOM_AUX_NONE ? self->applied.aux : NULL;
    GST_INFO_OBJECT(self, "engine: %dx%d preset %s, %d levels, workspace %zu bytes, latency %d rows",
                    cfg.width, cfg.height, bloom_preset_name(cfg.preset), info.levels, info.workspace_bytes,
                    info.latency_rows);
}

static gboolean gst_bloom_set_info(GstVideoFilter *filter, GstCaps *incaps, GstVideoInfo *in_info,
                                   GstCaps *outcaps, GstVideoInfo *out_info)
{
    GstBloom *self = GST_BLOOM(filter);
    const GstVideoFormat vf = GST_VIDEO_INFO_FORMAT(in_info);
    const int w = GST_VIDEO_INFO_WIDTH(in_info), h = GST_VIDEO_INFO_HEIGHT(in_info);
    const bloom_format_t fmt = engine_format(vf);
    (void)incaps;
    (void)outcaps;
    if (!fmt || vf != GST_VIDEO_INFO_FORMAT(out_info) || w != GST_VIDEO_INFO_WIDTH(out_info) ||
        h != GST_VIDEO_INFO_HEIGHT(out_info)) {
        GST_ELEMENT_ERROR(self, CORE, NEGOTIATION,
                          ("bloom takes RGB, BGRx or RGB16 and gives the same format and size"),
                          ("in %s %dx%d, out %s %dx%d", gst_video_format_to_string(vf), w, h,
                           gst_video_format_to_string(GST_VIDEO_INFO_FORMAT(out_info)),
                           GST_VIDEO_INFO_WIDTH(out_info), GST_VIDEO_INFO_HEIGHT(out_info)));
        return FALSE;
    }
    if (w < 1 || h < 1 || w > BLOOM_MAX_DIM || h > BLOOM_MAX_DIM) {
        GST_ELEMENT_ERROR(
            self, CORE, NEGOTIATION,
            ("bloom: the video is %dx%d, above the engine's limit of %d pixels a side", w, h, BLOOM_MAX_DIM),
            ("BLOOM_MAX_DIM is %d: scale the video down before bloom (videoscale)", BLOOM_MAX_DIM));
        return FALSE;
    }
    char *warn, *err;
    GST_OBJECT_LOCK(self);
    self->width = w;
    self->height = h;
    self->fmt = fmt;
    configure_locked(self, &warn, &err);
    const gboolean in_place = self->in_place;
    GST_OBJECT_UNLOCK(self);
    if (warn)
        GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS, ("bloom: %s", warn), (NULL));
    g_free(warn);
    if (err) {
        GST_ELEMENT_ERROR(self, LIBRARY, SETTINGS, ("bloom: %s", err),
                          ("%s %dx%d", gst_video_format_to_string(vf), w, h));
        g_free(err);
        return FALSE;
    }
    /* the same format both sides by the caps; in place also wants the strides */
    gst_base_transform_set_in_place(GST_BASE_TRANSFORM(self),
                                    in_place && GST_VIDEO_INFO_PLANE_STRIDE(in_info, 0) ==
                                                    GST_VIDEO_INFO_PLANE_STRIDE(out_info, 0));
    return TRUE;
}

/* ---- frames ------------------------------------------------------------------ */

static GstFlowReturn run_frame(GstBloom *self, const guint8 *src, ptrdiff_t src_stride, guint8 *dst,
                               ptrdiff_t dst_stride)
{
    char *warn = NULL, *err = NULL;
    GST_OBJECT_LOCK(self);
    if (self->dirty)
        configure_locked(self, &warn, &err);
    GST_OBJECT_UNLOCK(self);
    if (warn)
        GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS, ("bloom: %s", warn), (NULL));
    g_free(warn);
    if (err || !self->engine) {
        GST_ELEMENT_ERROR(self, LIBRARY, SETTINGS, ("bloom: %s", err ? err : "engine not configured"),
                          (NULL));
        g_free(err);
        return GST_FLOW_ERROR;
    }
    if (self->engine_aux)
        bloom_set_aux(self->engine, self->engine_aux->data, (ptrdiff_t)self->engine_aux->stride);
    const bloom_status_t st = bloom_process(self->engine, src, src_stride, dst, dst_stride);
    if (st != BLOOM_OK) {
        GST_ELEMENT_ERROR(self, STREAM, FAILED, ("bloom_process: %s", bloom_status_str(st)),
                          ("%dx%d, strides %td / %td", self->width, self->height, src_stride, dst_stride));
        return GST_FLOW_ERROR;
    }
    return GST_FLOW_OK;
}

static GstFlowReturn gst_bloom_transform_frame(GstVideoFilter *filter, GstVideoFrame *in, GstVideoFrame *out)
{
    return run_frame(GST_BLOOM(filter), GST_VIDEO_FRAME_PLANE_DATA(in, 0),
                     GST_VIDEO_FRAME_PLANE_STRIDE(in, 0), GST_VIDEO_FRAME_PLANE_DATA(out, 0),
                     GST_VIDEO_FRAME_PLANE_STRIDE(out, 0));
}

static GstFlowReturn gst_bloom_transform_frame_ip(GstVideoFilter *filter, GstVideoFrame *frame)
{
    guint8 *p = GST_VIDEO_FRAME_PLANE_DATA(frame, 0);
    const ptrdiff_t stride = GST_VIDEO_FRAME_PLANE_STRIDE(frame, 0);
    return run_frame(GST_BLOOM(filter), p, stride, p, stride);
}

/* Controlled properties (GstController) take their values per buffer. */
static void gst_bloom_before_transform(GstBaseTransform *trans, GstBuffer *buf)
{
    const GstClockTime t =
        gst_segment_to_stream_time(&trans->segment, GST_FORMAT_TIME, GST_BUFFER_TIMESTAMP(buf));
    if (GST_CLOCK_TIME_IS_VALID(t))
        gst_object_sync_values(GST_OBJECT(trans), t);
}

static gboolean gst_bloom_stop(GstBaseTransform *trans)
{
    GstBloom *self = GST_BLOOM(trans);
    GST_OBJECT_LOCK(self);
    self->engine = NULL;
    self->engine_aux = NULL;
    g_free(self->ws);
    self->ws = NULL;
    self->ws_bytes = 0;
    self->dirty = TRUE;
    GST_OBJECT_UNLOCK(self);
    return TRUE;
}

/* ---- the class ------------------------------------------------------------------ */

static void gst_bloom_finalize(GObject *object)
{
    GstBloom *self = GST_BLOOM(object);
    g_free(self->ws);
    gst_bloom_settings_clear(&self->settings);
    gst_bloom_settings_clear(&self->applied);
    G_OBJECT_CLASS(gst_bloom_parent_class)->finalize(object);
}

static void gst_bloom_class_init(GstBloomClass *klass)
{
    GObjectClass *oc = G_OBJECT_CLASS(klass);
    GstElementClass *ec = GST_ELEMENT_CLASS(klass);
    GstBaseTransformClass *tc = GST_BASE_TRANSFORM_CLASS(klass);
    GstVideoFilterClass *vc = GST_VIDEO_FILTER_CLASS(klass);

    oc->set_property = gst_bloom_set_property;
    oc->get_property = gst_bloom_get_property;
    oc->finalize = gst_bloom_finalize;

    gst_bloom_install_properties(oc); /* gstbloom_props.c */

    gst_element_class_set_static_metadata(
        ec, "Bloom", "Filter/Effect/Video",
        "Makes bright areas glow: pixels above a soft-knee threshold are blurred over an image "
        "pyramid and added back, in fixed-point integers (six presets: unity, gamedev, xna, "
        "attenuation, arm, cod). RGB, BGRx, RGB16; up to 16384 pixels a side",
        "the bloom engine (port/gstreamer)");
    gst_element_class_add_static_pad_template(ec, &sink_template);
    gst_element_class_add_static_pad_template(ec, &src_template);

    tc->before_transform = GST_DEBUG_FUNCPTR(gst_bloom_before_transform);
    tc->stop = GST_DEBUG_FUNCPTR(gst_bloom_stop);
    vc->set_info = GST_DEBUG_FUNCPTR(gst_bloom_set_info);
    vc->transform_frame = GST_DEBUG_FUNCPTR(gst_bloom_transform_frame);
    vc->transform_frame_ip = GST_DEBUG_FUNCPTR(gst_bloom_transform_frame_ip);
}

static void gst_bloom_init(GstBloom *self)
{
    gst_bloom_settings_init(&self->settings);
    gst_bloom_settings_init(&self->applied);
    self->in_place = TRUE;
    self->dirty = TRUE;
}

static gboolean plugin_init(GstPlugin *plugin)
{
    GST_DEBUG_CATEGORY_INIT(gst_bloom_debug, "bloom", 0, "fixed-point bloom");
    return gst_element_register(plugin, "bloom", GST_RANK_NONE, GST_TYPE_BLOOM);
}

GST_PLUGIN_DEFINE(GST_VERSION_MAJOR, GST_VERSION_MINOR, bloom,
                  "Fixed-point bloom (glow) filter on the bloom engine", plugin_init, GST_BLOOM_VERSION,
                  GST_LICENSE_UNKNOWN, "bloom engine", "port/gstreamer")
