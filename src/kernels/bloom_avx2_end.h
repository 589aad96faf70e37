/* The end of a file's AVX2 code (bloom_avx2.h has the start). */
#undef LD8
#undef ST8
#undef SET8
#undef GATHER
#undef PERM
#undef PICK
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
