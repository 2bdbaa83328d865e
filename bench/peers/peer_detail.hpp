#pragma once

// Shared between peer.cpp and the per-engine sources; not part of the public interface.

#include "peer.hpp"

#include <chrono>
#include <string>

namespace tumble::bench::detail {

/// Wall time (steady_clock) of `steps` calls of `step()`, s: the stepping loop alone, which is
/// what each peer reports as PeerResult::stepSeconds.
template <typename Step>
double timeSteps(long steps, const Step& step)
{
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < steps; ++i) {
        step();
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Bytes of heap in use by the whole process (glibc mallinfo2: uordblks + hblkhd), 0 elsewhere.
long long heapInUse();

/// Below this linear and angular speed (m/s, rad/s) a body counts as at rest in an engine or a
/// scene without sleeping.
constexpr double kAtRestSpeed = 1e-3;

/// Whether both speeds are below kAtRestSpeed.
bool slowerThanRest(const double velocity[3], const double angularVelocity[3]);

#ifdef TUMBLE_PEER_BULLET
std::string bulletName();
PeerResult runBullet(const PeerScene& scene);
#endif
#ifdef TUMBLE_PEER_ODE
std::string odeName();
PeerResult runOde(const PeerScene& scene);
#endif
#ifdef TUMBLE_PEER_MUJOCO
std::string mujocoName();
PeerResult runMujoco(const PeerScene& scene);
#endif
#ifdef TUMBLE_PEER_JOLT
std::string joltName();
PeerResult runJolt(const PeerScene& scene);
#endif
#ifdef TUMBLE_PEER_BOX3D
std::string box3dName();
PeerResult runBox3d(const PeerScene& scene);
#endif

} // namespace tumble::bench::detail
