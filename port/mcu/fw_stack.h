/* Stack high-water measurement by painting: fill the unused stack below the
 * current SP with a pattern, run a call, then find the lowest word the call
 * overwrote. Always inlined so that "the current SP" is the caller's own,
 * with its frame already allocated above it. */
#ifndef FW_STACK_H
#define FW_STACK_H

#include <stdint.h>

#define FW_STACK_PAINT 0xA5C3E10Fu

extern uint32_t __stack_limit[], __stack_top[]; /* from mps2.ld */

__attribute__((always_inline)) static inline uintptr_t fw_sp(void)
{
    uintptr_t sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    return sp;
}

__attribute__((always_inline)) static inline void fw_stack_paint(uintptr_t below)
{
    for (volatile uint32_t *p = __stack_limit; (uintptr_t)p < below; p++)
        *p = FW_STACK_PAINT;
}

/* The lowest stack address written since the paint (below if untouched). */
__attribute__((always_inline)) static inline uintptr_t fw_stack_low(uintptr_t below)
{
    const volatile uint32_t *p = __stack_limit;
    while ((uintptr_t)p < below && *p == FW_STACK_PAINT)
        p++;
    return (uintptr_t)p;
}

#endif
