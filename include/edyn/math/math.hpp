#ifndef EDYN_MATH_MATH_HPP
#define EDYN_MATH_MATH_HPP

#include "edyn/math/scalar.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

/// Converts an angle from degrees to radians, the unit of every angle in edyn.
/// @param degrees Angle in degrees.
/// @return The same angle in radians.
constexpr scalar to_radians(scalar degrees) noexcept { return degrees * pi / scalar(180); }

/// Converts an angle from radians to degrees, for example for display.
/// @param radians Angle in radians.
/// @return The same angle in degrees.
constexpr scalar to_degrees(scalar radians) noexcept { return radians * scalar(180) / pi; }

/// Converts a torque stiffness given per degree to the engine's unit, N·m per radian (for
/// example for `hinge_constraint::stiffness`).
/// @param Nm_per_degree Stiffness in N·m per degree.
/// @return The same stiffness in N·m per radian.
constexpr scalar to_Nm_per_radian(scalar Nm_per_degree) noexcept { return Nm_per_degree * scalar(180) / pi; }

/// Linear interpolation between `a` and `b`: `a` at s = 0, `b` at s = 1, extrapolated beyond.
/// Works for scalars, vectors and any type with `+` and multiplication by a scalar (for
/// orientations see `slerp`).
/// @param a Value at s = 0.
/// @param b Value at s = 1.
/// @param s Interpolation parameter.
/// @return `a * (1 - s) + b * s`.
template<typename T>
constexpr T lerp(const T &a, const T &b, scalar s) noexcept {
    return a * (scalar(1) - s) + b * s;
}

/// The square of a value.
/// @param x Any value with `*`.
/// @return `x * x`.
template<typename T>
constexpr T square(T x) noexcept {
    return x * x;
}

/// Wraps an angle into [-pi, pi).
/// @param angle Angle in radians, finite.
/// @return The angle plus or minus a whole number of turns, in [-pi, pi).
inline scalar normalize_angle(scalar angle) noexcept {
    angle = std::fmod(angle + pi, pi2);
    if (angle < 0) angle += pi2;
    return angle - pi;
}

} // namespace edyn

#endif // EDYN_MATH_MATH_HPP
