// A throw of several dice as TOML text: the world, the ground, the planes, the static bodies as
// the file gives them and the dice in their drawn states, so `tumble run` and `tumble view` show
// the throw and a die comes to rest on the same face at the same time.
#include "tumble/scenario/throw_dice.hpp"

#include "toml_text.hpp"

#include <sstream>

namespace tumble::scenario {

namespace {

using detail::exact;
using detail::tomlString;

void writeMaterial(std::ostream& out, const Material& material)
{
    out << "elasticity = " << exact(material.restitution) << '\n'
        << "friction = " << exact(material.friction) << '\n';
    if (material.staticFriction) {
        out << "static_friction = " << exact(*material.staticFriction) << '\n';
    }
}

void writeStaticGeometry(std::ostream& out, const Scenario& scenario)
{
    if (scenario.ground) {
        out << "\n[ground]\nheight = " << exact(scenario.ground->height) << '\n';
        if (scenario.groundMaterial) {
            writeMaterial(out, *scenario.groundMaterial);
        }
    }
    for (const StaticPlane& plane : scenario.planes) {
        out << "\n[[plane]]\npoint = " << exact(plane.point) << "\nnormal = "
            << exact(plane.normal) << '\n';
        if (plane.material) {
            writeMaterial(out, *plane.material);
        }
    }
}

void writeStaticBody(std::ostream& out, const BodySpec& body)
{
    const BodyDef& def = body.def;
    out << "\n[[body]]\nname = " << tomlString(body.name) << "\nmotion = \"static\"\n"
        << "size = " << exact(def.shape.size) << "\nposition = " << exact(def.position)
        << "\norientation = " << exact(def.orientation) << '\n';
    if (def.materialGiven) {
        writeMaterial(out, def.material);
    }
}

void writeDie(std::ostream& out, const BodySpec& body, const ThrowState& state)
{
    const BodyDef& def = body.def;
    // the orientation as drawn: the loader normalises it exactly as the throw did
    out << "\n[[body]]\nname = " << tomlString(body.name) << '\n'
        << "size = " << exact(def.shape.size) << "\nmass = " << exact(def.mass)
        << "\nposition = " << exact(state.position)
        << "\norientation = " << exact(state.orientation)
        << "\nvelocity = " << exact(state.velocity)
        << "\nangular_velocity = " << exact(state.angularVelocity) << '\n';
    writeMaterial(out, def.material);
}

} // namespace

std::string diceScenarioToml(const Scenario& scenario, std::span<const ThrowState> states,
                             const std::string& comment)
{
    std::ostringstream out;
    detail::writeCommentToml(out, comment);
    detail::writeWorldToml(out, scenario, scenario.throwSpec->maxTime);
    writeStaticGeometry(out, scenario);
    std::size_t die = 0;
    for (const BodySpec& body : scenario.bodies) {
        if (body.def.motion == BodyMotion::Static) {
            writeStaticBody(out, body);
        } else {
            writeDie(out, body, states[die++]);
        }
    }
    return out.str();
}

} // namespace tumble::scenario
