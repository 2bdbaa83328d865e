#include "viewer/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tumble::viewer {
namespace {

/// Pixel positions are compared to a hundredth of a pixel (float matrices).
constexpr float kPixelTolerance = 1e-2f;
constexpr float kTolerance = 1e-4f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(OrbitCamera, EyeSitsAtTheDistanceFromTheTarget)
{
    const OrbitCamera camera(glm::vec3(1.0f, 2.0f, 3.0f), 10.0f, 0.3f, 0.4f);
    EXPECT_NEAR(glm::length(camera.eye() - camera.target()), 10.0f, kTolerance);
    // pitch is the elevation above the target
    EXPECT_NEAR(camera.eye().y - camera.target().y, 10.0f * std::sin(0.4f), kTolerance);
}

TEST(OrbitCamera, BasisIsOrthonormalAndRightHanded)
{
    const OrbitCamera camera(glm::vec3(0.0f), 5.0f, 1.1f, 0.7f);
    EXPECT_NEAR(glm::length(camera.right()), 1.0f, kTolerance);
    EXPECT_NEAR(glm::length(camera.up()), 1.0f, kTolerance);
    EXPECT_NEAR(glm::dot(camera.right(), camera.forward()), 0.0f, kTolerance);
    EXPECT_NEAR(glm::dot(camera.up(), camera.forward()), 0.0f, kTolerance);
    expectNear(glm::cross(camera.right(), camera.up()), -camera.forward(), kTolerance);
    EXPECT_GT(camera.up().y, 0.0f);
}

TEST(OrbitCamera, TargetProjectsToTheImageCentre)
{
    const OrbitCamera camera(glm::vec3(2.0f, 1.0f, -3.0f), 12.0f);
    const glm::vec3 pixel = camera.projectToPixel(camera.target(), 640, 360);
    EXPECT_NEAR(pixel.x, 320.0f, kPixelTolerance);
    EXPECT_NEAR(pixel.y, 180.0f, kPixelTolerance);
    EXPECT_NEAR(pixel.z, 12.0f, kTolerance);
}

TEST(OrbitCamera, ProjectionPutsRightAndUpWhereTheyBelong)
{
    const OrbitCamera camera(glm::vec3(0.0f), 10.0f, 0.5f, 0.3f);
    const glm::vec3 right = camera.projectToPixel(camera.right(), 800, 600);
    const glm::vec3 up = camera.projectToPixel(camera.up(), 800, 600);
    EXPECT_GT(right.x, 400.0f);
    EXPECT_NEAR(right.y, 300.0f, kPixelTolerance);
    // image rows grow downwards
    EXPECT_LT(up.y, 300.0f);
    EXPECT_NEAR(up.x, 400.0f, kPixelTolerance);
}

TEST(OrbitCamera, PointBehindTheCameraHasNoPositiveDepth)
{
    const OrbitCamera camera(glm::vec3(0.0f), 10.0f);
    const glm::vec3 behind = camera.eye() - 5.0f * camera.forward();
    EXPECT_LE(camera.projectToPixel(behind, 100, 100).z, 0.0f);
}

TEST(OrbitCamera, OrbitTurnsYawAndClampsPitch)
{
    OrbitCamera camera(glm::vec3(0.0f), 10.0f, 0.0f, 0.0f);
    camera.orbit(-100.0f, 0.0f);
    EXPECT_NEAR(camera.yaw(), 100.0f * OrbitCamera::kOrbitRate, kTolerance);
    camera.orbit(0.0f, 1e6f);
    EXPECT_FLOAT_EQ(camera.pitch(), OrbitCamera::kMaxPitch);
    camera.orbit(0.0f, -1e6f);
    EXPECT_FLOAT_EQ(camera.pitch(), OrbitCamera::kMinPitch);
    // orbiting keeps the distance
    EXPECT_NEAR(glm::length(camera.eye() - camera.target()), 10.0f, kTolerance);
}

TEST(OrbitCamera, ZoomScalesTheDistanceAndClamps)
{
    OrbitCamera camera(glm::vec3(0.0f), 10.0f);
    camera.zoom(1.0f);
    EXPECT_NEAR(camera.distance(), 10.0f * (1.0f - OrbitCamera::kZoomStep), kTolerance);
    camera.zoom(-1.0f);
    EXPECT_NEAR(camera.distance(), 10.0f, 1e-3f);
    camera.zoom(1000.0f);
    EXPECT_FLOAT_EQ(camera.distance(), OrbitCamera::kMinDistance);
    camera.zoom(-1000.0f);
    EXPECT_FLOAT_EQ(camera.distance(), OrbitCamera::kMaxDistance);
}

TEST(OrbitCamera, PanMovesAPointAtTheTargetDepthWithTheCursor)
{
    OrbitCamera camera(glm::vec3(1.0f, 0.5f, 2.0f), 8.0f, 0.8f, 0.5f);
    const glm::vec3 point = camera.target();
    const glm::vec3 before = camera.projectToPixel(point, 1000, 500);
    camera.pan(40.0f, -25.0f, 500.0f);
    const glm::vec3 after = camera.projectToPixel(point, 1000, 500);
    EXPECT_NEAR(after.x - before.x, 40.0f, 0.05f);
    EXPECT_NEAR(after.y - before.y, -25.0f, 0.05f);
    EXPECT_NEAR(camera.distance(), 8.0f, kTolerance);
}

TEST(OrbitCamera, FollowClosesTheGapExponentially)
{
    OrbitCamera camera(glm::vec3(0.0f), 10.0f);
    const glm::vec3 body(4.0f, 0.0f, 0.0f);
    camera.follow(body, 0.1f);
    EXPECT_NEAR(camera.target().x, 4.0f * (1.0f - std::exp(-OrbitCamera::kFollowRate * 0.1f)),
                kTolerance);
    for (int frame = 0; frame < 120; ++frame) {
        camera.follow(body, 1.0f / 60.0f);
    }
    expectNear(camera.target(), body, 1e-3f);
}

TEST(ViewBounds, HoldEverySphereAndTheGroundUnderThem)
{
    const std::vector<glm::vec3> centres{{0.0f, 5.0f, 0.0f}, {10.0f, 3.0f, 0.0f}};
    const std::vector<float> radii{1.0f, 2.0f};
    const ViewBounds bounds = boundsOf(centres, radii, 0.0f);
    for (std::size_t i = 0; i < centres.size(); ++i) {
        EXPECT_LE(glm::length(centres[i] - bounds.centre) + radii[i], bounds.radius + kTolerance);
        const glm::vec3 ground(centres[i].x, 0.0f, centres[i].z);
        EXPECT_LE(glm::length(ground - bounds.centre), bounds.radius + kTolerance);
    }
}

TEST(ViewBounds, WithoutGroundHoldOnlyTheSpheres)
{
    const std::vector<glm::vec3> centres{{0.0f, 10.0f, 0.0f}};
    const std::vector<float> radii{1.0f};
    const ViewBounds bounds = boundsOf(centres, radii, std::nullopt);
    expectNear(bounds.centre, centres[0], kTolerance);
    EXPECT_NEAR(bounds.radius, 1.0f, kTolerance);
}

TEST(FrameBounds, WholeSphereProjectsInsideTheView)
{
    const ViewBounds bounds{.centre = {3.0f, 2.0f, -1.0f}, .radius = 4.0f};
    for (const glm::ivec2 size : {glm::ivec2(200, 400), glm::ivec2(400, 400), glm::ivec2(1280, 720)}) {
        const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
        const OrbitCamera camera = frameBounds(bounds, aspect);
        expectNear(camera.target(), bounds.centre, kTolerance);
        // the sphere's extreme points along the view's right and up axes stay on screen
        for (const glm::vec3& direction : {camera.right(), -camera.right(), camera.up(), -camera.up()}) {
            const glm::vec3 pixel =
                camera.projectToPixel(bounds.centre + bounds.radius * direction, size.x, size.y);
            EXPECT_GT(pixel.x, 0.0f);
            EXPECT_LT(pixel.x, static_cast<float>(size.x));
            EXPECT_GT(pixel.y, 0.0f);
            EXPECT_LT(pixel.y, static_cast<float>(size.y));
        }
    }
}

} // namespace
} // namespace tumble::viewer
