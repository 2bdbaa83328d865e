// tumble.World: a World built from Python, its ground, planes, bodies and impulses.
#include "bindings.hpp"
#include "convert.hpp"

#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>

namespace tumble::python {
namespace {

template <typename Enum, std::size_t N>
Enum choose(const std::string& value, const std::array<std::pair<const char*, Enum>, N>& names,
            const char* what)
{
    std::string allowed;
    for (const auto& [name, choice] : names) {
        if (value == name) {
            return choice;
        }
        allowed += (allowed.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    }
    throw py::value_error(std::string(what) + " must be one of " + allowed + ", got \"" + value +
                          "\"");
}

/// The material of a ground or plane: none when neither coefficient is given (its contacts then
/// take the body's, as in the handouts).
std::optional<Material> surfaceMaterial(std::optional<double> elasticity,
                                        std::optional<double> friction)
{
    if (!elasticity && !friction) {
        return std::nullopt;
    }
    Material material;
    material.restitution = elasticity.value_or(material.restitution);
    material.friction = friction.value_or(material.friction);
    requirePositive(material.friction, "friction", true);
    if (!(material.restitution >= 0.0 && material.restitution <= 1.0)) {
        throw py::value_error("elasticity must be in [0, 1]");
    }
    return material;
}

std::shared_ptr<WorldState> makeWorld(const Triple& gravity, const std::string& integrator,
                                      const std::string& response, int threads, bool allowSleep,
                                      const std::string& solver)
{
    WorldSettings settings;
    settings.gravity = finiteVec3(gravity, "gravity");
    settings.integrator = choose(integrator,
                                 std::array{std::pair{"exact", Integrator::Exact},
                                            std::pair{"handout", Integrator::Handout}},
                                 "integrator");
    settings.response = choose(response,
                               std::array{std::pair{"sequential", ContactResponse::Sequential},
                                          std::pair{"average", ContactResponse::Average}},
                               "response");
    if (threads < 0) {
        throw py::value_error("threads must be >= 0 (0: one per core)");
    }
    settings.threads = threads;
    settings.allowSleep = allowSleep;
    settings.solver = choose(solver,
                             std::array{std::pair{"exact", ContactSolver::Exact},
                                        std::pair{"soft", ContactSolver::Soft}},
                             "solver");
    return std::make_shared<WorldState>(WorldState{World(settings), {}, {}, false});
}

/// What add_body takes, as Python gives it.
struct BodyArguments {
    Triple size;
    double mass;
    Triple position;
    Quadruple orientation;
    Triple velocity;
    Triple angularVelocity;
    std::optional<double> elasticity;
    std::optional<double> friction;
    std::optional<double> staticFriction;
    std::string motion;
};

BodyDef bodyDef(const BodyArguments& given)
{
    BodyDef def;
    def.motion = choose(given.motion,
                        std::array{std::pair{"dynamic", BodyMotion::Dynamic},
                                   std::pair{"static", BodyMotion::Static}},
                        "motion");
    def.shape.size = finiteVec3(given.size, "size");
    for (int axis = 0; axis < 3; ++axis) {
        requirePositive(def.shape.size[axis], "size");
    }
    def.mass = given.mass;
    requirePositive(def.mass, "mass");
    def.position = finiteVec3(given.position, "position");
    def.orientation = unitQuat(given.orientation, "orientation");
    def.linearVelocity = finiteVec3(given.velocity, "velocity");
    def.angularVelocity = finiteVec3(given.angularVelocity, "angular_velocity");
    if (def.motion == BodyMotion::Static &&
        (lengthSquared(def.linearVelocity) > 0.0 || lengthSquared(def.angularVelocity) > 0.0)) {
        throw py::value_error("a static body does not move: give it no velocity");
    }
    // a static body that gives no material lends its contacts the dynamic body's (11.7)
    def.materialGiven = def.motion == BodyMotion::Dynamic || given.elasticity || given.friction;
    def.material = surfaceMaterial(given.elasticity.value_or(def.material.restitution),
                                   given.friction.value_or(def.material.friction))
                       .value();
    if (given.staticFriction) {
        if (!(*given.staticFriction >= def.material.friction) ||
            !std::isfinite(*given.staticFriction)) {
            throw py::value_error("static_friction must be finite and >= friction");
        }
        def.material.staticFriction = given.staticFriction;
    }
    return def;
}

BodyHandle addBody(const std::shared_ptr<WorldState>& state, const Triple& size, double mass,
                   const Triple& position, const Quadruple& orientation, const Triple& velocity,
                   const Triple& angularVelocity, std::optional<double> elasticity,
                   std::optional<double> friction, std::optional<double> staticFriction,
                   const std::string& motion, std::optional<std::string> name)
{
    const BodyDef def = bodyDef({size, mass, position, orientation, velocity, angularVelocity,
                                 elasticity, friction, staticFriction, motion});
    World& world = state->checked();
    std::string bodyName = name.value_or("body" + std::to_string(state->ids.size() + 1));
    return BodyHandle(state, state->adopt(world.createBody(def), std::move(bodyName)));
}

/// add_ground, add_plane, add_body, remove_body, apply_impulse and bodies.
void bindWorldContents(WorldClass& world)
{
    world.def(
        "add_ground",
        [](WorldState& s, double height, std::optional<double> elasticity,
           std::optional<double> friction) {
            if (!std::isfinite(height)) {
                throw py::value_error("height must be finite");
            }
            s.checked().setGround(Plane{height});
            s.world.setGroundMaterial(surfaceMaterial(elasticity, friction));
        },
        py::arg("height") = 0.0, py::arg("elasticity") = py::none(),
        py::arg("friction") = py::none(), R"doc(
Sets the ground: the plane y = height with normal +y. Without elasticity and friction its
contacts take each body's own (as in the handouts).
)doc");
    world.def(
        "add_plane",
        [](WorldState& s, const Triple& point, const Triple& normal,
           std::optional<double> elasticity, std::optional<double> friction) {
            StaticPlane plane;
            plane.point = finiteVec3(point, "point");
            const Vec3 n = finiteVec3(normal, "normal");
            if (!(glm::length(n) > 0.0)) {
                throw py::value_error("normal must not be zero");
            }
            plane.normal = glm::normalize(n);
            plane.material = surfaceMaterial(elasticity, friction);
            return s.checked().addPlane(plane);
        },
        py::arg("point"), py::arg("normal"), py::arg("elasticity") = py::none(),
        py::arg("friction") = py::none(), R"doc(
Adds a static half-space: the points x with normal . (x - point) <= 0 are inside it. The normal
is normalised. Returns the plane's index.
)doc");
    world.def("add_body", &addBody, py::kw_only(), py::arg("size") = Triple{2.0, 2.0, 2.0},
              py::arg("mass") = 1.0, py::arg("position") = Triple{0.0, 0.0, 0.0},
              py::arg("orientation") = Quadruple{1.0, 0.0, 0.0, 0.0},
              py::arg("velocity") = Triple{0.0, 0.0, 0.0},
              py::arg("angular_velocity") = Triple{0.0, 0.0, 0.0},
              py::arg("elasticity") = py::none(), py::arg("friction") = py::none(),
              py::arg("static_friction") = py::none(), py::arg("motion") = "dynamic",
              py::arg("name") = py::none(), R"doc(
Adds a solid cuboid and returns its handle. size: full extents (width, height, depth), m.
mass: kg. position: centre of mass, m. orientation: quaternion (w, x, y, z), normalised.
velocity (m/s) and angular_velocity (rad/s): world frame. elasticity: coefficient of restitution
in [0, 1] (default 0.6). friction: Coulomb coefficient (default 0.5; static_friction >=
friction, default equal).
motion: "dynamic" or "static" (fixed geometry: a wall, a tray; a static body given no
elasticity or friction lends its contacts the dynamic body's). name: default "body<k>".
)doc");
    world.def(
        "remove_body",
        [](WorldState& s, const BodyHandle& body) { s.world.destroyBody(body.id()); },
        py::arg("body"), "Removes a body; its handles are stale afterwards.");
    world.def(
        "apply_impulse",
        [](WorldState& s, const BodyHandle& body, const Triple& impulse, const Triple& offset) {
            const BodyId id = body.dynamicId("an impulse");
            const Vec3 point = s.world.body(id).position + finiteVec3(offset, "offset");
            s.world.applyImpulse(id, finiteVec3(impulse, "impulse"), point);
        },
        py::arg("body"), py::arg("impulse"), py::arg("offset") = Triple{0.0, 0.0, 0.0}, R"doc(
Applies an impulse (N s) at offset (the point minus the centre of mass, world axes, m):
dv = J / m, dw = I^-1 (offset x J). Wakes the body.
)doc");
    world.def_property_readonly(
        "bodies",
        [](const std::shared_ptr<WorldState>& s) {
            py::list bodies;
            for (std::size_t i = 0; i < s->ids.size(); ++i) {
                if (s->checked().isValid(s->ids[i])) {
                    bodies.append(BodyHandle(s, i));
                }
            }
            return bodies;
        },
        "Handles of the live bodies, in creation order.");
}

} // namespace

WorldClass bindWorld(py::module_& module)
{
    WorldClass world(module, "World", R"doc(
A world of rigid cuboids over an optional ground plane, stepped with a fixed time step.

    world = tumble.World(gravity=(0, -9.81, 0))
    world.add_ground(height=0.0)
    rb = world.add_body(size=(2, 6, 2), mass=2.0, position=(0, 5, 0))
    traj = world.run(duration=10.0, dt=1/240)

Units are SI (m, kg, s, rad); y is up. Bodies are reached through the handles add_body returns
(tumble.Body); a handle whose body was removed raises tumble.StaleBodyError.
)doc");
    world.def(py::init(&makeWorld), py::arg("gravity") = Triple{0.0, -9.81, 0.0},
              py::arg("integrator") = "exact", py::arg("response") = "sequential",
              py::arg("threads") = 1, py::arg("allow_sleep") = true,
              py::arg("solver") = "exact", R"doc(
gravity: acceleration, m/s^2.
integrator: "exact" (angular momentum conserved exactly) or "handout" (R += dt [w]x R).
response: "sequential" (impulses per contact point) or "average" (the handouts' single impulse).
threads: threads a step spreads the bodies over (0: one per core); results do not depend on it.
allow_sleep: whether a body at rest is put to sleep (velocities zeroed until woken).
solver: how bodies that touch each other are solved: "exact" (impacts in time order, contacts
    to a tolerance) or "soft" (the fixed-cost soft step of Box2D v3 and Box3D,
    docs/physics/12-soft-step.md); a body alone with the ground takes the exact path either way.
)doc");
    world.def_property(
        "gravity", [](WorldState& s) { return toArray(s.checked().settings().gravity); },
        [](WorldState& s, const Triple& g) { s.checked().setGravity(finiteVec3(g, "gravity")); },
        "Gravitational acceleration, m/s^2 (an ndarray of 3).");
    world.def_property_readonly(
        "time", [](WorldState& s) { return s.checked().time(); },
        "Simulated time, s: the sum of every step's dt.");
    bindWorldContents(world);
    return world;
}

} // namespace tumble::python
