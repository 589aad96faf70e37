/* The xna preset's zero-row skipping against the bit-true model and
 * BLOOM_FLAG_NO_SKIP (part of tests/test_preset_xna.c, which includes it
 * after its helpers xna_par_t and xna_cfg). */
#ifndef XNA_DARK_SKIP_H
#define XNA_DARK_SKIP_H

/* Zero-row skipping (xna.md, "Skipping"): frames dark up to the threshold
 * (every channel <= T, many exactly at the largest dark code or at T for
 * RGBQ16) with 0 .. 4 lights placed anywhere, edges included; bit-exact to
 * the bit-true model and the same bytes as BLOOM_FLAG_NO_SKIP, for every
 * format, LINEAR, SATURATE, DEBUG_VIEW and T = 0, 0.25, 0.9. */
static void dark_skip(void)
{
    static const struct {
        bloom_format_t in, out;
        uint32_t flags;
        int fill[3]; /* the dark fill for T = 0.25, 0, 0.9 (RGBQ16: T itself) */
    } f[] = {{BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, 0, {136, 0, 240}},
             {BLOOM_FMT_XRGB8888, BLOOM_FMT_XRGB8888, BLOOM_FLAG_SATURATE, {136, 0, 240}},
             {BLOOM_FMT_RGB565, BLOOM_FMT_RGB565, 0, {128, 0, 232}},
             {BLOOM_FMT_RGB888, BLOOM_FMT_RGB888, BLOOM_FLAG_LINEAR, {63, 0, 229}},
             {BLOOM_FMT_RGB888, BLOOM_FMT_RGB565, BLOOM_FLAG_DEBUG_VIEW, {136, 0, 240}},
             {BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16, 0, {-1, 0, -1}},
             {BLOOM_FMT_RGB565, BLOOM_FMT_RGB888, BLOOM_FLAG_COPY_SOURCE, {128, 0, 232}}};
    static const int sizes[][2] = {{1, 1}, {3, 2}, {9, 5}, {40, 17}, {67, 33}, {31, 64}, {129, 97}};
    static const uint32_t T[3] = {BLOOM_Q16(0.25), 0, BLOOM_Q16(0.9)};
    int cases = 0, bad = 0;
    uint32_t seed = 7;
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
        for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
            for (int k = 0; k < 3; k++) {
                const xna_par_t par = {T[k], BLOOM_Q16(k == 2 ? 4.0 : 1.0), 1 + (int)(z + i) % 4, f[i].flags};
                bloom_config_t c = xna_cfg(sizes[z][1], sizes[z][0], f[i].in, f[i].out, &par);
                const int q16 = f[i].in == BLOOM_FMT_RGBQ16;
                const int fill = q16 ? (int)T[k] : f[i].fill[k];
                frame_t src = frame_alloc(c.width, c.height, f[i].in, fill);
                for (int y = 0; y < src.h; y++) /* dark noise below the fill */
                    for (int x = 0; x < src.w; x++) {
                        uint8_t *q = src.p + (size_t)y * src.stride + (size_t)x * (size_t)src.bpp;
                        if (rng_next(&seed) % 3u == 0u)
                            continue;
                        if (q16) {
                            uint32_t v[3];
                            for (int ch = 0; ch < 3; ch++)
                                v[ch] = rng_next(&seed) % ((uint32_t)fill + 1u);
                            memcpy(q, v, sizeof v);
                        } else if (f[i].in != BLOOM_FMT_RGB565) {
                            for (int ch = 0; ch < 3; ch++)
                                q[ch] = (uint8_t)(rng_next(&seed) % ((uint32_t)fill + 1u));
                        }
                    }
                const int lights = (int)(z + (size_t)k + i) % 5;
                for (int l = 0; l < lights; l++) {
                    const uint32_t r = rng_next(&seed);
                    const int x = (int)(r % (uint32_t)src.w);
                    const int y =
                        l == 0 ? (int)(r >> 8) % 2 * (src.h - 1) : (int)((r >> 8) % (uint32_t)src.h);
                    uint8_t *q = src.p + (size_t)y * src.stride + (size_t)x * (size_t)src.bpp;
                    if (q16) {
                        const uint32_t v[3] = {2u << 16, 1u << 16, 3u << 15};
                        memcpy(q, v, sizeof v);
                    } else {
                        memset(q, 0xFF, (size_t)src.bpp);
                    }
                }
                preset_conform_t r = preset_conform(&c, &src, NULL, 0);
                frame_t a = run_engine(&c, &src);
                c.flags |= BLOOM_FLAG_NO_SKIP;
                frame_t b = run_engine(&c, &src);
                cases++;
                if (!r.ok || r.bittrue_diff != 0 || !frame_equal(&a, &b)) {
                    if (bad++ < 5)
                        fprintf(stderr, "dark skip: fmt %d -> %d flags %#x %dx%d T %u: %lld differ%s\n",
                                f[i].in, f[i].out, f[i].flags, c.width, c.height, T[k], r.bittrue_diff,
                                frame_equal(&a, &b) ? "" : ", NO_SKIP differs");
                }
                frame_free(&a);
                frame_free(&b);
                frame_free(&src);
            }
    /* one light at every row and at both edge columns of a dark frame at T */
    for (int y = 0; y < 45; y++)
        for (int e = 0; e < 2; e++) {
            const xna_par_t par = {BLOOM_Q16(0.25), BLOOM_Q16(1.0), 1 + y % 3, 0};
            bloom_config_t c = xna_cfg(13, 45, BLOOM_FMT_RGBQ16, BLOOM_FMT_RGBQ16, &par);
            frame_t src = frame_alloc(c.width, c.height, BLOOM_FMT_RGBQ16, (int)BLOOM_Q16(0.25));
            const uint32_t v[3] = {BLOOM_Q16(0.25) + 1u, 1u << 16, 0};
            memcpy(src.p + (size_t)y * src.stride + (size_t)(e ? c.width - 1 : 0) * 12u, v, sizeof v);
            preset_conform_t r = preset_conform(&c, &src, NULL, 0);
            frame_t a = run_engine(&c, &src);
            c.flags |= BLOOM_FLAG_NO_SKIP;
            frame_t b = run_engine(&c, &src);
            cases++;
            if ((!r.ok || r.bittrue_diff != 0 || !frame_equal(&a, &b)) && bad++ < 5)
                fprintf(stderr, "dark skip: one light at row %d: %lld differ\n", y, r.bittrue_diff);
            frame_free(&a);
            frame_free(&b);
            frame_free(&src);
        }
    CHECKF(bad == 0, "dark skip: %d of %d frames differ", bad, cases);
    printf("dark skip: %d frames bit-exact, skipping on and off\n", cases);
}

#endif
