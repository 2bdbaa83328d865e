// The extreme-but-valid cases: one table that extreme_test.cpp runs and asserts and
// robustness_doc.cpp turns into docs/robustness.md, so the document lists exactly what is tested.
#pragma once

#include "drop_case.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

namespace tumble::robustness {

struct ExtremeCase {
    std::string_view name;
    /// What is extreme about it, for the document.
    std::string_view what;
    DropCase drop;
    /// Dropped face down: the first impact must send it back up at restitution times the approach
    /// speed (within 1 %), which shows it bounced instead of passing through.
    bool mustBounce = false;
};

inline DropCase dropWith(auto&& change)
{
    DropCase drop;
    drop.steps = 480;
    change(drop);
    return drop;
}

/// A tilted, spinning start, so the body lands on a vertex or an edge.
inline constexpr Quat kTilted{0.9, 0.3, 0.2, 0.1};

inline std::vector<ExtremeCase> extremeCases()
{
    std::vector<ExtremeCase> cases;
    for (const Real mass : {1e-6, 1e-3, 1e4, 1e6}) {
        cases.push_back({"mass", "mass at the ends of the tested range", dropWith([&](DropCase& d) {
                             d.mass = mass;
                             d.orientation = kTilted;
                             d.angularVelocity = Vec3(1.0, 2.0, 0.5);
                         })});
    }
    for (const Real size : {1e-3, 1e-2, 100.0, 1e3}) {
        cases.push_back({"size", "cube edge at the ends of the tested range",
                         dropWith([&](DropCase& d) {
                             d.size = Vec3(size);
                             d.height = std::min(0.5 * size, 1.0);
                             d.orientation = kTilted;
                             d.steps = 960;
                         })});
    }
    for (const Real ratio : {100.0, 1000.0}) {
        cases.push_back({"plate", "flat plate, thickness 1/ratio of its width",
                         dropWith([&](DropCase& d) {
                             d.size = Vec3(2.0, 2.0 / ratio, 2.0);
                             d.orientation = kTilted;
                             d.angularVelocity = Vec3(0.5, 1.0, 0.2);
                         })});
        cases.push_back({"rod", "long rod, length ratio times its thickness, spinning",
                         dropWith([&](DropCase& d) {
                             d.size = Vec3(0.05, 0.05 * ratio, 0.05);
                             d.orientation = kTilted;
                             d.angularVelocity = Vec3(1.0, 2.0, 3.0);
                         })});
    }
    for (const Real dt : {1e-4, 1.0 / 240.0, 1.0 / 30.0, 0.1}) {
        cases.push_back({"200 m/s face down", "straight at the ground, one step covers up to 20 m",
                         dropWith([&](DropCase& d) {
                             d.velocity = Vec3(0.0, -200.0, 0.0);
                             d.dt = dt;
                             d.steps = static_cast<long long>(0.1 / dt) + 1;
                         }),
                         true});
    }
    cases.push_back({"200 m/s tumbling", "tilted and spinning, dt = 1/30 s",
                     dropWith([](DropCase& d) {
                         d.velocity = Vec3(3.0, -200.0, -2.0);
                         d.orientation = kTilted;
                         d.angularVelocity = Vec3(3.0, 1.0, 2.0);
                         d.dt = 1.0 / 30.0;
                         d.steps = 60;
                     })});
    cases.push_back({"1000 m/s face down", "the largest valid speed, dt = 0.1 s (the largest dt)",
                     dropWith([](DropCase& d) {
                         d.velocity = Vec3(0.0, -1000.0, 0.0);
                         d.dt = 0.1;
                         d.steps = 3;
                     }),
                     true});
    cases.push_back({"dt = 1e-6 s", "the smallest valid step", dropWith([](DropCase& d) {
                         d.dt = 1e-6;
                         d.height = 1e-4;
                         d.velocity = Vec3(0.0, -1.0, 0.0);
                         d.steps = 2000;
                     }),
                     true});
    for (const Real restitution : {0.0, 1.0}) {
        for (const Real friction : {0.0, 2.0, 10.0}) {
            cases.push_back({"elasticity/friction", "restitution and friction at their limits",
                             dropWith([&](DropCase& d) {
                                 d.restitution = restitution;
                                 d.friction = friction;
                                 d.orientation = kTilted;
                                 d.velocity = Vec3(5.0, -3.0, 1.0);
                                 d.angularVelocity = Vec3(2.0, -1.0, 4.0);
                                 d.steps = 2400;
                             })});
        }
    }
    cases.push_back({"1000 rad/s", "the largest valid spin, dt = 5e-4 s (0.5 rad per step)",
                     dropWith([](DropCase& d) {
                         d.size = Vec3(1.0, 2.0, 3.0);
                         d.orientation = kTilted;
                         d.angularVelocity = glm::normalize(Vec3(1.0, 2.0, 3.0)) * 1000.0;
                         d.dt = 5e-4;
                         d.steps = 2000;
                     })});
    return cases;
}

} // namespace tumble::robustness
