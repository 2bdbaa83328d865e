// tumble.Collision: the impacts of World.collisions.
#include "bindings.hpp"
#include "collision.hpp"
#include "convert.hpp"

#include <pybind11/stl.h>

namespace tumble::python {

Collision makeCollision(const std::shared_ptr<WorldState>& state, const CollisionEvent& event)
{
    const ContactManifold& manifold = event.manifold;
    py::array_t<double> points({static_cast<py::ssize_t>(manifold.pointCount), py::ssize_t{3}});
    auto view = points.mutable_unchecked<2>();
    for (int i = 0; i < manifold.pointCount; ++i) {
        const Vec3& p = manifold.points[static_cast<std::size_t>(i)].position;
        view(i, 0) = p.x;
        view(i, 1) = p.y;
        view(i, 2) = p.z;
    }
    Collision collision{event.time, BodyHandle(state, state->serialOf(manifold.body))};
    if (!manifold.other.isNull()) {
        collision.other = BodyHandle(state, state->serialOf(manifold.other));
    }
    if (manifold.plane >= 0) {
        collision.plane = manifold.plane;
    }
    collision.normal = toArray(manifold.normal);
    collision.points = points;
    collision.average = toArray(manifold.averagePoint());
    collision.approachSpeed = event.approachSpeed;
    collision.normalImpulse = toArray(event.normalImpulse);
    collision.frictionImpulse = toArray(event.frictionImpulse);
    collision.restitutionApplied = event.restitutionApplied;
    collision.kineticEnergyBefore = event.kineticEnergyBefore;
    collision.kineticEnergyAfter = event.kineticEnergyAfter;
    return collision;
}

void bindCollision(py::module_& module)
{
    py::class_<Collision> collision(module, "Collision", R"doc(
An impact of the last step (World.collisions): a body meeting the ground, a plane or another
body, and the impulses that resolved it. Vectors are NumPy arrays in world axes.
)doc");
    collision.def_readonly("time", &Collision::time, "Simulated time of the impact, s.")
        .def_readonly("body", &Collision::body, "The body (tumble.Body).")
        .def_readonly("other", &Collision::other,
                      "The other body, or None for the ground or a plane.")
        .def_readonly("plane", &Collision::plane,
                      "Index of the plane (World.add_plane), or None for the ground or a body.")
        .def_readonly("normal", &Collision::normal, "Contact normal, into the body's side.")
        .def_readonly("points", &Collision::points, "Touching points, an n x 3 array, m.")
        .def_readonly("average", &Collision::average, "Mean of the touching points, m.")
        .def_readonly("approach_speed", &Collision::approachSpeed,
                      "How fast the fastest point approached before the impact, m/s (> 0).")
        .def_readonly("normal_impulse", &Collision::normalImpulse,
                      "Sum of the normal impulses, N s.")
        .def_readonly("friction_impulse", &Collision::frictionImpulse,
                      "Sum of the friction impulses, N s.")
        .def_readonly("restitution_applied", &Collision::restitutionApplied,
                      "False for an approach slower than the restitution threshold (plastic).")
        .def_readonly("kinetic_energy_before", &Collision::kineticEnergyBefore,
                      "Kinetic energy just before the impact, J.")
        .def_readonly("kinetic_energy_after", &Collision::kineticEnergyAfter,
                      "Kinetic energy just after the impact, J.");
    collision.def("__repr__", [](const Collision& c) {
        return "<tumble.Collision t=" + py::repr(py::float_(c.time)).cast<std::string>() +
               " body=" + c.body.name() + ">";
    });
}

} // namespace tumble::python
