// The step's large-buffer allocator (libs/tumble/src/large_buffer.hpp): a buffer of a huge page
// or more starts on a huge page, and a vector keeps its elements as it grows across that size.
#include "large_buffer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tumble {
namespace {

struct Block {
    double values[64];
};

TEST(LargeBuffer, ABufferOfAHugePageOrMoreStartsOnAHugePage)
{
    std::vector<Block, LargeBufferAllocator<Block>> blocks;
    const std::size_t perHugePage = kHugePageBytes / sizeof(Block);
    blocks.resize(perHugePage + 1);
    const auto address = reinterpret_cast<std::uintptr_t>(blocks.data());
    EXPECT_EQ(address % kHugePageBytes, 0u);
}

TEST(LargeBuffer, AVectorKeepsItsElementsAsItGrowsPastAHugePage)
{
    std::vector<Block, LargeBufferAllocator<Block>> blocks;
    const std::size_t count = 3 * kHugePageBytes / sizeof(Block) + 7;
    for (std::size_t i = 0; i < count; ++i) {
        blocks.emplace_back();
        blocks.back().values[0] = static_cast<double>(i);
        blocks.back().values[63] = -static_cast<double>(i);
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
        kept += blocks[i].values[0] == static_cast<double>(i) &&
                blocks[i].values[63] == -static_cast<double>(i);
    }
    EXPECT_EQ(kept, count);
    blocks.clear();
    blocks.shrink_to_fit();
    EXPECT_EQ(blocks.capacity(), 0u);
}

} // namespace
} // namespace tumble
