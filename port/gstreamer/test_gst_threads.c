/* make test-gst: n-threads. The element's frames with 2 and 3 threads
 * (tiles on port/threads' pool) byte-identical to its frames with one, and
 * to the engine run directly, for every preset (the ones with a plane as
 * test_gst_frames.c gives them) and every RGB format; the property; 1 ->
 * 2 -> 1 mid-stream, out of place while threads run and in place again
 * after; changes racing the stream; YUY2 staying on the one engine's rows.
 * Part of test_gst (test_gst.c has main). */
#include <string.h>

#include "bloom_mt.h" /* BLOOM_MT_MAX_THREADS */
#include "test_gst.h"

#define W 201 /* 2 strips of 100 columns, 3 of 67 (at least BLOOM_MT_MIN_STRIP); odd: padded rows */
#define H 61

/* Every preset; those with a plane as test_pipeline_aux gives them. */
static const struct {
    bloom_preset_t preset;
    int aux; /* 0 none, 1 attenuation's 8-bit depth, 2 arm's 8-bit mask, 3 arm's 16-bit baked map */
} cases[] = {{BLOOM_PRESET_UNITY, 0}, {BLOOM_PRESET_GAMEDEV, 0}, {BLOOM_PRESET_XNA, 0},
             {BLOOM_PRESET_ARM, 0},   {BLOOM_PRESET_COD, 0},     {BLOOM_PRESET_ATTENUATION, 1},
             {BLOOM_PRESET_ARM, 2},   {BLOOM_PRESET_ARM, 3}};
#define N_CASES ((int)G_N_ELEMENTS(cases))

/* buf's frame (w x h of f, its own stride) as rows stride bytes apart. */
static guint8 *frame_copy(GstBuffer *buf, const tg_fmt_t *f, int w, int h, int stride)
{
    GstVideoInfo info;
    GstVideoFrame fr;
    gst_video_info_set_format(&info, f->vf, (guint)w, (guint)h);
    fail_unless(gst_video_frame_map(&fr, &info, buf, GST_MAP_READ));
    guint8 *p = g_malloc0((gsize)stride * (gsize)h);
    for (int y = 0; y < h; y++)
        memcpy(p + (gsize)y * (gsize)stride,
               (const guint8 *)GST_VIDEO_FRAME_PLANE_DATA(&fr, 0) +
                   (gsize)y * (gsize)GST_VIDEO_FRAME_PLANE_STRIDE(&fr, 0),
               (gsize)w * (gsize)f->bpp);
    gst_video_frame_unmap(&fr);
    return p;
}

/* appsrc ! bloom n-threads=N ! appsink for N = 1, 2, 3 on the same two
 * frames: 2 and 3 byte-identical to 1, and 1 to bloom_process. */
GST_START_TEST(test_threads_identical)
{
    const int ci = __i__ / TG_NFMTS, aux = cases[ci].aux;
    const bloom_preset_t pr = cases[ci].preset;
    const tg_fmt_t *f = &tg_fmts[__i__ % TG_NFMTS];
    const int stride = tg_default_stride(f, W, H), wide = aux == 3, aux_stride = W * (wide ? 2 : 1);
    guint8 *plane = NULL;
    char *path = NULL;
    bloom_config_t c;
    tg_config(&c, pr, W, H, f->bf);
    if (aux) {
        plane = tg_frame(&(tg_fmt_t){GST_VIDEO_FORMAT_GRAY8, 0, wide ? 2 : 1, "plane"}, W, H, aux_stride,
                         60u + (guint32)__i__);
        path = g_strdup_printf("%s/threads_plane%d.pgm", tg_tmp(), __i__);
        fail_unless(tg_write_pgm(path, W, H, wide, plane));
        c.aux_fmt = wide ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
        if (aux == 3) {
            c.flags |= BLOOM_FLAG_BAKED;
            c.p.strength = BLOOM_Q16(3.0);
        }
    }
    guint8 *px[2], *one[2] = {NULL, NULL};
    for (int k = 0; k < 2; k++)
        px[k] = tg_frame(f, W, H, stride, 1200u + (guint32)__i__ * 2u + (guint32)k);
    for (guint n = 1; n <= 3; n++) {
        tg_pipe_t p;
        tg_pipe_new(&p, f, W, H);
        gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", bloom_preset_name(pr));
        g_object_set(p.bloom, "n-threads", n, NULL);
        if (aux)
            g_object_set(p.bloom, "aux-location", path, NULL);
        if (aux == 3)
            g_object_set(p.bloom, "baked", TRUE, "strength", 3.0, NULL);
        fail_unless(tg_pipe_play(&p));
        for (int k = 0; k < 2; k++) {
            GstBuffer *out = tg_pipe_run(&p, f, W, H, px[k], stride);
            char *why = NULL;
            fail_unless(out != NULL, "%s aux %d %s n-threads=%u frame %d: no output", bloom_preset_name(pr),
                        aux, f->name, n, k);
            if (n == 1) {
                guint8 *exp = tg_engine(&c, px[k], stride, plane, aux_stride);
                fail_unless(exp && tg_same(out, f, W, H, exp, stride, &why), "%s aux %d n-threads=1: %s",
                            bloom_preset_name(pr), aux, why);
                g_free(exp);
                one[k] = frame_copy(out, f, W, H, stride);
            } else {
                fail_unless(tg_same(out, f, W, H, one[k], stride, &why),
                            "%s aux %d n-threads=%u frame %d against n-threads=1: %s", bloom_preset_name(pr),
                            aux, n, k, why);
            }
            gst_buffer_unref(out);
        }
        fail_unless(tg_bus_text(p.bus, GST_MESSAGE_ERROR | GST_MESSAGE_WARNING, 0) == NULL,
                    "n-threads=%u: a message on the bus", n);
        tg_pipe_free(&p);
    }
    for (int k = 0; k < 2; k++) {
        g_free(px[k]);
        g_free(one[k]);
    }
    g_free(plane);
    g_free(path);
}
GST_END_TEST;

GST_START_TEST(test_threads_property)
{
    GstElement *e = gst_element_factory_make("bloom", NULL);
    GParamSpec *ps = g_object_class_find_property(G_OBJECT_GET_CLASS(e), "n-threads");
    fail_unless(ps && G_IS_PARAM_SPEC_UINT(ps), "no uint property n-threads");
    const GParamSpecUInt *u = G_PARAM_SPEC_UINT(ps);
    fail_unless(u->minimum == 0 && u->maximum == BLOOM_MT_MAX_THREADS && u->default_value == 1,
                "n-threads: range %u..%u default %u", u->minimum, u->maximum, u->default_value);
    fail_unless(ps->flags & GST_PARAM_MUTABLE_PLAYING, "n-threads is not changeable while playing");
    guint n = 99;
    g_object_get(e, "n-threads", &n, NULL);
    fail_unless_equals_int(n, 1);
    g_object_set(e, "n-threads", 4u, NULL);
    ASSERT_WARNING(g_object_set(e, "n-threads", (guint)BLOOM_MT_MAX_THREADS + 1u, NULL));
    g_object_get(e, "n-threads", &n, NULL);
    fail_unless_equals_int(n, 4);
    gst_util_set_object_arg(G_OBJECT(e), "n-threads", "0");
    g_object_get(e, "n-threads", &n, NULL);
    fail_unless_equals_int(n, 0);
    gst_object_unref(e);
}
GST_END_TEST;

/* Through GstHarness, in-place=true on writable buffers with a padded
 * stride, cod: n-threads 1 -> 2 -> 1 -> 3 -> 1 -> 0 between frames. Every
 * frame byte-identical to the engine; with one thread the output is the
 * input's memory (in place), with 2 or 3 a new buffer (the pool never
 * works in place). 0 is the online CPUs: its bytes only. */
GST_START_TEST(test_threads_switch)
{
    static const guint seq[] = {1, 2, 1, 3, 1, 0, 1};
    const tg_fmt_t *f = &tg_fmts[__i__];
    const int stride = tg_default_stride(f, W, H) + 36;
    GstHarness *hs = gst_harness_new("bloom");
    GstBus *bus = gst_bus_new();
    gst_element_set_bus(hs->element, bus);
    g_object_set(hs->element, "preset", BLOOM_PRESET_COD, NULL);
    char *caps = tg_caps(f, W, H);
    gst_harness_set_src_caps_str(hs, caps);
    g_free(caps);
    bloom_config_t c;
    tg_config(&c, BLOOM_PRESET_COD, W, H, f->bf);
    for (gsize i = 0; i < G_N_ELEMENTS(seq); i++) {
        g_object_set(hs->element, "n-threads", seq[i], NULL);
        for (int k = 0; k < 2; k++) {
            guint8 *px = tg_frame(f, W, H, stride, 1400u + (guint32)(i * 2) + (guint32)k);
            guint8 *exp = tg_engine(&c, px, stride, NULL, 0);
            GstBuffer *in = tg_buffer(f, W, H, stride, px, stride);
            GstMapInfo m;
            fail_unless(gst_buffer_map(in, &m, GST_MAP_READ));
            const guint8 *in_data = m.data;
            gst_buffer_unmap(in, &m);
            fail_unless_equals_int(gst_harness_push(hs, in), GST_FLOW_OK);
            GstBuffer *out = gst_harness_try_pull(hs);
            char *why = NULL;
            fail_unless(out != NULL && exp != NULL, "n-threads=%u: no output", seq[i]);
            fail_unless(tg_same(out, f, W, H, exp, stride, &why), "%s n-threads=%u frame %d: %s", f->name,
                        seq[i], k, why);
            fail_unless(gst_buffer_map(out, &m, GST_MAP_READ));
            if (seq[i] != 0)
                fail_unless((m.data == in_data) == (seq[i] == 1),
                            "%s n-threads=%u frame %d: the output %s the input's memory", f->name, seq[i], k,
                            m.data == in_data ? "is" : "is not");
            gst_buffer_unmap(out, &m);
            gst_buffer_unref(out);
            g_free(exp);
            g_free(px);
        }
    }
    char *t = tg_bus_text(bus, GST_MESSAGE_ERROR | GST_MESSAGE_WARNING, 0);
    fail_unless(t == NULL, "on the bus: %s", t);
    gst_element_set_bus(hs->element, NULL);
    gst_object_unref(bus);
    gst_harness_teardown(hs);
}
GST_END_TEST;

/* Another thread flips n-threads between 1, 2 and 3 as fast as it can
 * while frames flow through appsrc ! bloom ! appsink: every frame is the
 * engine's, whatever the pool and the in-place choice at that moment. */
GST_START_TEST(test_threads_racing)
{
    const tg_fmt_t *f = &tg_fmts[0];
    const int stride = tg_default_stride(f, W, H);
    tg_pipe_t p;
    bloom_config_t c;
    tg_config(&c, BLOOM_PRESET_UNITY, W, H, f->bf);
    c.threshold = BLOOM_Q16(0.4);
    tg_pipe_new(&p, f, W, H);
    g_object_set(p.bloom, "threshold", 0.4, NULL);
    fail_unless(tg_pipe_play(&p));
    static const int counts[3] = {1, 2, 3};
    tg_racer_t r = {p.bloom, "n-threads", counts, 3, 200, 0, 0};
    GThread *t = g_thread_new("racer", tg_race, &r);
    for (int k = 0; k < 40; k++) {
        guint8 *px = tg_frame(f, W, H, stride, 1600u + (guint32)k);
        guint8 *exp = tg_engine(&c, px, stride, NULL, 0);
        GstBuffer *out = tg_pipe_run(&p, f, W, H, px, stride);
        char *why = NULL;
        fail_unless(out && exp, "frame %d: no output", k);
        fail_unless(tg_same(out, f, W, H, exp, stride, &why), "frame %d: %s", k, why);
        gst_buffer_unref(out);
        g_free(exp);
        g_free(px);
    }
    g_atomic_int_set(&r.stop, 1);
    g_thread_join(t);
    fail_unless(r.flips > 10, "only %d changes raced the stream", r.flips);
    tg_pipe_free(&p);
}
GST_END_TEST;

/* YUY2 stays on the one engine's row interface: n-threads=2 gives the
 * bytes of n-threads=1 and still works in place. */
GST_START_TEST(test_threads_yuy2)
{
    static const tg_fmt_t yuy2 = {GST_VIDEO_FORMAT_YUY2, BLOOM_FMT_RGB888, 2, "YUY2"};
    const int w = 200, stride = tg_default_stride(&yuy2, w, H);
    guint8 *px = tg_frame(&yuy2, w, H, stride, 1800u), *one = NULL;
    for (guint n = 1; n <= 2; n++) {
        GstHarness *hs = gst_harness_new("bloom");
        g_object_set(hs->element, "n-threads", n, NULL);
        char *caps = tg_caps(&yuy2, w, H);
        gst_harness_set_src_caps_str(hs, caps);
        g_free(caps);
        GstBuffer *in = tg_buffer(&yuy2, w, H, stride, px, stride);
        GstMapInfo m;
        fail_unless(gst_buffer_map(in, &m, GST_MAP_READ));
        const guint8 *in_data = m.data;
        gst_buffer_unmap(in, &m);
        fail_unless_equals_int(gst_harness_push(hs, in), GST_FLOW_OK);
        GstBuffer *out = gst_harness_try_pull(hs);
        char *why = NULL;
        fail_unless(out != NULL, "YUY2 n-threads=%u: no output", n);
        if (n == 1)
            one = frame_copy(out, &yuy2, w, H, stride);
        else
            fail_unless(tg_same(out, &yuy2, w, H, one, stride, &why), "YUY2 n-threads=2: %s", why);
        fail_unless(gst_buffer_map(out, &m, GST_MAP_READ));
        fail_unless(m.data == in_data, "YUY2 n-threads=%u: not in place", n);
        gst_buffer_unmap(out, &m);
        gst_buffer_unref(out);
        gst_harness_teardown(hs);
    }
    g_free(one);
    g_free(px);
}
GST_END_TEST;

void tg_add_thread_tests(Suite *s)
{
    TCase *tc = tg_tcase(s, "threads");
    tcase_add_test(tc, test_threads_property);
    tcase_add_loop_test(tc, test_threads_identical, 0, N_CASES * TG_NFMTS);
    tcase_add_loop_test(tc, test_threads_switch, 0, TG_NFMTS);
    tcase_add_test(tc, test_threads_racing);
    tcase_add_test(tc, test_threads_yuy2);
}
