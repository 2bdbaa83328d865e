// The soft step's bodies and manifolds at the step's start (docs/physics/12-soft-step.md, (12.3)).
#include "step/soft_manifolds.hpp"

#include "dynamics/solver_point.hpp"

namespace tumble {

SoftBody softBodyOf(const Body& body)
{
    SoftBody soft;
    soft.linearVelocity = body.linearVelocity;
    soft.angularVelocity = body.angularVelocity;
    soft.orientation = body.orientation;
    soft.invMass = body.invMass;
    soft.invInertia = body.invInertiaWorld;
    return soft;
}

SoftManifold softManifoldOf(const IslandContact& contact, std::span<const SoftBody> bodies,
                            std::span<const Vec3> centres, std::size_t staticIndex, bool rows)
{
    SoftManifold m;
    m.bodyA = contact.solverA;
    m.bodyB = contact.solverB;
    m.pointCount = contact.manifold.pointCount;
    m.againstStatic = m.bodyA == staticIndex || m.bodyB == staticIndex;
    m.normal = contact.manifold.normal;
    orthonormalBasis(m.normal, m.tangent1, m.tangent2);
    m.restitution = contact.restitution;
    const SoftBody& a = bodies[m.bodyA];
    const SoftBody& b = bodies[m.bodyB];
    const auto anchor = [&](std::uint32_t side, const Vec3& point) {
        return side == staticIndex ? Vec3(0.0) : point - centres[side];
    };
    for (int k = 0; k < m.pointCount; ++k) {
        const PairContactPoint& point = contact.manifold.points[k];
        SoftPoint& p = m.points[k];
        p.anchorA = anchor(m.bodyA, point.position);
        p.anchorB = anchor(m.bodyB, point.position);
        p.baseSeparation = point.separation - glm::dot(m.normal, p.anchorB - p.anchorA);
        p.relativeVelocity = glm::dot(m.normal, relativeVelocityAt(a, b, p.anchorA, p.anchorB));
    }
    if (rows) {
        prepareSoftRows(m, bodies);
    } else {
        centreSoftManifold(m);
    }
    m.friction = frictionAtCentre(relativeVelocityAt(a, b, m.centreA, m.centreB), m.normal,
                                  contact.staticFriction, contact.friction);
    return m;
}

} // namespace tumble
