/* make test-gst: the element "bloom" under GStreamer's own check library
 * (gstcheck-1.0), held byte for byte to the engine run directly
 * (bloom_process on the same frames) and to build/bloom_sim. Here: the
 * plugin, the caps, the properties, main; the frames in test_gst_frames.c,
 * streaming in test_gst_stream.c, YUY2 in test_gst_yuy2.c, n-threads in
 * test_gst_threads.c.
 *
 * Run by the make target with GST_PLUGIN_PATH_1_0 = build/gst and
 * GST_REGISTRY_1_0 = build/gst/registry.bin (the user's registry is never
 * touched); prints check's own report, then "N passed, N failed, N skipped"
 * counted from check's results, and exits 1 on any failure. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_gst.h"

/* ---- the plugin ---------------------------------------------------------------- */

GST_START_TEST(test_plugin_from_build)
{
    GstElementFactory *f = gst_element_factory_find("bloom");
    fail_unless(f != NULL, "no element bloom: GST_PLUGIN_PATH_1_0 must name build/gst");
    GstPlugin *pl = gst_plugin_feature_get_plugin(GST_PLUGIN_FEATURE(f));
    const char *want = g_getenv("BLOOM_GST_PLUGIN");
    char *a = g_canonicalize_filename(gst_plugin_get_filename(pl), NULL);
    char *b = want ? g_canonicalize_filename(want, NULL) : NULL;
    fail_unless(a && b && !strcmp(a, b), "bloom comes from %s, not %s", a ? a : "?", want ? want : "?");
    fail_unless_equals_string(gst_element_factory_get_metadata(f, GST_ELEMENT_METADATA_KLASS),
                              "Filter/Effect/Video");
    g_free(a);
    g_free(b);
    gst_object_unref(pl);
    gst_object_unref(f);
}
GST_END_TEST;

GST_START_TEST(test_inspect_page)
{
    char *argv[] = {"gst-inspect-1.0", "bloom", NULL}, *out = NULL, *err = NULL;
    gint status = 0;
    GError *e = NULL;
    fail_unless(g_spawn_sync(NULL, argv, NULL, G_SPAWN_SEARCH_PATH, NULL, NULL, &out, &err, &status, &e),
                "gst-inspect-1.0: %s", e ? e->message : "?");
    fail_unless(g_spawn_check_wait_status(status, NULL), "gst-inspect-1.0 bloom failed: %s", err);
    static const char *const want[] = {"Filter/Effect/Video",
                                       "preset",
                                       "threshold",
                                       "knee",
                                       "intensity",
                                       "levels",
                                       "view",
                                       "linear",
                                       "strength",
                                       "passes",
                                       "saturate",
                                       "attenuation",
                                       "max-reduction",
                                       "tint",
                                       "weights",
                                       "additive",
                                       "baked",
                                       "radius",
                                       "aux-location",
                                       "in-place",
                                       "n-threads",
                                       "bloom-only",
                                       "cod",
                                       "RGB16",
                                       "BGRx",
                                       "YUY2",
                                       "changeable in NULL, READY, PAUSED or PLAYING state"};
    for (gsize i = 0; i < G_N_ELEMENTS(want); i++)
        fail_unless(strstr(out, want[i]) != NULL, "gst-inspect-1.0 bloom does not show '%s'", want[i]);
    g_free(out);
    g_free(err);
}
GST_END_TEST;

/* ---- caps -------------------------------------------------------------------- */

static gboolean accepts(GstElement *e, const char *caps)
{
    GstPad *pad = gst_element_get_static_pad(e, "sink");
    GstCaps *c = gst_caps_from_string(caps);
    const gboolean ok = gst_pad_query_accept_caps(pad, c);
    gst_caps_unref(c);
    gst_object_unref(pad);
    return ok;
}

GST_START_TEST(test_caps_formats)
{
    GstElement *e = gst_element_factory_make("bloom", NULL);
    for (int i = 0; i < TG_NFMTS; i++) {
        char *c = tg_caps(&tg_fmts[i], 64, 48);
        fail_unless(accepts(e, c), "%s refused", c);
        g_free(c);
    }
    static const char *const refused[] = {"I420", "UYVY", "RGBA", "BGR", "GRAY8", "RGB15", "BGR16"};
    for (gsize i = 0; i < G_N_ELEMENTS(refused); i++) {
        char *c = g_strdup_printf("video/x-raw,format=%s,width=64,height=48,framerate=25/1", refused[i]);
        fail_if(accepts(e, c), "%s accepted", c);
        g_free(c);
    }
    gst_object_unref(e);
}
GST_END_TEST;

/* A size above BLOOM_MAX_DIM fails negotiation with a message saying so;
 * the largest and the smallest sizes run. */
GST_START_TEST(test_caps_sizes)
{
    static const int sizes[][3] = {
        {BLOOM_MAX_DIM + 1, 2, 0}, {2, BLOOM_MAX_DIM + 1, 0}, {BLOOM_MAX_DIM, 1, 1}, {1, 1, 1}, {1, 40, 1},
        {1, BLOOM_MAX_DIM, 1}};
    const tg_fmt_t *f = &tg_fmts[0];
    for (gsize i = 0; i < G_N_ELEMENTS(sizes); i++) {
        const int w = sizes[i][0], h = sizes[i][1], stride = tg_default_stride(f, w, h);
        GstHarness *hs = gst_harness_new("bloom");
        GstBus *bus = gst_bus_new();
        gst_element_set_bus(hs->element, bus);
        char *c = tg_caps(f, w, h);
        gst_harness_set_src_caps_str(hs, c);
        guint8 *px = tg_frame(f, w, h, stride, 7);
        const GstFlowReturn r = gst_harness_push(hs, tg_buffer(f, w, h, stride, px, stride));
        if (sizes[i][2]) {
            fail_unless_equals_int(r, GST_FLOW_OK);
            GstBuffer *out = gst_harness_try_pull(hs);
            bloom_config_t cfg;
            char *why = NULL;
            tg_config(&cfg, BLOOM_PRESET_UNITY, w, h, f->bf);
            guint8 *exp = tg_engine(&cfg, px, stride, NULL, 0);
            fail_unless(out && exp && tg_same(out, f, w, h, exp, stride, &why), "%s: %s", c, why);
            gst_buffer_unref(out);
            g_free(exp);
        } else {
            fail_unless_equals_int(r, GST_FLOW_NOT_NEGOTIATED);
            char *t = tg_bus_text(bus, GST_MESSAGE_ERROR, 0);
            fail_unless(t && strstr(t, "above the engine's limit of 16384"), "%s: %s", c, t ? t : "no error");
            g_free(t);
        }
        g_free(px);
        g_free(c);
        gst_element_set_bus(hs->element, NULL);
        gst_object_unref(bus);
        gst_harness_teardown(hs);
    }
}
GST_END_TEST;

/* ---- properties ----------------------------------------------------------------- */

GST_START_TEST(test_property_ranges)
{
    static const struct {
        const char *name;
        double min, max, def, in, out;
    } d[] = {
        {"threshold", 0, 256, 1.0, 0.6, 256.5}, {"knee", 0, 1, 0.5, 0.25, 1.01},
        {"intensity", 0, 10, 1.0, 2.5, 10.01},  {"strength", 0, 16, 1.0, 3.0, 16.5},
        {"attenuation", 0, 1, 0.75, 0.5, 1.5},  {"max-reduction", 0, 1, 0.25, 0.1, -0.1},
    };
    static const struct {
        const char *name;
        int min, max, def, in, out;
    } n[] = {{"levels", 1, 16, 5, 9, 17},
             {"passes", 1, 8, 3, 6, 0},
             {"radius", 0, 1 << 20, 0, 40, -1},
             {"sample-bits", 16, 32, 32, 16, 33}};
    GstElement *e = gst_element_factory_make("bloom", NULL);
    GObjectClass *oc = G_OBJECT_GET_CLASS(e);
    for (gsize i = 0; i < G_N_ELEMENTS(d); i++) {
        GParamSpecDouble *ps = G_PARAM_SPEC_DOUBLE(g_object_class_find_property(oc, d[i].name));
        double v = -1;
        fail_unless(ps->minimum == d[i].min && ps->maximum == d[i].max && ps->default_value == d[i].def,
                    "%s: range %g..%g default %g", d[i].name, ps->minimum, ps->maximum, ps->default_value);
        g_object_get(e, d[i].name, &v, NULL);
        fail_unless(v == d[i].def, "%s reads %g before any set, not %g", d[i].name, v, d[i].def);
        g_object_set(e, d[i].name, d[i].in, NULL);
        ASSERT_WARNING(g_object_set(e, d[i].name, d[i].out, NULL));
        g_object_get(e, d[i].name, &v, NULL);
        fail_unless(v == d[i].in, "%s: %g after refusing %g, not %g", d[i].name, v, d[i].out, d[i].in);
    }
    for (gsize i = 0; i < G_N_ELEMENTS(n); i++) {
        GParamSpecInt *ps = G_PARAM_SPEC_INT(g_object_class_find_property(oc, n[i].name));
        int v = -1;
        fail_unless(ps->minimum == n[i].min && ps->maximum == n[i].max && ps->default_value == n[i].def,
                    "%s: range %d..%d default %d", n[i].name, ps->minimum, ps->maximum, ps->default_value);
        g_object_set(e, n[i].name, n[i].in, NULL);
        ASSERT_WARNING(g_object_set(e, n[i].name, n[i].out, NULL));
        g_object_get(e, n[i].name, &v, NULL);
        fail_unless_equals_int(v, n[i].in);
    }
    gst_object_unref(e);
}
GST_END_TEST;

static char *get_str(GstElement *e, const char *name)
{
    char *s = NULL;
    g_object_get(e, name, &s, NULL);
    return s;
}

/* Presets by name; a parameter not given reads the preset's default, one
 * given keeps its value whatever the preset; the lists; the plane. */
GST_START_TEST(test_property_presets)
{
    GstElement *e = gst_element_factory_make("bloom", NULL);
    double t, k;
    int p, passes;
    char *s;
    gst_util_set_object_arg(G_OBJECT(e), "preset", "xna");
    g_object_get(e, "preset", &p, "threshold", &t, "passes", &passes, NULL);
    fail_unless(p == BLOOM_PRESET_XNA && t == 0.25 && passes == 3, "xna: %d %g %d", p, t, passes);
    g_object_set(e, "threshold", 0.5, NULL);
    gst_util_set_object_arg(G_OBJECT(e), "preset", "cod");
    g_object_get(e, "threshold", &t, "knee", &k, NULL);
    fail_unless(t == 0.5 && k == 0.0, "cod after threshold=0.5: threshold %g knee %g", t, k);
    s = get_str(e, "weights");
    fail_unless(s && strchr(s, ','), "cod's default weights read '%s'", s ? s : "(null)");
    g_free(s);
    g_object_set(e, "weights", "0.5, 0.25,1", "tint", "1,0.5,0.25", NULL);
    fail_unless_equals_string((s = get_str(e, "weights")), "0.5,0.25,1");
    g_free(s);
    fail_unless_equals_string((s = get_str(e, "tint")), "1,0.5,0.25");
    g_free(s);
    ASSERT_WARNING(g_object_set(e, "tint", "1,2,0", NULL));
    ASSERT_WARNING(g_object_set(e, "tint", "1,1", NULL));
    ASSERT_WARNING(g_object_set(e, "weights", "0.5,x", NULL));
    fail_unless_equals_string((s = get_str(e, "tint")), "1,0.5,0.25");
    g_free(s);
    g_object_set(e, "weights", "", NULL);
    s = get_str(e, "weights");
    fail_unless(s && strcmp(s, "0.5,0.25,1") && strchr(s, ','), "weights='' reads '%s'", s ? s : "(null)");
    g_free(s);
    gst_util_set_object_arg(G_OBJECT(e), "view", "bloom-only");
    g_object_get(e, "view", &p, NULL);
    fail_unless_equals_int(p, 1);
    ASSERT_WARNING(g_object_set(e, "aux-location", "/nonexistent/plane.pgm", NULL));
    fail_unless((s = get_str(e, "aux-location")) == NULL, "aux-location reads %s", s);
    gst_object_unref(e);
}
GST_END_TEST;

TCase *tg_tcase(Suite *s, const char *name)
{
    TCase *tc = tcase_create(name);
    tcase_set_timeout(tc, 120);
    suite_add_tcase(s, tc);
    return tc;
}

static Suite *bloom_suite(void)
{
    Suite *s = suite_create("bloom");
    TCase *tc = tg_tcase(s, "plugin");
    tcase_add_test(tc, test_plugin_from_build);
    tcase_add_test(tc, test_inspect_page);
    tc = tg_tcase(s, "caps");
    tcase_add_test(tc, test_caps_formats);
    tcase_add_test(tc, test_caps_sizes);
    tc = tg_tcase(s, "properties");
    tcase_add_test(tc, test_property_ranges);
    tcase_add_test(tc, test_property_presets);
    tg_add_frame_tests(s);  /* test_gst_frames.c */
    tg_add_stream_tests(s); /* test_gst_stream.c */
    tg_add_yuy2_tests(s);   /* test_gst_yuy2.c */
    tg_add_thread_tests(s); /* test_gst_threads.c */
    return s;
}

int main(int argc, char **argv)
{
    gst_check_init(&argc, &argv);
    SRunner *sr = srunner_create(bloom_suite());
    srunner_run_all(sr, CK_ENV); /* CK_VERBOSITY=verbose lists every test */
    const int n = srunner_ntests_run(sr);
    TestResult **r = srunner_results(sr);
    int pass = 0, fail = 0;
    GString *per = g_string_new(NULL);
    const char *tc = NULL;
    int tc_n = 0;
    for (int i = 0; i <= n; i++) {
        if (i == n || (tc && strcmp(tc, tr_tcname(r[i])))) {
            g_string_append_printf(per, "%s%s %d", per->len ? ", " : "", tc, tc_n);
            tc_n = 0;
        }
        if (i == n)
            break;
        tc = tr_tcname(r[i]);
        tc_n++;
        if (tr_rtype(r[i]) == CK_PASS) {
            pass++;
        } else {
            fail++;
            printf("FAILED: %s:%d: %s: %s\n", tr_lfile(r[i]), tr_lno(r[i]), tr_tcname(r[i]), tr_msg(r[i]));
        }
    }
    if (n)
        printf("test-gst: checks per case: %s\n", per->str);
    g_string_free(per, TRUE);
    free(r);
    srunner_free(sr);
    if (n == 0)
        fail = 1;
    printf("%d passed, %d failed, 0 skipped\n", pass, fail);
    return fail ? 1 : 0;
}
