#include "viewer/impulse_experiments.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace tumble::viewer {
namespace {

TEST(ImpulseExperiments, OneButtonPerHandoutExperiment)
{
    const std::vector<ImpulseExperiment> experiments = loadImpulseExperiments(TUMBLE_SCENARIO_DIR);
    // part 2 task 2 has six experiments, part 3 task 1 one
    ASSERT_EQ(experiments.size(), 7u);
    EXPECT_EQ(experiments.front().label, "part 2 task 2: left");
    EXPECT_EQ(experiments.back().label, "part 3 task 1");
}

TEST(ImpulseExperiments, CarryTheStartingVelocitiesAndTheTarget)
{
    const std::vector<ImpulseExperiment> experiments = loadImpulseExperiments(TUMBLE_SCENARIO_DIR);
    const auto stopAll = std::find_if(experiments.begin(), experiments.end(),
                                      [](const ImpulseExperiment& e) {
                                          return e.label == "part 2 task 2: stop_all";
                                      });
    ASSERT_NE(stopAll, experiments.end());
    EXPECT_EQ(stopAll->startVelocity, Vec3(3.0, 0.0, 0.0));
    EXPECT_EQ(stopAll->startAngularVelocity, Vec3(0.0, 0.0, 1.0));
    ASSERT_TRUE(stopAll->targetVelocity.has_value());
    EXPECT_EQ(*stopAll->targetVelocity, Vec3(0.0));

    const ImpulseExperiment& task1 = experiments.back();
    EXPECT_EQ(task1.startVelocity, Vec3(2.0, 0.0, 0.0));
    ASSERT_TRUE(task1.targetAngularVelocity.has_value());
    EXPECT_EQ(*task1.targetAngularVelocity, Vec3(0.0, 0.0, -0.6));
}

TEST(ImpulseExperiments, MissingFilesGiveNone)
{
    EXPECT_TRUE(loadImpulseExperiments("/no/such/folder").empty());
}

} // namespace
} // namespace tumble::viewer
