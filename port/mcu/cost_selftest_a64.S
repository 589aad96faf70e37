// The Cortex-A counter's known program (port/mcu/cost_selftest.py):
// exactly 1 + 2 * N + 3 instructions, N = ST_N.
    .global _start
    .text
_start:
    mov x0, #ST_N
1:  subs x0, x0, #1
    b.ne 1b
    mov x8, #93             // exit
    mov x0, #0
    svc #0
