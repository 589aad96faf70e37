/* Shared helpers of the libFuzzer targets (tests/fuzz/README.md): the
 * input as a regular file, as a pipe or as a memory stream, a cursor that
 * takes numbers off the input, and ASan-poisoned canaries. */
#ifndef BLOOM_FUZZ_H
#define BLOOM_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A regular file holding data, the same per-process path every call
 * (rewritten), removed at exit. */
const char *fz_file(const uint8_t *data, size_t size);
/* "/proc/self/fd/N" of a pipe already holding data (up to 1 MiB) with its
 * write end closed: a reader that opens the path gets the data, then end
 * of file, and cannot seek or fstat a size. Valid until the next call. */
const char *fz_pipe(const uint8_t *data, size_t size);
/* The same pipe as a stream (the caller closes it). */
FILE *fz_pipe_stream(const uint8_t *data, size_t size);
/* A read-only memory stream over data: seekable, with no descriptor. */
FILE *fz_mem_stream(const uint8_t *data, size_t size);

/* Numbers off the input; zeros once it is used up. */
typedef struct {
    const uint8_t *p;
    size_t n;
} fz_in_t;
unsigned fz_u8(fz_in_t *in);
unsigned fz_u16(fz_in_t *in);
uint32_t fz_u32(fz_in_t *in);

/* A failed check: prints the message and aborts (libFuzzer saves the input). */
void fz_fail(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2), noreturn))
#endif
    ;
#define FZ_CHECK(cond)                                                                                       \
    do {                                                                                                     \
        if (!(cond))                                                                                         \
            fz_fail("%s:%d: check failed: %s", __FILE__, __LINE__, #cond);                                   \
    } while (0)
/* The same with a message: FZ_CHECKF(cond, "fmt", ...). */
#define FZ_CHECKF(cond, ...)                                                                                 \
    do {                                                                                                     \
        if (!(cond)) {                                                                                       \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);                         \
            fz_fail(__VA_ARGS__);                                                                            \
        }                                                                                                    \
    } while (0)

/* Canaries: n bytes of a fixed pattern, poisoned for ASan (any access by
 * the code under test is reported), checked by fz_canary_ok. */
void fz_canary_set(uint8_t *p, size_t n);
int fz_canary_ok(uint8_t *p, size_t n);

/* Frames larger than this many pixels (or samples) are skipped by the
 * targets whose inputs can declare them cheaply and legitimately (a small
 * compressed file of a large image): decoding them is correct but takes
 * the fuzzer's memory and time. Sides above the engine's limit still run,
 * so their refusal is fuzzed. */
#define FZ_MAX_PIXELS (1u << 20)

#endif
