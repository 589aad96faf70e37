@ The Cortex-M counter's known program (port/mcu/cost_selftest.py): a
@ loop of a known class mix, called from st_main outside the counted
@ region st_loop. Changing it changes the expected counts there.
    .syntax unified
    .thumb
    .cpu cortex-m4
    .text
    .global st_main, st_loop
    .thumb_func
st_main:                    @ r0 = iterations: outside the region
    push {lr}
    ldr r1, =st_buf
    bl st_loop
    adds r0, #0
    pop {pc}

    .thumb_func
st_loop:                    @ r0 = iterations (>= 1), r1 = 3 words
    push {r4, r5, lr}       @ store
    movs r2, #0             @ other
    movs r5, #7             @ other
1:  ldr r3, [r1]            @ load
    ldr r4, [r1, #4]        @ load, pipelined after the first
    mla r2, r3, r4, r2      @ mul
    udiv r3, r2, r5         @ div
    uqadd8 r3, r3, r4       @ dsp
    str r3, [r1, #8]        @ store
    cmp r3, #0              @ other
    it eq                   @ it
    addeq r2, #1            @ other (counted whether its condition passes or not)
    subs r0, #1             @ other
    bne 1b                  @ taken N-1 times, not taken once
    mov r0, r2              @ other
    pop {r4, r5, pc}        @ taken (the return)
    .ltorg

    .data
    .align 2
st_buf: .word 3, 5, 0
