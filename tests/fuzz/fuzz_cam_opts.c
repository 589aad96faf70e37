/* fuzz_cam_opts: bloom_cam's command line (port/linux/cam_opts.c). The
 * input is split at NUL and newline bytes into argv[1..]; what parses must
 * hold the documented ranges and give a configuration the engine takes
 * (cam_parse_opts checks it with bloom_query at the --size asked). */
#include "fuzz.h"

#include "cam.h"

#include <stdlib.h>
#include <string.h>

#define MAX_ARGS 48

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 4096)
        return 0;
    char *buf = malloc(size + 1);
    char *argv[MAX_ARGS + 2];
    int argc = 1;
    argv[0] = (char *)"bloom_cam";
    memcpy(buf, data, size);
    buf[size] = '\0';
    char *a = buf;
    for (size_t i = 0; i <= size && argc <= MAX_ARGS; i++)
        if (buf[i] == '\0' || buf[i] == '\n') {
            buf[i] = '\0';
            argv[argc++] = a;
            a = buf + i + 1;
        }
    argv[argc] = NULL;
    cam_opts_t o;
    char err[256];
    err[0] = '\0';
    const int rc = cam_parse_opts(&o, argc, argv, err, sizeof err);
    FZ_CHECK(rc >= -1 && rc <= 1);
    if (rc == -1)
        FZ_CHECK(err[0] != '\0' && memchr(err, '\0', sizeof err) != NULL);
    if (rc == 0) {
        FZ_CHECK(o.width >= 2 && o.width <= BLOOM_MAX_DIM && o.height >= 1 && o.height <= BLOOM_MAX_DIM);
        FZ_CHECK((unsigned)o.format < CAM_FMT_COUNT); /* auto, or a format of the table (cam_fmt.c) */
        FZ_CHECK(o.format != CAM_FMT_YUYV || o.width % 2 == 0);
        FZ_CHECK(o.levels >= 1 && o.levels <= BLOOM_MAX_LEVELS);
        FZ_CHECK(o.threshold <= BLOOM_MAX_THRESHOLD && o.knee <= BLOOM_ONE &&
                 o.intensity <= BLOOM_MAX_INTENSITY);
        FZ_CHECK(o.buffers >= 2 && o.buffers <= CAM_MAX_BUFFERS && o.timeout_ms >= 1);
        FZ_CHECK((unsigned)o.mode < CAM_MODE_COUNT && o.frames >= 0);
        FZ_CHECK(bloom_preset_available(o.preset));
        FZ_CHECK(strcmp(cam_format_name(o.format), "?") && strcmp(cam_mode_name(o.mode), "?"));
        bloom_config_t c;
        bloom_info_t info;
        cam_opts_config(&o, o.width, o.height, &c);
        const bloom_status_t st = bloom_query(&c, &info);
        FZ_CHECKF(st == BLOOM_OK, "%s", bloom_status_str(st));
        /* the driver may set another size: never a crash, and a refusal
         * only for the size */
        const int w2 = 2 + (int)(size % 64), h2 = 1 + (int)(size % 37);
        cam_opts_config(&o, w2, h2, &c);
        const bloom_status_t st2 = bloom_query(&c, &info);
        FZ_CHECKF(st2 == BLOOM_OK || st2 == BLOOM_E_SIZE, "%dx%d: %s", w2, h2, bloom_status_str(st2));
    }
    free(buf);
    return 0;
}
