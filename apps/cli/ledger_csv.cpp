#include "ledger_csv.hpp"

#include <cstdio>
#include <string>

namespace tumble::cli {

EnergyCsv::EnergyCsv(const std::string& path) : m_output(path)
{
    std::fputs("time,body,kinetic_linear,kinetic_rotational,potential,total,removed_normal,"
               "removed_friction,removed_correction,removed_integration,removed_rest,added,"
               "balance_error\n",
               m_output.handle());
}

void EnergyCsv::writeStep(const scenario::Runner& runner)
{
    const World& world = runner.world();
    for (std::size_t i = 0; i < runner.bodies().size(); ++i) {
        const Body& body = world.body(runner.bodies()[i]);
        if (body.isStatic()) {
            continue;
        }
        const EnergyLedger& ledger = body.ledger;
        const Real linear = 0.5 * body.mass * lengthSquared(body.linearVelocity);
        const Real rotational = 0.5 * glm::dot(body.angularVelocity, body.angularMomentum());
        const Real potential = body.potentialEnergy(world.settings().gravity);
        const Real total = linear + rotational + potential;
        std::fprintf(m_output.handle(),
                     "%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                     runner.time(), csvField(runner.bodyName(i)).c_str(), linear, rotational,
                     potential, total, ledger.removedByNormal, ledger.removedByFriction,
                     ledger.removedByCorrection, ledger.removedByIntegration, ledger.removedByRest,
                     ledger.added, ledger.imbalance(total));
    }
}

ContactsCsv::ContactsCsv(const std::string& path) : m_output(path)
{
    std::fputs("time,body,phase,vertex,px,py,pz,rx,ry,rz,nx,ny,nz,vn_before,vtx_before,"
               "vty_before,vtz_before,vn_after,vtx_after,vty_after,vtz_after,normal_impulse,"
               "friction_x,friction_y,friction_z,friction_state,restitution,other\n",
               m_output.handle());
}

void ContactsCsv::writeStep(const scenario::Runner& runner)
{
    for (const ContactRecord& record : runner.world().contactRecords()) {
        const ContactManifold& manifold = record.manifold;
        const std::string name = csvField(runner.bodyName(runner.bodyIndex(manifold.body)));
        // what the body touches: another body by name, a plane by index, or the ground
        const std::string other =
            !manifold.other.isNull()
                ? csvField(runner.bodyName(runner.bodyIndex(manifold.other)))
                : (manifold.plane >= 0 ? "plane " + std::to_string(manifold.plane) : "ground");
        const Vec3& n = manifold.normal;
        for (int i = 0; i < manifold.pointCount; ++i) {
            const ContactPoint& point = manifold.points[i];
            const Vec3 offset = point.position - record.centreOfMass;
            const Real normalBefore = glm::dot(n, point.velocityBefore);
            const Real normalAfter = glm::dot(n, point.velocityAfter);
            const Vec3 tangentBefore = point.velocityBefore - normalBefore * n;
            const Vec3 tangentAfter = point.velocityAfter - normalAfter * n;
            std::fprintf(
                m_output.handle(),
                "%.17g,%s,%s,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s,%s,%s\n",
                record.time, name.c_str(), contactPhaseName(record.phase), point.vertex,
                point.position.x, point.position.y, point.position.z, offset.x, offset.y, offset.z,
                n.x, n.y, n.z, normalBefore, tangentBefore.x, tangentBefore.y, tangentBefore.z,
                normalAfter, tangentAfter.x, tangentAfter.y, tangentAfter.z, point.normalImpulse,
                point.frictionImpulse.x, point.frictionImpulse.y, point.frictionImpulse.z,
                point.sliding ? "slip" : "stick", restitutionStateName(point.restitution),
                other.c_str());
        }
    }
}

} // namespace tumble::cli
