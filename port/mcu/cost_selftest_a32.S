@ The armhf counter's known program (port/mcu/cost_selftest.py): exactly
@ 1 + 2 * N + 3 instructions, N = ST_N.
    .syntax unified
    .arm
    .global _start
    .text
_start:
    mov r0, #ST_N
1:  subs r0, r0, #1
    bne 1b
    mov r7, #1              @ exit
    mov r0, #0
    svc #0
