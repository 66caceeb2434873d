// Where the library's memory comes from: the host's allocator
// (ct_tracker_create_with_allocator(), like zstd's ZSTD_customMem), or
// operator new. Every container of the library is a Vec, whose allocator
// remembers the tracker's Memory from the moment it was made: the C ABI
// names the tracker's Memory for the call in progress on its thread
// (MemoryScope), and whatever the call makes allocates from it, and frees
// to it later wherever it is freed.
#ifndef CTRACK_MEMORY_H
#define CTRACK_MEMORY_H

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace ctrack {

// A host's allocator; alloc returns memory aligned for any type (as malloc
// does) or NULL.
struct Memory {
    void *(*alloc)(void *opaque, size_t size) = nullptr;
    void (*free)(void *opaque, void *ptr) = nullptr;
    void *opaque = nullptr;
};

// The Memory of the call in progress on this thread; null: operator new.
const Memory *current_memory() noexcept;

// Sets the current Memory until end() or its end, whichever comes first
// (nesting restores the outer).
class MemoryScope {
public:
    explicit MemoryScope(const Memory *m) noexcept;
    ~MemoryScope() { end(); }
    MemoryScope(const MemoryScope &) = delete;
    MemoryScope &operator=(const MemoryScope &) = delete;
    void end() noexcept;

private:
    const Memory *saved_;
    bool ended_ = false;
};

// n bytes from m (operator new when m is null or has no alloc); throws
// std::bad_alloc when there are none.
void *allocate(const Memory *m, size_t n);
void release(const Memory *m, void *p) noexcept;

template <typename T> class HostAllocator {
public:
    static_assert(alignof(T) <= alignof(std::max_align_t),
                  "a host's allocator aligns for the standard types only");
    using value_type = T;
    using propagate_on_container_copy_assignment = std::true_type;
    using propagate_on_container_move_assignment = std::true_type;
    using propagate_on_container_swap = std::true_type;
    using is_always_equal = std::false_type;

    HostAllocator() noexcept : memory_(current_memory()) {}
    template <typename U>
    HostAllocator(const HostAllocator<U> &o) noexcept : memory_(o.memory()) {}

    T *allocate(size_t n)
    {
        if (n > (size_t)-1 / sizeof(T))
            throw std::bad_alloc();
        return static_cast<T *>(ctrack::allocate(memory_, n * sizeof(T)));
    }
    void deallocate(T *p, size_t) noexcept { ctrack::release(memory_, p); }
    const Memory *memory() const noexcept { return memory_; }

    template <typename U> bool operator==(const HostAllocator<U> &o) const noexcept
    {
        return memory_ == o.memory();
    }
    template <typename U> bool operator!=(const HostAllocator<U> &o) const noexcept
    {
        return memory_ != o.memory();
    }

private:
    const Memory *memory_;
};

template <typename T> using Vec = std::vector<T, HostAllocator<T>>;

// An object of the library's own on the heap, from the current Memory.
template <typename T> struct Release {
    const Memory *memory = nullptr;
    void operator()(T *p) const noexcept
    {
        p->~T();
        ctrack::release(memory, p);
    }
};
template <typename T> using Owned = std::unique_ptr<T, Release<T>>;

template <typename T, typename... A> Owned<T> make_owned(A &&...args)
{
    const Memory *m = current_memory();
    void *p = allocate(m, sizeof(T));
    try {
        return Owned<T>(new (p) T(std::forward<A>(args)...), Release<T>{m});
    } catch (...) {
        release(m, p);
        throw;
    }
}

} // namespace ctrack

#endif
