#ifndef EDYN_MATH_MATH_HPP
#define EDYN_MATH_MATH_HPP

#include "edyn/math/scalar.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

constexpr scalar to_radians(scalar degrees) noexcept { return degrees * pi / scalar(180); }

constexpr scalar to_degrees(scalar radians) noexcept { return radians * scalar(180) / pi; }

// Converts a torque stiffness given per degree to the engine's unit, Nm per radian.
constexpr scalar to_Nm_per_radian(scalar Nm_per_degree) noexcept { return Nm_per_degree * scalar(180) / pi; }

template<typename T>
constexpr T lerp(const T &a, const T &b, scalar s) noexcept {
    return a * (scalar(1) - s) + b * s;
}

template<typename T>
constexpr T square(T x) noexcept {
    return x * x;
}

// Wraps an angle into [-pi, pi).
inline scalar normalize_angle(scalar angle) noexcept {
    angle = std::fmod(angle + pi, pi2);
    if (angle < 0) angle += pi2;
    return angle - pi;
}

} // namespace edyn

#endif // EDYN_MATH_MATH_HPP
