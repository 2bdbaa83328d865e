// World::step allocates nothing (issue 5): every operator new of this program is counted, and a
// world of tumbling cuboids is stepped through impacts, resting contact and sleep on two threads.
// A separate executable, because replacing the global operator new affects the whole program.
// (The OpenMP runtime's own thread pool is created with malloc, not operator new; it is made once
// by the first parallel step, before counting starts.)
#include "tumble/world.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<long> g_allocations{0};

} // namespace

void* operator new(std::size_t size)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* memory = std::malloc(size == 0 ? 1 : size)) {
        return memory;
    }
    throw std::bad_alloc();
}

void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }

namespace tumble {
namespace {

TEST(StepAllocation, SteppingManyBodiesAllocatesNothing)
{
    World world(WorldSettings{.threads = 2});
    world.setGround(Plane{});
    // 300 cuboids, tilted and spinning differently, dropped from different heights: they hit
    // the ground, bounce, slide and fall asleep during the 6 s.
    for (int i = 0; i < 300; ++i) {
        BodyDef def;
        def.shape.size = Vec3(2, 6, 2);
        def.mass = 2.0;
        // far enough apart that no two ever touch: islands of touching bodies still allocate
        // (docs/plan-speed.md)
        def.position = Vec3(20.0 * (i % 20), 4.0 + 0.02 * i, 20.0 * (i / 20));
        def.orientation = glm::normalize(Quat(1.0, 0.01 * i, 0.3, -0.002 * i));
        def.angularVelocity = Vec3(0.005 * i, 1.0, -0.5);
        world.createBody(def);
    }
    world.step(1.0 / 240.0);
    const long before = g_allocations.load();
    int impacts = 0;
    int rests = 0;
    for (int step = 1; step < 1440; ++step) {
        world.step(1.0 / 240.0);
        impacts += static_cast<int>(world.collisions().size());
        rests += static_cast<int>(world.restEvents().size());
    }
    EXPECT_EQ(g_allocations.load() - before, 0);
    // The steps counted did the work that could allocate: impacts and rest events.
    EXPECT_GT(impacts, 300);
    EXPECT_GT(rests, 150);
}

} // namespace
} // namespace tumble
