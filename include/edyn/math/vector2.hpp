#ifndef EDYN_MATH_VECTOR2_HPP
#define EDYN_MATH_VECTOR2_HPP

#include "edyn/math/scalar.hpp"
#include <cmath>

namespace edyn {

struct vector2 {
    scalar x, y;

    constexpr scalar &operator[](int i) noexcept { return i == 0 ? x : y; }
    constexpr scalar operator[](int i) const noexcept { return i == 0 ? x : y; }
    constexpr bool operator==(const vector2 &) const noexcept = default;
};

inline constexpr vector2 vector2_zero{0, 0};
inline constexpr vector2 vector2_one{1, 1};
inline constexpr vector2 vector2_x{1, 0};
inline constexpr vector2 vector2_y{0, 1};

constexpr vector2 operator+(const vector2 &a, const vector2 &b) noexcept { return {a.x + b.x, a.y + b.y}; }
constexpr vector2 operator-(const vector2 &a, const vector2 &b) noexcept { return {a.x - b.x, a.y - b.y}; }
constexpr vector2 operator-(const vector2 &v) noexcept { return {-v.x, -v.y}; }
constexpr vector2 operator*(const vector2 &v, scalar s) noexcept { return {v.x * s, v.y * s}; }
constexpr vector2 operator*(scalar s, const vector2 &v) noexcept { return v * s; }
constexpr vector2 operator/(const vector2 &v, scalar s) noexcept { return {v.x / s, v.y / s}; }
constexpr vector2 &operator+=(vector2 &a, const vector2 &b) noexcept { return a = a + b; }
constexpr vector2 &operator-=(vector2 &a, const vector2 &b) noexcept { return a = a - b; }
constexpr vector2 &operator*=(vector2 &v, scalar s) noexcept { return v = v * s; }

constexpr scalar dot(const vector2 &a, const vector2 &b) noexcept { return a.x * b.x + a.y * b.y; }
// z component of the 3D cross product of (a, 0) and (b, 0).
constexpr scalar perp_product(const vector2 &a, const vector2 &b) noexcept { return a.x * b.y - a.y * b.x; }
// a rotated by 90 degrees counter-clockwise.
constexpr vector2 orthogonal(const vector2 &v) noexcept { return {-v.y, v.x}; }
constexpr scalar length_sqr(const vector2 &v) noexcept { return dot(v, v); }
inline scalar length(const vector2 &v) noexcept { return std::sqrt(length_sqr(v)); }
inline scalar distance(const vector2 &a, const vector2 &b) noexcept { return length(a - b); }
inline scalar distance_sqr(const vector2 &a, const vector2 &b) noexcept { return length_sqr(a - b); }

// Precondition: v is not the zero vector.
inline vector2 normalize(const vector2 &v) noexcept { return v / length(v); }

} // namespace edyn

#endif // EDYN_MATH_VECTOR2_HPP
