// ODE peer: dWorldQuickStep (ODE's fast iterative stepper) over a hash space, contact joints with
// bounce and Coulomb friction, and auto-disable at ODE's default thresholds.

#include "peer_detail.hpp"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tumble::bench::detail {
namespace {

constexpr int kMaxContactsPerPair = 4;
// ODE's documented remedy for resting-contact jitter, which would otherwise keep bodies awake.
constexpr dReal kSurfaceLayer = 0.001;

struct Material {
    dReal restitution;
    dReal friction;
};

// dInitODE2 and dCloseODE must pair even when building the world throws.
struct OdeLibrary {
    OdeLibrary() {
        dInitODE2(0);
        dAllocateODEDataForThread(dAllocateMaskAll);
    }
    OdeLibrary(const OdeLibrary&) = delete;
    OdeLibrary& operator=(const OdeLibrary&) = delete;
    ~OdeLibrary() { dCloseODE(); }
};

struct OdeWorld {
    dWorldID world = dWorldCreate();
    dSpaceID space = dHashSpaceCreate(nullptr);
    dJointGroupID contacts = dJointGroupCreate(0);
    std::vector<dBodyID> bodies;
    std::vector<Material> materials; // indexed like bodies; each body's data points at its entry
    // Below this approach speed a contact does not bounce (bounce_vel): the scene's threshold,
    // set by build.
    dReal bounceVelocity = 0;

    OdeWorld() = default;
    OdeWorld(const OdeWorld&) = delete;
    OdeWorld& operator=(const OdeWorld&) = delete;
    ~OdeWorld() {
        dJointGroupDestroy(contacts);
        dSpaceDestroy(space); // the space owns (and destroys) the geoms: cleanup mode is on
        dWorldDestroy(world); // destroys the bodies
    }
};

bool awake(dBodyID body) {
    return body != nullptr && dBodyIsEnabled(body) != 0;
}

// Between two bodies: geometric-mean friction and the larger restitution, as Box2D does; against
// the ground (no body) the body's own values apply.
dSurfaceParameters surface(dBodyID b1, dBodyID b2, dReal bounceVelocity) {
    const Material* m1 = b1 ? static_cast<const Material*>(dBodyGetData(b1)) : nullptr;
    const Material* m2 = b2 ? static_cast<const Material*>(dBodyGetData(b2)) : nullptr;
    Material m{};
    if (m1 && m2) {
        m = {std::max(m1->restitution, m2->restitution), std::sqrt(m1->friction * m2->friction)};
    } else {
        m = m1 ? *m1 : *m2;
    }
    dSurfaceParameters s{};
    // Approx1 makes mu a Coulomb coefficient; without it ODE treats mu as a fixed force limit.
    s.mode = dContactBounce | dContactApprox1;
    s.mu = m.friction;
    s.bounce = m.restitution;
    s.bounce_vel = bounceVelocity;
    return s;
}

void nearCallback(void* data, dGeomID g1, dGeomID g2) {
    auto& ow = *static_cast<OdeWorld*>(data);
    const dBodyID b1 = dGeomGetBody(g1);
    const dBodyID b2 = dGeomGetBody(g2);
    // Disabled bodies are not stepped, so contacts among them and the ground would be wasted work;
    // a pair with an awake body still gets its joint, which is what wakes the other body.
    if (!awake(b1) && !awake(b2)) {
        return;
    }
    dContact contact[kMaxContactsPerPair];
    const int count = dCollide(g1, g2, kMaxContactsPerPair, &contact[0].geom, sizeof(dContact));
    if (count == 0) {
        return;
    }
    const dSurfaceParameters params = surface(b1, b2, ow.bounceVelocity);
    for (int i = 0; i < count; ++i) {
        contact[i].surface = params;
        const dJointID joint = dJointCreateContact(ow.world, ow.contacts, &contact[i]);
        dJointAttach(joint, b1, b2);
    }
}

void build(OdeWorld& ow, const PeerScene& scene) {
    dWorldSetGravity(ow.world, scene.gravity[0], scene.gravity[1], scene.gravity[2]);
    dWorldSetContactSurfaceLayer(ow.world, kSurfaceLayer);
    // Bodies copy the world's auto-disable settings when created, so this must come first.
    dWorldSetAutoDisableFlag(ow.world, scene.sleep ? 1 : 0);
    ow.bounceVelocity = scene.restitutionThreshold;

    dCreatePlane(ow.space, 0, 1, 0, scene.groundHeight);

    ow.bodies.reserve(scene.bodies.size());
    ow.materials.reserve(scene.bodies.size());
    for (const PeerBody& body : scene.bodies) {
        ow.materials.push_back({body.restitution, body.friction});
        const dBodyID id = dBodyCreate(ow.world);
        dMass mass;
        dMassSetBoxTotal(&mass, body.mass, body.size[0], body.size[1], body.size[2]);
        dBodySetMass(id, &mass);
        dBodySetPosition(id, body.position[0], body.position[1], body.position[2]);
        const dQuaternion q{body.orientation[0], body.orientation[1], body.orientation[2],
                            body.orientation[3]};
        dBodySetQuaternion(id, q);
        dBodySetLinearVel(id, body.velocity[0], body.velocity[1], body.velocity[2]);
        dBodySetAngularVel(id, body.angularVelocity[0], body.angularVelocity[1],
                           body.angularVelocity[2]);
        dBodySetData(id, &ow.materials.back());
        const dGeomID geom = dCreateBox(ow.space, body.size[0], body.size[1], body.size[2]);
        dGeomSetBody(geom, id);
        ow.bodies.push_back(id);
    }
}

std::string describe(const OdeWorld& ow) {
    std::ostringstream out;
    out << "dWorldQuickStep " << dWorldGetQuickStepNumIterations(ow.world)
        << " iterations (ODE default), SOR w " << dWorldGetQuickStepW(ow.world) << ", ERP "
        << dWorldGetERP(ow.world) << ", CFM " << dWorldGetCFM(ow.world) << ", surface layer "
        << dWorldGetContactSurfaceLayer(ow.world) << " m; "
        << (sizeof(dReal) == sizeof(double) ? "double" : "single")
        << " precision; dHashSpace, dCreatePlane ground, dCreateBox; up to " << kMaxContactsPerPair
        << " contacts per pair, dContactBounce (bounce = restitution, "
        << "bounce_vel " << ow.bounceVelocity
        << " m/s) + dContactApprox1 (Coulomb pyramid, mu = friction); body-body: max restitution, "
        << "sqrt(mu1 mu2); pairs with no awake body skipped; ";
    if (dWorldGetAutoDisableFlag(ow.world) != 0) {
        out << "auto-disable on (ODE defaults): below "
            << dWorldGetAutoDisableLinearThreshold(ow.world) << " m/s and "
            << dWorldGetAutoDisableAngularThreshold(ow.world) << " rad/s for "
            << dWorldGetAutoDisableSteps(ow.world) << " steps and "
            << dWorldGetAutoDisableTime(ow.world) << " s, averaged over "
            << dWorldGetAutoDisableAverageSamplesCount(ow.world) << " sample(s)";
    } else {
        out << "auto-disable off: at rest means |v|, |w| < " << kAtRestSpeed;
    }
    return out.str();
}

} // namespace

std::string odeName() {
    return "ODE " TUMBLE_PEER_ODE_VERSION;
}

PeerResult runOde(const PeerScene& scene) {
    PeerResult result;
    result.engine = odeName();

    const OdeLibrary library;
    const long long heapBefore = heapInUse();
    OdeWorld ow;
    build(ow, scene);
    result.heapBytes = heapInUse() - heapBefore;

    result.stepSeconds = timeSteps(scene.steps, [&] {
        dSpaceCollide(ow.space, &ow, &nearCallback);
        dWorldQuickStep(ow.world, scene.dt);
        dJointGroupEmpty(ow.contacts);
    });
    result.heapBytesAtEnd = heapInUse() - heapBefore;

    result.finalPositions.reserve(ow.bodies.size());
    for (const dBodyID body : ow.bodies) {
        const dReal* v = dBodyGetLinearVel(body);
        const dReal* w = dBodyGetAngularVel(body);
        const double velocity[3] = {v[0], v[1], v[2]};
        const double angularVelocity[3] = {w[0], w[1], w[2]};
        if (!dBodyIsEnabled(body) || (!scene.sleep && slowerThanRest(velocity, angularVelocity))) {
            ++result.bodiesAtRest;
        }
        const dReal* p = dBodyGetPosition(body);
        result.finalPositions.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    result.settings = describe(ow);
    return result;
}

} // namespace tumble::bench::detail
