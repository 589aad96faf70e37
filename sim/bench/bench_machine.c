/* The machine a benchmark ran on, for its report: CPU model and count,
 * last-level cache (sysfs and sysconf), load average (bench.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"

char cpu_model[160] = "unknown";
int ncpu = 1;
size_t llc_sysfs, llc_sysconf;
int llc_level;

void bench_read_machine(void)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[512], model[128] = "unknown", fam[32] = "", mod[32] = "";
    if (f) {
        while (fgets(line, sizeof line, f)) {
            char *v = strchr(line, ':');
            if (!v)
                continue;
            v++;
            while (*v == ' ' || *v == '\t')
                v++;
            v[strcspn(v, "\n")] = 0;
            if (!strncmp(line, "model name", 10) && !strcmp(model, "unknown"))
                snprintf(model, sizeof model, "%s", v);
            else if (!strncmp(line, "cpu family", 10) && !fam[0])
                snprintf(fam, sizeof fam, "%s", v);
            else if (!strncmp(line, "model\t", 6) && !mod[0])
                snprintf(mod, sizeof mod, "%s", v);
        }
        fclose(f);
    }
    if (fam[0] && mod[0])
        snprintf(cpu_model, sizeof cpu_model, "%s (family %s model %s)", model, fam, mod);
    else
        snprintf(cpu_model, sizeof cpu_model, "%s", model);
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    ncpu = n > 0 ? (int)n : 1;

    /* Largest data/unified cache of cpu0 in sysfs ... */
    for (int i = 0; i < 16; i++) {
        char path[128], type[32] = "", size[32] = "";
        int level = 0;
        snprintf(path, sizeof path, "/sys/devices/system/cpu/cpu0/cache/index%d/level", i);
        if (!(f = fopen(path, "r")))
            break;
        if (fscanf(f, "%d", &level) != 1)
            level = 0;
        fclose(f);
        snprintf(path, sizeof path, "/sys/devices/system/cpu/cpu0/cache/index%d/type", i);
        if ((f = fopen(path, "r"))) {
            if (!fgets(type, sizeof type, f))
                type[0] = 0;
            fclose(f);
        }
        snprintf(path, sizeof path, "/sys/devices/system/cpu/cpu0/cache/index%d/size", i);
        if ((f = fopen(path, "r"))) {
            if (!fgets(size, sizeof size, f))
                size[0] = 0;
            fclose(f);
        }
        if (!strncmp(type, "Instruction", 11))
            continue;
        char *end;
        size_t bytes = (size_t)strtoull(size, &end, 10);
        if (*end == 'K')
            bytes <<= 10;
        else if (*end == 'M')
            bytes <<= 20;
        if (level >= llc_level && bytes > 0) {
            llc_level = level;
            llc_sysfs = bytes;
        }
    }
    /* ... and what sysconf says (a VM may report the whole package). */
    long s = -1;
#ifdef _SC_LEVEL4_CACHE_SIZE
    s = sysconf(_SC_LEVEL4_CACHE_SIZE);
#endif
#ifdef _SC_LEVEL3_CACHE_SIZE
    if (s <= 0)
        s = sysconf(_SC_LEVEL3_CACHE_SIZE);
#endif
#ifdef _SC_LEVEL2_CACHE_SIZE
    if (s <= 0)
        s = sysconf(_SC_LEVEL2_CACHE_SIZE);
#endif
    llc_sysconf = s > 0 ? (size_t)s : 0;
}

double loadavg1(void)
{
    double v = -1.0;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &v) != 1)
            v = -1.0;
        fclose(f);
    }
    return v;
}
