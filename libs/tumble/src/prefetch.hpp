// Asking the memory for data a loop reads a few iterations later, where the data lies in many
// separate places that no hardware prefetcher can guess (docs/benchmark.md, "Rows from levers and
// centres, look-ups in owner order, and reads asked for ahead").
#pragma once

#include <cstddef>

namespace tumble {

/// Prefetches the cache lines of `bytes` bytes from `data` for reading.
inline void prefetchLines(const void* data, std::size_t bytes)
{
    constexpr std::size_t kLine = 64;
    const char* first = static_cast<const char*>(data);
    for (std::size_t offset = 0; offset < bytes; offset += kLine) {
        __builtin_prefetch(first + offset);
    }
}

} // namespace tumble
