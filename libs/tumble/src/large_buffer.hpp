// The allocator of the step's large buffers (the lanes' blocks, an island's contacts): what they
// grow by is left unwritten, for the thread that fills it to write first, and a buffer of a huge
// page or more is asked for in huge pages (docs/benchmark.md, "Large buffers in huge pages").
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <utility>

namespace tumble {

/// The huge page of x86-64 and AArch64 Linux; a buffer smaller than this stays in the heap.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// Asks the system to back [data, data + bytes) with huge pages where it can (Linux's
/// madvise(MADV_HUGEPAGE)); elsewhere nothing. `data` is aligned to kHugePageBytes.
void adviseHugePages(void* data, std::size_t bytes) noexcept;

/// std::allocator, except that (a) an element made without arguments is default-initialised,
/// so the elements a vector grows by are left unwritten, and (b) a buffer of kHugePageBytes or
/// more is aligned to a huge page and advised into huge pages: a fresh page costs its first
/// write a fault, and one huge page takes the fault of 512 small ones.
template <typename T>
struct LargeBufferAllocator : std::allocator<T> {
    template <typename U>
    struct rebind {
        using other = LargeBufferAllocator<U>;
    };
    LargeBufferAllocator() = default;
    template <typename U>
    LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept
    {
    }

    T* allocate(std::size_t count)
    {
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kHugePageBytes) {
            return std::allocator<T>::allocate(count);
        }
        const std::size_t whole = hugePagesFor(bytes);
        void* data = ::operator new(whole, std::align_val_t{kHugePageBytes});
        adviseHugePages(data, whole);
        return static_cast<T*>(data);
    }
    void deallocate(T* data, std::size_t count) noexcept
    {
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kHugePageBytes) {
            std::allocator<T>::deallocate(data, count);
            return;
        }
        // the unsized form: clang declares the sized one only with -fsized-deallocation
        ::operator delete(data, std::align_val_t{kHugePageBytes});
    }

    template <typename U>
    void construct(U* place) noexcept(std::is_nothrow_default_constructible_v<U>)
    {
        ::new (static_cast<void*>(place)) U;
    }
    template <typename U, typename... Args>
    void construct(U* place, Args&&... args)
    {
        ::new (static_cast<void*>(place)) U(std::forward<Args>(args)...);
    }

private:
    static std::size_t hugePagesFor(std::size_t bytes)
    {
        return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
    }
};

template <typename T, typename U>
bool operator==(const LargeBufferAllocator<T>&, const LargeBufferAllocator<U>&) noexcept
{
    return true;
}

} // namespace tumble
