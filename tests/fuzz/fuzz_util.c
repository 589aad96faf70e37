/* Shared helpers of the fuzz targets (fuzz.h). */
#define _GNU_SOURCE /* F_SETPIPE_SZ */
#include "fuzz.h"

#include <fcntl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <sanitizer/asan_interface.h>

static char file_path[256];
static char pipe_path[64];
static int pipe_rd = -1;

static void remove_file(void)
{
    if (file_path[0])
        unlink(file_path);
}

const char *fz_file(const uint8_t *data, size_t size)
{
    if (!file_path[0]) {
        const char *t = getenv("TMPDIR");
        /* tmpfs when there is one: the file is rewritten every run */
        if (!t || !*t)
            t = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
        snprintf(file_path, sizeof file_path, "%s/bloom_fuzz_%ld.bin", t, (long)getpid());
        atexit(remove_file);
    }
    FILE *f = fopen(file_path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0)
        fz_fail("cannot write %s", file_path);
    return file_path;
}

const char *fz_pipe(const uint8_t *data, size_t size)
{
    int p[2];
    if (pipe_rd >= 0)
        close(pipe_rd);
    if (pipe(p) != 0)
        fz_fail("pipe failed");
    (void)fcntl(p[1], F_SETPIPE_SZ, 1 << 20);
    (void)fcntl(p[1], F_SETFL, O_NONBLOCK); /* what does not fit is dropped */
    size_t off = 0;
    while (off < size) {
        ssize_t w = write(p[1], data + off, size - off);
        if (w <= 0)
            break;
        off += (size_t)w;
    }
    close(p[1]);
    pipe_rd = p[0];
    snprintf(pipe_path, sizeof pipe_path, "/proc/self/fd/%d", p[0]);
    return pipe_path;
}

FILE *fz_pipe_stream(const uint8_t *data, size_t size)
{
    FILE *f = fopen(fz_pipe(data, size), "rb");
    if (!f)
        fz_fail("cannot open %s", pipe_path);
    return f;
}

FILE *fz_mem_stream(const uint8_t *data, size_t size)
{
    /* fmemopen refuses a zero size: an empty stream is a one-byte buffer read past */
    static const uint8_t none[1];
    FILE *f =
        size ? fmemopen((void *)(uintptr_t)data, size, "rb") : fmemopen((void *)(uintptr_t)none, 1, "rb");
    if (!f)
        fz_fail("fmemopen failed");
    if (!size)
        (void)fgetc(f);
    return f;
}

unsigned fz_u8(fz_in_t *in)
{
    if (!in->n)
        return 0;
    in->n--;
    return *in->p++;
}

unsigned fz_u16(fz_in_t *in)
{
    unsigned a = fz_u8(in);
    return a | fz_u8(in) << 8;
}

uint32_t fz_u32(fz_in_t *in)
{
    uint32_t a = fz_u16(in);
    return a | (uint32_t)fz_u16(in) << 16;
}

void fz_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    abort();
}

#define CANARY 0xA5u

void fz_canary_set(uint8_t *p, size_t n)
{
    memset(p, CANARY, n);
    ASAN_POISON_MEMORY_REGION(p, n);
}

int fz_canary_ok(uint8_t *p, size_t n)
{
    ASAN_UNPOISON_MEMORY_REGION(p, n);
    int ok = 1;
    for (size_t i = 0; i < n; i++)
        ok &= p[i] == CANARY;
    ASAN_POISON_MEMORY_REGION(p, n);
    return ok;
}
