// Smoke test for the peer engines, run by CI: a single tall box dropped onto the ground, and a
// sparse grid of 1000 boxes, in every engine compiled in. Fails if a body ends up non-finite or
// sunk into the ground.

#include "peer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace {

using tumble::bench::PeerBody;
using tumble::bench::PeerResult;
using tumble::bench::PeerScene;

constexpr double kGround = 0.0;
// A resting box's centre sits at least its smallest half extent above the ground; more sinking
// than this means the engine let it through.
constexpr double kSinkTolerance = 0.1;

PeerBody box(double sx, double sy, double sz, double mass, double x, double y, double z) {
    PeerBody body{};
    body.size[0] = sx;
    body.size[1] = sy;
    body.size[2] = sz;
    body.mass = mass;
    body.position[0] = x;
    body.position[1] = y;
    body.position[2] = z;
    body.orientation[0] = 1.0;
    body.restitution = 0.3;
    body.friction = 0.5;
    return body;
}

PeerScene emptyScene(long steps) {
    PeerScene scene{};
    scene.gravity[1] = -9.81;
    scene.groundHeight = kGround;
    scene.dt = 1.0 / 240.0;
    scene.steps = steps;
    return scene;
}

PeerScene singleBox() {
    PeerScene scene = emptyScene(480); // 2 s
    scene.bodies.push_back(box(2, 6, 2, 2, 0, 5, 0));
    return scene;
}

// Unit boxes 10 m apart, starting 5 cm above the ground so they land within the 100 steps.
PeerScene grid(int columns, int rows) {
    PeerScene scene = emptyScene(100);
    for (int i = 0; i < columns; ++i) {
        for (int k = 0; k < rows; ++k) {
            scene.bodies.push_back(box(1, 1, 1, 1, 10.0 * i, 0.55, 10.0 * k));
        }
    }
    return scene;
}

// A unit cube of e = 0.9 dropped from 4 cm: it meets the ground at sqrt(2 g h) = 0.89 m/s at
// t = 0.090 s and, if it bounces, rises e^2 h = 32 mm by t = 0.172 s. 41 steps end at 0.171 s.
PeerScene lowDrop(double restitutionThreshold) {
    PeerScene scene = emptyScene(41);
    scene.bodies.push_back(box(1, 1, 1, 1, 0, 0.54, 0));
    scene.bodies.back().restitution = 0.9;
    scene.restitutionThreshold = restitutionThreshold;
    return scene;
}

// Whether the engine is given the scene's restitution threshold: its settings line names it, and
// the cube bounces under a threshold of 0.1 m/s and not under 1 m/s, so it ends at least 16 mm
// higher under the first. Bullet's plane gives one new contact point a step, so a slow flat
// landing rocks from corner to corner (the cube rose 12 mm under 0.1 m/s and 30 mm under 1 m/s):
// only its settings line is checked. MuJoCo's spring-damper contacts have no threshold.
int thresholdFailures(const std::string& name) {
    if (name.rfind("MuJoCo", 0) == 0) {
        std::printf("  restitution threshold: none in this engine\n");
        return 0;
    }
    const PeerResult low = tumble::bench::runPeer(name, lowDrop(0.1));
    const PeerResult high = tumble::bench::runPeer(name, lowDrop(1.0));
    const double bounced = low.finalPositions.at(0)[1];
    const double held = high.finalPositions.at(0)[1];
    std::printf("  restitution threshold: a cube meeting the ground at 0.89 m/s ends at y %.4f "
                "under 0.1 m/s, %.4f under 1 m/s\n",
                bounced, held);
    int failures = 0;
    if (low.settings.find("0.1 m/s") == std::string::npos ||
        high.settings.find(" 1 m/s") == std::string::npos) {
        std::printf("  BAD: the settings line does not name the scene's threshold\n");
        ++failures;
    }
    if (name.rfind("Bullet", 0) != 0 && !(bounced - held >= 0.016)) {
        std::printf("  BAD: the threshold does not decide the bounce\n");
        ++failures;
    }
    return failures;
}

// Counts bodies whose final position is non-finite or sunk below the ground, printing the first.
int badBodies(const PeerScene& scene, const PeerResult& result) {
    int bad = 0;
    for (std::size_t i = 0; i < result.finalPositions.size(); ++i) {
        const auto& p = result.finalPositions[i];
        const double* size = scene.bodies[i].size;
        const double lowest = kGround + std::min({size[0], size[1], size[2]}) / 2 - kSinkTolerance;
        const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
        if (!finite || p[1] < lowest) {
            if (bad == 0) {
                std::printf("  BAD body %zu at (%g, %g, %g)\n", i, p[0], p[1], p[2]);
            }
            ++bad;
        }
    }
    if (result.finalPositions.size() != scene.bodies.size()) {
        std::printf("  BAD: %zu final positions for %zu bodies\n", result.finalPositions.size(),
                    scene.bodies.size());
        ++bad;
    }
    return bad;
}

void print(const char* label, const PeerScene& scene, const PeerResult& result) {
    const double bodies = static_cast<double>(scene.bodies.size());
    const double nsPerBodyStep =
        result.stepSeconds * 1e9 / (bodies * static_cast<double>(std::max(scene.steps, 1L)));
    std::printf("  %-7s %4zu bodies x %3ld steps: %.4f s, %.1f ns/body-step, %ld at rest, "
                "%.0f bytes/body\n",
                label, scene.bodies.size(), scene.steps, result.stepSeconds, nsPerBodyStep,
                result.bodiesAtRest, static_cast<double>(result.heapBytes) / bodies);
}

} // namespace

int main() {
    const auto peers = tumble::bench::availablePeers();
    if (peers.empty()) {
        std::printf("peers_smoke: no peer engine compiled in; nothing to check\n");
        return 0;
    }
    const PeerScene single = singleBox();
    const PeerScene many = grid(40, 25);
    // Still exercises many bodies in an engine that cannot hold the full grid (MuJoCo 2.2).
    const PeerScene fewer = grid(10, 25);
    int failures = 0;
    for (const std::string& name : peers) {
        std::printf("%s\n", name.c_str());
        try {
            const PeerResult one = tumble::bench::runPeer(name, single);
            print("single", single, one);
            std::printf("  single box final y %.4f (upright on its 2 x 2 face: 3)\n",
                        one.finalPositions.at(0)[1]);
            failures += badBodies(single, one);
            failures += thresholdFailures(name);

            const PeerScene* scene = &many;
            PeerResult result;
            try {
                result = tumble::bench::runPeer(name, many);
            } catch (const tumble::bench::PeerCapacityError& limit) {
                std::printf("  grid of %zu skipped, engine limit: %s\n", many.bodies.size(),
                            limit.what());
                scene = &fewer;
                result = tumble::bench::runPeer(name, fewer);
            }
            print("grid", *scene, result);
            failures += badBodies(*scene, result);
            std::printf("  settings: %s\n", result.settings.c_str());
        } catch (const std::exception& error) {
            std::printf("  FAILED: %s\n", error.what());
            ++failures;
        }
    }
    if (failures != 0) {
        std::printf("peers_smoke: %d failure(s)\n", failures);
        return 1;
    }
    std::printf("peers_smoke: ok\n");
    return 0;
}
