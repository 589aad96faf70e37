/* Minimal ARM semihosting (bkpt 0xAB on M-profile), enough for a report
 * and an exit status under qemu-system-arm -semihosting. */
#ifndef SEMIHOST_H
#define SEMIHOST_H

/* Write a NUL-terminated string to the host's console (SYS_WRITE0). */
void semi_write0(const char *s);
/* End the emulation with this exit status; never returns. */
_Noreturn void semi_exit(int status);

#endif
