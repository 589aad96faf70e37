/* make test-gst: the element's frames against the engine run directly
 * (bloom_process on the same frames), in and out of place, with padded
 * strides, every preset and format, the channel order, the aux plane,
 * build/bloom_sim and the README's launch lines. Part of test_gst
 * (test_gst.c has main, test_gst_stream.c the streaming cases). */
#include <stdlib.h>
#include <string.h>

#include "test_gst.h"

#define W 97 /* odd: RGB and RGB16 rows are padded to 4 bytes by default */
#define H 61

static const bloom_preset_t no_aux[] = {BLOOM_PRESET_UNITY, BLOOM_PRESET_GAMEDEV, BLOOM_PRESET_XNA,
                                        BLOOM_PRESET_ARM, BLOOM_PRESET_COD};
#define N_NO_AUX 5

/* ---- frames: every preset without a plane, every format ---------------------------- */

/* appsrc ! bloom preset=P ! appsink, two frames, each against the engine;
 * then EOS reaches the sink. */
GST_START_TEST(test_pipeline_presets)
{
    const bloom_preset_t pr = no_aux[__i__ / TG_NFMTS];
    const tg_fmt_t *f = &tg_fmts[__i__ % TG_NFMTS];
    const int stride = tg_default_stride(f, W, H);
    tg_pipe_t p;
    bloom_config_t cfg;
    tg_pipe_new(&p, f, W, H);
    gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", bloom_preset_name(pr));
    fail_unless(tg_pipe_play(&p));
    tg_config(&cfg, pr, W, H, f->bf);
    for (int k = 0; k < 2; k++) {
        guint8 *px = tg_frame(f, W, H, stride, 100u + (guint32)__i__ * 2u + (guint32)k);
        guint8 *exp = tg_engine(&cfg, px, stride, NULL, 0);
        GstBuffer *out = tg_pipe_run(&p, f, W, H, px, stride);
        char *why = NULL;
        fail_unless(exp && out, "%s %s: no output", bloom_preset_name(pr), f->name);
        fail_unless(tg_same(out, f, W, H, exp, stride, &why), "%s frame %d: %s", bloom_preset_name(pr), k,
                    why);
        gst_buffer_unref(out);
        g_free(exp);
        g_free(px);
    }
    fail_unless_equals_int(gst_app_src_end_of_stream(GST_APP_SRC(p.src)), GST_FLOW_OK);
    char *t = tg_bus_text(p.bus, GST_MESSAGE_EOS | GST_MESSAGE_ERROR, 10 * GST_SECOND);
    fail_unless(t && !strcmp(t, "eos"), "after EOS: %s", t ? t : "nothing");
    fail_unless(gst_app_sink_is_eos(GST_APP_SINK(p.sink)));
    g_free(t);
    tg_pipe_free(&p);
}
GST_END_TEST;

/* Every engine parameter through its property, against a configuration
 * built here by hand. */
GST_START_TEST(test_pipeline_parameters)
{
    const tg_fmt_t *f = &tg_fmts[__i__ % TG_NFMTS];
    const int stride = tg_default_stride(f, W, H);
    bloom_config_t c;
    tg_pipe_t p;
    tg_pipe_new(&p, f, W, H);
    switch (__i__ / TG_NFMTS) {
    case 0:
        gst_util_set_object_arg(G_OBJECT(p.bloom), "view", "bloom-only");
        g_object_set(p.bloom, "threshold", 0.6, "knee", 0.2, "intensity", 2.5, "levels", 3, "linear", TRUE,
                     NULL);
        tg_config(&c, BLOOM_PRESET_UNITY, W, H, f->bf);
        c.threshold = BLOOM_Q16(0.6);
        c.soft_knee = BLOOM_Q16(0.2);
        c.intensity = BLOOM_Q16(2.5);
        c.levels = 3;
        c.flags |= BLOOM_FLAG_LINEAR | BLOOM_FLAG_DEBUG_VIEW;
        break;
    case 1: /* given before the preset: still wins */
        g_object_set(p.bloom, "strength", 2.5, "threshold", 0.5, NULL);
        gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", "gamedev");
        tg_config(&c, BLOOM_PRESET_GAMEDEV, W, H, f->bf);
        c.p.strength = BLOOM_Q16(2.5);
        c.threshold = BLOOM_Q16(0.5);
        break;
    case 2:
        gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", "xna");
        g_object_set(p.bloom, "passes", 5, "saturate", TRUE, "threshold", 0.4, NULL);
        tg_config(&c, BLOOM_PRESET_XNA, W, H, f->bf);
        c.p.passes = 5;
        c.flags |= BLOOM_FLAG_SATURATE;
        c.threshold = BLOOM_Q16(0.4);
        break;
    case 4: /* 16-bit samples */
        g_object_set(p.bloom, "sample-bits", 16, "threshold", 0.8, "levels", 4, NULL);
        tg_config(&c, BLOOM_PRESET_UNITY, W, H, f->bf);
        c.sample_bits = 16;
        c.threshold = BLOOM_Q16(0.8);
        c.levels = 4;
        break;
    default:
        gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", "cod");
        g_object_set(p.bloom, "radius", 40, "tint", "1,0.8,0.6", "weights", "0.5,0.75", "additive", TRUE,
                     "levels", 2 /* radius overrides it */, NULL);
        bloom_config_default(&c, W, H);
        c.in_fmt = c.out_fmt = f->bf;
        c.levels = bloom_levels_for_radius(40);
        fail_unless(bloom_config_preset(&c, BLOOM_PRESET_COD) == BLOOM_OK);
        c.p.tint[0] = BLOOM_Q16(1.0);
        c.p.tint[1] = BLOOM_Q16(0.8);
        c.p.tint[2] = BLOOM_Q16(0.6);
        c.p.level_weight[0] = BLOOM_Q16(0.5);
        c.p.level_weight[1] = BLOOM_Q16(0.75);
        c.flags |= BLOOM_FLAG_ADDITIVE;
        break;
    }
    fail_unless(tg_pipe_play(&p));
    guint8 *px = tg_frame(f, W, H, stride, 300u + (guint32)__i__);
    guint8 *exp = tg_engine(&c, px, stride, NULL, 0);
    GstBuffer *out = tg_pipe_run(&p, f, W, H, px, stride);
    char *why = NULL;
    fail_unless(exp && out, "case %d: no output", __i__);
    fail_unless(tg_same(out, f, W, H, exp, stride, &why), "case %d: %s", __i__, why);
    gst_buffer_unref(out);
    g_free(exp);
    g_free(px);
    tg_pipe_free(&p);
}
GST_END_TEST;

/* The presets that read a plane, through aux-location: attenuation (8-bit
 * depth), arm's mask (8-bit) and arm baked (16-bit map); then the refusals. */
GST_START_TEST(test_pipeline_aux)
{
    const tg_fmt_t *f = &tg_fmts[0];
    const int stride = tg_default_stride(f, W, H);
    for (int k = 0; k < 3; k++) {
        const int wide = k == 2;
        guint8 *plane = tg_frame(&(tg_fmt_t){GST_VIDEO_FORMAT_GRAY8, 0, wide ? 2 : 1, "plane"}, W, H,
                                 W * (wide ? 2 : 1), 40u + (guint32)k);
        char *path = g_strdup_printf("%s/plane%d.pgm", tg_tmp(), k);
        fail_unless(tg_write_pgm(path, W, H, wide, plane));
        tg_pipe_t p;
        bloom_config_t c;
        tg_pipe_new(&p, f, W, H);
        gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", k == 0 ? "attenuation" : "arm");
        g_object_set(p.bloom, "aux-location", path, "baked", k == 2, "strength", 3.0, NULL);
        tg_config(&c, k == 0 ? BLOOM_PRESET_ATTENUATION : BLOOM_PRESET_ARM, W, H, f->bf);
        c.aux_fmt = wide ? BLOOM_AUX_U16 : BLOOM_AUX_U8;
        if (k == 2) {
            c.flags |= BLOOM_FLAG_BAKED;
            c.p.strength = BLOOM_Q16(3.0);
        }
        fail_unless(tg_pipe_play(&p));
        guint8 *px = tg_frame(f, W, H, stride, 50u + (guint32)k);
        guint8 *exp = tg_engine(&c, px, stride, plane, W * (wide ? 2 : 1));
        GstBuffer *out = tg_pipe_run(&p, f, W, H, px, stride);
        char *why = NULL;
        fail_unless(exp && out, "aux case %d: no output", k);
        fail_unless(tg_same(out, f, W, H, exp, stride, &why), "aux case %d: %s", k, why);
        gst_buffer_unref(out);
        g_free(exp);
        g_free(px);
        g_free(plane);
        tg_pipe_free(&p);
        g_free(path);
    }
    /* no plane, and a plane of another size: negotiation fails, saying why */
    static const char *const need[] = {"aux plane missing", "is 10x10 but the video is 97x61"};
    guint8 small[100] = {0};
    char *path = g_strdup_printf("%s/small.pgm", tg_tmp());
    fail_unless(tg_write_pgm(path, 10, 10, 0, small));
    for (int k = 0; k < 2; k++) {
        tg_pipe_t p;
        tg_pipe_new(&p, f, W, H);
        gst_util_set_object_arg(G_OBJECT(p.bloom), "preset", "attenuation");
        if (k)
            g_object_set(p.bloom, "aux-location", path, NULL);
        fail_unless(tg_pipe_play(&p));
        guint8 *px = tg_frame(f, W, H, stride, 1);
        GstBuffer *out = tg_pipe_run(&p, f, W, H, px, stride);
        fail_unless(out == NULL);
        char *t = tg_bus_text(p.bus, GST_MESSAGE_ERROR, 5 * GST_SECOND);
        fail_unless(t && strstr(t, need[k]) && strstr(t, "aux"), "case %d: %s", k, t ? t : "no error");
        g_free(t);
        g_free(px);
        tg_pipe_free(&p);
    }
    g_free(path);
}
GST_END_TEST;

/* ---- in place, out of place, strides ------------------------------------------------ */

/* Through GstHarness (synchronous): in-place on a writable buffer works in
 * it; in-place on a buffer still referenced works on GstBaseTransform's
 * copy and leaves the input as it was; out of place (in-place=false)
 * writes a new buffer even when the input is writable; each with a padded
 * input stride (GstVideoMeta), each byte-identical to the engine. */
GST_START_TEST(test_in_place)
{
    const tg_fmt_t *f = &tg_fmts[__i__ % TG_NFMTS];
    const int mode = __i__ / TG_NFMTS; /* 0 in place, 1 in place on a shared input, 2 out of place */
    const int stride = tg_default_stride(f, W, H) + 36;
    GstHarness *hs = gst_harness_new("bloom");
    g_object_set(hs->element, "in-place", mode < 2, "preset", BLOOM_PRESET_COD, NULL);
    char *caps = tg_caps(f, W, H);
    gst_harness_set_src_caps_str(hs, caps);
    g_free(caps);
    bloom_config_t c;
    tg_config(&c, BLOOM_PRESET_COD, W, H, f->bf);
    for (int k = 0; k < 2; k++) {
        guint8 *px = tg_frame(f, W, H, stride, 500u + (guint32)(__i__ * 2 + k));
        guint8 *exp = tg_engine(&c, px, stride, NULL, 0);
        GstBuffer *in = tg_buffer(f, W, H, stride, px, stride);
        GstMapInfo m;
        fail_unless(gst_buffer_map(in, &m, GST_MAP_READ));
        const guint8 *in_data = m.data;
        gst_buffer_unmap(in, &m);
        if (mode == 1)
            gst_buffer_ref(in); /* not writable: GstBaseTransform copies it */
        fail_unless_equals_int(gst_harness_push(hs, in), GST_FLOW_OK);
        GstBuffer *out = gst_harness_try_pull(hs);
        char *why = NULL;
        fail_unless(out != NULL && exp != NULL);
        fail_unless(tg_same(out, f, W, H, exp, stride, &why), "mode %d %s: %s", mode, f->name, why);
        fail_unless(gst_buffer_map(out, &m, GST_MAP_READ));
        fail_unless((m.data == in_data) == (mode == 0), "mode %d: output %s the input's memory", mode,
                    m.data == in_data ? "is" : "is not");
        gst_buffer_unmap(out, &m);
        if (mode == 1) { /* the input is left as it was */
            fail_unless(tg_same(in, f, W, H, px, stride, &why), "mode %d: input changed: %s", mode, why);
            gst_buffer_unref(in);
        }
        gst_buffer_unref(out);
        g_free(exp);
        g_free(px);
    }
    gst_harness_teardown(hs);
}
GST_END_TEST;

/* The channel order each format is given to the engine in: an RGB frame
 * of red, green and blue lights, converted by videoconvert to the format,
 * through bloom and back to RGB, against the engine's RGB888 output (BGRx
 * exactly; RGB16 within its 5/6-bit steps). A swapped channel would put
 * the red glow in blue: 255 codes off. */
GST_START_TEST(test_format_order)
{
    const tg_fmt_t *f = &tg_fmts[__i__], *rgb = &tg_fmts[0];
    const int w = 96, h = 64, stride = w * 3;
    guint8 *px = g_malloc0((gsize)stride * h);
    for (int y = 8; y < 24; y++)
        for (int x = 0; x < 90; x++)
            px[y * stride + x * 3 + (x / 30)] = 255; /* red, green, blue blocks */
    for (int y = 40; y < 56; y++)
        for (int x = 10; x < 86; x++)
            px[y * stride + x * 3 + (x < 48 ? 0 : 2)] = (guint8)(x < 48 ? 250 : 230);
    bloom_config_t c;
    tg_config(&c, BLOOM_PRESET_UNITY, w, h, BLOOM_FMT_RGB888);
    c.threshold = BLOOM_Q16(0.5);
    c.intensity = BLOOM_Q16(2.0);
    guint8 *exp = tg_engine(&c, px, stride, NULL, 0);
    GError *err = NULL;
    char *desc = g_strdup_printf("appsrc name=src format=time caps=\"video/x-raw,format=RGB,width=%d,"
                                 "height=%d,framerate=25/1\" ! videoconvert dither=none ! "
                                 "video/x-raw,format=%s ! bloom name=bloom threshold=0.5 intensity=2 ! "
                                 "videoconvert dither=none ! video/x-raw,format=RGB ! appsink name=sink",
                                 w, h, f->name);
    tg_pipe_t p = {0};
    p.pipe = gst_parse_launch(desc, &err);
    fail_unless(p.pipe && !err, "%s: %s", desc, err ? err->message : "?");
    p.src = gst_bin_get_by_name(GST_BIN(p.pipe), "src");
    p.bloom = gst_bin_get_by_name(GST_BIN(p.pipe), "bloom");
    p.sink = gst_bin_get_by_name(GST_BIN(p.pipe), "sink");
    p.bus = gst_element_get_bus(p.pipe);
    fail_unless(tg_pipe_play(&p));
    GstBuffer *out = tg_pipe_run(&p, rgb, w, h, px, stride);
    fail_unless(out && exp, "%s: no output", f->name);
    GstMapInfo m;
    fail_unless(gst_buffer_map(out, &m, GST_MAP_READ) && m.size >= (gsize)stride * h);
    const int tol = f->bf == BLOOM_FMT_RGB565 ? 24 : 0; /* three 5-bit steps */
    int worst = 0, wx = 0, wy = 0, glow = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < stride; x++) {
            const int d = abs(m.data[y * stride + x] - exp[y * stride + x]);
            glow |= exp[y * stride + x] != px[y * stride + x];
            if (d > worst) {
                worst = d;
                wx = x;
                wy = y;
            }
        }
    gst_buffer_unmap(out, &m);
    fail_unless(glow, "the test frame does not glow");
    fail_unless(worst <= tol, "%s: row %d byte %d differs from the engine's RGB888 by %d (at most %d)",
                f->name, wy, wx, worst, tol);
    gst_buffer_unref(out);
    tg_pipe_free(&p);
    g_free(desc);
    g_free(exp);
    g_free(px);
}
GST_END_TEST;

/* ---- the simulator, and the README's pipelines ------------------------------------------- */

/* rocket_floodlights.ppm through appsrc ! bloom ! appsink and through
 * build/bloom_sim with the same options: the same bytes. */
GST_START_TEST(test_bloom_sim)
{
    const char *sim = g_getenv("BLOOM_SIM"), *data = g_getenv("BLOOM_DATA_DIR");
    fail_unless(sim && data, "BLOOM_SIM and BLOOM_DATA_DIR unset: run make test-gst");
    char *in = g_build_filename(data, "rocket_floodlights.ppm", NULL);
    char *outp = g_strdup_printf("%s/sim%d.ppm", tg_tmp(), __i__);
    char *argv[][12] = {{(char *)sim, "-q", "--threshold", "0.6", "--intensity", "1.5", "-o", outp, in, NULL},
                        {(char *)sim, "-q", "--preset", "cod", "--radius", "30", "-o", outp, in, NULL}};
    gint status;
    char *sout = NULL, *serr = NULL;
    fail_unless(g_spawn_sync(NULL, argv[__i__], NULL, 0, NULL, NULL, &sout, &serr, &status, NULL));
    fail_unless(g_spawn_check_wait_status(status, NULL), "bloom_sim failed: %s", serr);
    int w, h, ch, w2, h2, ch2;
    guint8 *px = tg_read_pnm(in, &w, &h, &ch), *exp = tg_read_pnm(outp, &w2, &h2, &ch2);
    fail_unless(px && exp && ch == 3 && w == w2 && h == h2 && ch2 == 3, "cannot read %s or %s", in, outp);
    const tg_fmt_t *f = &tg_fmts[0];
    tg_pipe_t p;
    tg_pipe_new(&p, f, w, h);
    if (__i__ == 0)
        g_object_set(p.bloom, "threshold", 0.6, "intensity", 1.5, NULL);
    else
        g_object_set(p.bloom, "preset", BLOOM_PRESET_COD, "radius", 30, NULL);
    fail_unless(tg_pipe_play(&p));
    GstBuffer *out = tg_pipe_run(&p, f, w, h, px, w * 3);
    char *why = NULL;
    fail_unless(out && tg_same(out, f, w, h, exp, w * 3, &why), "against bloom_sim: %s", why);
    gst_buffer_unref(out);
    tg_pipe_free(&p);
    g_free(px);
    g_free(exp);
    g_free(sout);
    g_free(serr);
    g_free(in);
    g_free(outp);
}
GST_END_TEST;

/* The README's camera-to-screen pipeline with videotestsrc for the camera
 * and fakesink for fbdevsink (both in the packages make deps installs),
 * and launch lines with the preset options; one the engine refuses. */
GST_START_TEST(test_launch_lines)
{
    static const struct {
        const char *line, *want;
    } l[] = {
        {"videotestsrc num-buffers=5 ! video/x-raw,width=320,height=240 ! videoconvert ! bloom ! "
         "videoconvert ! fakesink",
         "eos"},
        {"videotestsrc num-buffers=3 pattern=ball ! video/x-raw,width=160,height=120 ! videoconvert ! "
         "bloom preset=cod radius=20 tint=\"1,0.8,0.6\" ! videoconvert ! video/x-raw,format=I420 ! fakesink",
         "eos"},
        {"videotestsrc num-buffers=3 ! video/x-raw,format=RGB16,width=64,height=64 ! "
         "bloom preset=gamedev strength=2 threshold=0.5 view=bloom-only ! fakesink",
         "eos"},
        {"videotestsrc num-buffers=3 ! video/x-raw,width=64,height=64 ! videoconvert ! "
         "bloom threshold=1.5 preset=xna ! videoconvert ! fakesink",
         "threshold above 256.0"},
    };
    for (gsize i = 0; i < G_N_ELEMENTS(l); i++) {
        GError *err = NULL;
        GstElement *pipe = gst_parse_launch(l[i].line, &err);
        fail_unless(pipe && !err, "%s: %s", l[i].line, err ? err->message : "?");
        GstBus *bus = gst_element_get_bus(pipe);
        gst_element_set_state(pipe, GST_STATE_PLAYING);
        char *t = tg_bus_text(bus, GST_MESSAGE_EOS | GST_MESSAGE_ERROR, 30 * GST_SECOND);
        fail_unless(t && strstr(t, l[i].want), "%s: %s", l[i].line, t ? t : "timeout");
        g_free(t);
        gst_element_set_state(pipe, GST_STATE_NULL);
        gst_object_unref(bus);
        gst_object_unref(pipe);
    }
}
GST_END_TEST;

void tg_add_frame_tests(Suite *s)
{
    TCase *tc = tg_tcase(s, "frames");
    tcase_add_loop_test(tc, test_pipeline_presets, 0, N_NO_AUX * TG_NFMTS);
    tcase_add_loop_test(tc, test_pipeline_parameters, 0, 5 * TG_NFMTS);
    tcase_add_test(tc, test_pipeline_aux);
    tcase_add_loop_test(tc, test_in_place, 0, 3 * TG_NFMTS);
    tcase_add_loop_test(tc, test_format_order, 0, TG_NFMTS);
    tc = tg_tcase(s, "tools");
    tcase_add_loop_test(tc, test_bloom_sim, 0, 2);
    tcase_add_test(tc, test_launch_lines);
}
