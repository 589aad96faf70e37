/* The part of the Cortex-M example that the firmware and the host build
 * share: the test frame, the engine run, the checksum and the report lines.
 * Both builds print the same "frame ..." lines for the same input, so a test
 * can compare them as text (port/mcu/test_firmware.sh). */
#ifndef FW_APP_H
#define FW_APP_H

#include <stddef.h>
#include <stdint.h>

#include "bloom.h"

#define FW_W 320
#define FW_H 240
#define FW_STRIDE (FW_W * 2) /* RGB565 */
#ifndef FW_LEVELS
#define FW_LEVELS 5 /* the default preset; the make rules also build the deepest (7) */
#endif

/* What the platform provides: a line sink and the two engine calls, which
 * the firmware wraps to measure the stack they use (*stack = bytes, or 0
 * when not measured). */
typedef struct {
    void (*puts)(const char *line); /* one line, no newline */
    bloom_status_t (*init)(bloom_t **b, void *ws, size_t ws_bytes, const bloom_config_t *cfg,
                           uint32_t *stack);
    bloom_status_t (*process)(bloom_t *b, uint8_t *fb, uint32_t *stack);
    /* src to dst, both stride bytes a row (a tile is never in place) */
    bloom_status_t (*run)(bloom_t *b, const uint8_t *src, uint8_t *dst, ptrdiff_t stride, uint32_t *stack);
} fw_platform_t;

/* Pixel (x, y) of the test frame, RGB565: a dim gradient with low noise and
 * a few lamps above the bloom threshold. Pure, so the frame can be
 * regenerated to count changed pixels after the in-place run. */
uint16_t fw_pattern_pixel(int x, int y);
void fw_pattern(uint8_t *fb);
uint32_t fw_fnv1a(const uint8_t *p, size_t n);

/* Generate, run the default preset at FW_LEVELS in place, report. Returns 0
 * when every engine call succeeded. */
int fw_app(const fw_platform_t *pf);

/* The tiles case (fw_tiles.c, issue 14): a 640x480 RGB565 frame whose
 * untiled workspace exceeds a 64 KB on-chip SRAM, rendered in strips with a
 * static workspace of 32 KB on the target, untiled on the host. Both print
 * the same "frame ..." lines. Returns 0 on success. */
int fw_tiles_app(const fw_platform_t *pf);

/* The cost bench (fw_cost.c, issue 21): one frame of the job the harness
 * writes into the image (port/mcu/mcu_count.py). Returns 0 on success. */
int fw_cost_app(const fw_platform_t *pf);

/* A line under construction, for targets without printf. */
typedef struct {
    char s[120];
    size_t n;
} fw_line_t;
void fw_str(fw_line_t *l, const char *s);
void fw_dec(fw_line_t *l, uint32_t v);
void fw_hex(fw_line_t *l, uint32_t v);

#endif
