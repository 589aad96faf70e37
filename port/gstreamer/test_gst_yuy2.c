/* make test-gst: YUY2 in and out. The element converts each row with the
 * camera tool's converters (port/linux/cam_conv.c, BT.601 limited range)
 * around the engine's row calls; here the expectation is computed with the
 * same converters and the library directly: every row decoded
 * (cam_yuyv_row_to_rgb888), bloom_process on the RGB888 frame, every row
 * encoded back (cam_rgb888_row_to_yuyv). Part of test_gst (test_gst.c has
 * main). */
#include <string.h>

#include "cam_conv.h"
#include "test_gst.h"

#define H 61

static const tg_fmt_t yuy2 = {GST_VIDEO_FORMAT_YUY2, BLOOM_FMT_RGB888, 2, "YUY2"};

static const bloom_preset_t no_aux[] = {BLOOM_PRESET_UNITY, BLOOM_PRESET_GAMEDEV, BLOOM_PRESET_XNA,
                                        BLOOM_PRESET_ARM, BLOOM_PRESET_COD};
#define N_NO_AUX 5

/* Bytes of a YUY2 row: whole pairs (an odd width's last pair holds one
 * pixel and a padding one, as GStreamer lays it out). */
static int row_bytes(int w)
{
    return GST_ROUND_UP_2(w) * 2;
}

/* A YUY2 frame of random codes over the whole byte range (out-of-gamut
 * pairs included), a dark top third with bright spots; padding 0xA5. */
static guint8 *yuy2_frame(int w, int h, int stride, guint32 seed)
{
    GRand *r = g_rand_new_with_seed(seed);
    guint8 *p = g_malloc((gsize)stride * (gsize)h);
    memset(p, 0xA5, (gsize)stride * (gsize)h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < row_bytes(w); x++) {
            const int luma = !(x & 1), dark = y < h / 3, spot = g_rand_int_range(r, 0, 100) < 3;
            p[(gsize)y * (gsize)stride + (gsize)x] =
                (guint8)(!luma  ? g_rand_int_range(r, 0, 256)
                         : dark ? (spot ? 235 : g_rand_int_range(r, 16, 40))
                                : g_rand_int_range(r, 0, 256));
        }
    g_rand_free(r);
    return p;
}

/* The expectation: decode, bloom_process on RGB888, encode (rows stride
 * bytes apart, the padding as in src). */
static guint8 *yuy2_expect(const bloom_config_t *cfg, const guint8 *src, int stride, const guint8 *aux,
                           int aux_stride)
{
    const int w = cfg->width, h = cfg->height, rgb_stride = GST_ROUND_UP_2(w) * 3;
    guint8 *rgb = g_malloc((gsize)rgb_stride * (gsize)h);
    for (int y = 0; y < h; y++)
        cam_yuyv_row_to_rgb888(src + (gsize)y * (gsize)stride, rgb + (gsize)y * (gsize)rgb_stride,
                               GST_ROUND_UP_2(w));
    guint8 *out = tg_engine(cfg, rgb, rgb_stride, aux, aux_stride);
    guint8 *dst = NULL;
    if (out) {
        dst = g_memdup2(src, (gsize)stride * (gsize)h);
        for (int y = 0; y < h; y++)
            cam_rgb888_row_to_yuyv(out + (gsize)y * (gsize)rgb_stride, dst + (gsize)y * (gsize)stride, w);
    }
    g_free(out);
    g_free(rgb);
    return dst;
}

static GstBuffer *yuy2_buffer(int w, int h, int stride, const guint8 *px)
{
    GstBuffer *b = gst_buffer_new_allocate(NULL, (gsize)stride * (gsize)h, NULL);
    fail_unless(gst_buffer_fill(b, 0, px, (gsize)stride * (gsize)h) == (gsize)stride * (gsize)h);
    if (stride != tg_default_stride(&yuy2, w, h)) {
        gsize offset[GST_VIDEO_MAX_PLANES] = {0};
        gint strides[GST_VIDEO_MAX_PLANES] = {stride};
        gst_buffer_add_video_meta_full(b, GST_VIDEO_FRAME_FLAG_NONE, GST_VIDEO_FORMAT_YUY2, (guint)w,
                                       (guint)h, 1, offset, strides);
    }
    return b;
}

/* Whether buf holds exp, every byte of every row's pairs; *why names the
 * first difference. */
static gboolean yuy2_same(GstBuffer *buf, int w, int h, const guint8 *exp, int exp_stride, char **why)
{
    GstVideoInfo info;
    GstVideoFrame fr;
    *why = NULL;
    gst_video_info_set_format(&info, GST_VIDEO_FORMAT_YUY2, (guint)w, (guint)h);
    if (!gst_video_frame_map(&fr, &info, buf, GST_MAP_READ)) {
        *why = g_strdup("cannot map the output as a video frame");
        return FALSE;
    }
    const guint8 *d = GST_VIDEO_FRAME_PLANE_DATA(&fr, 0);
    const int stride = GST_VIDEO_FRAME_PLANE_STRIDE(&fr, 0);
    for (int y = 0; y < h && !*why; y++)
        for (int x = 0; x < row_bytes(w); x++) {
            const guint8 a = d[(gsize)y * (gsize)stride + (gsize)x],
                         e = exp[(gsize)y * (gsize)exp_stride + (gsize)x];
            if (a != e) {
                *why = g_strdup_printf("YUY2 %dx%d: row %d byte %d (%s) is %u, expected %u", w, h, y, x,
                                       (const char *[]){"Y0", "U", "Y1", "V"}[x % 4], a, e);
                break;
            }
        }
    gst_video_frame_unmap(&fr);
    return *why == NULL;
}

static char *yuy2_caps(int w, int h, const char *extra)
{
    return g_strdup_printf("video/x-raw,format=YUY2,width=%d,height=%d,framerate=25/1%s", w, h, extra);
}

/* ---- caps ------------------------------------------------------------------------- */

static gboolean accepts(GstElement *e, const char *caps)
{
    GstPad *pad = gst_element_get_static_pad(e, "sink");
    GstCaps *c = gst_caps_from_string(caps);
    const gboolean ok = gst_pad_query_accept_caps(pad, c);
    gst_caps_unref(c);
    gst_object_unref(pad);
    return ok;
}

/* YUY2 accepted both sides (even and odd widths) in limited-range BT.601
 * (cam_conv.c's rule); full range and BT.709 are not offered (a
 * videoconvert in front converts them: test_yuy2_launch). */
GST_START_TEST(test_yuy2_caps)
{
    GstElement *e = gst_element_factory_make("bloom", NULL);
    for (int w = 64; w <= 65; w++) {
        char *c = yuy2_caps(w, 48, "");
        fail_unless(accepts(e, c), "%s refused", c);
        g_free(c);
    }
    static const char *const ok[] = {",colorimetry=bt601", ",colorimetry=2:4:7:1"},
                             *const refused[] = {",colorimetry=1:4:0:0", ",colorimetry=bt709",
                                                 ",colorimetry=jpeg"};
    for (gsize i = 0; i < G_N_ELEMENTS(ok); i++) {
        char *c = yuy2_caps(64, 48, ok[i]);
        fail_unless(accepts(e, c), "%s refused", c);
        g_free(c);
    }
    for (gsize i = 0; i < G_N_ELEMENTS(refused); i++) {
        char *c = yuy2_caps(64, 48, refused[i]);
        fail_if(accepts(e, c), "%s accepted", c);
        g_free(c);
    }
    GstPad *src = gst_element_get_static_pad(e, "src");
    GstCaps *out = gst_pad_query_caps(src, NULL);
    GstCaps *want = gst_caps_from_string("video/x-raw,format=YUY2,colorimetry=bt601");
    fail_unless(gst_caps_can_intersect(out, want), "src pad caps %" GST_PTR_FORMAT " lack YUY2", out);
    gst_caps_unref(want);
    gst_caps_unref(out);
    gst_object_unref(src);
    gst_object_unref(e);
}
GST_END_TEST;

/* ---- frames ------------------------------------------------------------------------- */

/* Every preset without a plane x even / odd width x in place / out of
 * place, a padded stride, two frames each: byte-identical to decode,
 * bloom_process, encode. */
GST_START_TEST(test_yuy2_presets)
{
    const bloom_preset_t pr = no_aux[__i__ / 4];
    const int w = 96 + (__i__ & 1), in_place = !(__i__ & 2);
    const int stride = tg_default_stride(&yuy2, w, H) + 20;
    GstHarness *hs = gst_harness_new("bloom");
    g_object_set(hs->element, "in-place", in_place, NULL);
    gst_util_set_object_arg(G_OBJECT(hs->element), "preset", bloom_preset_name(pr));
    char *caps = yuy2_caps(w, H, "");
    gst_harness_set_src_caps_str(hs, caps);
    g_free(caps);
    bloom_config_t c;
    tg_config(&c, pr, w, H, BLOOM_FMT_RGB888);
    for (int k = 0; k < 2; k++) {
        guint8 *px = yuy2_frame(w, H, stride, 700u + (guint32)(__i__ * 2 + k));
        guint8 *exp = yuy2_expect(&c, px, stride, NULL, 0);
        GstBuffer *in = yuy2_buffer(w, H, stride, px);
        GstMapInfo m;
        fail_unless(gst_buffer_map(in, &m, GST_MAP_READ));
        const guint8 *in_data = m.data;
        gst_buffer_unmap(in, &m);
        fail_unless_equals_int(gst_harness_push(hs, in), GST_FLOW_OK);
        GstBuffer *out = gst_harness_try_pull(hs);
        char *why = NULL;
        fail_unless(out != NULL && exp != NULL, "%s: no output", bloom_preset_name(pr));
        fail_unless(yuy2_same(out, w, H, exp, stride, &why), "%s %s frame %d: %s", bloom_preset_name(pr),
                    in_place ? "in place" : "out of place", k, why);
        fail_unless(memcmp(exp, px, (gsize)stride * H) != 0, "%s: the test frame did not change",
                    bloom_preset_name(pr));
        fail_unless(gst_buffer_map(out, &m, GST_MAP_READ));
        fail_unless((m.data == in_data) == in_place, "output %s the input's memory",
                    m.data == in_data ? "is" : "is not");
        gst_buffer_unmap(out, &m);
        gst_buffer_unref(out);
        g_free(exp);
        g_free(px);
    }
    gst_harness_teardown(hs);
}
GST_END_TEST;

/* A preset reading its plane row by row (bloom_push_row_aux), and
 * parameters through their properties. */
GST_START_TEST(test_yuy2_aux)
{
    const int w = 96, stride = tg_default_stride(&yuy2, w, H);
    guint8 *plane = tg_frame(&(tg_fmt_t){GST_VIDEO_FORMAT_GRAY8, 0, 1, "plane"}, w, H, w, 77);
    char *path = g_strdup_printf("%s/yuy2_depth.pgm", tg_tmp());
    fail_unless(tg_write_pgm(path, w, H, 0, plane));
    GstHarness *hs = gst_harness_new("bloom");
    gst_util_set_object_arg(G_OBJECT(hs->element), "preset", "attenuation");
    g_object_set(hs->element, "aux-location", path, "threshold", 0.5, "intensity", 2.0, NULL);
    char *caps = yuy2_caps(w, H, "");
    gst_harness_set_src_caps_str(hs, caps);
    bloom_config_t c;
    tg_config(&c, BLOOM_PRESET_ATTENUATION, w, H, BLOOM_FMT_RGB888);
    c.aux_fmt = BLOOM_AUX_U8;
    c.threshold = BLOOM_Q16(0.5);
    c.intensity = BLOOM_Q16(2.0);
    guint8 *px = yuy2_frame(w, H, stride, 78);
    guint8 *exp = yuy2_expect(&c, px, stride, plane, w);
    fail_unless_equals_int(gst_harness_push(hs, yuy2_buffer(w, H, stride, px)), GST_FLOW_OK);
    GstBuffer *out = gst_harness_try_pull(hs);
    char *why = NULL;
    fail_unless(out && exp && yuy2_same(out, w, H, exp, stride, &why), "attenuation: %s", why);
    gst_buffer_unref(out);
    gst_harness_teardown(hs);
    g_free(exp);
    g_free(px);
    g_free(caps);
    g_free(path);
    g_free(plane);
}
GST_END_TEST;

/* Dark frames, nothing above the threshold. YUV -> RGB -> YUV is the
 * identity exactly on the pairs whose two pixels decode without clamping
 * (cam_ycbcr_to_rgb's three sums all within 0 .. 255: in gamut; checked
 * by hand over all 2^32 pairs). Those frames come back byte-identical:
 * black, dark greys, dark colours in gamut. A pair outside the gamut
 * (e.g. Y = 16 with U, V away from 128, a colour darker than black)
 * decodes clamped, and RGB888 cannot carry it back: such a frame is
 * asserted equal to the round trip of its rows (the engine leaves the
 * RGB888 frame as it was) and shown to differ from the input. */
static int in_gamut(int y, int cb, int cr)
{
    const int u = cb - 128, v = cr - 128, yy = 76309 * (y - 16) + 32768;
    const int t[3] = {yy + 104597 * v, yy - 25675 * u - 53279 * v, yy + 132201 * u};
    for (int i = 0; i < 3; i++)
        if (t[i] < 0 || t[i] >= 256 << 16)
            return 0;
    return 1;
}

GST_START_TEST(test_yuy2_dark)
{
    const int w = 96, stride = tg_default_stride(&yuy2, w, H);
    GRand *r = g_rand_new_with_seed(90u + (guint32)__i__);
    guint8 *px = g_malloc0((gsize)stride * H);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < w; x += 2) {
            guint8 *p = px + (gsize)y * (gsize)stride + (gsize)x * 2;
            int y0, y1, cb, cr;
            do {
                switch (__i__) {
                case 0: /* black */
                    y0 = y1 = 16, cb = cr = 128;
                    break;
                case 1: /* dark greys */
                    y0 = g_rand_int_range(r, 16, 70), y1 = g_rand_int_range(r, 16, 70), cb = cr = 128;
                    break;
                case 2: /* dark colours in gamut */
                    y0 = g_rand_int_range(r, 16, 70), y1 = g_rand_int_range(r, 16, 70);
                    cb = g_rand_int_range(r, 108, 149), cr = g_rand_int_range(r, 108, 149);
                    break;
                default: /* below black: out of gamut */
                    y0 = y1 = 16, cb = g_rand_int_range(r, 100, 157), cr = g_rand_int_range(r, 100, 157);
                    break;
                }
            } while ((__i__ < 3) != (in_gamut(y0, cb, cr) && in_gamut(y1, cb, cr)));
            p[0] = (guint8)y0, p[1] = (guint8)cb, p[2] = (guint8)y1, p[3] = (guint8)cr;
        }
    g_rand_free(r);
    bloom_config_t c;
    tg_config(&c, BLOOM_PRESET_UNITY, w, H, BLOOM_FMT_RGB888);
    /* no glow: the engine gives the RGB888 frame back as it was */
    const int rgb_stride = w * 3;
    guint8 *rgb = g_malloc((gsize)rgb_stride * H);
    for (int y = 0; y < H; y++)
        cam_yuyv_row_to_rgb888(px + (gsize)y * (gsize)stride, rgb + (gsize)y * (gsize)rgb_stride, w);
    guint8 *rgb_out = tg_engine(&c, rgb, rgb_stride, NULL, 0);
    fail_unless(rgb_out && !memcmp(rgb_out, rgb, (gsize)rgb_stride * H), "case %d: the engine changed RGB888",
                __i__);
    guint8 *exp = yuy2_expect(&c, px, stride, NULL, 0);
    GstHarness *hs = gst_harness_new("bloom");
    char *caps = yuy2_caps(w, H, "");
    gst_harness_set_src_caps_str(hs, caps);
    fail_unless_equals_int(gst_harness_push(hs, yuy2_buffer(w, H, stride, px)), GST_FLOW_OK);
    GstBuffer *out = gst_harness_try_pull(hs);
    char *why = NULL;
    fail_unless(out && exp && yuy2_same(out, w, H, exp, stride, &why), "case %d: %s", __i__, why);
    if (__i__ < 3)
        fail_unless(yuy2_same(out, w, H, px, stride, &why), "case %d: not the input: %s", __i__, why);
    else
        fail_if(yuy2_same(out, w, H, px, stride, &why), "case 3: out-of-gamut pairs came back unchanged");
    g_free(why);
    gst_buffer_unref(out);
    gst_harness_teardown(hs);
    g_free(caps);
    g_free(exp);
    g_free(rgb_out);
    g_free(rgb);
    g_free(px);
}
GST_END_TEST;

/* The README's YUY2 lines: a camera's YUY2 straight into bloom (here from
 * videotestsrc), bloom between two YUY2 elements (an odd width), and
 * full-range and BT.709 YUY2 through videoconvert first. */
GST_START_TEST(test_yuy2_launch)
{
    static const char *const lines[] = {
        "videotestsrc num-buffers=5 pattern=ball ! video/x-raw,format=YUY2,width=320,height=240 ! "
        "bloom threshold=0.8 ! videoconvert ! fakesink",
        "videotestsrc num-buffers=3 ! video/x-raw,format=YUY2,width=161,height=120 ! bloom preset=cod "
        "radius=20 ! video/x-raw,format=YUY2 ! fakesink",
        "videotestsrc num-buffers=3 ! video/x-raw,format=YUY2,colorimetry=1:4:0:0,width=64,height=48 ! "
        "videoconvert ! bloom ! fakesink",
        "videotestsrc num-buffers=3 ! video/x-raw,format=YUY2,colorimetry=bt709,width=64,height=48 ! "
        "videoconvert ! bloom ! video/x-raw,format=YUY2 ! fakesink",
    };
    for (gsize i = 0; i < G_N_ELEMENTS(lines); i++) {
        GError *err = NULL;
        GstElement *pipe = gst_parse_launch(lines[i], &err);
        fail_unless(pipe && !err, "%s: %s", lines[i], err ? err->message : "?");
        GstBus *bus = gst_element_get_bus(pipe);
        gst_element_set_state(pipe, GST_STATE_PLAYING);
        char *t = tg_bus_text(bus, GST_MESSAGE_EOS | GST_MESSAGE_ERROR, 30 * GST_SECOND);
        fail_unless(t && !strcmp(t, "eos"), "%s: %s", lines[i], t ? t : "timeout");
        g_free(t);
        gst_element_set_state(pipe, GST_STATE_NULL);
        gst_object_unref(bus);
        gst_object_unref(pipe);
    }
}
GST_END_TEST;

void tg_add_yuy2_tests(Suite *s)
{
    TCase *tc = tg_tcase(s, "yuy2");
    tcase_add_test(tc, test_yuy2_caps);
    tcase_add_loop_test(tc, test_yuy2_presets, 0, N_NO_AUX * 4);
    tcase_add_test(tc, test_yuy2_aux);
    tcase_add_loop_test(tc, test_yuy2_dark, 0, 4);
    tcase_add_test(tc, test_yuy2_launch);
}
