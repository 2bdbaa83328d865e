// tumble.Body: the handle of one body, reading its state and changing it through World's
// setters (which keep the inverse inertia and the energy ledger consistent).
#include "bindings.hpp"
#include "convert.hpp"

#include "tumble/shape.hpp"

#include <functional>
#include <sstream>

namespace tumble::python {
namespace {

/// A read-only property computed from the body's state.
template <typename Read>
void readOnly(py::class_<BodyHandle>& body, const char* name, Read read, const char* doc)
{
    body.def_property_readonly(
        name, [read](const BodyHandle& handle) { return read(handle.body()); }, doc);
}

std::string describe(const BodyHandle& handle)
{
    std::ostringstream text;
    text << "<tumble.Body " << handle.name() << " #" << handle.serial();
    if (!handle.alive()) {
        text << " (removed)";
    }
    text << '>';
    return text.str();
}

/// The state a user may set: pose, velocities, mass and material.
void bindWritableState(py::class_<BodyHandle>& body)
{
    body.def_property(
        "position", [](const BodyHandle& h) { return toArray(h.body().position); },
        [](const BodyHandle& h, const Triple& p) {
            h.state().world.setTransform(h.id(), finiteVec3(p, "position"), h.body().orientation);
        },
        "Centre of mass, m.");
    body.def_property(
        "orientation", [](const BodyHandle& h) { return toArray(h.body().orientation); },
        [](const BodyHandle& h, const Quadruple& q) {
            h.state().world.setTransform(h.id(), h.body().position, unitQuat(q, "orientation"));
        },
        "Unit quaternion (w, x, y, z) from body to world axes; set values are normalised.");
    body.def_property(
        "velocity", [](const BodyHandle& h) { return toArray(h.body().linearVelocity); },
        [](const BodyHandle& h, const Triple& v) {
            h.state().world.setLinearVelocity(h.dynamicId("a velocity"),
                                              finiteVec3(v, "velocity"));
        },
        "Velocity of the centre of mass, m/s.");
    body.def_property(
        "angular_velocity", [](const BodyHandle& h) { return toArray(h.body().angularVelocity); },
        [](const BodyHandle& h, const Triple& w) {
            h.state().world.setAngularVelocity(h.dynamicId("an angular velocity"),
                                               finiteVec3(w, "angular_velocity"));
        },
        "Angular velocity, rad/s.");
    body.def_property(
        "mass", [](const BodyHandle& h) { return h.body().mass; },
        [](const BodyHandle& h, double mass) {
            requirePositive(mass, "mass");
            h.state().world.setMass(h.id(), mass);
        },
        "Mass, kg; setting it recomputes the inverse inertia.");
    body.def_property(
        "elasticity", [](const BodyHandle& h) { return h.body().material.restitution; },
        [](const BodyHandle& h, double e) {
            if (!(e >= 0.0 && e <= 1.0)) {
                throw py::value_error("elasticity must be in [0, 1]");
            }
            Material material = h.body().material;
            material.restitution = e;
            h.state().world.setMaterial(h.id(), material);
        },
        "Coefficient of restitution, in [0, 1].");
    body.def_property(
        "friction", [](const BodyHandle& h) { return h.body().material.friction; },
        [](const BodyHandle& h, double f) {
            requirePositive(f, "friction", true);
            Material material = h.body().material;
            material.friction = f;
            h.state().world.setMaterial(h.id(), material);
        },
        "Kinetic Coulomb friction coefficient.");
}

/// What follows from the state: size, inertia, energies, momenta, the face down.
void bindDerivedState(py::class_<BodyHandle>& body)
{
    readOnly(body, "motion", [](const Body& b) { return b.isStatic() ? "static" : "dynamic"; },
             "\"dynamic\" or \"static\".");
    readOnly(body, "size", [](const Body& b) { return toArray(b.shape.size); },
             "Full extents (width, height, depth), m.");
    readOnly(body, "inverse_mass", [](const Body& b) { return b.invMass; }, "1 / mass, 1/kg.");
    readOnly(body, "inverse_inertia_world",
             [](const Body& b) { return toArray(b.invInertiaWorld); },
             "World-frame inverse inertia R I0^-1 R^T, a 3 x 3 ndarray, 1/(kg m^2).");
    readOnly(body, "inertia_world", [](const Body& b) { return toArray(b.inertiaWorld()); },
             "World-frame inertia R I0 R^T, a 3 x 3 ndarray, kg m^2.");
    readOnly(body, "kinetic_energy", [](const Body& b) { return b.kineticEnergy(); },
             "Translational plus rotational kinetic energy, J.");
    readOnly(body, "linear_momentum", [](const Body& b) { return toArray(b.linearMomentum()); },
             "m v, N s.");
    readOnly(body, "angular_momentum", [](const Body& b) { return toArray(b.angularMomentum()); },
             "I w about the centre of mass, N m s.");
    readOnly(body, "asleep", [](const Body& b) { return b.asleep; },
             "True while the body sleeps at rest.");
    const auto faceDown = [](const Body& b) {
        return faceName(faceAlong(b.orientation, Vec3(0.0, -1.0, 0.0)));
    };
    readOnly(body, "face_down", faceDown,
             "The face pointing most nearly down: \"+x\", \"-x\", \"+y\", \"-y\", \"+z\" or "
             "\"-z\".");
    body.def_property_readonly(
        "potential_energy",
        [](const BodyHandle& h) {
            return h.body().potentialEnergy(h.state().world.settings().gravity);
        },
        "-m g . x, J (zero at the origin).");
    body.def_property_readonly(
        "energy", [](const BodyHandle& h) { return h.state().world.energyOf(h.body()); },
        "Kinetic plus potential energy, J.");
}

} // namespace

void bindBody(py::module_& module)
{
    py::class_<BodyHandle> body(module, "Body", R"doc(
Handle of a body in a tumble.World (from World.add_body or World.bodies). Reading or writing a
property of a removed body raises tumble.StaleBodyError. Vectors are NumPy arrays in world axes;
setting a property goes through the world, which keeps the derived quantities consistent.
)doc");
    body.def_property_readonly("name", &BodyHandle::name, "The body's name.");
    body.def_property_readonly("index", &BodyHandle::serial,
                               "Creation order in its world: the `body` column of World.run.");
    body.def_property_readonly("alive", &BodyHandle::alive,
                               "False once the body was removed from its world.");
    body.def_property_readonly(
        "world", [](const BodyHandle& h) { return h.sharedState(); }, "The tumble.World it is in.");
    body.def("__repr__", &describe);
    body.def("__eq__", [](const BodyHandle& a, const BodyHandle& b) {
        return &a.state() == &b.state() && a.serial() == b.serial();
    });
    body.def("__hash__", [](const BodyHandle& h) {
        return std::hash<const void*>()(&h.state()) ^ std::hash<std::size_t>()(h.serial());
    });
    bindWritableState(body);
    bindDerivedState(body);
}

} // namespace tumble::python
