/* Stand-ins for test binaries, for the runner's self-test (selftest.sh):
 * what each does is picked by the name it is run under (a link to this
 * program). Each misbehaves the way a real test can, and the runner must
 * count every one but "good" and "skip" as a failure. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    const char *n = strrchr(argv[0], '/');
    n = n ? n + 1 : argv[0];
    (void)argc;
    fflush(stdout);
    if (!strcmp(n, "good")) {
        puts("3 passed, 0 failed, 0 skipped");
        return 0;
    }
    if (!strcmp(n, "skip")) { /* a named skip: a skip, not a failure (outside CI) */
        puts("skipped: standin: the thing it needs is absent");
        puts("2 passed, 0 failed, 1 skipped");
        return 0;
    }
    if (!strcmp(n, "cpuskip")) { /* a CPU feature absent: accepted under CI too */
        puts("skipped: cpu without FOO: the FOO kernels");
        puts("2 passed, 0 failed, 1 skipped");
        return 0;
    }
    if (!strcmp(n, "segv")) { /* a count printed, then a real crash */
        puts("5 passed, 0 failed");
        fflush(stdout);
        raise(SIGSEGV);
    }
    if (!strcmp(n, "abort")) {
        puts("5 passed, 0 failed");
        fflush(stdout);
        abort();
    }
    if (!strcmp(n, "canary")) { /* testutil.h's status for an overwritten canary */
        puts("4 passed, 0 failed, 0 skipped");
        fputs("workspace canary overwritten\n", stderr);
        return 2;
    }
    if (!strcmp(n, "wrongcount")) { /* failures counted, status 0 */
        puts("2 passed, 1 failed, 0 skipped");
        return 0;
    }
    if (!strcmp(n, "hiddenskip")) { /* a skip counted but not named */
        puts("2 passed, 0 failed, 1 skipped");
        return 0;
    }
    if (!strcmp(n, "nosummary")) /* status 0 but no count at all */
        return 0;
    if (!strcmp(n, "empty")) { /* ran nothing */
        puts("0 passed, 0 failed, 0 skipped");
        return 0;
    }
    fprintf(stderr, "standin: unknown name %s\n", n);
    return 3;
}
