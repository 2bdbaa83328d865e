#include "viewer/ground_shadow.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tumble::viewer {
namespace {

float signedArea(const std::vector<glm::vec2>& polygon)
{
    float twice = 0.0f;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::vec2& a = polygon[i];
        const glm::vec2& b = polygon[(i + 1) % polygon.size()];
        twice += a.x * b.y - a.y * b.x;
    }
    return 0.5f * twice;
}

TEST(ConvexHull, DropsInteriorAndCollinearPointsCounterClockwise)
{
    const std::vector<glm::vec2> hull = convexHull(
        {{0.0f, 0.0f}, {2.0f, 0.0f}, {1.0f, 0.0f}, {2.0f, 2.0f}, {0.0f, 2.0f}, {1.0f, 1.0f}});
    EXPECT_EQ(hull.size(), 4u);
    EXPECT_NEAR(signedArea(hull), 4.0f, 1e-5f);
}

TEST(ConvexHull, FewerThanThreeDistinctPointsStayAsTheyAre)
{
    EXPECT_EQ(convexHull({{1.0f, 1.0f}, {1.0f, 1.0f}}).size(), 1u);
}

TEST(GroundShadow, OfABoxUnderALightStraightAboveIsItsFootprint)
{
    // a 2 x 1 x 4 box centred 3 m up: its shadow is the 2 x 4 rectangle under it
    const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 3.0f, -2.0f)),
                                       glm::vec3(2.0f, 1.0f, 4.0f));
    const std::vector<glm::vec2> shadow = groundShadow(model, glm::vec3(0.0f, 1.0f, 0.0f), 0.0f);
    ASSERT_EQ(shadow.size(), 4u);
    EXPECT_NEAR(signedArea(shadow), 8.0f, 1e-4f);
    for (const glm::vec2& corner : shadow) {
        EXPECT_NEAR(std::fabs(corner.x - 1.0f), 1.0f, 1e-5f);
        EXPECT_NEAR(std::fabs(corner.y + 2.0f), 2.0f, 1e-5f);
    }
}

TEST(GroundShadow, SlantedLightShiftsItAwayFromTheLight)
{
    // light from +x at 45 degrees: a unit cube 5 m up casts its shadow 5 m towards -x
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 5.0f, 0.0f));
    const std::vector<glm::vec2> shadow =
        groundShadow(model, glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)), 0.0f);
    glm::vec2 centre(0.0f);
    for (const glm::vec2& corner : shadow) {
        centre += corner;
    }
    centre /= static_cast<float>(shadow.size());
    EXPECT_NEAR(centre.x, -5.0f, 1e-4f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-4f);
    EXPECT_GT(signedArea(shadow), 1.0f);
}

} // namespace
} // namespace tumble::viewer
