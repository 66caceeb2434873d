#include "base/memory.h"

namespace ctrack {

namespace {
thread_local const Memory *g_current = nullptr;
}

const Memory *current_memory() noexcept
{
    return g_current;
}

MemoryScope::MemoryScope(const Memory *m) noexcept : saved_(g_current)
{
    g_current = m;
}

void MemoryScope::end() noexcept
{
    if (!ended_)
        g_current = saved_;
    ended_ = true;
}

void *allocate(const Memory *m, size_t n)
{
    if (!m || !m->alloc)
        return ::operator new(n);
    void *p = m->alloc(m->opaque, n ? n : 1);
    if (!p)
        throw std::bad_alloc();
    return p;
}

void release(const Memory *m, void *p) noexcept
{
    if (!p)
        return;
    if (!m || !m->alloc)
        ::operator delete(p);
    else
        m->free(m->opaque, p);
}

} // namespace ctrack
