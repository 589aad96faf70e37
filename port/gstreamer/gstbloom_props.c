/* bloom element: its properties — the enum types, the GParamSpecs with
 * the engine's limits, set (under the object lock: only the settings, the
 * engine is re-configured before the next frame) and get (what was given,
 * else the preset's default). */
#include <string.h>

#include "gstbloom.h"

enum {
    PROP_0,
    PROP_PRESET,
    PROP_THRESHOLD,
    PROP_KNEE,
    PROP_INTENSITY,
    PROP_LEVELS,
    PROP_VIEW,
    PROP_LINEAR,
    PROP_STRENGTH,
    PROP_PASSES,
    PROP_SATURATE,
    PROP_ATTENUATION,
    PROP_MAX_REDUCTION,
    PROP_TINT,
    PROP_WEIGHTS,
    PROP_ADDITIVE,
    PROP_BAKED,
    PROP_RADIUS,
    PROP_AUX_LOCATION,
    PROP_IN_PLACE,
    PROP_N_THREADS,
    PROP_SAMPLE_BITS
};

#define GST_TYPE_BLOOM_PRESET (gst_bloom_preset_get_type())
static GType gst_bloom_preset_get_type(void)
{
    static GType type = 0;
    static const GEnumValue values[] = {
        {BLOOM_PRESET_UNITY, "Unity PPv2 / Catlike Coding: box down, tent up, soft knee, additive", "unity"},
        {BLOOM_PRESET_GAMEDEV,
         "Rec.709 luminance threshold, 9-tap Gaussian at 1/2..1/8, Reinhard, gamma 1/2.2", "gamedev"},
        {BLOOM_PRESET_XNA, "XNA: threshold subtraction at 1/4, Kawase passes, screen combine", "xna"},
        {BLOOM_PRESET_ATTENUATION, "unity with level 1 scaled by a depth plane (needs aux-location)",
         "attenuation"},
        {BLOOM_PRESET_ARM, "Arm dual filtering on luminance, optional mask, baked map (aux-location)", "arm"},
        {BLOOM_PRESET_COD, "13-tap down with Karis average, 3x3 tent up, energy-conserving weights", "cod"},
        {0, NULL, NULL}};
    if (g_once_init_enter(&type))
        g_once_init_leave(&type, g_enum_register_static("GstBloomPreset", values));
    return type;
}

#define GST_TYPE_BLOOM_VIEW (gst_bloom_view_get_type())
static GType gst_bloom_view_get_type(void)
{
    static GType type = 0;
    static const GEnumValue values[] = {
        {0, "The frame with the glow added (S + I*B)", "apply"},
        {1, "The glow alone (I*B, the engine's bloom-only view)", "bloom-only"},
        {0, NULL, NULL}};
    if (g_once_init_enter(&type))
        g_once_init_leave(&type, g_enum_register_static("GstBloomView", values));
    return type;
}

/* ---- properties ---------------------------------------------------------------- */

void gst_bloom_set_property(GObject *object, guint id, const GValue *value, GParamSpec *pspec)
{
    GstBloom *self = GST_BLOOM(object);
    double list[BLOOM_MAX_LEVELS];
    int n = 0;
    GstBloomAux *aux = NULL;
    /* outside the lock: parse the lists, read the plane */
    if (id == PROP_TINT || id == PROP_WEIGHTS) {
        const char *str = g_value_get_string(value);
        const int max = id == PROP_TINT ? 3 : BLOOM_MAX_LEVELS;
        if (id == PROP_WEIGHTS && (!str || !*str))
            n = 0; /* back to the preset's weights */
        else if ((n = gst_bloom_parse_list01(str, list, max)) < (id == PROP_TINT ? 3 : 1)) {
            g_warning("bloom: %s '%s' is not %s: the value is kept", pspec->name, str ? str : "(null)",
                      id == PROP_TINT ? "R,G,B (three values, each 0..1)"
                                      : "c0,c1,... (1 to 16 values, each 0..1)");
            return;
        }
    } else if (id == PROP_AUX_LOCATION) {
        const char *path = g_value_get_string(value);
        char *err = NULL;
        if (path && *path && !(aux = gst_bloom_aux_load(path, &err))) {
            g_warning("bloom: %s: the previous plane is kept", err);
            g_free(err);
            return;
        }
    }
    GST_OBJECT_LOCK(self);
    GstBloomSettings *s = &self->settings, before;
    memcpy(&before, s, sizeof before);
    switch (id) {
    case PROP_PRESET:
        s->preset = (bloom_preset_t)g_value_get_enum(value);
        break;
    case PROP_THRESHOLD:
        s->threshold = g_value_get_double(value);
        s->given |= GB_GIVEN_THRESHOLD;
        break;
    case PROP_KNEE:
        s->knee = g_value_get_double(value);
        s->given |= GB_GIVEN_KNEE;
        break;
    case PROP_INTENSITY:
        s->intensity = g_value_get_double(value);
        s->given |= GB_GIVEN_INTENSITY;
        break;
    case PROP_LEVELS:
        s->levels = g_value_get_int(value);
        break;
    case PROP_SAMPLE_BITS:
        s->sample_bits = g_value_get_int(value);
        break;
    case PROP_VIEW:
        s->bloom_only = g_value_get_enum(value) == 1;
        break;
    case PROP_LINEAR:
        s->linear = g_value_get_boolean(value);
        break;
    case PROP_STRENGTH:
        s->strength = g_value_get_double(value);
        s->given |= GB_GIVEN_STRENGTH;
        break;
    case PROP_PASSES:
        s->passes = g_value_get_int(value);
        s->given |= GB_GIVEN_PASSES;
        break;
    case PROP_SATURATE:
        s->saturate = g_value_get_boolean(value);
        break;
    case PROP_ATTENUATION:
        s->attenuation = g_value_get_double(value);
        s->given |= GB_GIVEN_ATTENUATION;
        break;
    case PROP_MAX_REDUCTION:
        s->max_reduction = g_value_get_double(value);
        s->given |= GB_GIVEN_MAX_REDUCTION;
        break;
    case PROP_TINT:
        memcpy(s->tint, list, sizeof s->tint);
        s->given |= GB_GIVEN_TINT;
        break;
    case PROP_WEIGHTS:
        memset(s->weights, 0, sizeof s->weights);
        memcpy(s->weights, list, sizeof list[0] * (size_t)n);
        s->nweights = n;
        s->given = n ? s->given | GB_GIVEN_WEIGHTS : s->given & ~(unsigned)GB_GIVEN_WEIGHTS;
        break;
    case PROP_ADDITIVE:
        s->additive = g_value_get_boolean(value);
        break;
    case PROP_BAKED:
        s->baked = g_value_get_boolean(value);
        break;
    case PROP_RADIUS:
        s->radius = g_value_get_int(value);
        break;
    case PROP_AUX_LOCATION: {
        GstBloomAux *old = s->aux;
        s->aux = aux; /* the settings own the new plane's reference */
        aux = old;    /* released below, outside the lock */
        break;
    }
    case PROP_IN_PLACE:
        self->in_place = g_value_get_boolean(value);
        break;
    case PROP_N_THREADS:
        if (self->n_threads != g_value_get_uint(value)) {
            self->n_threads = g_value_get_uint(value);
            self->dirty = TRUE; /* the pool is rebuilt (or dropped) before the next frame */
        }
        break;
    default:
        GST_OBJECT_UNLOCK(self);
        G_OBJECT_WARN_INVALID_PROPERTY_ID(object, id, pspec);
        return;
    }
    if (memcmp(&before, s, sizeof before) != 0)
        self->dirty = TRUE; /* the engine is re-configured before the next frame */
    GST_OBJECT_UNLOCK(self);
    if (aux)
        gst_bloom_aux_unref(aux);
}

/* A parameter's value as it reads back: the stored one when it was given
 * or the preset does not read it (param), else the preset's (Q16.16 q). */
static double effective(const GstBloomSettings *s, unsigned given_bit, uint32_t param, double stored,
                        uint32_t q)
{
    const uint32_t reads = param ? bloom_preset_params(s->preset) : 0u;
    return ((s->given & given_bit) || (param && !(reads & param))) ? stored : q / 65536.0;
}

/* What a property reads back: the value given, else the preset's default
 * (at the negotiated size, or 1920x1080 before negotiation). */
void gst_bloom_get_property(GObject *object, guint id, GValue *value, GParamSpec *pspec)
{
    GstBloom *self = GST_BLOOM(object);
    bloom_config_t c;
    bloom_info_t info;
    char *why = NULL;
    double list[BLOOM_MAX_LEVELS];
    GST_OBJECT_LOCK(self);
    const GstBloomSettings *s = &self->settings;
    const uint32_t reads = bloom_preset_params(s->preset);
    const bloom_status_t st =
        gst_bloom_settings_config(s, self->width ? self->width : 1920, self->height ? self->height : 1080,
                                  BLOOM_FMT_RGB888, &c, &info, &why);
    g_free(why);
    switch (id) {
    case PROP_PRESET:
        g_value_set_enum(value, s->preset);
        break;
    case PROP_THRESHOLD:
        g_value_set_double(value, effective(s, GB_GIVEN_THRESHOLD, 0, s->threshold, c.threshold));
        break;
    case PROP_KNEE:
        g_value_set_double(value, effective(s, GB_GIVEN_KNEE, 0, s->knee, c.soft_knee));
        break;
    case PROP_INTENSITY:
        g_value_set_double(value, effective(s, GB_GIVEN_INTENSITY, 0, s->intensity, c.intensity));
        break;
    case PROP_LEVELS:
        g_value_set_int(value, s->levels);
        break;
    case PROP_VIEW:
        g_value_set_enum(value, s->bloom_only ? 1 : 0);
        break;
    case PROP_LINEAR:
        g_value_set_boolean(value, s->linear);
        break;
    case PROP_STRENGTH:
        g_value_set_double(value,
                           effective(s, GB_GIVEN_STRENGTH, BLOOM_PARAM_STRENGTH, s->strength, c.p.strength));
        break;
    case PROP_PASSES:
        g_value_set_int(value, ((s->given & GB_GIVEN_PASSES) || !(reads & BLOOM_PARAM_PASSES)) ? s->passes
                                                                                               : c.p.passes);
        break;
    case PROP_SATURATE:
        g_value_set_boolean(value, s->saturate);
        break;
    case PROP_ATTENUATION:
        g_value_set_double(value, effective(s, GB_GIVEN_ATTENUATION, BLOOM_PARAM_ATTENUATION, s->attenuation,
                                            c.p.attenuation));
        break;
    case PROP_MAX_REDUCTION:
        g_value_set_double(value, effective(s, GB_GIVEN_MAX_REDUCTION, BLOOM_PARAM_MAX_REDUCTION,
                                            s->max_reduction, c.p.max_reduction));
        break;
    case PROP_TINT:
        for (int k = 0; k < 3; k++)
            list[k] = effective(s, GB_GIVEN_TINT, BLOOM_PARAM_TINT, s->tint[k], c.p.tint[k]);
        g_value_take_string(value, gst_bloom_format_list(list, 3));
        break;
    case PROP_WEIGHTS:
        if (s->given & GB_GIVEN_WEIGHTS) {
            g_value_take_string(value, gst_bloom_format_list(s->weights, s->nweights));
        } else if (reads & BLOOM_PARAM_WEIGHTS) {
            const int L = st == BLOOM_OK ? info.levels : c.levels;
            for (int k = 0; k < L; k++)
                list[k] = c.p.level_weight[k] / 65536.0;
            g_value_take_string(value, gst_bloom_format_list(list, L));
        } else {
            g_value_set_string(value, "");
        }
        break;
    case PROP_ADDITIVE:
        g_value_set_boolean(value, s->additive);
        break;
    case PROP_BAKED:
        g_value_set_boolean(value, s->baked);
        break;
    case PROP_RADIUS:
        g_value_set_int(value, s->radius);
        break;
    case PROP_SAMPLE_BITS:
        g_value_set_int(value, s->sample_bits);
        break;
    case PROP_AUX_LOCATION:
        g_value_set_string(value, s->aux ? s->aux->path : NULL);
        break;
    case PROP_IN_PLACE:
        g_value_set_boolean(value, self->in_place);
        break;
    case PROP_N_THREADS:
        g_value_set_uint(value, self->n_threads);
        break;
    default:
        GST_OBJECT_UNLOCK(self);
        G_OBJECT_WARN_INVALID_PROPERTY_ID(object, id, pspec);
        return;
    }
    GST_OBJECT_UNLOCK(self);
}

#define GB_FLAGS (G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS | GST_PARAM_MUTABLE_PLAYING)
#define GB_CTRL (GB_FLAGS | GST_PARAM_CONTROLLABLE)

static void install(GObjectClass *oc, guint id, GParamSpec *ps)
{
    g_object_class_install_property(oc, id, ps);
}

void gst_bloom_install_properties(GObjectClass *oc)
{
    install(oc, PROP_PRESET,
            g_param_spec_enum("preset", "Preset",
                              "The bloom recipe; the other parameters start at its defaults and "
                              "a value set explicitly wins whatever the order (attenuation, and "
                              "arm with baked, need aux-location)",
                              GST_TYPE_BLOOM_PRESET, BLOOM_PRESET_UNITY, GB_FLAGS));
    install(oc, PROP_THRESHOLD,
            g_param_spec_double("threshold", "Threshold",
                                "Linear brightness above which pixels glow (default: the preset's: "
                                "unity 1.0, gamedev 0.75, xna 0.25 and below 1.0, cod 0)",
                                0.0, BLOOM_MAX_THRESHOLD / 65536.0, 1.0, GB_CTRL));
    install(oc, PROP_KNEE,
            g_param_spec_double("knee", "Soft knee",
                                "Soft knee of the threshold, 0 = hard (default: the preset's: 0.5, "
                                "gamedev and cod 0)",
                                0.0, 1.0, 0.5, GB_CTRL));
    install(oc, PROP_INTENSITY,
            g_param_spec_double("intensity", "Intensity", "Glow intensity, gamma space (0: no glow)", 0.0,
                                BLOOM_MAX_INTENSITY / 65536.0, 1.0, GB_CTRL));
    install(oc, PROP_LEVELS,
            g_param_spec_int("levels", "Levels",
                             "Pyramid depth asked for (fewer where the frame is too small; gamedev "
                             "always 3; cod: radius overrides it)",
                             1, BLOOM_MAX_LEVELS, 5, GB_CTRL));
    install(oc, PROP_SAMPLE_BITS,
            g_param_spec_int("sample-bits", "Sample bits",
                             "Bits per pyramid sample: 32, or 16 (unity, attenuation, xna and arm on 8-bit "
                             "video: 0.7-0.85x the memory; other values and presets are refused)",
                             16, 32, 32, GB_FLAGS));
    install(oc, PROP_VIEW,
            g_param_spec_enum("view", "View", "What comes out: the frame with its glow, or the glow alone",
                              GST_TYPE_BLOOM_VIEW, 0, GB_FLAGS));
    install(oc, PROP_LINEAR,
            g_param_spec_boolean("linear", "Linear", "The codes are linear light (no sRGB decode and encode)",
                                 FALSE, GB_FLAGS));
    install(oc, PROP_STRENGTH,
            g_param_spec_double("strength", "Strength",
                                "gamedev: scene + strength * bloom; arm with baked: the map's "
                                "strength",
                                0.0, 16.0, 1.0, GB_CTRL));
    install(oc, PROP_PASSES,
            g_param_spec_int("passes", "Passes", "xna: Kawase blur passes", 1, 8, 3, GB_CTRL));
    install(oc, PROP_SATURATE,
            g_param_spec_boolean("saturate", "Saturate",
                                 "xna: clamp at 1.0 between passes, as 8-bit render targets did", FALSE,
                                 GB_FLAGS));
    install(oc, PROP_ATTENUATION,
            g_param_spec_double("attenuation", "Attenuation",
                                "attenuation: a of max(lerp(1, depth, a), max-reduction)", 0.0, 1.0, 0.75,
                                GB_CTRL));
    install(oc, PROP_MAX_REDUCTION,
            g_param_spec_double("max-reduction", "Maximum reduction",
                                "attenuation: r, the floor of the depth factor", 0.0, 1.0, 0.25, GB_CTRL));
    install(
        oc, PROP_TINT,
        g_param_spec_string("tint", "Tint", "cod, arm: glow colour \"R,G,B\", each 0..1", "1,1,1", GB_FLAGS));
    install(oc, PROP_WEIGHTS,
            g_param_spec_string("weights", "Level weights",
                                "cod: blend factors \"c0,c1,...\" (1..16 values, each 0..1; c0 is "
                                "the final composite); empty = the energy-conserving defaults of the "
                                "level count",
                                "", GB_FLAGS));
    install(oc, PROP_ADDITIVE,
            g_param_spec_boolean("additive", "Additive",
                                 "cod: add the levels instead of the energy-conserving blend", FALSE,
                                 GB_FLAGS));
    install(oc, PROP_BAKED,
            g_param_spec_boolean("baked", "Baked",
                                 "arm: no pyramid, out = S + S * map * strength with aux-location as "
                                 "the map",
                                 FALSE, GB_FLAGS));
    install(oc, PROP_RADIUS,
            g_param_spec_int("radius", "Radius",
                             "cod: the level count whose glow reaches about this many pixels "
                             "(0: use levels)",
                             0, 1 << 20, 0, GB_CTRL));
    install(oc, PROP_AUX_LOCATION,
            g_param_spec_string("aux-location", "Aux plane",
                                "attenuation's depth plane, arm's mask or baked map: a binary PGM "
                                "(8 or 16 bit) of the video's size, read when set",
                                NULL, GB_FLAGS));
    install(oc, PROP_IN_PLACE,
            g_param_spec_boolean("in-place", "In place",
                                 "Work in the input buffer (GstBaseTransform copies it first when it "
                                 "is not writable); false: write a new buffer (better after a tee)",
                                 TRUE, G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS | GST_PARAM_MUTABLE_READY));
    install(oc, PROP_N_THREADS,
            g_param_spec_uint("n-threads", "Threads",
                              "Threads per frame: the frame cut into tiles, one engine each, the "
                              "same bytes whatever the count (0: the online CPUs; 1: no thread). "
                              "Above one the element works out of place (a new buffer) whatever "
                              "in-place says; YUY2 always runs on one",
                              0, BLOOM_MT_MAX_THREADS, 1, GB_FLAGS));
    gst_type_mark_as_plugin_api(GST_TYPE_BLOOM_PRESET, 0);
    gst_type_mark_as_plugin_api(GST_TYPE_BLOOM_VIEW, 0);
}
