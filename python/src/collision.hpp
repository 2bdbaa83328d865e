// Collision: one impact of the last step as tumble.World.collisions reports it, with body
// handles in place of ids.
#pragma once

#include "world_state.hpp"

#include "tumble/contact.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>

namespace tumble::python {

namespace py = pybind11;

struct Collision {
    double time = 0.0;
    BodyHandle body;
    /// The other body of a contact between two bodies; none for the ground or a plane.
    std::optional<BodyHandle> other;
    /// The plane's index (World.add_plane) when the other side is a plane; none otherwise.
    std::optional<int> plane;
    py::array normal;
    /// The touching points, an n x 3 array.
    py::array points;
    py::array average;
    double approachSpeed = 0.0;
    py::array normalImpulse;
    py::array frictionImpulse;
    bool restitutionApplied = false;
    double kineticEnergyBefore = 0.0;
    double kineticEnergyAfter = 0.0;
};

/// The record of `event`, whose ids are bodies of `state`.
Collision makeCollision(const std::shared_ptr<WorldState>& state, const CollisionEvent& event);

} // namespace tumble::python
