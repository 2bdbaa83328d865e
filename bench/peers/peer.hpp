#pragma once

// Plain-data interface to the peer engines (Bullet, ODE, MuJoCo, and Jolt and Box3D from external
// builds) that the benchmark compares tumble against. It deliberately needs no tumble header, so
// the peers can be built and run on their own.

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace tumble::bench {

/// One cuboid. y is up; SI units.
struct PeerBody {
    double size[3];            ///< full edge lengths along the body's local axes, m
    double mass;               ///< kg, uniform solid cuboid
    double position[3];        ///< centre of mass, m
    double orientation[4];     ///< unit quaternion w, x, y, z (body to world)
    double velocity[3];        ///< m/s
    double angularVelocity[3]; ///< rad/s, world frame
    double restitution;        ///< coefficient of restitution in [0, 1]
    double friction;           ///< Coulomb coefficient
};

struct PeerScene {
    std::vector<PeerBody> bodies;
    double gravity[3];   ///< e.g. 0, -9.81, 0
    double groundHeight; ///< the ground is the infinite plane y = groundHeight
    double dt;           ///< fixed step, s
    long steps;          ///< number of steps to run
    /// Whether bodies may sleep (deactivate) at the engine's own thresholds; a scene that compares
    /// with sleeping off (a stack, Jolt's pyramid) turns it off in every engine.
    bool sleep = true;
    /// Approach speed (m/s) at or below which a contact does not bounce, whatever its
    /// restitution: every engine is given the scene's (tumble's `world.restitution_threshold`),
    /// so that they bounce alike; MuJoCo's spring-damper contacts have no such threshold.
    double restitutionThreshold = 1.0;
    /// Threads the engine steps on, where it can use several (peerRunsOnThreads).
    int threads = 1;
};

struct PeerResult {
    std::string engine;     ///< e.g. "Bullet 3.24", "ODE 0.16.2", "MuJoCo 2.2.2", "Jolt 5.5.1 (3b47ec39)"
    std::string settings;   ///< one line: solver, contact model, sleeping thresholds, ...
    double stepSeconds = 0; ///< wall time of the stepping loop only (steady_clock)
    /// Bodies asleep/disabled at the end, or with |v| and |w| below 1e-3 where the engine has no
    /// sleeping or the scene turns it off.
    long bodiesAtRest = 0;
    /// Heap in use after building the world minus before (glibc mallinfo2: uordblks + hblkhd);
    /// bytes per body = heapBytes / N. Allocations made later, while stepping, are not counted.
    long long heapBytes = 0;
    /// Heap in use after the last step, the world still alive, minus before building: the world
    /// with the contact storage the scene made it grow.
    long long heapBytesAtEnd = 0;
    std::vector<std::array<double, 3>> finalPositions; ///< per body, y-up
};

/// Thrown by runPeer when the engine cannot hold the scene at all (e.g. MuJoCo 2.2's fixed-size
/// buffers for a thousand boxes): a limit of the engine to report, not a failure of the run.
struct PeerCapacityError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Names accepted by runPeer, one per engine compiled in (e.g. "Bullet 3.24"); may be empty.
std::vector<std::string> availablePeers();

/// Whether the named engine steps on PeerScene::threads threads here (Jolt, through its own
/// thread pool); the others step on one whatever the scene asks.
bool peerRunsOnThreads(const std::string& name);

/// Runs the scene in the named engine. Throws std::invalid_argument for an unknown name or an
/// unusable scene (dt <= 0, steps < 0, non-positive mass or size), PeerCapacityError if the engine
/// cannot hold the scene, std::runtime_error if the engine rejects it otherwise.
PeerResult runPeer(const std::string& name, const PeerScene& scene);

} // namespace tumble::bench
