// The panels' layout: full-width columns in a wide window, shrinking ones in a narrow window so
// the 3D view keeps at least 40 % of it (issue 14, item 18).
#include "viewer/ui/layout.hpp"

#include <gtest/gtest.h>

namespace tumble::viewer::ui {
namespace {

TEST(Layout, AWideWindowGetsTheFullColumns)
{
    const glm::vec2 display(1920.0f, 1080.0f);
    EXPECT_EQ(leftColumn(display).size().x, kLeftWidth);
    EXPECT_EQ(rightColumn(display).size().x, kRightWidth);
}

TEST(Layout, ANarrowWindowKeepsMostOfItsWidthForTheView)
{
    for (const float width : {640.0f, 800.0f, 900.0f}) {
        const glm::vec2 display(width, 600.0f);
        const ViewRegion view = freeViewRegion(display);
        EXPECT_GE(view.size().x, 0.4f * width) << width;
        // the view lies between the columns, which do not overlap it
        EXPECT_GE(view.min.x, leftColumn(display).max.x) << width;
        EXPECT_LE(view.max.x, rightColumn(display).min.x) << width;
    }
}

} // namespace
} // namespace tumble::viewer::ui
