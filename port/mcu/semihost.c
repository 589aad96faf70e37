/* ARM semihosting calls: operation in r0, argument (a pointer) in r1,
 * result in r0. The debugger (here QEMU) traps bkpt 0xAB. */
#include <stdint.h>

#include "semihost.h"

#define SYS_WRITE0 0x04
#define SYS_EXIT 0x18
#define SYS_EXIT_EXTENDED 0x20
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR 0x20023u

static int semi_call(int op, const void *arg)
{
    register int r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void semi_write0(const char *s)
{
    semi_call(SYS_WRITE0, s);
}

_Noreturn void semi_exit(int status)
{
    /* SYS_EXIT on 32-bit ARM carries no status; SYS_EXIT_EXTENDED does. */
    const uint32_t block[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status};
    semi_call(SYS_EXIT_EXTENDED, block);
    /* only reached if the host lacks SYS_EXIT_EXTENDED: pass/fail at least */
    semi_call(SYS_EXIT,
              (const void *)(uintptr_t)(status ? ADP_STOPPED_RUNTIME_ERROR : ADP_STOPPED_APPLICATION_EXIT));
    for (;;)
        __asm__ volatile("wfi");
}
