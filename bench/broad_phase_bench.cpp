// Micro benchmarks of the broad phase on Jolt's pyramid of 1240 cubes: after tiny moves (a
// resting pile), unmoved (the sweep alone) and from scratch (std::sort instead of a kept order).
#include "collision/broad_phase.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace tumble;

/// Jolt's pyramid performance scene: 15 layers, layer i holding the 2 m cubes j, k in
/// [i/2, 15 - (i+1)/2), centred at (-15 + 2j + o, 1 + 2.5 i, -15 + 2k + o), o = 1 on odd layers.
std::vector<BroadPhaseProxy> pyramidProxies()
{
    constexpr int kLayers = 15;
    std::vector<BroadPhaseProxy> proxies;
    for (int i = 0; i < kLayers; ++i) {
        const Real offset = i % 2 == 1 ? 1.0 : 0.0;
        for (int j = i / 2; j < kLayers - (i + 1) / 2; ++j) {
            for (int k = i / 2; k < kLayers - (i + 1) / 2; ++k) {
                const Vec3 centre(-15.0 + 2.0 * j + offset, 1.0 + 2.5 * i,
                                  -15.0 + 2.0 * k + offset);
                const auto body = static_cast<std::uint32_t>(proxies.size());
                proxies.push_back({expanded(Aabb{centre - Vec3(1.0), centre + Vec3(1.0)}, 0.02),
                                   body, true});
            }
        }
    }
    return proxies;
}

void BM_BroadPhase_Pyramid1240TinyMoves(benchmark::State& state)
{
    // every box moves by 1e-6 m one way then back, as boxes of a settling pile do; the kept
    // order needs only the insertion sort's checks
    std::vector<BroadPhaseProxy> proxies = pyramidProxies();
    BroadPhase broadPhase;
    broadPhase.update(proxies);
    Real direction = 1.0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < proxies.size(); ++i) {
            const Vec3 move = (i % 2 == 0 ? direction : -direction) * Vec3(1e-6, -1e-6, 1e-6);
            proxies[i].box.min += move;
            proxies[i].box.max += move;
        }
        direction = -direction;
        broadPhase.update(proxies);
        benchmark::DoNotOptimize(broadPhase.pairs().data());
    }
    state.counters["pairs"] = static_cast<double>(broadPhase.pairs().size());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(proxies.size()));
}
BENCHMARK(BM_BroadPhase_Pyramid1240TinyMoves);

void BM_BroadPhase_Pyramid1240Unmoved(benchmark::State& state)
{
    // the same boxes every time: the insertion sort only checks the order, so this is the
    // sweep's own cost
    const std::vector<BroadPhaseProxy> proxies = pyramidProxies();
    BroadPhase broadPhase;
    broadPhase.update(proxies);
    for (auto _ : state) {
        broadPhase.update(proxies);
        benchmark::DoNotOptimize(broadPhase.pairs().data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(proxies.size()));
}
BENCHMARK(BM_BroadPhase_Pyramid1240Unmoved);

void BM_BroadPhase_Pyramid1240FromScratch(benchmark::State& state)
{
    // a new broad phase each time: std::sort instead of the kept order
    const std::vector<BroadPhaseProxy> proxies = pyramidProxies();
    for (auto _ : state) {
        BroadPhase broadPhase;
        broadPhase.update(proxies);
        benchmark::DoNotOptimize(broadPhase.pairs().data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(proxies.size()));
}
BENCHMARK(BM_BroadPhase_Pyramid1240FromScratch);

} // namespace
