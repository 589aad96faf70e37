/* make test-gst: streaming — properties changed between frames while
 * playing (each frame against the engine with the configuration it had),
 * a refused change, changes racing the stream from another thread,
 * controlled properties (GstController), new caps mid-stream, flushing
 * and EOS. Part of
 * test_gst (test_gst.c has main). */
#include <string.h>

#include <gst/controller/controller.h>

#include "test_gst.h"

#define W 97
#define H 61

/* ---- streaming: changes while playing, flushing ---------------------------------------- */

static void run_check(tg_pipe_t *p, const tg_fmt_t *f, const bloom_config_t *c, guint32 seed,
                      const char *what)
{
    const int stride = tg_default_stride(f, W, H);
    guint8 *px = tg_frame(f, W, H, stride, seed);
    guint8 *exp = tg_engine(c, px, stride, NULL, 0);
    GstBuffer *out = tg_pipe_run(p, f, W, H, px, stride);
    char *why = NULL;
    fail_unless(exp && out, "%s: no output", what);
    fail_unless(tg_same(out, f, W, H, exp, stride, &why), "%s: %s", what, why);
    gst_buffer_unref(out);
    g_free(exp);
    g_free(px);
}

GST_START_TEST(test_change_while_playing)
{
    const tg_fmt_t *f = &tg_fmts[1];
    tg_pipe_t p;
    bloom_config_t c;
    tg_pipe_new(&p, f, W, H);
    fail_unless(tg_pipe_play(&p));
    tg_config(&c, BLOOM_PRESET_UNITY, W, H, f->bf);
    run_check(&p, f, &c, 1, "before any change");
    g_object_set(p.bloom, "threshold", 0.5, "intensity", 2.0, "levels", 7, NULL);
    c.threshold = BLOOM_Q16(0.5);
    c.intensity = BLOOM_Q16(2.0);
    c.levels = 7;
    run_check(&p, f, &c, 2, "threshold 0.5, intensity 2, levels 7");
    gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", "cod");
    bloom_config_preset(&c, BLOOM_PRESET_COD);
    c.threshold = BLOOM_Q16(0.5);
    c.intensity = BLOOM_Q16(2.0);
    run_check(&p, f, &c, 3, "then preset cod");
    /* refused by the engine (xna needs a threshold below 1): a warning with
     * bloom_status_str's text, the previous configuration kept */
    g_object_set(p.bloom, "threshold", 1.5, NULL);
    gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", "xna");
    run_check(&p, f, &c, 4, "after a refused change");
    char *t = tg_bus_text(p.bus, GST_MESSAGE_WARNING, 5 * GST_SECOND);
    fail_unless(t && strstr(t, bloom_status_str(BLOOM_E_THRESHOLD)) &&
                    strstr(t, "previous configuration is kept"),
                "warning: %s", t ? t : "none");
    g_free(t);
    int preset;
    double th;
    g_object_get(p.bloom, "preset", &preset, "threshold", &th, NULL);
    fail_unless(preset == BLOOM_PRESET_COD && th == 0.5, "after the refusal: preset %d threshold %g", preset,
                th);
    g_object_set(p.bloom, "threshold", 0.3, NULL);
    c.threshold = BLOOM_Q16(0.3);
    run_check(&p, f, &c, 5, "a good change after the refused one");
    tg_pipe_free(&p);
}
GST_END_TEST;

GST_START_TEST(test_flush)
{
    const tg_fmt_t *f = &tg_fmts[2];
    const int stride = tg_default_stride(f, W, H);
    GstHarness *hs = gst_harness_new("bloom");
    char *caps = tg_caps(f, W, H);
    gst_harness_set_src_caps_str(hs, caps);
    g_free(caps);
    bloom_config_t c;
    tg_config(&c, BLOOM_PRESET_UNITY, W, H, f->bf);
    for (int k = 0; k < 3; k++) {
        guint8 *px = tg_frame(f, W, H, stride, 900u + (guint32)k);
        guint8 *exp = tg_engine(&c, px, stride, NULL, 0);
        if (k == 1) { /* flushing: buffers are refused, then the stream resumes */
            fail_unless(gst_harness_push_event(hs, gst_event_new_flush_start()));
            fail_unless_equals_int(gst_harness_push(hs, tg_buffer(f, W, H, stride, px, stride)),
                                   GST_FLOW_FLUSHING);
            fail_unless(gst_harness_push_event(hs, gst_event_new_flush_stop(TRUE)));
            GstSegment seg;
            gst_segment_init(&seg, GST_FORMAT_TIME);
            fail_unless(gst_harness_push_event(hs, gst_event_new_segment(&seg)));
            g_object_set(hs->element, "intensity", 3.0, NULL); /* a change across the flush */
            c.intensity = BLOOM_Q16(3.0);
            g_free(exp);
            exp = tg_engine(&c, px, stride, NULL, 0);
        }
        fail_unless_equals_int(gst_harness_push(hs, tg_buffer(f, W, H, stride, px, stride)), GST_FLOW_OK);
        GstBuffer *out = gst_harness_try_pull(hs);
        char *why = NULL;
        fail_unless(out && exp && tg_same(out, f, W, H, exp, stride, &why), "frame %d: %s", k, why);
        gst_buffer_unref(out);
        g_free(exp);
        g_free(px);
    }
    fail_unless(gst_harness_push_event(hs, gst_event_new_eos()));
    GstEvent *ev;
    gboolean eos = FALSE;
    while ((ev = gst_harness_try_pull_event(hs))) {
        eos |= GST_EVENT_TYPE(ev) == GST_EVENT_EOS;
        gst_event_unref(ev);
    }
    fail_unless(eos, "EOS did not come through");
    gst_harness_teardown(hs);
}
GST_END_TEST;

/* Another thread flips the preset between unity and cod as fast as it can
 * while frames flow: every frame comes out as the engine gives it with one
 * of the two configurations, never a mix, and nothing deadlocks. */
GST_START_TEST(test_changes_racing)
{
    const tg_fmt_t *f = &tg_fmts[0];
    const int stride = tg_default_stride(f, W, H);
    tg_pipe_t p;
    bloom_config_t a, b;
    tg_config(&a, BLOOM_PRESET_UNITY, W, H, f->bf);
    tg_config(&b, BLOOM_PRESET_COD, W, H, f->bf);
    a.threshold = b.threshold = BLOOM_Q16(0.4);
    tg_pipe_new(&p, f, W, H);
    g_object_set(p.bloom, "threshold", 0.4, NULL);
    fail_unless(tg_pipe_play(&p));
    static const int presets[2] = {BLOOM_PRESET_COD, BLOOM_PRESET_UNITY};
    tg_racer_t r = {p.bloom, "preset", presets, 2, 50, 0, 0};
    GThread *t = g_thread_new("racer", tg_race, &r);
    int seen[2] = {0, 0};
    for (int k = 0; k < 40; k++) {
        guint8 *px = tg_frame(f, W, H, stride, 700u + (guint32)k);
        guint8 *ea = tg_engine(&a, px, stride, NULL, 0), *eb = tg_engine(&b, px, stride, NULL, 0);
        GstBuffer *out = tg_pipe_run(&p, f, W, H, px, stride);
        char *wa = NULL, *wb = NULL;
        fail_unless(out && ea && eb, "frame %d: no output", k);
        const int is_a = tg_same(out, f, W, H, ea, stride, &wa),
                  is_b = tg_same(out, f, W, H, eb, stride, &wb);
        fail_unless(is_a || is_b, "frame %d is neither unity's (%s) nor cod's (%s)", k, wa, wb);
        seen[is_b]++;
        g_free(wa);
        g_free(wb);
        gst_buffer_unref(out);
        g_free(ea);
        g_free(eb);
        g_free(px);
    }
    g_atomic_int_set(&r.stop, 1);
    g_thread_join(t);
    fail_unless(r.flips > 40, "only %d changes raced the stream", r.flips);
    tg_pipe_free(&p);
}
GST_END_TEST;

/* intensity under a GstController: 1.0 at 0 s, 2.0 at 40 ms (the second
 * frame), interpolated linearly; each frame with the value at its time. */
GST_START_TEST(test_controlled)
{
    const tg_fmt_t *f = &tg_fmts[1];
    tg_pipe_t p;
    bloom_config_t c;
    tg_pipe_new(&p, f, W, H);
    GstControlSource *cs = gst_interpolation_control_source_new();
    g_object_set(cs, "mode", GST_INTERPOLATION_MODE_LINEAR, NULL);
    /* direct-absolute: the control values are the property's own units */
    fail_unless(gst_object_add_control_binding(
        GST_OBJECT(p.bloom), gst_direct_control_binding_new_absolute(GST_OBJECT(p.bloom), "intensity", cs)));
    gst_timed_value_control_source_set(GST_TIMED_VALUE_CONTROL_SOURCE(cs), 0, 1.0);
    gst_timed_value_control_source_set(GST_TIMED_VALUE_CONTROL_SOURCE(cs), GST_SECOND / 25, 2.0);
    gst_timed_value_control_source_set(GST_TIMED_VALUE_CONTROL_SOURCE(cs), 3 * GST_SECOND / 25, 3.0);
    fail_unless(tg_pipe_play(&p));
    tg_config(&c, BLOOM_PRESET_UNITY, W, H, f->bf);
    static const double at[] = {1.0, 2.0, 2.5, 3.0};
    for (int k = 0; k < 4; k++) {
        c.intensity = BLOOM_Q16(at[k]);
        char what[48];
        g_snprintf(what, sizeof what, "frame %d, intensity %g", k, at[k]);
        run_check(&p, f, &c, 800u + (guint32)k, what);
    }
    tg_pipe_free(&p);
    gst_object_unref(cs);
}
GST_END_TEST;

/* New caps mid-stream (another format and size, larger and smaller): the
 * engine is re-configured for them, each frame against the engine. */
GST_START_TEST(test_caps_change)
{
    static const struct {
        int fmt, w, h;
    } seq[] = {{0, W, H}, {1, 200, 150}, {2, 33, 20}, {0, 400, 9}};
    GstHarness *hs = gst_harness_new("bloom");
    g_object_set(hs->element, "preset", BLOOM_PRESET_XNA, NULL);
    for (gsize i = 0; i < G_N_ELEMENTS(seq); i++) {
        const tg_fmt_t *f = &tg_fmts[seq[i].fmt];
        const int w = seq[i].w, h = seq[i].h, stride = tg_default_stride(f, w, h);
        char *caps = tg_caps(f, w, h), *why = NULL;
        gst_harness_set_src_caps_str(hs, caps);
        bloom_config_t c;
        tg_config(&c, BLOOM_PRESET_XNA, w, h, f->bf);
        guint8 *px = tg_frame(f, w, h, stride, 1000u + (guint32)i);
        guint8 *exp = tg_engine(&c, px, stride, NULL, 0);
        fail_unless_equals_int(gst_harness_push(hs, tg_buffer(f, w, h, stride, px, stride)), GST_FLOW_OK);
        GstBuffer *out = gst_harness_try_pull(hs);
        fail_unless(out && exp && tg_same(out, f, w, h, exp, stride, &why), "%s: %s", caps,
                    why ? why : "no output");
        gst_buffer_unref(out);
        g_free(exp);
        g_free(px);
        g_free(caps);
    }
    gst_harness_teardown(hs);
}
GST_END_TEST;

void tg_add_stream_tests(Suite *s)
{
    TCase *tc = tg_tcase(s, "streaming");
    tcase_add_test(tc, test_change_while_playing);
    tcase_add_test(tc, test_changes_racing);
    tcase_add_test(tc, test_controlled);
    tcase_add_test(tc, test_caps_change);
    tcase_add_test(tc, test_flush);
}
