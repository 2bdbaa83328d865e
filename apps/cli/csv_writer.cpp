#include "csv_writer.hpp"

#include <cstdio>

namespace tumble::cli {
namespace {

constexpr const char* kHeader =
    "time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic,potential\n";

} // namespace

CsvWriter::CsvWriter(const std::string& path) : m_output(path)
{
    std::fputs(kHeader, m_output.handle());
}

void CsvWriter::writeSample(const scenario::Runner& runner)
{
    const Vec3& gravity = runner.world().settings().gravity;
    const Real time = runner.time();
    for (std::size_t i = 0; i < runner.bodies().size(); ++i) {
        const Body& body = runner.world().body(runner.bodies()[i]);
        // one row per dynamic body: static geometry never moves
        if (body.isStatic()) {
            continue;
        }
        const Vec3& x = body.position;
        const Quat& q = body.orientation;
        const Vec3& v = body.linearVelocity;
        const Vec3& w = body.angularVelocity;
        std::fprintf(m_output.handle(),
                     "%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                     "%.17g,%.17g,%.17g,%.17g\n",
                     time, csvField(runner.bodyName(i)).c_str(), x.x, x.y, x.z, q.w, q.x, q.y, q.z,
                     v.x, v.y, v.z, w.x, w.y, w.z, body.kineticEnergy(),
                     body.potentialEnergy(gravity));
    }
}

} // namespace tumble::cli
