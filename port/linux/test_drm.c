/* make test-linux-host: the DRM output's pure rules (drm_pick.c) and the
 * display options (cam_opts.c). No device: what drm.c does with a real
 * one is make test-linux's, under QEMU on bochs-drm and cirrus. */
#include <stdio.h>
#include <string.h>

#include "cam.h"
#include "harness.h"

static void test_modes(void)
{
    /* as bochs lists them: the preferred first, then by size */
    const cam_drm_mode_t m[] = {{1024, 768, 60, 1}, {1920, 1080, 60, 0}, {1280, 720, 60, 0},
                                {1280, 720, 75, 0}, {1024, 768, 75, 0},  {640, 480, 60, 0}};
    const int n = (int)(sizeof m / sizeof m[0]);
    CHECK(cam_drm_pick_mode(m, n, 0, 0) == 0);       /* the preferred */
    CHECK(cam_drm_pick_mode(m, n, 640, 480) == 5);   /* the one of that size */
    CHECK(cam_drm_pick_mode(m, n, 1280, 720) == 3);  /* the faster of two */
    CHECK(cam_drm_pick_mode(m, n, 1024, 768) == 0);  /* the preferred over a faster one */
    CHECK(cam_drm_pick_mode(m, n, 800, 600) == -1);  /* not offered */
    CHECK(cam_drm_pick_mode(m, n, 768, 1024) == -1); /* rotated is another size */
    CHECK(cam_drm_pick_mode(m, 0, 0, 0) == -1);      /* no modes */
    /* none flagged preferred: the first listed */
    const cam_drm_mode_t u[] = {{800, 600, 60, 0}, {1024, 768, 60, 0}};
    CHECK(cam_drm_pick_mode(u, 2, 0, 0) == 0);
    /* the preferred one not first */
    const cam_drm_mode_t p[] = {{800, 600, 60, 0}, {1024, 768, 60, 1}};
    CHECK(cam_drm_pick_mode(p, 2, 0, 0) == 1);
}

static void test_formats(void)
{
    bloom_format_t out[2] = {0, 0};
    const uint32_t bochs[] = {CAM_DRM_XRGB8888, CAM_FOURCC('B', 'X', '2', '4')};
    const uint32_t cirrus[] = {CAM_DRM_RGB565, CAM_FOURCC('R', 'G', '2', '4'), CAM_DRM_XRGB8888};
    const uint32_t other[] = {CAM_FOURCC('X', 'B', '2', '4'), CAM_FOURCC('A', 'R', '2', '4')};
    /* the fourccs are drm_fourcc.h's */
    CHECK(CAM_DRM_XRGB8888 == 0x34325258u && CAM_DRM_RGB565 == 0x36314752u);
    CHECK(cam_drm_pick_formats(bochs, 2, (bloom_format_t)0, out) == 1 && out[0] == BLOOM_FMT_XRGB8888);
    CHECK(cam_drm_pick_formats(bochs, 2, BLOOM_FMT_RGB565, out) == 0); /* bochs has no RGB565 */
    /* auto: XRGB8888 first, RGB565 to fall back on, whatever the plane's order */
    CHECK(cam_drm_pick_formats(cirrus, 3, (bloom_format_t)0, out) == 2 && out[0] == BLOOM_FMT_XRGB8888 &&
          out[1] == BLOOM_FMT_RGB565);
    CHECK(cam_drm_pick_formats(cirrus, 3, BLOOM_FMT_RGB565, out) == 1 && out[0] == BLOOM_FMT_RGB565);
    CHECK(cam_drm_pick_formats(cirrus, 3, BLOOM_FMT_XRGB8888, out) == 1 && out[0] == BLOOM_FMT_XRGB8888);
    CHECK(cam_drm_pick_formats(other, 2, (bloom_format_t)0, out) == 0);
    CHECK(cam_drm_pick_formats(other, 0, (bloom_format_t)0, out) == 0);
}

static int parse(cam_opts_t *o, const char *line, char *err, size_t errlen)
{
    char buf[512], *argv[32];
    int argc = 0;
    snprintf(buf, sizeof buf, "bloom_cam %s", line);
    for (char *t = strtok(buf, " "); t && argc < 31; t = strtok(NULL, " "))
        argv[argc++] = t;
    argv[argc] = NULL;
    err[0] = '\0';
    return cam_parse_opts(o, argc, argv, err, errlen);
}

static void test_options(void)
{
    cam_opts_t o;
    char err[256];
    CHECK(parse(&o, "", err, sizeof err) == 0 && o.display == CAM_DISPLAY_AUTO && !o.fb_given &&
          !o.drm_card && o.drm_w == 0 && o.drm_format == 0 && !strcmp(o.fb, "/dev/fb0"));
    /* auto: DRM when a card is connected and --fb was not given */
    CHECK(cam_display_use_drm(&o, 1) == 1 && cam_display_use_drm(&o, 0) == 0);
    CHECK(parse(&o, "--fb /dev/fb1", err, sizeof err) == 0 && o.fb_given && o.display == CAM_DISPLAY_AUTO);
    CHECK(cam_display_use_drm(&o, 1) == 0); /* the framebuffer given wins */
    CHECK(parse(&o, "--fb none", err, sizeof err) == 0 && cam_display_use_drm(&o, 1) == 0);
    CHECK(parse(&o, "--display fbdev", err, sizeof err) == 0 && cam_display_use_drm(&o, 1) == 0);
    CHECK(parse(&o, "--display=auto", err, sizeof err) == 0 && o.display == CAM_DISPLAY_AUTO);
    /* the VT option (left alone with either display) */
    CHECK(parse(&o, "--vt off", err, sizeof err) == 0 && !strcmp(o.vt, "off"));
    CHECK(parse(&o, "--vt=/dev/tty2", err, sizeof err) == 0 && !strcmp(o.vt, "/dev/tty2"));
    if (cam_drm_available) {
        CHECK(parse(&o, "--display drm", err, sizeof err) == 0 && cam_display_use_drm(&o, 0) == 1);
        CHECK(parse(&o, "--drm-mode 1280x720 --drm-card /dev/dri/card1 --drm-format rgb565", err,
                    sizeof err) == 0 &&
              o.drm_w == 1280 && o.drm_h == 720 && !strcmp(o.drm_card, "/dev/dri/card1") &&
              o.drm_format == BLOOM_FMT_RGB565 && o.display == CAM_DISPLAY_DRM); /* --drm-* ask for DRM */
        CHECK(parse(&o, "--drm-format=xrgb8888", err, sizeof err) == 0 && o.drm_format == BLOOM_FMT_XRGB8888);
        CHECK(parse(&o, "--drm-format auto --display drm", err, sizeof err) == 0 && o.drm_format == 0);
        /* --mode is still the view, not the screen's mode */
        CHECK(parse(&o, "--display drm --mode off", err, sizeof err) == 0 && o.mode == CAM_MODE_OFF);
    } else {
        CHECKF(parse(&o, "--display drm", err, sizeof err) < 0 && strstr(err, "built without libdrm"), "%s",
               err);
        SKIP("test_drm: --drm-* accepted: built without libdrm (Debian libdrm-dev)");
    }
    static const struct {
        const char *line, *msg;
    } bad[] = {
        {"--display kms", "--display: 'kms' is not drm, fbdev or auto"},
        {"--display", "--display needs a value"},
        {"--drm-mode 1280", "--drm-mode: '1280' is not WxH"},
        {"--drm-mode 0x720", "--drm-mode: '0x720' is not WxH"},
        {"--drm-format bgr888", "--drm-format: 'bgr888' is not auto, xrgb8888 or rgb565"},
        {"--display fbdev --drm-mode 640x480", "are for --display drm, not fbdev"},
        {"--fb /dev/fb0 --drm-card /dev/dri/card0", "give one of them"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
        CHECKF(parse(&o, bad[k].line, err, sizeof err) < 0 && strstr(err, bad[k].msg), "'%s': got '%s'",
               bad[k].line, err);
    if (cam_drm_available)
        CHECKF(parse(&o, "--display drm --fb /dev/fb0", err, sizeof err) < 0 &&
                   strstr(err, "--fb is the fbdev output: not with --display drm"),
               "got '%s'", err);
}

int main(void)
{
    test_modes();
    test_formats();
    test_options();
    printf("test_drm: mode choice, format choice, auto's rule, the display options\n");
    return harness_finish();
}
