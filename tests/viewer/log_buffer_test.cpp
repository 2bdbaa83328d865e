#include "viewer/log_buffer.hpp"

#include <gtest/gtest.h>

namespace tumble::viewer {
namespace {

TEST(LogBuffer, SplitsTextIntoLines)
{
    LogBuffer log;
    log.append("one\ntwo\n");
    log.append("three");
    ASSERT_EQ(log.lines().size(), 3u);
    EXPECT_EQ(log.lines()[0], "one");
    EXPECT_EQ(log.lines()[1], "two");
    EXPECT_EQ(log.lines()[2], "three");
}

TEST(LogBuffer, EmptyTextAddsNothingAndBlankLinesStay)
{
    LogBuffer log;
    log.append("");
    EXPECT_TRUE(log.lines().empty());
    log.append("a\n\nb\n");
    ASSERT_EQ(log.lines().size(), 3u);
    EXPECT_EQ(log.lines()[1], "");
}

TEST(LogBuffer, KeepsTheNewestLines)
{
    LogBuffer log(2);
    log.append("1\n2\n3\n");
    ASSERT_EQ(log.lines().size(), 2u);
    EXPECT_EQ(log.lines()[0], "2");
    EXPECT_EQ(log.lines()[1], "3");
}

} // namespace
} // namespace tumble::viewer
