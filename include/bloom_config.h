/* Compile-time switches of the bloom core.
 *
 * Every switch has a default here; override with -D on the command line or
 * by defining it before this header is included (LVGL style). */
#ifndef BLOOM_CONFIG_H
#define BLOOM_CONFIG_H

/* Pixel formats compiled into the row kernels. A format that is compiled out
 * is refused by bloom_query()/bloom_init() with BLOOM_E_FORMAT. */
#ifndef BLOOM_USE_RGB888
#define BLOOM_USE_RGB888 1
#endif
#ifndef BLOOM_USE_XRGB8888
#define BLOOM_USE_XRGB8888 1
#endif
#ifndef BLOOM_USE_RGB565
#define BLOOM_USE_RGB565 1
#endif
#ifndef BLOOM_USE_RGBQ16
#define BLOOM_USE_RGBQ16 1 /* linear Q16.16 words: HDR input and output */
#endif
#ifndef BLOOM_USE_RGBF32 /* linear binary32 input: with RGBQ16 unless said otherwise */
#define BLOOM_USE_RGBF32 BLOOM_USE_RGBQ16
#endif

/* Presets besides the default (sim/docs/presets.md). 0 leaves a preset's
 * code out; bloom_query() then refuses it with BLOOM_E_PRESET. With all of
 * them 0 the engine carries only the default's graph. */
#ifndef BLOOM_USE_GAMEDEV
#define BLOOM_USE_GAMEDEV 1
#endif
#ifndef BLOOM_USE_XNA
#define BLOOM_USE_XNA 1
#endif
#ifndef BLOOM_USE_ATTENUATION
#define BLOOM_USE_ATTENUATION 1
#endif
#ifndef BLOOM_USE_ARM
#define BLOOM_USE_ARM 1
#endif
#ifndef BLOOM_USE_COD
#define BLOOM_USE_COD 1
#endif
#define BLOOM_USE_GRAPH                                                                                      \
    (BLOOM_USE_GAMEDEV || BLOOM_USE_XNA || BLOOM_USE_ATTENUATION || BLOOM_USE_ARM || BLOOM_USE_COD)

/* 16-bit pyramid samples (cfg.sample_bits = 16): the default preset's
 * rings hold uint16_t (sim/docs/fixed-point.md, "16-bit samples"). 0
 * leaves the code out and bloom_query refuses 16 with
 * BLOOM_E_SAMPLE_BITS: the size build's choice (its flash budget). */
#ifndef BLOOM_USE_S16
#define BLOOM_USE_S16 (!BLOOM_SMALL)
#endif
/* With 16-bit samples, the pyramid levels whose rows are 16-bit (1 ..
 * BLOOM_S16_LEVELS; 16: all of them). The deeper levels keep 32-bit rows:
 * they are a quarter of the memory and less, and a level-k sample spreads
 * over 4^k output pixels, so their roundings at the 16-bit step were most
 * of that path's error (fixed-point.md, "16-bit samples": error and memory
 * for 1, 2 and all). */
#ifndef BLOOM_S16_LEVELS
#define BLOOM_S16_LEVELS 2
#endif

/* Skip what a scene does not need: dark source rows, all-zero rows of every
 * level, output rows without bloom (a copy). 0 leaves the code out. */
#ifndef BLOOM_USE_SKIP
#define BLOOM_USE_SKIP 1
#endif

/* bloom_process copies a dark source row to its destination right after
 * its dark test, while the row is in the data cache: a dark frame is then
 * one read of each row, not two. A dark row that still gets bloom is
 * written again at its turn. On a microcontroller (ARM M profile: no data
 * cache on Cortex-M0 to M4, framebuffers often uncached on M7) the early
 * copy saves no read and costs that second write (0.9 instructions per
 * pixel on the firmware's scene, sim/docs/targets.md), so it is off there.
 * Needs BLOOM_USE_SKIP; the size build leaves it out. Same bits. */
#ifndef BLOOM_DARK_COPY
#if defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M'
#define BLOOM_DARK_COPY 0
#else
#define BLOOM_DARK_COPY 1
#endif
#endif

/* Fraction bits of the internal linear samples, 16..20 (Q12.20 by default;
 * fewer only to measure precision against accuracy: make report). The
 * sRGB tables must be generated for the same value (sim/gen_tables.c F). */
#ifndef BLOOM_LIN_BITS
#define BLOOM_LIN_BITS 20
#endif

/* Internal consistency checks of the row scheduler (cheap: per row, never
 * per pixel). Keep them on unless code size is the last word. */
#ifndef BLOOM_CHECK_RINGS
#define BLOOM_CHECK_RINGS 1
#endif

/* Smallest code over speed: the sRGB encoder searches the thresholds
 * instead of using its 5.6 KB of bucket tables, and the row kernels are not
 * copied per pixel format. Same results bit for bit (tested). */
#ifndef BLOOM_SMALL
#define BLOOM_SMALL 0
#endif

/* The static schedule: the order in which rows are made is computed once,
 * at bloom_init, into a table in the workspace (about 6 bytes per frame
 * row, sim/docs/streaming.md), every frame walks it, and each ring keeps
 * its slots' pointers and tags twice over with a cursor per reader. 0 (the
 * size build's choice, with BLOOM_SMALL only) makes each pull find its rows
 * by walking the graph down from the output instead: less code and
 * workspace, more instructions per row. Same results bit for bit. */
#ifndef BLOOM_SCHED_TABLE
#define BLOOM_SCHED_TABLE (!BLOOM_SMALL)
#endif
#if !BLOOM_SCHED_TABLE && !BLOOM_SMALL
#error "BLOOM_SCHED_TABLE 0 goes with BLOOM_SMALL (tiles read their rows through the table's gathers)"
#endif

/* Pixels per chunk of the fused output kernel: a stack buffer of
 * 3 * 4 * BLOOM_OUT_CHUNK bytes. */
#ifndef BLOOM_OUT_CHUNK
#define BLOOM_OUT_CHUNK 16
#endif

/* SIMD row kernels (SSE2 on x86-64, NEON on aarch64), bit-identical to the
 * C kernels and picked per engine at bloom_init. 1 leaves them out and
 * always uses the C kernels (BLOOM_FLAG_NO_SIMD does it at run time).
 * Targets without one of those ISAs use the C kernels anyway. */
#ifndef BLOOM_NO_SIMD
#define BLOOM_NO_SIMD 0
#endif

/* AVX2 twins of the level-1 row, the tents and the output encode
 * (src/kernels/bloom_row_avx2.c, GCC or clang on x86-64), used where CPUID and
 * XGETBV report AVX2 (BLOOM_FLAG_NO_AVX2 keeps SSE2 at run time). 1 leaves
 * them out of the build. */
#ifndef BLOOM_NO_AVX2
#define BLOOM_NO_AVX2 0
#endif

#endif
