/* Counting every heap allocation of the process, for the benchmarks: this
 * object, linked into an executable, interposes malloc, calloc, realloc and
 * free (the library's and the C++ runtime's calls included). */
#ifndef CT_BENCH_ALLOC_COUNT_H
#define CT_BENCH_ALLOC_COUNT_H

#ifdef __cplusplus
extern "C" {
#endif

/* Allocations made so far (malloc, calloc, realloc). */
extern unsigned long long ct_allocations;
/* Bytes held now (usable sizes). */
extern long long ct_live_bytes;

#ifdef __cplusplus
}
#endif

#endif
