// Bullet peer: btDiscreteDynamicsWorld with its default pipeline (dbvt broadphase, sequential
// impulse solver), a static plane for the ground and deactivation at Bullet's default thresholds.

#include "peer_detail.hpp"

#include <btBulletDynamicsCommon.h>

#include <array>
#include <map>
#include <memory>
#include <sstream>

namespace tumble::bench::detail {
namespace {

// Bullet does not own anything it is handed, and the world must outlive the bodies in it while
// they are removed; declaration order gives the reverse destruction order Bullet needs.
struct BulletWorld {
    std::unique_ptr<btDefaultCollisionConfiguration> configuration =
        std::make_unique<btDefaultCollisionConfiguration>();
    std::unique_ptr<btCollisionDispatcher> dispatcher =
        std::make_unique<btCollisionDispatcher>(configuration.get());
    std::unique_ptr<btDbvtBroadphase> broadphase = std::make_unique<btDbvtBroadphase>();
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver =
        std::make_unique<btSequentialImpulseConstraintSolver>();
    std::unique_ptr<btDiscreteDynamicsWorld> world = std::make_unique<btDiscreteDynamicsWorld>(
        dispatcher.get(), broadphase.get(), solver.get(), configuration.get());
    std::unique_ptr<btStaticPlaneShape> groundShape;
    // Bodies of equal size share one shape, as a Bullet application would.
    std::map<std::array<double, 3>, std::unique_ptr<btBoxShape>> boxShapes;
    std::unique_ptr<btRigidBody> ground;
    std::vector<std::unique_ptr<btRigidBody>> bodies;

    BulletWorld() = default;
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;
    ~BulletWorld() {
        for (auto& body : bodies) {
            world->removeRigidBody(body.get());
        }
        if (ground) {
            world->removeRigidBody(ground.get());
        }
    }
};

btVector3 vec(const double v[3]) {
    return {btScalar(v[0]), btScalar(v[1]), btScalar(v[2])};
}

btBoxShape* boxShape(BulletWorld& bw, const double size[3]) {
    const std::array<double, 3> key{size[0], size[1], size[2]};
    auto& shape = bw.boxShapes[key];
    if (!shape) {
        // btBoxShape takes half extents and keeps its collision margin inside them.
        shape = std::make_unique<btBoxShape>(
            btVector3(btScalar(size[0] / 2), btScalar(size[1] / 2), btScalar(size[2] / 2)));
    }
    return shape.get();
}

void build(BulletWorld& bw, const PeerScene& scene) {
    bw.world->setGravity(vec(scene.gravity));
    bw.world->getSolverInfo().m_restitutionVelocityThreshold =
        btScalar(scene.restitutionThreshold);

    // Bullet combines materials by multiplying friction and restitution, so a ground of 1 and 1
    // leaves each body's own values in force against the ground.
    bw.groundShape =
        std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), btScalar(scene.groundHeight));
    btRigidBody::btRigidBodyConstructionInfo groundInfo(0, nullptr, bw.groundShape.get());
    bw.ground = std::make_unique<btRigidBody>(groundInfo);
    bw.ground->setRestitution(1);
    bw.ground->setFriction(1);
    bw.world->addRigidBody(bw.ground.get());

    bw.bodies.reserve(scene.bodies.size());
    for (const PeerBody& body : scene.bodies) {
        btBoxShape* shape = boxShape(bw, body.size);
        btVector3 inertia(0, 0, 0);
        shape->calculateLocalInertia(btScalar(body.mass), inertia);
        // No motion state: nothing renders, and the start transform then comes from the info.
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(body.mass), nullptr, shape, inertia);
        const btQuaternion rotation(btScalar(body.orientation[1]), btScalar(body.orientation[2]),
                                    btScalar(body.orientation[3]), btScalar(body.orientation[0]));
        info.m_startWorldTransform = btTransform(rotation, vec(body.position));
        info.m_restitution = btScalar(body.restitution);
        info.m_friction = btScalar(body.friction);
        auto rigid = std::make_unique<btRigidBody>(info);
        rigid->setLinearVelocity(vec(body.velocity));
        rigid->setAngularVelocity(vec(body.angularVelocity));
        if (!scene.sleep) {
            rigid->setActivationState(DISABLE_DEACTIVATION);
        }
        bw.world->addRigidBody(rigid.get());
        bw.bodies.push_back(std::move(rigid));
    }
}

std::string describe(const BulletWorld& bw, bool sleep) {
    const btContactSolverInfo& info = bw.world->getSolverInfo();
    const btScalar linearSleep =
        bw.bodies.empty() ? btScalar(0.8) : bw.bodies.front()->getLinearSleepingThreshold();
    const btScalar angularSleep =
        bw.bodies.empty() ? btScalar(1.0) : bw.bodies.front()->getAngularSleepingThreshold();
    std::ostringstream out;
    out << "btDiscreteDynamicsWorld, btDbvtBroadphase, btSequentialImpulseConstraintSolver "
        << info.m_numIterations << " iterations, erp " << info.m_erp << ", split impulse "
        << (info.m_splitImpulse ? "on" : "off") << " (threshold "
        << info.m_splitImpulsePenetrationThreshold << " m), warm starting "
        << ((info.m_solverMode & SOLVER_USE_WARMSTARTING) != 0 ? "on" : "off")
        << ", restitution only above " << info.m_restitutionVelocityThreshold
        << " m/s; btStaticPlaneShape ground (default convex-plane contacts: one new manifold "
        << "point per step, no multipoint perturbation), btBoxShape (margin 0.04 m inside the "
        << "extents), "
        << (sizeof(btScalar) == sizeof(double) ? "double" : "single")
        << " precision; materials multiply (ground friction 1, restitution 1); "
        << "stepSimulation(dt, 0, dt); ";
    if (sleep) {
        out << "deactivation on: sleep below " << linearSleep << " m/s and " << angularSleep
            << " rad/s for " << gDeactivationTime << " s";
    } else {
        out << "deactivation off (DISABLE_DEACTIVATION): at rest means |v|, |w| < "
            << kAtRestSpeed;
    }
    return out.str();
}

} // namespace

std::string bulletName() {
    const int version = btGetVersion();
    return "Bullet " + std::to_string(version / 100) + "." + std::to_string(version % 100);
}

PeerResult runBullet(const PeerScene& scene) {
    PeerResult result;
    result.engine = bulletName();

    const long long heapBefore = heapInUse();
    BulletWorld bw;
    build(bw, scene);
    result.heapBytes = heapInUse() - heapBefore;

    // maxSubSteps 0 steps by exactly dt each call, with no accumulator or interpolation.
    const btScalar dt = btScalar(scene.dt);
    result.stepSeconds = timeSteps(scene.steps, [&] { bw.world->stepSimulation(dt, 0, dt); });
    result.heapBytesAtEnd = heapInUse() - heapBefore;

    result.finalPositions.reserve(bw.bodies.size());
    for (const auto& body : bw.bodies) {
        const btVector3& v = body->getLinearVelocity();
        const btVector3& w = body->getAngularVelocity();
        const double velocity[3] = {v.x(), v.y(), v.z()};
        const double angularVelocity[3] = {w.x(), w.y(), w.z()};
        const bool asleep = body->getActivationState() == ISLAND_SLEEPING;
        if (asleep || (!scene.sleep && slowerThanRest(velocity, angularVelocity))) {
            ++result.bodiesAtRest;
        }
        const btVector3& p = body->getCenterOfMassPosition();
        result.finalPositions.push_back({double(p.x()), double(p.y()), double(p.z())});
    }
    result.settings = describe(bw, scene.sleep);
    return result;
}

} // namespace tumble::bench::detail
