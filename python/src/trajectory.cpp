// Trajectory: run samples as a NumPy structured array.
#include "trajectory.hpp"

#include <memory>

namespace tumble::python {

void registerTrajectoryDtype()
{
    PYBIND11_NUMPY_DTYPE(TrajectoryRow, time, body, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy,
                         wz, kinetic, potential);
}

void Trajectory::sample(const World& world, std::span<const BodyId> bodies, double time)
{
    const Vec3& gravity = world.settings().gravity;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (!world.isValid(bodies[i])) {
            continue;
        }
        const Body& body = world.body(bodies[i]);
        if (body.isStatic()) {
            continue;
        }
        const Vec3& x = body.position;
        const Quat& q = body.orientation;
        const Vec3& v = body.linearVelocity;
        const Vec3& w = body.angularVelocity;
        m_rows.push_back({time, static_cast<std::int64_t>(i), x.x, x.y, x.z, q.w, q.x, q.y, q.z,
                          v.x, v.y, v.z, w.x, w.y, w.z, body.kineticEnergy(),
                          body.potentialEnergy(gravity)});
    }
}

py::array Trajectory::release()
{
    if (m_rows.empty()) {
        return py::array_t<TrajectoryRow>(0);
    }
    // the vector moves into a capsule that NumPy frees with the array
    auto rows = std::make_unique<std::vector<TrajectoryRow>>(std::move(m_rows));
    m_rows = {};
    const auto size = static_cast<py::ssize_t>(rows->size());
    TrajectoryRow* data = rows->data();
    py::capsule owner(rows.get(), [](void* pointer) {
        delete static_cast<std::vector<TrajectoryRow>*>(pointer);
    });
    rows.release();
    return py::array_t<TrajectoryRow>({size}, {static_cast<py::ssize_t>(sizeof(TrajectoryRow))},
                                      data, owner);
}

long long sampleCount(long long stepCount, long long every)
{
    const long long multiples = stepCount / every;
    return 1 + multiples + (stepCount % every != 0 ? 1 : 0);
}

} // namespace tumble::python
