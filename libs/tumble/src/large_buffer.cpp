#include "large_buffer.hpp"

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sys/mman.h>
#endif

namespace tumble {

void adviseHugePages([[maybe_unused]] void* data, [[maybe_unused]] std::size_t bytes) noexcept
{
#if defined(__linux__) && !defined(__EMSCRIPTEN__) && defined(MADV_HUGEPAGE)
    // advice only: where the kernel has no transparent huge pages the buffer keeps small ones
    static_cast<void>(madvise(data, bytes, MADV_HUGEPAGE));
#endif
}

} // namespace tumble
