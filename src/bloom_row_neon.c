/* NEON twins of the hot row kernels (aarch64). Same bits as the C kernels
 * of bloom_row.c; the kernels are written once in bloom_row_simd.h. Empty
 * on other targets. */
#include "bloom_internal.h"

#if defined(BLOOM_SIMD_NEON)
#include <arm_neon.h>
#include <string.h>

typedef uint32x4_t VT;
#define LD4(p) vld1q_u32(p)
#define ST4(p, v) vst1q_u32((p), (v))
#define LD2(p) vcombine_u32(vld1_u32(p), vdup_n_u32(0))
#define ST2(p, v) vst1_u32((p), vget_low_u32(v))
#define ADD(a, b) vaddq_u32((a), (b))
#define AND(a, b) vandq_u32((a), (b))
#define OR(a, b) vorrq_u32((a), (b))
static inline uint32_t or_lanes(uint32x4_t v)
{
    const uint32x2_t t = vorr_u32(vget_low_u32(v), vget_high_u32(v));
    return vget_lane_u32(t, 0) | vget_lane_u32(t, 1);
}
#define OR_LANES(v) or_lanes(v)
#define SHL(a, n) vshlq_n_u32((a), (n))
#define SHR(a, n) vshrq_n_u32((a), (n))
#define DUP(c) vdupq_n_u32(c)
#define ADD_SHR3(acc, v) vsraq_n_u32((acc), (v), 3)
#define PACK_LO(e, o) vsetq_lane_u32(vgetq_lane_u32((o), 0), (e), 3)
#define PACK_HI(o) vextq_u32((o), (o), 1)

/* Whether a byte of the 30 at s[r] + off (r = 0..3) exceeds c (reads 32). */
static inline int bright30(const uint8_t *const s[4], size_t off, uint32_t c)
{
    uint8x16_t a = vld1q_u8(s[0] + off), b = vld1q_u8(s[0] + off + 16);
    for (int r = 1; r < 4; r++) {
        a = vmaxq_u8(a, vld1q_u8(s[r] + off));
        b = vmaxq_u8(b, vld1q_u8(s[r] + off + 16));
    }
    static const uint8_t keep[16] = {255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0};
    b = vandq_u8(b, vld1q_u8(keep)); /* bytes 30, 31 out */
    return vmaxvq_u8(vmaxq_u8(a, b)) > c;
}
#define BRIGHT30(s, off, c) bright30((s), (off), (c))

/* The same over the 40 bytes of ten XRGB8888 pixels, X bytes out (reads 48). */
static inline int bright40x(const uint8_t *const s[4], size_t off, uint32_t c)
{
    uint8x16_t a = vld1q_u8(s[0] + off), b = vld1q_u8(s[0] + off + 16), d = vld1q_u8(s[0] + off + 32);
    for (int r = 1; r < 4; r++) {
        a = vmaxq_u8(a, vld1q_u8(s[r] + off));
        b = vmaxq_u8(b, vld1q_u8(s[r] + off + 16));
        d = vmaxq_u8(d, vld1q_u8(s[r] + off + 32));
    }
    static const uint8_t rgb[16] = {255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0};
    static const uint8_t lo8[16] = {255, 255, 255, 0, 255, 255, 255, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    d = vandq_u8(d, vld1q_u8(lo8)); /* bytes 40..47 out */
    return vmaxvq_u8(vandq_u8(vmaxq_u8(a, b), vld1q_u8(rgb))) > c || vmaxvq_u8(d) > c;
}
#define BRIGHT40X(s, off, c) bright40x((s), (off), (c))

/* Whether a 5/6/5 field of the ten RGB565 pixels at s[r] + off (r = 0..3)
 * exceeds its dark code (reads 32 bytes; the words are little-endian, as
 * the format). */
static inline int bright20_565(const uint8_t *const s[4], size_t off, uint32_t c5, uint32_t c6)
{
    const uint16x8_t lr = vdupq_n_u16((uint16_t)((c5 << 11) | 0x7FFu)), lg = vdupq_n_u16((uint16_t)(c6 << 5));
    const uint16x8_t lb = vdupq_n_u16((uint16_t)c5), mg = vdupq_n_u16(0x07E0), mb = vdupq_n_u16(31);
    static const uint16_t k2[8] = {0xFFFF, 0xFFFF, 0, 0, 0, 0, 0, 0}; /* words 8, 9 of the ten */
    const uint16x8_t keep2 = vld1q_u16(k2);
    uint16x8_t o = vdupq_n_u16(0);
    for (int r = 0; r < 4; r++) {
        const uint16x8_t a = vreinterpretq_u16_u8(vld1q_u8(s[r] + off));
        const uint16x8_t b = vandq_u16(vreinterpretq_u16_u8(vld1q_u8(s[r] + off + 16)), keep2);
        o = vorrq_u16(o, vorrq_u16(vqsubq_u16(a, lr), vqsubq_u16(b, lr)));
        o = vorrq_u16(o, vorrq_u16(vqsubq_u16(vandq_u16(a, mg), lg), vqsubq_u16(vandq_u16(b, mg), lg)));
        o = vorrq_u16(o, vorrq_u16(vqsubq_u16(vandq_u16(a, mb), lb), vqsubq_u16(vandq_u16(b, mb), lb)));
    }
    return vmaxvq_u16(o) != 0;
}
#define BRIGHT20_565(s, off, c5, c6) bright20_565((s), (off), (c5), (c6))

#include "bloom_row_simd.h"

void bloom_row_box_neon_any(const uint32_t *const s[4], uint32_t *dst, int dw, int sw)
{
    box_any(s, dst, dw, sw);
}

void bloom_row_tent_neon_any(const uint32_t *const u[3], int odd, const uint32_t *add,
                             uint32_t *dst, int x0, int n, int sw)
{
    tent_any(u, odd, add, dst, x0, n, sw);
}

/* ((I bl + 32768) >> 16) + sv: a rounding shift-accumulate in 64 bits,
 * then a saturating narrow to 32 bits. */
void bloom_row_composite_neon_any(uint32_t *bl, const uint32_t *sv, int n, uint32_t intensity)
{
    const uint32x2_t I = vdup_n_u32(intensity);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t b = vld1q_u32(bl + i), s = vld1q_u32(sv + i);
        const uint64x2_t lo = vrsraq_n_u64(vmovl_u32(vget_low_u32(s)), vmull_u32(vget_low_u32(b), I), 16);
        const uint64x2_t hi = vrsraq_n_u64(vmovl_u32(vget_high_u32(s)), vmull_u32(vget_high_u32(b), I), 16);
        vst1q_u32(bl + i, vcombine_u32(vqmovn_u64(lo), vqmovn_u64(hi)));
    }
    if (i < n)
        bloom_row_composite_c(bl + i, sv + i, n - i, intensity);
}

#if !BLOOM_SMALL
bool bloom_row_d1_neon(const uint8_t *const s[4], bloom_format_t fmt, bool linear, uint32_t *dst, int dw,
                       int sw, const bloom_knee_t *kn, const bloom_dark_t *dk)
{
#if BLOOM_USE_RGB888 || BLOOM_USE_XRGB8888 || BLOOM_USE_RGB565
    return d1_any(s, fmt, linear, dst, dw, sw, kn, dk);
#else
    return bloom_row_d1_c(s, fmt, linear, dst, dw, sw, kn, dk);
#endif
}

uint32_t bloom_row_vtent_neon(const uint32_t *a, const uint32_t *b, const uint32_t *c, uint32_t *dst, int n)
{
    return vtent_flat(a, b, c, dst, n);
}

uint32_t bloom_row_htent_eo_neon(const uint32_t *v, uint32_t *e, uint32_t *o, int n)
{
    return htent_eo_flat(v, e, o, n);
}

/* x = low 32 bits of (I x + 32768) >> 16: a widening multiply, then a
 * rounding narrowing shift (truncating, as the C twin's cast). */
void bloom_row_scale_neon(uint32_t *x, int n, uint32_t intensity)
{
    const uint32x2_t I = vdup_n_u32(intensity);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const uint32x4_t v = vld1q_u32(x + i);
        const uint32x2_t lo = vrshrn_n_u64(vmull_u32(vget_low_u32(v), I), 16);
        const uint32x2_t hi = vrshrn_n_u64(vmull_u32(vget_high_u32(v), I), 16);
        vst1q_u32(x + i, vcombine_u32(lo, hi));
    }
    if (i < n)
        bloom_row_scale_c(x + i, n - i, intensity);
}
#endif

#else
typedef int bloom_row_neon_empty; /* ISO C wants a declaration in every file */
#endif
