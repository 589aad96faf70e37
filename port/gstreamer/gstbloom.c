/* GStreamer element "bloom": the fixed-point bloom engine as a
 * GstVideoFilter (port/gstreamer/README.md).
 *
 * RGB, BGRx and RGB16 in, the same format and size out, frames of 1 ..
 * BLOOM_MAX_DIM each side, each frame through bloom_process with its own
 * plane stride. YUY2 too, without a full-frame conversion: each row is
 * converted to RGB888 by the camera tool's converter (port/linux/cam_conv.c,
 * BT.601 limited range), pushed to the engine (bloom_push_row, which copies
 * the rows it reads back: BLOOM_FLAG_COPY_SOURCE), and each output row
 * pulled (bloom_pull_row) is converted back to YUY2 by the same file's
 * encoder: two RGB888 rows of the element's own (run_yuy2). In place
 * (transform_frame_ip) when the in-place property allows it and the
 * formats and strides match, which GstBaseTransform then does on the input
 * buffer when it is writable (a copy of it otherwise); out of place
 * (transform_frame) into a new buffer otherwise.
 *
 * n-threads above one (RGB, BGRx, RGB16): the frame is cut into tiles, each
 * rendered by its own engine on a pool of POSIX threads (port/threads,
 * bloom_mt_process, bit for bit the one engine's frame), all carved from
 * ws. A tile's halo reads its neighbours' source, so the pool never works
 * in place: while it runs the element is out of place whatever in-place
 * says, switched before the buffer that first runs on it (and back when
 * n-threads returns to one). YUY2 stays on the one engine's rows.
 *
 * Properties only touch the settings, under the object lock; the streaming
 * thread re-configures the engine (or the pool) from them before the next
 * frame (still under the lock) and allocates only when the workspace must
 * grow: no allocation per frame, the pool's threads started at
 * configuration only. A configuration the engine refuses is reported on
 * the bus (a warning while playing, an error at negotiation) with
 * bloom_status_str's text, and the previous one is kept. */
#include "gstbloom.h"

#include "cam_conv.h" /* port/linux: the camera tool's row converters */

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
/* YUY2 in the colorimetries whose range and matrix are cam_conv.c's rule,
 * limited-range BT.601 (the transfer and primaries do not enter it):
 * GStreamer's bt601 (2:4:16:4), its form before 1.18 (2:4:5:4), and what
 * v4l2src reports for a camera's sRGB (2:4:7:1) and 470BG (2:4:5:3)
 * Y'CbCr. Anything else (full range as jpegdec gives, BT.709 HD video) is
 * not offered, so a videoconvert in front converts it properly (to one of
 * these or to RGB) instead of bloom decoding it with the wrong rule. */
#define GB_YUY2_CAPS                                                                                         \
    GST_VIDEO_CAPS_MAKE("YUY2") ", colorimetry = (string) { bt601, 2:4:5:4, 2:4:7:1, 2:4:5:3 }"
#define GB_CAPS GST_VIDEO_CAPS_MAKE(GB_FORMATS) "; " GB_YUY2_CAPS

static GstStaticPadTemplate sink_template =
    GST_STATIC_PAD_TEMPLATE("sink", GST_PAD_SINK, GST_PAD_ALWAYS, GST_STATIC_CAPS(GB_CAPS));
static GstStaticPadTemplate src_template =
    GST_STATIC_PAD_TEMPLATE("src", GST_PAD_SRC, GST_PAD_ALWAYS, GST_STATIC_CAPS(GB_CAPS));

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
    case GST_VIDEO_FORMAT_YUY2:
        return BLOOM_FMT_RGB888; /* row by row through cam_conv.c (run_yuy2) */
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
static bloom_status_t stream_config(const GstBloom *self, bloom_config_t *cfg, bloom_info_t *info, char **why)
{
    bloom_status_t st =
        gst_bloom_settings_config(&self->settings, self->width, self->height, self->fmt, cfg, info, why);
    if (st == BLOOM_OK && self->yuy2) {
        /* the converted rows are gone once the next row is converted: the
         * engine keeps the ones it reads back (info->ring_bytes[0]) */
        cfg->flags |= BLOOM_FLAG_COPY_SOURCE;
        st = bloom_query(cfg, info);
        if (st != BLOOM_OK)
            *why = g_strdup_printf("YUY2 at %dx%d: %s", self->width, self->height, bloom_status_str(st));
    }
    return st;
}

/* Appends text (taken) to *msg ("; " between). */
static void add_text(char **msg, char *text)
{
    if (!*msg) {
        *msg = text;
        return;
    }
    char *both = g_strdup_printf("%s; %s", *msg, text);
    g_free(*msg);
    g_free(text);
    *msg = both;
}

/* The engines gone (object lock held): the pool stopped and joined first,
 * its state and its tiles' workspaces being in ws. ws itself is kept. */
static void drop_engine_locked(GstBloom *self)
{
    bloom_mt_free(self->mt);
    self->mt = NULL;
    self->engine = NULL;
    self->tiles = 1;
}

/* ws of at least need bytes: kept when it is large enough and not four
 * times too large, else allocated anew (FALSE, ws unchanged, when that
 * fails). Only with the engines dropped. */
static gboolean ws_reserve(GstBloom *self, size_t need)
{
    if (self->ws && need <= self->ws_bytes && need >= self->ws_bytes / 4)
        return TRUE;
    void *ws = g_try_malloc(need);
    if (!ws)
        return FALSE;
    g_free(self->ws);
    self->ws = ws;
    self->ws_bytes = need;
    return TRUE;
}

/* n-threads resolved (object lock held): 0 is the online CPUs; YUY2 stays
 * on the one engine's row interface (run_yuy2). */
static int threads_wanted(const GstBloom *self)
{
    if (self->yuy2)
        return 1;
    return self->n_threads ? (int)self->n_threads : bloom_mt_cpus();
}

/* The tile engines on their pool for cfg, in ws (object lock held, engines
 * dropped); FALSE with *warn saying why when it cannot be (one engine
 * then). */
static gboolean start_pool_locked(GstBloom *self, const bloom_config_t *cfg, int n, char **warn)
{
    const size_t bytes = bloom_mt_size(cfg, n);
    bloom_status_t st;
    if (!bytes)
        add_text(warn, g_strdup_printf("n-threads %d: the engine refuses the tiles: one thread", n));
    else if (!ws_reserve(self, bytes))
        add_text(warn, g_strdup_printf("n-threads %d: cannot allocate %zu bytes: one thread", n, bytes));
    else if ((st = bloom_mt_init(&self->mt, self->ws, self->ws_bytes, cfg, n)) != BLOOM_OK)
        add_text(warn, g_strdup_printf("n-threads %d: %s: one thread", n, bloom_mt_status_str(st)));
    else
        self->tiles = bloom_mt_tiles(self->mt);
    return self->mt != NULL; /* bloom_mt_init leaves it NULL on a failure */
}

/* Configure the engine from self->settings and n-threads for the
 * negotiated size (object lock held). A refused configuration: *warn says
 * why and the previous settings are restored and used; when there are
 * none, or they fail too, *err says why and the engine is gone. With more
 * than one tile (n-threads, RGB formats) the tile engines and their pool
 * are built instead of the one engine; a pool that cannot be built falls
 * back to one engine with a warning. Allocates only when the buffer must
 * grow (or shrink below a quarter); the pool's threads are started here,
 * never per frame. */
static void configure_locked(GstBloom *self, char **warn, char **err)
{
    bloom_config_t cfg;
    bloom_info_t info;
    char *why = NULL;
    *warn = *err = NULL;
    self->dirty = FALSE;
    bloom_status_t st = stream_config(self, &cfg, &info, &why);
    if (st != BLOOM_OK && self->have_applied) {
        *warn = g_strdup_printf("%s: the previous configuration is kept", why);
        g_free(why);
        gst_bloom_settings_copy(&self->settings, &self->applied);
        st = stream_config(self, &cfg, &info, &why);
    }
    drop_engine_locked(self); /* before ws is reused or freed */
    if (st != BLOOM_OK) {
        *err = why;
        return;
    }
    const int n = threads_wanted(self);
    if (n <= 1 || bloom_mt_tiles_for(&cfg, n) <= 1 || !start_pool_locked(self, &cfg, n, warn)) {
        if (!ws_reserve(self, info.workspace_bytes)) {
            *err =
                g_strdup_printf("cannot allocate the engine's workspace (%zu bytes)", info.workspace_bytes);
            return;
        }
        bloom_t *b = NULL;
        st = bloom_init(&b, self->ws, self->ws_bytes, &cfg);
        if (st != BLOOM_OK) {
            *err = g_strdup_printf("bloom_init: %s", bloom_status_str(st));
            return;
        }
        self->engine = b;
    }
    self->cfg = cfg;
    self->info = info;
    gst_bloom_settings_copy(&self->applied, &self->settings);
    self->have_applied = TRUE;
    self->engine_aux = cfg.aux_fmt != BLOOM_AUX_NONE ? self->applied.aux : NULL;
    GST_INFO_OBJECT(self,
                    "engine: %dx%d preset %s, %d levels, workspace %zu bytes (source copy %zu), latency %d "
                    "rows, YUY2 rows %zu bytes; %d tile(s), buffer %zu bytes",
                    cfg.width, cfg.height, bloom_preset_name(cfg.preset), info.levels, info.workspace_bytes,
                    info.ring_bytes[0], info.latency_rows, self->rows_bytes, self->tiles, self->ws_bytes);
}

/* In place when the in-place property asks for it, the strides allow it
 * and no pool runs (object lock held). */
static gboolean want_in_place_locked(const GstBloom *self)
{
    return self->in_place && self->strides_match && !self->mt;
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
                          ("bloom takes RGB, BGRx, RGB16 or YUY2 and gives the same format and size"),
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
    const gboolean yuy2 = vf == GST_VIDEO_FORMAT_YUY2;
    if (yuy2 && (GST_VIDEO_INFO_COLORIMETRY(in_info).range != GST_VIDEO_COLOR_RANGE_16_235 ||
                 GST_VIDEO_INFO_COLORIMETRY(in_info).matrix != GST_VIDEO_COLOR_MATRIX_BT601)) {
        /* cam_conv.c's rule (the caps say so; a caller can still force
         * other caps): full-range codes would clip, BT.709 shift hues */
        GST_ELEMENT_ERROR(self, CORE, NEGOTIATION,
                          ("bloom takes YUY2 in limited range (16-235), BT.601 only: put videoconvert in "
                           "front for another colorimetry"),
                          ("colorimetry %s", gst_video_colorimetry_to_string(&in_info->colorimetry)));
        return FALSE;
    }
    /* YUY2: the two RGB888 rows of run_yuy2 (an odd width converts its
     * padding pixel too: GStreamer's YUY2 rows hold whole pairs) */
    const size_t row = yuy2 ? (size_t)GST_ROUND_UP_2(w) * 3u : 0u;
    guint8 *rows = NULL;
    if (yuy2 && !(rows = g_try_malloc(2 * row))) {
        GST_ELEMENT_ERROR(self, RESOURCE, NO_SPACE_LEFT, ("bloom: cannot allocate 2 rows of %zu bytes", row),
                          (NULL));
        return FALSE;
    }
    char *warn, *err;
    GST_OBJECT_LOCK(self);
    self->width = w;
    self->height = h;
    self->fmt = fmt;
    self->yuy2 = yuy2;
    g_free(self->rgb_in);
    self->rgb_in = rows;
    self->rgb_out = rows ? rows + row : NULL;
    self->rows_bytes = 2 * row;
    /* the same format both sides by the caps; in place also wants the strides */
    self->strides_match = GST_VIDEO_INFO_PLANE_STRIDE(in_info, 0) == GST_VIDEO_INFO_PLANE_STRIDE(out_info, 0);
    configure_locked(self, &warn, &err);
    self->have_caps = err == NULL;
    const gboolean in_place = want_in_place_locked(self);
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
    /* before GstBaseTransform decides the allocation (after set_caps) */
    self->in_place_now = in_place;
    gst_base_transform_set_in_place(GST_BASE_TRANSFORM(self), in_place);
    return TRUE;
}

/* ---- frames ------------------------------------------------------------------ */

/* A YUY2 frame through the engine's row interface: each source row to
 * RGB888 into rgb_in and pushed (the engine copies what it reads back),
 * each output row pulled into rgb_out and written back as YUY2 to its row
 * of dst. Output row y comes after source row y is pushed, so dst may be
 * src (in place). The same pulls and pushes as bloom_run_rows. */
static bloom_status_t run_yuy2(GstBloom *self, const guint8 *src, ptrdiff_t src_stride, guint8 *dst,
                               ptrdiff_t dst_stride)
{
    bloom_t *b = self->engine;
    const GstBloomAux *aux = self->engine_aux;
    const int w = self->width, h = self->height;
    bloom_status_t st = bloom_begin(b);
    while (st == BLOOM_OK) {
        int y;
        while (y = bloom_rows_out(b), (st = bloom_pull_row(b, self->rgb_out)) == BLOOM_OK)
            cam_rgb888_row_to_yuyv(self->rgb_out, dst + (ptrdiff_t)y * dst_stride, w);
        if (st < 0 || st == BLOOM_DONE)
            break;
        y = bloom_rows_in(b);
        cam_yuyv_row_to_rgb888(src + (ptrdiff_t)y * src_stride, self->rgb_in, GST_ROUND_UP_2(w));
        st = bloom_push_row_aux(b, self->rgb_in, aux ? aux->data + (size_t)y * aux->stride : NULL);
    }
    if (st == BLOOM_DONE)
        st = bloom_rows_out(b) == h ? BLOOM_OK : BLOOM_E_INTERNAL;
    return st;
}

/* One frame through what configure_locked built: the pool (out of place
 * only), the one engine's whole frame, or YUY2's rows. The configuration
 * is made before the frame (gst_bloom_before_transform), not here: the
 * frame's in-place or out-of-place call was chosen for it. */
static GstFlowReturn run_frame(GstBloom *self, const guint8 *src, ptrdiff_t src_stride, guint8 *dst,
                               ptrdiff_t dst_stride)
{
    if (!self->engine && !self->mt) {
        GST_ELEMENT_ERROR(self, LIBRARY, SETTINGS,
                          ("bloom: %s", self->pending_err ? self->pending_err : "engine not configured"),
                          (NULL));
        g_free(self->pending_err);
        self->pending_err = NULL;
        return GST_FLOW_ERROR;
    }
    const GstBloomAux *aux = self->engine_aux;
    bloom_status_t st;
    if (self->mt) {
        st = aux ? bloom_mt_set_aux(self->mt, aux->data, (ptrdiff_t)aux->stride) : BLOOM_OK;
        if (st == BLOOM_OK)
            st = bloom_mt_process(self->mt, src, src_stride, dst, dst_stride);
    } else {
        if (aux)
            bloom_set_aux(self->engine, aux->data, (ptrdiff_t)aux->stride);
        st = self->yuy2 ? run_yuy2(self, src, src_stride, dst, dst_stride)
                        : bloom_process(self->engine, src, src_stride, dst, dst_stride);
    }
    if (st != BLOOM_OK) {
        GST_ELEMENT_ERROR(
            self, STREAM, FAILED,
            ("%s: %s", self->mt ? "bloom_mt_process" : "bloom_process", bloom_mt_status_str(st)),
            ("%dx%d, strides %td / %td, %d tile(s)", self->width, self->height, src_stride, dst_stride,
             self->tiles));
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

/* Before each buffer, in the streaming thread, ahead of GstBaseTransform's
 * choice of an output buffer: controlled properties (GstController) take
 * their values, then the engine is re-configured when a property changed.
 * When that starts or stops the pool, the element turns out of place (or
 * back to the in-place property's choice) from this very buffer, and the
 * source pad is marked for reconfiguration so that GstBaseTransform redoes
 * its allocation (a buffer pool out of place, none in place) before it
 * prepares this buffer's output (default_submit_input_buffer). */
static void gst_bloom_before_transform(GstBaseTransform *trans, GstBuffer *buf)
{
    GstBloom *self = GST_BLOOM(trans);
    const GstClockTime t =
        gst_segment_to_stream_time(&trans->segment, GST_FORMAT_TIME, GST_BUFFER_TIMESTAMP(buf));
    if (GST_CLOCK_TIME_IS_VALID(t))
        gst_object_sync_values(GST_OBJECT(trans), t);
    char *warn = NULL, *err = NULL;
    GST_OBJECT_LOCK(self);
    const gboolean configure = self->dirty && self->have_caps;
    if (configure)
        configure_locked(self, &warn, &err);
    const gboolean in_place = want_in_place_locked(self);
    GST_OBJECT_UNLOCK(self);
    if (warn)
        GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS, ("bloom: %s", warn), (NULL));
    g_free(warn);
    if (configure) { /* an error is posted by the frame, which fails */
        g_free(self->pending_err);
        self->pending_err = err;
    }
    if (in_place != self->in_place_now) {
        GST_DEBUG_OBJECT(self, "%s place from this buffer (%d tile(s))", in_place ? "in" : "out of",
                         self->tiles);
        self->in_place_now = in_place;
        gst_base_transform_set_in_place(trans, in_place);
        gst_base_transform_reconfigure_src(trans);
    }
}

static gboolean gst_bloom_stop(GstBaseTransform *trans)
{
    GstBloom *self = GST_BLOOM(trans);
    GST_OBJECT_LOCK(self);
    drop_engine_locked(self); /* the pool's threads joined */
    self->engine_aux = NULL;
    self->have_caps = FALSE;
    g_free(self->pending_err);
    self->pending_err = NULL;
    g_free(self->ws);
    self->ws = NULL;
    self->ws_bytes = 0;
    g_free(self->rgb_in);
    self->rgb_in = self->rgb_out = NULL;
    self->rows_bytes = 0;
    self->dirty = TRUE;
    GST_OBJECT_UNLOCK(self);
    return TRUE;
}

/* ---- the class ------------------------------------------------------------------ */

static void gst_bloom_finalize(GObject *object)
{
    GstBloom *self = GST_BLOOM(object);
    drop_engine_locked(self); /* stop() has already, when it ran */
    g_free(self->ws);
    g_free(self->rgb_in);
    g_free(self->pending_err);
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
        "attenuation, arm, cod). RGB, BGRx, RGB16, and YUY2 row by row (BT.601 limited range); up to "
        "16384 pixels a side",
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
    self->in_place_now = TRUE;
    self->n_threads = 1;
    self->tiles = 1;
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
