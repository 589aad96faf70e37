/* Minimal test harness: CHECK records a failure and goes on; each test binary
 * ends with harness_finish(), which prints "N passed, N failed" and returns
 * the exit status. Header-only so every test file stays self-contained. */
#ifndef BLOOM_TEST_HARNESS_H
#define BLOOM_TEST_HARNESS_H

#include <stdio.h>

static int harness_pass, harness_fail;

#define CHECK(cond)                                                          \
    do {                                                                     \
        if (cond) {                                                          \
            harness_pass++;                                                  \
        } else {                                                             \
            harness_fail++;                                                  \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, \
                    #cond);                                                  \
        }                                                                    \
    } while (0)

#define CHECKF(cond, ...)                                                     \
    do {                                                                      \
        if (cond) {                                                           \
            harness_pass++;                                                   \
        } else {                                                              \
            harness_fail++;                                                   \
            fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__,  \
                    #cond);                                                   \
            fprintf(stderr, __VA_ARGS__);                                     \
            fputc('\n', stderr);                                              \
        }                                                                     \
    } while (0)

static inline int harness_finish(void)
{
    printf("%d passed, %d failed\n", harness_pass, harness_fail);
    return harness_fail ? 1 : 0;
}

#endif
