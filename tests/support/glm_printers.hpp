// Readable GoogleTest output for tumble's glm types, and tolerance checks that print both values.
#pragma once

#include "tumble/math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>

namespace glm {

inline void PrintTo(const tumble::Vec3& v, std::ostream* os)
{
    *os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
}

inline void PrintTo(const tumble::Quat& q, std::ostream* os)
{
    *os << "quat(w=" << q.w << ", " << q.x << ", " << q.y << ", " << q.z << ")";
}

inline void PrintTo(const tumble::Mat3& m, std::ostream* os)
{
    // Printed by rows; glm stores columns, m[column][row].
    *os << "[";
    for (int row = 0; row < 3; ++row) {
        *os << (row ? ", [" : "[") << m[0][row] << ", " << m[1][row] << ", " << m[2][row] << "]";
    }
    *os << "]";
}

} // namespace glm

namespace tumble::testing {

/// Largest absolute component difference.
inline Real maxDifference(const Vec3& a, const Vec3& b)
{
    const Vec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

inline Real maxDifference(const Mat3& a, const Mat3& b)
{
    Real largest = 0.0;
    for (int column = 0; column < 3; ++column) {
        largest = std::max(largest, maxDifference(a[column], b[column]));
    }
    return largest;
}

/// Every component of `actual` within `tolerance` of `expected` (Vec3 or Mat3).
template <typename Value>
::testing::AssertionResult near(const Value& actual, const Value& expected, Real tolerance)
{
    if (maxDifference(actual, expected) <= tolerance) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << "actual " << ::testing::PrintToString(actual) << " expected "
           << ::testing::PrintToString(expected) << " tolerance " << tolerance;
}

/// Quaternions compare up to sign: q and -q are the same rotation.
inline ::testing::AssertionResult sameRotation(const Quat& actual, const Quat& expected,
                                                Real tolerance)
{
    if (1.0 - std::abs(glm::dot(actual, expected)) <= tolerance) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << "actual " << ::testing::PrintToString(actual) << " expected "
           << ::testing::PrintToString(expected);
}

} // namespace tumble::testing
