// Conversions between glm values and what Python sees: three-number sequences in, NumPy arrays
// out (copies, so an array a user keeps never aliases the engine's state).
#pragma once

#include "tumble/math.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
// every file that takes a Triple sees the same (STL) caster for it
#include <pybind11/stl.h>

#include <array>
#include <string>

namespace tumble::python {

namespace py = pybind11;

/// Three numbers as pybind11 accepts them from any sequence (tuple, list, ndarray).
using Triple = std::array<double, 3>;
/// Four numbers (a quaternion, w first).
using Quadruple = std::array<double, 4>;

/// The vector, after checking that every component is finite (ValueError naming `what`).
Vec3 finiteVec3(const Triple& value, const std::string& what);
/// The unit quaternion (w, x, y, z) / |q|; ValueError when it is not finite or is zero.
Quat unitQuat(const Quadruple& value, const std::string& what);

py::array_t<double> toArray(const Vec3& value);
/// (w, x, y, z).
py::array_t<double> toArray(const Quat& value);
/// A 3 x 3 array indexed [row, column] (glm stores [column][row]).
py::array_t<double> toArray(const Mat3& value);

/// ValueError unless `value` is finite and > 0 (or >= 0 when `zeroAllowed`).
void requirePositive(double value, const std::string& what, bool zeroAllowed = false);

} // namespace tumble::python
