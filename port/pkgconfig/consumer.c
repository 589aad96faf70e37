/* A program built against an installed libbloom through pkg-config only
 * (test_install.sh): the default preset and one other on a small frame,
 * printed as an FNV-1a hash of the output, so that the shared, the static
 * and the in-tree library can be compared. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <bloom.h>

static uint32_t fnv(const uint8_t *p, size_t n, uint32_t h)
{
    for (size_t i = 0; i < n; i++)
        h = (h ^ p[i]) * 16777619u;
    return h;
}

int main(void)
{
    enum { W = 96, H = 64 };
    static uint8_t src[W * H * 3], dst[W * H * 3];
    for (int i = 0; i < W * H * 3; i++)
        src[i] = (uint8_t)((i * 37) ^ (i >> 7));
    uint32_t h = 2166136261u;
    const char *presets[] = {"unity", "xna"};
    for (int k = 0; k < 2; k++) {
        bloom_config_t c;
        bloom_config_default(&c, W, H);
        const int p = bloom_preset_from_name(presets[k]);
        if (p < 0 || bloom_config_preset(&c, (bloom_preset_t)p) != BLOOM_OK) {
            printf("preset %s: not in this library\n", presets[k]);
            continue;
        }
        c.threshold = BLOOM_Q16(0.5);
        const size_t n = bloom_workspace_size(&c);
        void *ws = malloc(n + 8);
        bloom_t *b = NULL;
        bloom_status_t st = ws ? bloom_init(&b, ws, n, &c) : BLOOM_E_NULL;
        if (st == BLOOM_OK)
            st = bloom_process(b, src, W * 3, dst, W * 3);
        if (st != BLOOM_OK) {
            printf("%s: %s\n", presets[k], bloom_status_str(st));
            free(ws);
            return 1;
        }
        h = fnv(dst, sizeof dst, h);
        free(ws);
    }
    printf("consumer: output fnv1a %08x\n", (unsigned)h);
    return 0;
}
