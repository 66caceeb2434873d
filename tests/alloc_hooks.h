// The C library's malloc family and operator new, replaced for one test
// program, each allocation first asked of the test's hook:
//     static bool allocation_allowed(bool through_malloc);
// which the including file defines before it includes this header (false:
// the allocation fails, NULL with errno ENOMEM or std::bad_alloc). The
// executable's malloc interposes on every shared library's. Under
// AddressSanitizer or ThreadSanitizer, whose runtimes own malloc, only
// operator new is replaced (INTERPOSE_MALLOC is 0).
#ifndef CTRACK_TESTS_ALLOC_HOOKS_H
#define CTRACK_TESTS_ALLOC_HOOKS_H

#include <cerrno>
#include <cstdlib>
#include <new>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define INTERPOSE_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define INTERPOSE_MALLOC 0
#endif
#endif
#ifndef INTERPOSE_MALLOC
#define INTERPOSE_MALLOC 1
#endif

#if INTERPOSE_MALLOC
extern "C" {
void *__libc_malloc(size_t);
void *__libc_calloc(size_t, size_t);
void *__libc_realloc(void *, size_t);
void *__libc_memalign(size_t, size_t);
void __libc_free(void *);

static void *refused_malloc()
{
    errno = ENOMEM;
    return nullptr;
}
void *malloc(size_t n) { return allocation_allowed(true) ? __libc_malloc(n) : refused_malloc(); }
void *calloc(size_t n, size_t k)
{
    return allocation_allowed(true) ? __libc_calloc(n, k) : refused_malloc();
}
void *realloc(void *p, size_t n)
{
    if (!p)
        return malloc(n);
    return allocation_allowed(true) ? __libc_realloc(p, n) : refused_malloc();
}
void free(void *p) { __libc_free(p); }
void *memalign(size_t a, size_t n)
{
    return allocation_allowed(true) ? __libc_memalign(a, n) : refused_malloc();
}
void *aligned_alloc(size_t a, size_t n) { return memalign(a, n); }
int posix_memalign(void **out, size_t a, size_t n)
{
    void *p = memalign(a, n);
    if (!p)
        return ENOMEM;
    *out = p;
    return 0;
}
}
static void *raw_malloc(size_t n) { return __libc_malloc(n); }
static void raw_free(void *p) { __libc_free(p); }
#else
static void *raw_malloc(size_t n) { return std::malloc(n); }
static void raw_free(void *p) { std::free(p); }
#endif

void *operator new(std::size_t n)
{
    if (!allocation_allowed(false))
        throw std::bad_alloc();
    void *p = raw_malloc(n ? n : 1);
    if (!p)
        throw std::bad_alloc();
    return p;
}
void *operator new[](std::size_t n) { return operator new(n); }
void operator delete(void *p) noexcept { raw_free(p); }
void operator delete[](void *p) noexcept { raw_free(p); }
void operator delete(void *p, std::size_t) noexcept { raw_free(p); }
void operator delete[](void *p, std::size_t) noexcept { raw_free(p); }

#endif
