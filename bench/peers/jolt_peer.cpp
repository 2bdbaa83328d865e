// Jolt peer: one JPH::PhysicsSystem stepped with Jolt's default solver settings on one thread (or
// on Jolt's own thread pool when the scene asks for several), a
// static box for the ground and sleeping at Jolt's default thresholds when the scene allows it.
// Jolt is an external build (tools/build-jolt-peer.sh); this file must be compiled with the same
// JPH_* definitions and SIMD flags as libJolt.a, which VerifyJoltVersionID() checks at run time.

#include "peer_detail.hpp"

// Jolt.h must come first: it sets up the definitions every other Jolt header relies on.
#include <Jolt/Jolt.h>

#include <Jolt/Core/Factory.h>
#include <Jolt/Core/JobSystemSingleThreaded.h>
#include <Jolt/Core/JobSystemThreadPool.h>
#include <Jolt/Core/TempAllocator.h>
#include <Jolt/Physics/Body/BodyCreationSettings.h>
#include <Jolt/Physics/Collision/BroadPhase/BroadPhaseLayerInterfaceTable.h>
#include <Jolt/Physics/Collision/BroadPhase/ObjectVsBroadPhaseLayerFilterTable.h>
#include <Jolt/Physics/Collision/ObjectLayerPairFilterTable.h>
#include <Jolt/Physics/Collision/Shape/BoxShape.h>
#include <Jolt/Physics/PhysicsSystem.h>
#include <Jolt/RegisterTypes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace tumble::bench::detail {
namespace {

// Two object layers, as every Jolt application has at least: the static ground and the moving
// boxes; statics never test against statics. Each maps to its own broad-phase tree.
constexpr JPH::ObjectLayer kStaticLayer = 0;
constexpr JPH::ObjectLayer kMovingLayer = 1;
constexpr JPH::uint kLayerCount = 2;

// Scratch memory for one Update, allocated once per run like an application's frame arena. It is
// made before the heap is first read, so heapBytes counts the world and not this arena.
constexpr std::size_t kTempAllocatorBytes = 64u * 1024u * 1024u;

// The ground: a box whose top face is the plane y = groundHeight, wider than any scene (Jolt's
// own Pyramid scene uses a 100 m box the same way).
constexpr float kGroundHalfWidth = 1000.0f;
constexpr float kGroundHalfThickness = 1.0f;

// Jolt needs its allocator hooks, factory and type registry once per process; they are never torn
// down, since later runs in the same process reuse them.
void initialiseJoltOnce() {
    static std::once_flag once;
    std::call_once(once, [] {
        JPH::RegisterDefaultAllocator();
        JPH::Factory::sInstance = new JPH::Factory();
        JPH::RegisterTypes();
    });
}

// Jolt mixes friction by geometric mean. Against the ground each body keeps its own friction, as
// in the other peers and in tumble's scenes (whose ground has no material of its own); between
// two bodies Jolt's default rule stays.
float combineFriction(const JPH::Body& body1, const JPH::SubShapeID&, const JPH::Body& body2,
                      const JPH::SubShapeID&) {
    if (body1.IsStatic()) {
        return body2.GetFriction();
    }
    if (body2.IsStatic()) {
        return body1.GetFriction();
    }
    return std::sqrt(body1.GetFriction() * body2.GetFriction());
}

// The filters and the system hold references to each other; declaration order gives the reverse
// destruction order they need.
struct JoltWorld {
    JPH::ObjectLayerPairFilterTable layerPairs{kLayerCount};
    JPH::BroadPhaseLayerInterfaceTable broadPhaseLayers{kLayerCount, kLayerCount};
    std::unique_ptr<JPH::ObjectVsBroadPhaseLayerFilterTable> layerVsBroadPhase;
    JPH::PhysicsSystem system;
    JPH::BodyID ground;
    std::vector<JPH::BodyID> bodies;
};

JPH::Vec3 vec(const double v[3]) {
    return {float(v[0]), float(v[1]), float(v[2])};
}

void build(JoltWorld& jw, const PeerScene& scene) {
    jw.layerPairs.EnableCollision(kMovingLayer, kStaticLayer);
    jw.layerPairs.EnableCollision(kMovingLayer, kMovingLayer);
    jw.broadPhaseLayers.MapObjectToBroadPhaseLayer(kStaticLayer, JPH::BroadPhaseLayer(0));
    jw.broadPhaseLayers.MapObjectToBroadPhaseLayer(kMovingLayer, JPH::BroadPhaseLayer(1));
    jw.layerVsBroadPhase = std::make_unique<JPH::ObjectVsBroadPhaseLayerFilterTable>(
        jw.broadPhaseLayers, kLayerCount, jw.layerPairs, kLayerCount);

    // Capacities: room for every body and the ground, and far more pairs and contacts than a
    // settled pile of boxes makes (each box touches a handful of others).
    const auto bodyCount = static_cast<JPH::uint>(scene.bodies.size());
    const JPH::uint maxBodies = bodyCount + 1;
    const JPH::uint maxPairs = std::max<JPH::uint>(65536, 32 * maxBodies);
    const JPH::uint maxContacts = std::max<JPH::uint>(20480, 16 * maxBodies);
    jw.system.Init(maxBodies, 0, maxPairs, maxContacts, jw.broadPhaseLayers,
                   *jw.layerVsBroadPhase, jw.layerPairs);
    jw.system.SetGravity(vec(scene.gravity));
    jw.system.SetCombineFriction(&combineFriction);
    JPH::PhysicsSettings physicsSettings = jw.system.GetPhysicsSettings();
    physicsSettings.mAllowSleeping = scene.sleep;
    physicsSettings.mMinVelocityForRestitution = float(scene.restitutionThreshold);
    jw.system.SetPhysicsSettings(physicsSettings);

    JPH::BodyInterface& bodies = jw.system.GetBodyInterface();

    // Restitution mixes by maximum in Jolt, so a ground of 0 leaves each body's own value.
    JPH::BodyCreationSettings ground(
        new JPH::BoxShape(JPH::Vec3(kGroundHalfWidth, kGroundHalfThickness, kGroundHalfWidth)),
        JPH::RVec3(0.0f, float(scene.groundHeight) - kGroundHalfThickness, 0.0f),
        JPH::Quat::sIdentity(), JPH::EMotionType::Static, kStaticLayer);
    ground.mRestitution = 0.0f;
    jw.ground = bodies.CreateAndAddBody(ground, JPH::EActivation::DontActivate);

    // Bodies of equal size share one shape, as a Jolt application would. Convex radius 0 keeps
    // the corners sharp, like tumble's cuboids and Jolt's own Pyramid scene.
    std::map<std::array<double, 3>, JPH::RefConst<JPH::Shape>> shapes;
    jw.bodies.reserve(scene.bodies.size());
    for (const PeerBody& body : scene.bodies) {
        auto& shape = shapes[{body.size[0], body.size[1], body.size[2]}];
        if (shape == nullptr) {
            shape = new JPH::BoxShape(
                JPH::Vec3(float(body.size[0] / 2), float(body.size[1] / 2), float(body.size[2] / 2)),
                0.0f);
        }
        const JPH::Quat orientation =
            JPH::Quat(float(body.orientation[1]), float(body.orientation[2]),
                      float(body.orientation[3]), float(body.orientation[0]))
                .Normalized();
        JPH::BodyCreationSettings settings(shape, JPH::RVec3(vec(body.position)), orientation,
                                           JPH::EMotionType::Dynamic, kMovingLayer);
        // The given mass, with the inertia of a uniform solid box scaled to it.
        settings.mOverrideMassProperties = JPH::EOverrideMassProperties::CalculateInertia;
        settings.mMassPropertiesOverride.mMass = float(body.mass);
        settings.mFriction = float(body.friction);
        settings.mRestitution = float(body.restitution);
        settings.mLinearVelocity = vec(body.velocity);
        settings.mAngularVelocity = vec(body.angularVelocity);
        settings.mAllowSleeping = scene.sleep;
        jw.bodies.push_back(bodies.CreateAndAddBody(settings, JPH::EActivation::Activate));
    }
    // Jolt's advice after adding many bodies at once: rebuild the broad-phase trees before stepping.
    jw.system.OptimizeBroadPhase();
}

std::string describe(const JoltWorld& jw, bool sleep, int threads) {
    const JPH::PhysicsSettings& settings = jw.system.GetPhysicsSettings();
    std::ostringstream out;
    out << "PhysicsSystem, Update(dt, 1 collision step) on "
        << (threads > 1 ? "JobSystemThreadPool (the calling thread and " +
                              std::to_string(threads - 1) + " workers)"
                        : std::string("JobSystemSingleThreaded"))
        << ", "
        << settings.mNumVelocitySteps << " velocity / " << settings.mNumPositionSteps
        << " position iterations, baumgarte " << settings.mBaumgarte << ", penetration slop "
        << settings.mPenetrationSlop << " m, speculative distance "
        << settings.mSpeculativeContactDistance
        << " m, warm starting on; BoxShape convex radius 0, static BoxShape ground, discrete "
        << "motion quality, default damping 0.05/s linear and angular, single precision; "
        << "friction geometric mean between bodies, body's own against the ground; restitution "
        << "max (ground 0), only above " << settings.mMinVelocityForRestitution << " m/s; ";
    if (sleep) {
        out << "sleeping on: below " << settings.mPointVelocitySleepThreshold << " m/s for "
            << settings.mTimeBeforeSleep << " s";
    } else {
        out << "sleeping off (mAllowSleeping false): at rest means |v|, |w| < " << kAtRestSpeed;
    }
    return out.str();
}

} // namespace

std::string joltName() {
    std::string name = "Jolt " + std::to_string(JPH_VERSION_MAJOR) + "." +
                       std::to_string(JPH_VERSION_MINOR) + "." + std::to_string(JPH_VERSION_PATCH);
#ifdef TUMBLE_PEER_JOLT_COMMIT
    name += std::string(" (") + TUMBLE_PEER_JOLT_COMMIT + ")";
#endif
    return name;
}

PeerResult runJolt(const PeerScene& scene) {
    initialiseJoltOnce();
    // A header/library mismatch in JPH_* definitions would corrupt memory silently.
    if (!JPH::VerifyJoltVersionID()) {
        throw std::runtime_error("tumble peers: libJolt.a was built with other JPH_* definitions "
                                 "than the peer (see TUMBLE_JOLT_DEFINITIONS)");
    }
    PeerResult result;
    result.engine = joltName();

    JPH::TempAllocatorImpl tempAllocator(kTempAllocatorBytes);
    // Several threads: Jolt's own pool, whose Update also runs jobs on the calling thread while
    // it waits, so `threads - 1` workers make `threads` threads at work.
    std::unique_ptr<JPH::JobSystem> jobSystem;
    if (scene.threads > 1) {
        jobSystem = std::make_unique<JPH::JobSystemThreadPool>(
            JPH::cMaxPhysicsJobs, JPH::cMaxPhysicsBarriers, scene.threads - 1);
    } else {
        jobSystem = std::make_unique<JPH::JobSystemSingleThreaded>(JPH::cMaxPhysicsJobs);
    }

    const long long heapBefore = heapInUse();
    JoltWorld jw;
    build(jw, scene);
    result.heapBytes = heapInUse() - heapBefore;

    const float dt = float(scene.dt);
    result.stepSeconds = timeSteps(scene.steps, [&] {
        const JPH::EPhysicsUpdateError error =
            jw.system.Update(dt, 1, &tempAllocator, jobSystem.get());
        if (error != JPH::EPhysicsUpdateError::None) {
            throw PeerCapacityError("tumble peers: Jolt ran out of body pairs or contact "
                                    "constraints (EPhysicsUpdateError " +
                                    std::to_string(int(error)) + ")");
        }
    });
    result.heapBytesAtEnd = heapInUse() - heapBefore;

    const JPH::BodyInterface& bodies = jw.system.GetBodyInterface();
    result.finalPositions.reserve(jw.bodies.size());
    for (const JPH::BodyID id : jw.bodies) {
        const JPH::Vec3 v = bodies.GetLinearVelocity(id);
        const JPH::Vec3 w = bodies.GetAngularVelocity(id);
        const double velocity[3] = {v.GetX(), v.GetY(), v.GetZ()};
        const double angularVelocity[3] = {w.GetX(), w.GetY(), w.GetZ()};
        const bool asleep = scene.sleep && !bodies.IsActive(id);
        if (asleep || (!scene.sleep && slowerThanRest(velocity, angularVelocity))) {
            ++result.bodiesAtRest;
        }
        const JPH::RVec3 p = bodies.GetCenterOfMassPosition(id);
        result.finalPositions.push_back(
            {double(p.GetX()), double(p.GetY()), double(p.GetZ())});
    }
    result.settings = describe(jw, scene.sleep, scene.threads);

    // Bodies are removed and destroyed before the system goes, the order Jolt's samples keep.
    jw.bodies.push_back(jw.ground);
    JPH::BodyInterface& writable = jw.system.GetBodyInterface();
    writable.RemoveBodies(jw.bodies.data(), int(jw.bodies.size()));
    writable.DestroyBodies(jw.bodies.data(), int(jw.bodies.size()));
    return result;
}

} // namespace tumble::bench::detail
