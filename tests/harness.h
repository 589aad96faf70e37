/* Minimal test harness: CHECK records a failure and goes on; SKIP names
 * something not run and why; each test binary ends with harness_finish(),
 * which prints "N passed, N failed, N skipped" and returns the exit status
 * (tests/verdict.sh holds the protocol). Header-only so every test file
 * stays self-contained. */
#ifndef BLOOM_TEST_HARNESS_H
#define BLOOM_TEST_HARNESS_H

#include <stdio.h>

static int harness_pass, harness_fail, harness_skip;

#define CHECK(cond)                                                                                          \
    do {                                                                                                     \
        if (cond) {                                                                                          \
            harness_pass++;                                                                                  \
        } else {                                                                                             \
            harness_fail++;                                                                                  \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);                         \
        }                                                                                                    \
    } while (0)

#define CHECKF(cond, ...)                                                                                    \
    do {                                                                                                     \
        if (cond) {                                                                                          \
            harness_pass++;                                                                                  \
        } else {                                                                                             \
            harness_fail++;                                                                                  \
            fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond);                         \
            fprintf(stderr, __VA_ARGS__);                                                                    \
            fputc('\n', stderr);                                                                             \
        }                                                                                                    \
    } while (0)

/* One skipped thing, named on a line "skipped: WHAT: WHY". WHAT starting
 * "cpu" marks a CPU feature the machine lacks, the only skip CI accepts. */
#define SKIP(...)                                                                                            \
    do {                                                                                                     \
        harness_skip++;                                                                                      \
        printf("skipped: " __VA_ARGS__);                                                                     \
        putchar('\n');                                                                                       \
        fflush(stdout);                                                                                      \
    } while (0)

static inline int harness_finish(void)
{
    printf("%d passed, %d failed, %d skipped\n", harness_pass, harness_fail, harness_skip);
    return harness_fail ? 1 : 0;
}

#endif
