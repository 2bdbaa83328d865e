// Box3D peer: one b3World stepped on one thread (no task callbacks, one worker) with Box3D's
// default solver and contact settings, a static box for the ground and sleeping at Box3D's default
// thresholds when the scene allows it. Box3D is an external build (tools/build-box3d-peer.sh) in
// single precision, which this file's view of b3Pos assumes and b3IsDoublePrecision() checks.

#include "peer_detail.hpp"

#include <box3d/box3d.h>
#include <box3d/collision.h>
#include <box3d/constants.h>
#include <box3d/math_functions.h>
#include <box3d/types.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tumble::bench::detail {
namespace {

// Box3D's own samples and benchmark step with four sub-steps (sample.h, benchmark/main.c), the
// count b3World_Step's documentation recommends.
constexpr int kSubSteps = 4;

// The ground: a box whose top face is the plane y = groundHeight, wider than any scene (Box3D's
// own benchmarks use a box 2 m thick and hundreds of metres wide the same way).
constexpr float kGroundHalfWidth = 1000.0f;
constexpr float kGroundHalfThickness = 1.0f;

// Marks the ground's material for the friction callback, which sees materials and not bodies.
constexpr std::uint64_t kGroundMaterial = 1;

// Box3D mixes friction by geometric mean. Against the ground each body keeps its own friction, as
// in the other peers and in tumble's scenes (whose ground has no material of its own); between
// two bodies Box3D's default rule stays.
float combineFriction(float frictionA, std::uint64_t materialA, float frictionB,
                      std::uint64_t materialB) {
    if (materialA == kGroundMaterial) {
        return frictionB;
    }
    if (materialB == kGroundMaterial) {
        return frictionA;
    }
    return std::sqrt(frictionA * frictionB);
}

b3Vec3 vec(const double v[3]) {
    return b3Vec3{float(v[0]), float(v[1]), float(v[2])};
}

// The world is destroyed with everything in it, also when building or stepping throws.
struct Box3dWorld {
    b3WorldId id = b3_nullWorldId;
    b3BodyId ground = b3_nullBodyId;
    std::vector<b3BodyId> bodies;

    Box3dWorld() = default;
    Box3dWorld(const Box3dWorld&) = delete;
    Box3dWorld& operator=(const Box3dWorld&) = delete;
    ~Box3dWorld() {
        if (b3World_IsValid(id)) {
            b3DestroyWorld(id);
        }
    }
};

b3WorldDef worldDef(const PeerScene& scene) {
    b3WorldDef def = b3DefaultWorldDef();
    def.gravity = vec(scene.gravity);
    def.enableSleep = scene.sleep;
    def.frictionCallback = &combineFriction;
    def.restitutionThreshold = float(scene.restitutionThreshold);
    // One worker and no task callbacks: Box3D runs its tasks inline on the calling thread and
    // starts no scheduler.
    def.workerCount = 1;
    def.enqueueTask = nullptr;
    def.finishTask = nullptr;
    return def;
}

void build(Box3dWorld& bw, const PeerScene& scene) {
    b3WorldDef def = worldDef(scene);
    // Room for every body and shape up front, as Box3D's benchmarks reserve, so building the world
    // does not regrow its arrays body by body.
    const int bodyCount = static_cast<int>(scene.bodies.size());
    def.capacity.staticBodyCount = 1;
    def.capacity.staticShapeCount = 1;
    def.capacity.dynamicBodyCount = bodyCount;
    def.capacity.dynamicShapeCount = bodyCount;
    bw.id = b3CreateWorld(&def);
    if (!b3World_IsValid(bw.id)) {
        throw std::runtime_error("tumble peers: Box3D could not create a world (at most " +
                                 std::to_string(b3GetMaxWorldCount()) + " at a time)");
    }

    // Restitution mixes by maximum in Box3D, so a ground of 0 leaves each body's own value.
    b3BodyDef groundDef = b3DefaultBodyDef();
    groundDef.type = b3_staticBody;
    groundDef.position = b3Pos{0.0f, float(scene.groundHeight) - kGroundHalfThickness, 0.0f};
    bw.ground = b3CreateBody(bw.id, &groundDef);
    const b3BoxHull groundBox =
        b3MakeBoxHull(kGroundHalfWidth, kGroundHalfThickness, kGroundHalfWidth);
    b3ShapeDef groundShape = b3DefaultShapeDef();
    groundShape.baseMaterial.restitution = 0.0f;
    groundShape.baseMaterial.userMaterialId = kGroundMaterial;
    b3CreateHullShape(bw.ground, &groundShape, &groundBox.base);

    // One box hull per size; the world keeps one copy of each distinct hull whatever the number of
    // shapes made from it.
    std::map<std::array<double, 3>, b3BoxHull> hulls;
    bw.bodies.reserve(scene.bodies.size());
    for (const PeerBody& body : scene.bodies) {
        const std::array<double, 3> size{body.size[0], body.size[1], body.size[2]};
        const auto [hull, added] = hulls.try_emplace(size);
        if (added) {
            hull->second =
                b3MakeBoxHull(float(size[0] / 2), float(size[1] / 2), float(size[2] / 2));
        }
        const double* q = body.orientation;
        const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        b3BodyDef bodyDef = b3DefaultBodyDef();
        bodyDef.type = b3_dynamicBody;
        bodyDef.position = vec(body.position);
        bodyDef.rotation = b3Quat{
            b3Vec3{float(q[1] / norm), float(q[2] / norm), float(q[3] / norm)}, float(q[0] / norm)};
        bodyDef.linearVelocity = vec(body.velocity);
        bodyDef.angularVelocity = vec(body.angularVelocity);
        const b3BodyId id = b3CreateBody(bw.id, &bodyDef);

        // The given mass as the density of a uniform solid box, so Box3D's mass computation gives
        // that mass and the box's inertia.
        b3ShapeDef shapeDef = b3DefaultShapeDef();
        shapeDef.density = float(body.mass / (size[0] * size[1] * size[2]));
        shapeDef.baseMaterial.friction = float(body.friction);
        shapeDef.baseMaterial.restitution = float(body.restitution);
        b3CreateHullShape(id, &shapeDef, &hull->second.base);
        bw.bodies.push_back(id);
    }
}

std::string describe(const Box3dWorld& bw, const PeerScene& scene) {
    const b3WorldDef def = worldDef(scene);
    const b3BodyDef bodyDef = b3DefaultBodyDef();
    const float dt = float(scene.dt);
    // Box3D lowers the contact stiffness for long sub-steps (physics_world.c: at most an eighth
    // of the sub-step rate), so the value in force is printed beside the requested one.
    const float hertzInForce = std::fmin(def.contactHertz, 0.125f * kSubSteps / dt);
    std::ostringstream out;
    out << "b3World_Step(dt, " << kSubSteps << " sub-steps) with workerCount 1 and no task "
        << "callbacks (single thread); soft step: per sub-step one solve and one relax iteration, "
        << "then restitution (threshold " << def.restitutionThreshold << " m/s); soft contacts "
        << def.contactHertz << " Hz (" << hertzInForce << " Hz in force at this dt), damping ratio "
        << def.contactDampingRatio << ", push-out speed " << def.contactSpeed
        << " m/s, static contacts twice the stiffness and half the damping ratio; linear slop "
        << B3_LINEAR_SLOP << " m, speculative distance " << B3_SPECULATIVE_DISTANCE
        << " m, warm starting " << (b3World_IsWarmStartingEnabled(bw.id) ? "on" : "off")
        << ", contact recycling within " << b3World_GetContactRecycleDistance(bw.id)
        << " m; continuous collision " << (def.enableContinuous ? "on" : "off")
        << " against the static ground; box hulls (sharp corners), static box hull ground, no "
        << "damping, max speed " << def.maximumLinearSpeed
        << " m/s, single precision, SIMD as libbox3d.a was built (SSE2 by "
        << "tools/build-box3d-peer.sh); friction geometric mean between bodies, "
        << "body's own against the ground; restitution max (ground 0); ";
    if (scene.sleep) {
        out << "sleeping on: below " << bodyDef.sleepThreshold << " m/s for " << B3_TIME_TO_SLEEP
            << " s (island-wide)";
    } else {
        out << "sleeping off (enableSleep false): at rest means |v|, |w| < " << kAtRestSpeed;
    }
    return out.str();
}

} // namespace

std::string box3dName() {
    const b3Version version = b3GetVersion();
    std::string name = "Box3D " + std::to_string(version.major) + "." +
                       std::to_string(version.minor) + "." + std::to_string(version.revision);
#ifdef TUMBLE_PEER_BOX3D_COMMIT
    name += std::string(" (") + TUMBLE_PEER_BOX3D_COMMIT + ")";
#endif
    return name;
}

PeerResult runBox3d(const PeerScene& scene) {
    // b3Pos is three doubles in a double-precision library and three floats here: a mismatch
    // would corrupt every position silently.
    if (b3IsDoublePrecision()) {
        throw std::runtime_error("tumble peers: libbox3d.a was built with BOX3D_DOUBLE_PRECISION, "
                                 "the peer without (see tools/build-box3d-peer.sh)");
    }
    PeerResult result;
    result.engine = box3dName();

    const long long heapBefore = heapInUse();
    Box3dWorld bw;
    build(bw, scene);
    result.heapBytes = heapInUse() - heapBefore;

    const float dt = float(scene.dt);
    result.stepSeconds = timeSteps(scene.steps, [&] { b3World_Step(bw.id, dt, kSubSteps); });
    result.heapBytesAtEnd = heapInUse() - heapBefore;

    result.finalPositions.reserve(bw.bodies.size());
    for (const b3BodyId id : bw.bodies) {
        const b3Vec3 v = b3Body_GetLinearVelocity(id);
        const b3Vec3 w = b3Body_GetAngularVelocity(id);
        const double velocity[3] = {v.x, v.y, v.z};
        const double angularVelocity[3] = {w.x, w.y, w.z};
        const bool asleep = scene.sleep && !b3Body_IsAwake(id);
        if (asleep || (!scene.sleep && slowerThanRest(velocity, angularVelocity))) {
            ++result.bodiesAtRest;
        }
        const b3Pos p = b3Body_GetWorldCenter(id);
        result.finalPositions.push_back({double(p.x), double(p.y), double(p.z)});
    }
    result.settings = describe(bw, scene);
    return result;
}

} // namespace tumble::bench::detail
