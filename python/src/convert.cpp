// Conversions between glm values and NumPy arrays, with the checks the engine leaves to callers.
#include "convert.hpp"

#include <cmath>
#include <sstream>

namespace tumble::python {
namespace {

std::string printed(double value)
{
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
}

} // namespace

Vec3 finiteVec3(const Triple& value, const std::string& what)
{
    const Vec3 vector(value[0], value[1], value[2]);
    if (!isFinite(vector)) {
        throw py::value_error(what + " must be three finite numbers");
    }
    return vector;
}

Quat unitQuat(const Quadruple& value, const std::string& what)
{
    const Quat q(value[0], value[1], value[2], value[3]);
    const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!isFinite(q) || !(norm > 0.0) || !std::isfinite(norm)) {
        throw py::value_error(what + " must be four finite numbers (w, x, y, z), not all zero");
    }
    return Quat(q.w / norm, q.x / norm, q.y / norm, q.z / norm);
}

py::array_t<double> toArray(const Vec3& value)
{
    py::array_t<double> out(3);
    auto view = out.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < 3; ++i) {
        view(i) = value[static_cast<glm::length_t>(i)];
    }
    return out;
}

py::array_t<double> toArray(const Quat& value)
{
    py::array_t<double> out(4);
    auto view = out.mutable_unchecked<1>();
    view(0) = value.w;
    view(1) = value.x;
    view(2) = value.y;
    view(3) = value.z;
    return out;
}

py::array_t<double> toArray(const Mat3& value)
{
    py::array_t<double> out({3, 3});
    auto view = out.mutable_unchecked<2>();
    for (py::ssize_t row = 0; row < 3; ++row) {
        for (py::ssize_t column = 0; column < 3; ++column) {
            view(row, column) =
                value[static_cast<glm::length_t>(column)][static_cast<glm::length_t>(row)];
        }
    }
    return out;
}

void requirePositive(double value, const std::string& what, bool zeroAllowed)
{
    const bool inRange = zeroAllowed ? value >= 0.0 : value > 0.0;
    if (!std::isfinite(value) || !inRange) {
        throw py::value_error(what + " must be finite and " + (zeroAllowed ? ">= 0" : "> 0") +
                              ", got " + printed(value));
    }
}

} // namespace tumble::python
