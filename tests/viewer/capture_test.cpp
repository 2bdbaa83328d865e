// The capture mode end to end: `tumble view FILE --screenshot OUT.png --at T` under xvfb-run
// (the test executable runs inside one X server), and the PNG checked pixel by pixel: its size,
// that it is not blank, the cuboid where the camera should see it, and a falling body moving.
#include "png_image.hpp"

#include "viewer/camera.hpp"
#include "viewer/scene_bounds.hpp"
#include "viewer/sim_runner.hpp"
#include "viewer/ui/layout.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace tumble::viewer {
namespace {

using testing::PngImage;

const std::filesystem::path kScenarios = TUMBLE_SCENARIO_DIR;
const std::filesystem::path kCaptures = TUMBLE_CAPTURE_DIR;

struct ProgramRun {
    int exitCode = -1;
    std::string output;
};

ProgramRun runTumble(const std::string& arguments)
{
    ProgramRun run;
    const std::string command = std::string(TUMBLE_EXE) + " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return run;
    }
    std::array<char, 512> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
        run.output += buffer.data();
    }
    const int status = pclose(pipe);
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

/// Captures `scenario` at `time` into captures/<name>.png and reads it back.
PngImage capture(const std::string& scenario, double time, const std::string& name,
                 const std::string& extra = "")
{
    std::filesystem::create_directories(kCaptures);
    const std::filesystem::path png = kCaptures / (name + ".png");
    std::filesystem::remove(png);
    const ProgramRun run = runTumble("view " + (kScenarios / scenario).string() + " --screenshot " +
                              png.string() + " --at " + std::to_string(time) + " " + extra);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("frame render time:"), std::string::npos) << run.output;
    ::testing::Test::RecordProperty(name, run.output);
    return PngImage(png);
}

/// Where the centre of the scenario's first body is at `time` in the default view, pixels; with
/// the panels, the 3D view is the part of the image they leave free.
glm::vec2 expectedCentre(const std::string& scenario, double time, const glm::ivec2& size,
                         bool withPanels)
{
    SimRunner sim(kScenarios / scenario);
    sim.advanceTo(time);
    const ViewRegion region = withPanels ? ui::freeViewRegion(glm::vec2(size)) : wholeView(size);
    const glm::ivec2 view(glm::round(region.size()));
    const OrbitCamera camera = frameBounds(
        runBounds(sim.scenario()), static_cast<float>(view.x) / static_cast<float>(view.y));
    const glm::vec3 pixel = camera.projectToPixel(glm::vec3(sim.body(0).position), view.x, view.y);
    EXPECT_GT(pixel.z, 0.0f);
    return region.min + glm::vec2(pixel);
}

TEST(Capture, FrictionScenarioWithPanelsShowsTheCuboid)
{
    const PngImage image = capture("part3_task4_friction.toml", 0.3, "friction_panels");
    ASSERT_EQ(image.width(), 1280);
    ASSERT_EQ(image.height(), 720);
    EXPECT_GT(image.distinctColours(), 200u);
    // in flight, before its first impact at 0.81 s: faces all around its centre
    const glm::vec2 centre = expectedCentre("part3_task4_friction.toml", 0.3, {1280, 720}, true);
    EXPECT_GT(image.cuboidFraction(centre, 12.0f), 0.6) << centre.x << ", " << centre.y;
}

TEST(Capture, AThrowOfTheTrayShowsItsDrawnDiceInTheTray)
{
    // view --throw I plays the replay of throw I: the tray's static bodies and the two dice
    // where throw I releases them, so two throws give two pictures that differ
    const PngImage three =
        capture("dice_two_in_tray.toml", 0.0, "tray_throw_3", "--throw 3 --size 640x360 --no-ui");
    const PngImage four =
        capture("dice_two_in_tray.toml", 0.0, "tray_throw_4", "--throw 4 --size 640x360 --no-ui");
    for (const PngImage* image : {&three, &four}) {
        ASSERT_EQ(image->width(), 640);
        ASSERT_EQ(image->height(), 360);
        EXPECT_GT(image->distinctColours(), 50u);
    }
    // the dice are small in the framed scene (a few hundred pixels of 230,400): the pictures of
    // one throw are identical, those of two throws differ where the dice are
    EXPECT_GT(three.differingFraction(four, 0.1f), 0.0001);
}

TEST(Capture, FallingCubeMovesBetweenTwoTimes)
{
    const PngImage before = capture("face_down_drop.toml", 0.0, "drop_0", "--size 640x360 --no-ui");
    const PngImage after = capture("face_down_drop.toml", 0.6, "drop_0_6", "--size 640x360 --no-ui");
    for (const PngImage* image : {&before, &after}) {
        ASSERT_EQ(image->width(), 640);
        ASSERT_EQ(image->height(), 360);
        EXPECT_GT(image->distinctColours(), 50u);
        // the sky in the top-left corner is no cuboid
        EXPECT_LT(image->cuboidFraction(glm::vec2(12.0f, 12.0f), 10.0f), 0.05);
    }
    const glm::vec2 centreBefore = expectedCentre("face_down_drop.toml", 0.0, {640, 360}, false);
    const glm::vec2 centreAfter = expectedCentre("face_down_drop.toml", 0.6, {640, 360}, false);
    EXPECT_GT(before.cuboidFraction(centreBefore, 6.0f), 0.6);
    EXPECT_GT(after.cuboidFraction(centreAfter, 6.0f), 0.6);

    // it fell 1.77 m: well down the picture, and the two pictures differ
    EXPECT_GT(centreAfter.y - centreBefore.y, 20.0f);
    EXPECT_GT(after.differingFraction(before, 0.1f), 0.01);
}

TEST(Capture, BadSizeOrFileIsBadInput)
{
    const ProgramRun badSize = runTumble("view --size 10x10000 --screenshot " +
                                  (kCaptures / "never.png").string());
    EXPECT_EQ(badSize.exitCode, 2) << badSize.output;
    EXPECT_NE(badSize.output.find("--size"), std::string::npos) << badSize.output;

    const ProgramRun badFile = runTumble("view /no/such/file.toml --screenshot " +
                                  (kCaptures / "never.png").string());
    EXPECT_EQ(badFile.exitCode, 2) << badFile.output;
    EXPECT_FALSE(std::filesystem::exists(kCaptures / "never.png"));
}

// a capture that cannot be stored (a full disk) is exit 3 with the system's reason, not "wrote"
TEST(Capture, AWriteErrorIsAnOutputError)
{
    std::filesystem::create_directories(kCaptures);
    const std::filesystem::path full = kCaptures / "full.png";
    std::filesystem::remove(full);
    std::filesystem::create_symlink("/dev/full", full);
    const ProgramRun run = runTumble("view --size 64x64 --screenshot " + full.string());
    std::filesystem::remove(full);
    EXPECT_EQ(run.exitCode, 3) << run.output;
    EXPECT_NE(run.output.find("tumble: error: cannot write " + full.string() +
                              ": No space left on device\n"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("wrote"), std::string::npos) << run.output;
}

} // namespace
} // namespace tumble::viewer
