/* bloom_sim tests: environment, running the tool, files, the direct engine. */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700 /* posix_openpt, grantpt, ptsname, mkdtemp */
#endif

#include "simtest.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

static char dir[128];

int st_setup_dir(void)
{
    const char *t = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/bloom_simtest-XXXXXX", t && *t ? t : "/tmp");
    return mkdtemp(dir) ? 0 : -1;
}

void st_remove_dir(void)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char p[512];
    while (d && (e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        remove(p);
    }
    if (d)
        closedir(d);
    rmdir(dir);
}

const char *st_path(const char *name)
{
    static char buf[8][512];
    static int k;
    k = (k + 1) % 8;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

int st_count_tmp_files(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += strstr(e->d_name, ".tmp-") != NULL;
    if (d)
        closedir(d);
    return n;
}

/* ---- running the tool ------------------------------------------------------ */

static void slurp(const char *path, char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(buf, 1, cap - 1, f) : 0;
    buf[n] = '\0';
    if (f)
        fclose(f);
}

static int wait_status(pid_t pid)
{
    int ws;
    while (waitpid(pid, &ws, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + (WIFSIGNALED(ws) ? WTERMSIG(ws) : 0);
}

static char **make_argv(const char *tool, const char *const *args)
{
    int n = 0;
    while (args[n])
        n++;
    char **av = calloc((size_t)n + 2, sizeof *av);
    if (!av)
        return NULL;
    av[0] = (char *)(uintptr_t)tool; /* execv's prototype predates const */
    for (int i = 0; i < n; i++)
        av[i + 1] = (char *)(uintptr_t)args[i];
    return av;
}

int st_run(st_run_t *r, const char *tool, const char *stdin_path, const char *const *args)
{
    char outp[512], errp[512];
    snprintf(outp, sizeof outp, "%s", st_path("run.stdout"));
    snprintf(errp, sizeof errp, "%s", st_path("run.stderr"));
    char **av = make_argv(tool, args);
    if (!av)
        return -1;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        int in = open(stdin_path ? stdin_path : "/dev/null", O_RDONLY);
        int out = open(outp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int er = open(errp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || out < 0 || er < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(er, 2) < 0)
            _exit(126);
        execv(tool, av);
        _exit(127);
    }
    free(av);
    if (pid < 0)
        return -1;
    r->status = wait_status(pid);
    slurp(outp, r->out, sizeof r->out);
    slurp(errp, r->err, sizeof r->err);
    remove(outp);
    remove(errp);
    return r->status;
}

int st_run_tty(const char *tool, const char *const *args, char *tty_out, size_t cap)
{
    tty_out[0] = '\0';
    int m = posix_openpt(O_RDWR | O_NOCTTY);
    if (m < 0 || grantpt(m) || unlockpt(m) || !ptsname(m)) {
        if (m >= 0)
            close(m);
        return -1;
    }
    char slave[256];
    snprintf(slave, sizeof slave, "%s", ptsname(m));
    char **av = make_argv(tool, args);
    if (!av) {
        close(m);
        return -1;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        int s = open(slave, O_RDWR | O_NOCTTY);
        int nul = open("/dev/null", O_RDWR);
        if (s < 0 || nul < 0 || dup2(nul, 0) < 0 || dup2(nul, 1) < 0 || dup2(s, 2) < 0)
            _exit(126);
        close(m);
        execv(tool, av);
        _exit(127);
    }
    free(av);
    if (pid < 0) {
        close(m);
        return -1;
    }
    /* The child writes a few hundred bytes at most: the pty buffer holds
     * them, so reading after it has exited is enough. */
    int status = wait_status(pid);
    fcntl(m, F_SETFL, fcntl(m, F_GETFL) | O_NONBLOCK);
    size_t n = 0;
    for (;;) {
        ssize_t k = read(m, tty_out + n, cap - 1 - n);
        if (k <= 0)
            break;
        n += (size_t)k;
    }
    tty_out[n] = '\0';
    close(m);
    return status;
}

/* ---- files ------------------------------------------------------------------- */

int st_write_file(const char *path, const void *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    int ok = fwrite(data, 1, len, f) == len;
    return fclose(f) == 0 && ok ? 0 : -1;
}

unsigned char *st_read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    unsigned char *b = malloc(cap + 1);
    for (size_t k; b && (k = fread(b + n, 1, cap - n, f)) > 0;) {
        n += k;
        if (n == cap) {
            unsigned char *nb = realloc(b, 2 * cap + 1);
            if (!nb) {
                free(b);
                b = NULL;
                break;
            }
            b = nb;
            cap *= 2;
        }
    }
    fclose(f);
    if (b) {
        b[n] = '\0';
        *len = n;
    }
    return b;
}

int st_same_file(const char *path, const void *data, size_t len)
{
    size_t n;
    unsigned char *b = st_read_file(path, &n);
    int same = b && n == len && !memcmp(b, data, len);
    free(b);
    return same;
}

/* ---- the engine ---------------------------------------------------------------- */

int st_engine(const bloom_config_t *c, const void *src, void *dst)
{
    size_t ws = bloom_workspace_size(c);
    void *mem = ws ? malloc(ws) : NULL;
    bloom_t *b;
    int rc = -1;
    if (mem && bloom_init(&b, mem, ws, c) == BLOOM_OK &&
        bloom_process(b, src, (ptrdiff_t)c->width * bloom_format_bpp(c->in_fmt), dst,
                      (ptrdiff_t)c->width * bloom_format_bpp(c->out_fmt)) == BLOOM_OK)
        rc = 0;
    free(mem);
    return rc;
}
