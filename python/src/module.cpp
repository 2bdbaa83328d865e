// The _tumble extension module: tumble's engine, scenario layer, throws and validation for
// Python (issue 18, docs/python.md). The package tumble (python/tumble) re-exports it.
#include "bindings.hpp"
#include "trajectory.hpp"

#include "tumble/scenario/scenario.hpp"

#include <pybind11/pybind11.h>

namespace py = pybind11;

PYBIND11_MODULE(_tumble, module)
{
    module.doc() = "tumble: rigid cuboids falling, bouncing and sliding (the C++ extension; "
                   "import tumble instead)";
    module.attr("__version__") = TUMBLE_VERSION;

    // a bad scenario reads as the CLI's one-line message "FILE:LINE: KEY: problem"
    py::register_exception<tumble::scenario::ScenarioError>(module, "ScenarioError",
                                                            PyExc_ValueError);
    py::register_exception<tumble::python::StaleBodyError>(module, "StaleBodyError",
                                                           PyExc_LookupError);
    py::register_exception<tumble::python::WorldBusyError>(module, "WorldBusyError",
                                                           PyExc_RuntimeError);
    tumble::python::registerTrajectoryDtype();

    tumble::python::bindBody(module);
    tumble::python::bindCollision(module);
    tumble::python::WorldClass world = tumble::python::bindWorld(module);
    tumble::python::bindWorldRun(world);
    tumble::python::bindScenario(module);
    tumble::python::bindThrow(module);
    tumble::python::bindValidation(module);
}
