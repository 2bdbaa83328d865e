#include "peer.hpp"

#include "peer_detail.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace tumble::bench {
namespace detail {

long long heapInUse() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    const struct mallinfo2 info = mallinfo2();
    return static_cast<long long>(info.uordblks + info.hblkhd);
#else
    return 0;
#endif
}

bool slowerThanRest(const double velocity[3], const double angularVelocity[3]) {
    const auto length = [](const double v[3]) {
        return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    };
    return length(velocity) < kAtRestSpeed && length(angularVelocity) < kAtRestSpeed;
}

} // namespace detail

namespace {

using Runner = PeerResult (*)(const PeerScene&);

struct Entry {
    std::string name;
    Runner run;
    bool threaded = false;
};

std::vector<Entry> entries() {
    std::vector<Entry> list;
#ifdef TUMBLE_PEER_BULLET
    list.push_back({detail::bulletName(), &detail::runBullet});
#endif
#ifdef TUMBLE_PEER_ODE
    list.push_back({detail::odeName(), &detail::runOde});
#endif
#ifdef TUMBLE_PEER_MUJOCO
    list.push_back({detail::mujocoName(), &detail::runMujoco});
#endif
#ifdef TUMBLE_PEER_JOLT
    list.push_back({detail::joltName(), &detail::runJolt, true});
#endif
#ifdef TUMBLE_PEER_BOX3D
    list.push_back({detail::box3dName(), &detail::runBox3d});
#endif
    return list;
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// Accepts the full name ("Bullet 3.24") or just the engine ("bullet"), so callers need not track
// the installed versions.
bool matches(const std::string& entryName, const std::string& requested) {
    const std::string entry = lower(entryName);
    const std::string wanted = lower(requested);
    return entry == wanted || entry.substr(0, entry.find(' ')) == wanted;
}

void validate(const PeerScene& scene) {
    if (!(scene.dt > 0.0) || !std::isfinite(scene.dt)) {
        throw std::invalid_argument("tumble peers: dt must be positive and finite");
    }
    if (scene.threads < 1) {
        throw std::invalid_argument("tumble peers: threads must be at least 1");
    }
    if (scene.steps < 0) {
        throw std::invalid_argument("tumble peers: steps must not be negative");
    }
    for (const PeerBody& body : scene.bodies) {
        if (!(body.mass > 0.0) || !(body.size[0] > 0.0) || !(body.size[1] > 0.0) ||
            !(body.size[2] > 0.0)) {
            throw std::invalid_argument("tumble peers: every body needs positive mass and size");
        }
    }
}

} // namespace

std::vector<std::string> availablePeers() {
    std::vector<std::string> names;
    for (const Entry& entry : entries()) {
        names.push_back(entry.name);
    }
    return names;
}

bool peerRunsOnThreads(const std::string& name) {
    for (const Entry& entry : entries()) {
        if (matches(entry.name, name)) {
            return entry.threaded;
        }
    }
    return false;
}

PeerResult runPeer(const std::string& name, const PeerScene& scene) {
    for (const Entry& entry : entries()) {
        if (matches(entry.name, name)) {
            validate(scene);
            return entry.run(scene);
        }
    }
    throw std::invalid_argument("tumble peers: unknown or unavailable engine '" + name + "'");
}

} // namespace tumble::bench
