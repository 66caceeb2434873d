#define _GNU_SOURCE
#include "alloc_count.h"

#include <malloc.h>
#include <stddef.h>

extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);
extern void __libc_free(void *);

unsigned long long ct_allocations;
long long ct_live_bytes;

void *malloc(size_t n)
{
    void *p = __libc_malloc(n);
    if (p) {
        ct_allocations++;
        ct_live_bytes += (long long)malloc_usable_size(p);
    }
    return p;
}

void *calloc(size_t a, size_t b)
{
    void *p = __libc_calloc(a, b);
    if (p) {
        ct_allocations++;
        ct_live_bytes += (long long)malloc_usable_size(p);
    }
    return p;
}

void *realloc(void *old, size_t n)
{
    long long before = old ? (long long)malloc_usable_size(old) : 0;
    void *p = __libc_realloc(old, n);
    if (p) {
        ct_allocations++;
        ct_live_bytes += (long long)malloc_usable_size(p) - before;
    }
    return p;
}

void free(void *p)
{
    if (p)
        ct_live_bytes -= (long long)malloc_usable_size(p);
    __libc_free(p);
}
