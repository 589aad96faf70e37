/* Startup for the MPS2 boards under QEMU: the vector table, a reset handler
 * that sets up .data and .bss and paints the stack, and a fault handler that
 * reports over semihosting instead of hanging the emulator. */
#include <stdint.h>

#include "fw_stack.h"
#include "semihost.h"

extern uint32_t __data_load[], __data_start[], __data_end[], __bss_start[], __bss_end[];
int main(void);
void fw_reset(void);
void fw_fault(void);

typedef void (*fw_handler_t)(void);
typedef struct {
    uint32_t *initial_sp;
    fw_handler_t handler[15]; /* exceptions 1 (reset) .. 15 (SysTick) */
} fw_vectors_t;

/* No interrupts are enabled, so the system exceptions are all there is. */
__attribute__((section(".vectors"), used)) const fw_vectors_t fw_vectors = {
    __stack_top,
    {fw_reset, fw_fault, fw_fault, fw_fault, fw_fault, fw_fault, 0, 0, 0, 0, fw_fault, fw_fault, 0, fw_fault,
     fw_fault},
};

void fw_reset(void)
{
    const uint32_t *s = __data_load;
    for (uint32_t *d = __data_start; d < __data_end;)
        *d++ = *s++;
    for (uint32_t *d = __bss_start; d < __bss_end;)
        *d++ = 0;
    fw_stack_paint(fw_sp()); /* for the whole-program peak (fw_main.c) */
    semi_exit(main());
}

void fw_fault(void)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    static char msg[] = "fault: exception 00\n";
    msg[17] = (char)('0' + (ipsr & 0x1ffu) / 10u % 10u);
    msg[18] = (char)('0' + (ipsr & 0x1ffu) % 10u);
    semi_write0(msg);
    semi_exit(3);
}
