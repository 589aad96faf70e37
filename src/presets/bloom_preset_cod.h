/* The cod preset's own row kernels (bloom_preset_cod_kern.c) and their
 * AVX2 twins (bloom_preset_cod_avx2.c: level 1 and the 13-tap;
 * bloom_preset_cod_avx2_up.c: the blends, decode and encode), the same
 * bits, and NEON twins of the 13-tap and the blends
 * (bloom_preset_cod_neon.c); the preset picks them by ctx->kern.isa
 * (cod_kernels; the SSE2 set and the rest of the NEON set are C). Samples are interleaved R, G, B uint32_t.
 * Padded rows: column j (-2 .. n + 2) of a row of n pixels at p[3 (j + 2)
 * + ch], the edge columns repeated (cod_pad_edges). */
#ifndef BLOOM_PRESET_COD_H
#define BLOOM_PRESET_COD_H

#include "bloom_kernels.h"

/* Six rows of 8-bit sRGB codes (n samples each, RGB888) decoded by
 * bloom_srgb_dec8 and summed: t = rows 0..3, c = rows 1..4, b = rows 2..5. */
typedef void (*cod_vsum6_fn)(const uint8_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n);
/* The same sums of six rows of decoded samples (each <= 2^28, so every sum
 * <= 2^30): BLOOM_FLAG_KEEP_LEVELS's level 1 from the decoded source. */
typedef void (*cod_vsum6w_fn)(const uint32_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n);
/* The Karis 13-tap of w level-1 pixels from the padded column sums vt, vc,
 * vb (top, centre, bottom; each word <= 2^32 - 1 and every 4-column sum too)
 * into o (3 w samples); returns the OR of o. May overwrite vt, vc, vb. */
typedef uint32_t (*cod_karis_fn)(uint32_t *vt, uint32_t *vc, uint32_t *vb, uint32_t *o, int w);
/* down13 of w pixels from six rows r[0..5] of sw pixels (samples <= 2^28),
 * vo and vi scratch rows of 3 sw + 16 words; returns the OR of o. */
typedef uint32_t (*cod_down13_fn)(const uint32_t *const r[6], uint32_t *vo, uint32_t *vi, uint32_t *o, int w,
                                  int sw);
/* The tent of four rows u[0..3] (rows m-2+odd .. m+1+odd of sw pixels,
 * samples <= 2^28) onto w output pixels of parity odd, blended:
 * blend: o = (a d + c T4 + 2^23) >> 24, low 32 bits (a <= 2^24, c <= 2^16);
 * mix:   o = min((a d + f_ch T4 + 2^23) >> 24, 2^32 - 1) (a <= 2^24, f <= 2^16).
 * scr: two contiguous 8-aligned scratch rows of 3 (2 sw - 1) + 16 words or more. */
typedef void (*cod_blend_fn)(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w,
                             int sw, uint32_t a, uint32_t c, uint32_t *scr);
typedef void (*cod_mix_fn)(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                           uint32_t a, const uint32_t f[3], uint32_t *scr);
/* bloom_decode_row and bloom_encode_row. */
typedef void (*cod_dec_fn)(bloom_format_t fmt, bool linear, const uint8_t *src, uint32_t *dst, int n);
typedef void (*cod_enc_fn)(bloom_format_t fmt, bool linear, const uint32_t *v, uint8_t *dst, int n);

typedef struct {
    cod_vsum6_fn vsum6;
    cod_vsum6w_fn vsum6w;
    cod_karis_fn karis;
    cod_down13_fn down13;
    cod_blend_fn blend;
    cod_mix_fn mix;
    cod_dec_fn dec;
    cod_enc_fn enc;
} cod_kernels_t;

void cod_vsum6_c(const uint8_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n);
void cod_vsum6w_c(const uint32_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n);
uint32_t cod_karis_c(uint32_t *vt, uint32_t *vc, uint32_t *vb, uint32_t *o, int w);
uint32_t cod_down13_c(const uint32_t *const r[6], uint32_t *vo, uint32_t *vi, uint32_t *o, int w, int sw);
void cod_blend_c(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                 uint32_t a, uint32_t c, uint32_t *scr);
void cod_mix_c(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw, uint32_t a,
               const uint32_t f[3], uint32_t *scr);
#if defined(BLOOM_SIMD_AVX2)
void cod_vsum6_avx2(const uint8_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n);
void cod_vsum6w_avx2(const uint32_t *const s[6], uint32_t *t, uint32_t *c, uint32_t *b, int n);
uint32_t cod_karis_avx2(uint32_t *vt, uint32_t *vc, uint32_t *vb, uint32_t *o, int w);
uint32_t cod_down13_avx2(const uint32_t *const r[6], uint32_t *vo, uint32_t *vi, uint32_t *o, int w, int sw);
void cod_blend_avx2(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                    uint32_t a, uint32_t c, uint32_t *scr);
void cod_mix_avx2(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                  uint32_t a, const uint32_t f[3], uint32_t *scr);
void cod_dec_avx2(bloom_format_t fmt, bool linear, const uint8_t *src, uint32_t *dst, int n);
void cod_enc_avx2(bloom_format_t fmt, bool linear, const uint32_t *v, uint8_t *dst, int n);
/* Test hooks: the Karis twin's divisions, n a multiple of 8. q = floor(2^48 / d)
 * for 699051 <= d < 3 2^20; q = floor(num / w) for 715827880 <= w <= 2^31,
 * num < 2^52 + 2^30 (cod.md, "SIMD twins"). */
void cod_recip48_avx2(const uint32_t *d, uint32_t *q, int n);
void cod_qdiv_avx2(const uint32_t *w, const uint64_t *num, uint32_t *q, int n);
#endif
#if defined(BLOOM_SIMD_NEON)
uint32_t cod_down13_neon(const uint32_t *const r[6], uint32_t *vo, uint32_t *vi, uint32_t *o, int w, int sw);
void cod_blend_neon(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                    uint32_t a, uint32_t c, uint32_t *scr);
void cod_mix_neon(const uint32_t *const u[4], int odd, const uint32_t *d, uint32_t *o, int w, int sw,
                  uint32_t a, const uint32_t f[3], uint32_t *scr);
#endif

/* The kernels for an instruction set (the C ones for BLOOM_ISA_C or a set
 * this build has no cod twins for). */
void cod_kernels(bloom_isa_t isa, cod_kernels_t *k);

/* The padding of a row of n pixels at p (2 columns left, 3 right). */
#define COD_PAD 6
static inline void cod_pad_edges(uint32_t *p, int n)
{
    for (int ch = 0; ch < 3; ch++) {
        const uint32_t l = p[COD_PAD + ch], r = p[COD_PAD + 3 * (n - 1) + ch];
        p[ch] = p[3 + ch] = l;
        for (int j = 0; j < 3; j++)
            p[COD_PAD + 3 * (n + j) + ch] = r;
    }
}

#endif
