/* The Cortex-M firmware: runs fw_app() (the frame, the engine, the checksum)
 * with semihosting output, and measures the stack bloom_init and
 * bloom_process use by painting (fw_stack.h). */
#include <stdint.h>

#include "fw_app.h"
#include "fw_stack.h"
#include "semihost.h"

static uintptr_t fw_lowest = UINTPTR_MAX; /* lowest stack address seen written */

static void fw_puts(const char *line)
{
    semi_write0(line);
    semi_write0("\n");
}

__attribute__((always_inline)) static inline uint32_t used_since(uintptr_t sp)
{
    const uintptr_t low = fw_stack_low(sp);
    if (low < fw_lowest)
        fw_lowest = low;
    return (uint32_t)(sp - low);
}

/* noinline: the painted region starts right below this frame, so the figure
 * is exactly what the engine call and everything it calls push. */
__attribute__((noinline)) static bloom_status_t fw_init(bloom_t **b, void *ws, size_t ws_bytes,
                                                        const bloom_config_t *cfg, uint32_t *stack)
{
    const uintptr_t sp = fw_sp();
    fw_stack_paint(sp);
    const bloom_status_t st = bloom_init(b, ws, ws_bytes, cfg);
    *stack = used_since(sp);
    return st;
}

__attribute__((noinline)) static bloom_status_t fw_process(bloom_t *b, uint8_t *fb, uint32_t *stack)
{
    const uintptr_t sp = fw_sp();
    fw_stack_paint(sp);
    const bloom_status_t st = bloom_process(b, fb, FW_STRIDE, fb, FW_STRIDE);
    *stack = used_since(sp);
    return st;
}

__attribute__((noinline)) static bloom_status_t fw_run(bloom_t *b, const uint8_t *src, uint8_t *dst,
                                                       ptrdiff_t stride, uint32_t *stack)
{
    const uintptr_t sp = fw_sp();
    fw_stack_paint(sp);
    const bloom_status_t st = bloom_process(b, src, stride, dst, stride);
    *stack = used_since(sp);
    return st;
}

/* FW_MAIN_APP: which application this image runs (mcu.mk builds the tiles
 * case with fw_tiles_app). */
#ifndef FW_MAIN_APP
#define FW_MAIN_APP fw_app
#endif

int main(void)
{
    static const fw_platform_t pf = {fw_puts, fw_init, fw_process, fw_run};
    fw_line_t l = {.n = 0};
    const uint32_t cpuid = *(const volatile uint32_t *)0xE000ED00u; /* SCB->CPUID */
    const uint32_t part = (cpuid >> 4) & 0xfffu;
    fw_str(&l, "cpu: ");
    fw_str(&l, part == 0xc24u ? "Cortex-M4" : part == 0xc27u ? "Cortex-M7" : "other");
    fw_str(&l, " (CPUID ");
    fw_hex(&l, cpuid);
    fw_str(&l, ")");
    fw_puts(l.s);

    int rc = FW_MAIN_APP(&pf);

    const uintptr_t low = fw_stack_low(fw_sp());
    if (low < fw_lowest)
        fw_lowest = low;
    l.n = 0;
    fw_str(&l, "stack whole program: ");
    fw_dec(&l, (uint32_t)((uintptr_t)__stack_top - fw_lowest));
    fw_str(&l, " bytes of ");
    fw_dec(&l, (uint32_t)((uintptr_t)__stack_top - (uintptr_t)__stack_limit));
    fw_str(&l, " reserved");
    fw_puts(l.s);
    if (fw_lowest <= (uintptr_t)__stack_limit) {
        fw_puts("error: the stack reservation was exhausted");
        rc = 2;
    }
    return rc;
}
