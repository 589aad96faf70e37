/* The host build of the Cortex-M example: the same frame, engine and
 * checksum (fw_app.c) compiled with the host compiler, printing to stdout.
 * port/mcu/test_firmware.sh compares its "frame" lines with the firmware's. */
#include <stdio.h>

#include "fw_app.h"

static void host_puts(const char *line)
{
    puts(line);
}

static bloom_status_t host_init(bloom_t **b, void *ws, size_t ws_bytes, const bloom_config_t *cfg,
                                uint32_t *stack)
{
    *stack = 0; /* measured on the target only */
    return bloom_init(b, ws, ws_bytes, cfg);
}

static bloom_status_t host_process(bloom_t *b, uint8_t *fb, uint32_t *stack)
{
    *stack = 0;
    return bloom_process(b, fb, FW_STRIDE, fb, FW_STRIDE);
}

static bloom_status_t host_run(bloom_t *b, const uint8_t *src, uint8_t *dst, ptrdiff_t stride,
                               uint32_t *stack)
{
    *stack = 0;
    return bloom_process(b, src, stride, dst, stride);
}

#ifndef FW_MAIN_APP
#define FW_MAIN_APP fw_app
#endif

int main(void)
{
    static const fw_platform_t pf = {host_puts, host_init, host_process, host_run};
    return FW_MAIN_APP(&pf);
}
