#include "viewer/ring_buffer.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tumble::viewer {
namespace {

TEST(RingBuffer, KeepsValuesInOrderUntilFull)
{
    RingBuffer<int> buffer(4);
    EXPECT_TRUE(buffer.empty());
    buffer.push(1);
    buffer.push(2);
    buffer.push(3);
    ASSERT_EQ(buffer.size(), 3u);
    EXPECT_EQ(buffer[0], 1);
    EXPECT_EQ(buffer[2], 3);
    EXPECT_EQ(buffer.front(), 1);
    EXPECT_EQ(buffer.back(), 3);
}

TEST(RingBuffer, DropsTheOldestWhenFull)
{
    RingBuffer<int> buffer(3);
    for (int i = 1; i <= 7; ++i) {
        buffer.push(i);
    }
    ASSERT_EQ(buffer.size(), 3u);
    EXPECT_EQ(buffer.capacity(), 3u);
    EXPECT_EQ(buffer[0], 5);
    EXPECT_EQ(buffer[1], 6);
    EXPECT_EQ(buffer[2], 7);
}

TEST(RingBuffer, DropWhileRemovesOldValuesOnly)
{
    RingBuffer<int> buffer(5);
    for (int i = 1; i <= 8; ++i) {
        buffer.push(i);
    }
    buffer.dropWhile([](int value) { return value < 6; });
    ASSERT_EQ(buffer.size(), 3u);
    EXPECT_EQ(buffer.front(), 6);
    buffer.push(9);
    EXPECT_EQ(buffer.back(), 9);
    EXPECT_EQ(buffer.size(), 4u);
}

TEST(RingBuffer, ClearEmptiesAndKeepsCapacity)
{
    RingBuffer<std::string> buffer(2);
    buffer.push("a");
    buffer.push("b");
    buffer.push("c");
    buffer.clear();
    EXPECT_TRUE(buffer.empty());
    buffer.push("d");
    EXPECT_EQ(buffer.front(), "d");
    EXPECT_EQ(buffer.capacity(), 2u);
}

TEST(RingBuffer, ZeroCapacityHoldsOne)
{
    RingBuffer<int> buffer(0);
    buffer.push(1);
    buffer.push(2);
    EXPECT_EQ(buffer.size(), 1u);
    EXPECT_EQ(buffer.back(), 2);
}

} // namespace
} // namespace tumble::viewer
