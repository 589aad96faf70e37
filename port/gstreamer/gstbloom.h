/* GStreamer element "bloom": the fixed-point bloom engine (include/bloom.h)
 * as a GstVideoFilter. gstbloom.c is the element (caps, frames, the
 * engine's re-configuration, n-threads through port/threads/bloom_mt.h);
 * gstbloom_props.c its properties; gstbloom_conf.c turns the properties'
 * settings into an engine configuration (and reads the aux plane), with no
 * GObject in it. */
#ifndef GST_BLOOM_H
#define GST_BLOOM_H

#include <gst/gst.h>
#include <gst/video/gstvideofilter.h>
#include <gst/video/video.h>

#include "bloom.h"
#include "bloom_mt.h" /* port/threads: tile engines on a pool of threads */

G_BEGIN_DECLS

/* ---- settings: what the properties ask for (gstbloom_conf.c) ------------- */

/* A parameter given explicitly: it overrides the preset's default whatever
 * the order the properties were set in (as bloom_sim and bloom_cam do). */
enum {
    GB_GIVEN_THRESHOLD = 1u << 0,
    GB_GIVEN_KNEE = 1u << 1,
    GB_GIVEN_INTENSITY = 1u << 2,
    GB_GIVEN_STRENGTH = 1u << 3,
    GB_GIVEN_PASSES = 1u << 4,
    GB_GIVEN_ATTENUATION = 1u << 5,
    GB_GIVEN_MAX_REDUCTION = 1u << 6,
    GB_GIVEN_TINT = 1u << 7,
    GB_GIVEN_WEIGHTS = 1u << 8
};

/* The one-channel plane of aux-location (a binary PGM), shared between the
 * settings that name it (reference counted, g_rc_box). */
typedef struct {
    char *path;
    int width, height;
    bloom_aux_format_t fmt; /* BLOOM_AUX_U8 (maxval <= 255) or BLOOM_AUX_U16 */
    size_t stride;          /* bytes per row: width * 1 or 2 */
    guint8 *data;           /* native samples, rescaled to 255 / 65535 */
} GstBloomAux;

typedef struct {
    bloom_preset_t preset;
    double threshold, knee, intensity; /* as given (GB_GIVEN_*) */
    int levels;                        /* 1 .. 16 */
    gboolean bloom_only, linear;       /* view, linear */
    double strength, attenuation, max_reduction, tint[3];
    int passes;
    int nweights;
    double weights[BLOOM_MAX_LEVELS];
    gboolean saturate, additive, baked;
    int radius;      /* 0: the level count is `levels` */
    int sample_bits; /* 32 or 16 (cfg.sample_bits) */
    unsigned given;
    GstBloomAux *aux; /* NULL: no plane */
} GstBloomSettings;

void gst_bloom_settings_init(GstBloomSettings *s);
/* dst becomes a copy of src (dst's own aux released first). */
void gst_bloom_settings_copy(GstBloomSettings *dst, const GstBloomSettings *src);
void gst_bloom_settings_clear(GstBloomSettings *s);

/* The engine configuration of s for w x h frames of fmt: the preset's
 * defaults for that size, then what was given. Checked with bloom_query
 * (info); on a refusal returns the status and, in *why (g_free), a message
 * naming the parameter and what to do. */
bloom_status_t gst_bloom_settings_config(const GstBloomSettings *s, int w, int h, bloom_format_t fmt,
                                         bloom_config_t *cfg, bloom_info_t *info, char **why);

/* "R,G,B" / "c0,c1,...": n (max) values in 0 .. 1; the count, or -1. */
int gst_bloom_parse_list01(const char *str, double *out, int max);
/* The list as a string ("1,0.5,0.25"), g_free. */
char *gst_bloom_format_list(const double *v, int n);

/* Reads a binary PGM (P5, maxval 1..65535) as bloom_cam --aux does; NULL
 * with *err (g_free) on failure. */
GstBloomAux *gst_bloom_aux_load(const char *path, char **err);
GstBloomAux *gst_bloom_aux_ref(GstBloomAux *a);
void gst_bloom_aux_unref(GstBloomAux *a);

/* ---- the element ----------------------------------------------------------- */

#define GST_TYPE_BLOOM (gst_bloom_get_type())
G_DECLARE_FINAL_TYPE(GstBloom, gst_bloom, GST, BLOOM, GstVideoFilter)

struct _GstBloom {
    GstVideoFilter parent;

    /* under the object lock: what the properties ask for, and the last
     * settings the engine accepted (kept when a change is refused) */
    GstBloomSettings settings, applied;
    gboolean have_applied;
    gboolean dirty;    /* settings changed since the engine was configured */
    gboolean in_place; /* property in-place */
    guint n_threads;   /* property n-threads: 0 the online CPUs, else the count */

    /* streaming thread (configured under the object lock, between frames) */
    int width, height;
    bloom_format_t fmt;
    bloom_config_t cfg;
    bloom_info_t info;
    bloom_t *engine; /* one engine: NULL until configured, and while mt runs */
    /* threads (n-threads resolving to more than one tile, RGB formats
     * only): the tile engines and their pool, carved from ws; never in
     * place (bloom_mt_process refuses src == dst), so the element is
     * out of place while mt is set (gst_bloom_before_transform) */
    bloom_mt_t *mt;
    int tiles; /* mt's tiles (= threads, the streaming one included); 1 without */
    void *ws;  /* the workspace, ws_bytes: bloom_workspace_size, or bloom_mt_size with mt */
    size_t ws_bytes;
    gboolean have_caps;            /* set_info succeeded (the size and format are known) */
    gboolean strides_match;        /* in and out plane strides equal (set_info): in place possible */
    gboolean in_place_now;         /* what GstBaseTransform was last told (gst_base_transform_set_in_place) */
    char *pending_err;             /* a configuration error of before_transform, posted by the frame */
    const GstBloomAux *engine_aux; /* the plane the engine reads (in applied) */

    /* YUY2: the engine runs RGB888 with BLOOM_FLAG_COPY_SOURCE (it keeps the
     * source rows its composite reads back in its workspace) and each frame
     * goes through row by row (run_yuy2 in gstbloom.c); the only buffers of
     * the element's own are these two RGB888 rows, allocated at caps time */
    gboolean yuy2;
    guint8 *rgb_in, *rgb_out; /* round_up_2(width) * 3 bytes each, in one block */
    size_t rows_bytes;        /* the block: 2 rows */
};

/* The properties (gstbloom_props.c). */
void gst_bloom_install_properties(GObjectClass *oc);
void gst_bloom_set_property(GObject *object, guint id, const GValue *value, GParamSpec *pspec);
void gst_bloom_get_property(GObject *object, guint id, GValue *value, GParamSpec *pspec);

G_END_DECLS
#endif
