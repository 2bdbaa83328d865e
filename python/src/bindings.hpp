// The parts of the _tumble extension module, each adding its classes and functions to it.
#pragma once

#include "world_state.hpp"

#include <pybind11/pybind11.h>

#include <memory>

namespace tumble::python {

namespace py = pybind11;

using WorldClass = py::class_<WorldState, std::shared_ptr<WorldState>>;

/// tumble.World: construction, ground, planes, bodies, impulses (world_bindings.cpp).
WorldClass bindWorld(py::module_& module);
/// World.step, World.run and World.collisions (world_run.cpp).
void bindWorldRun(WorldClass& world);
/// tumble.Body, the handle add_body returns (body_bindings.cpp).
void bindBody(py::module_& module);
/// tumble.Collision, the records of World.collisions (collision_bindings.cpp).
void bindCollision(py::module_& module);
/// tumble.load_scenario and tumble.Scenario (scenario_bindings.cpp).
void bindScenario(py::module_& module);
/// tumble._throw_outcomes and the dice statistics behind tumble.throw (throw_bindings.cpp).
void bindThrow(py::module_& module);
/// tumble._validation_rows behind tumble.validate (validation_bindings.cpp).
void bindValidation(py::module_& module);

} // namespace tumble::python
