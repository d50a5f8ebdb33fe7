#ifndef EDYN_MATH_VECTOR2_HPP
#define EDYN_MATH_VECTOR2_HPP

#include "edyn/config/assert.hpp"
#include "edyn/math/scalar.hpp"
#include <cmath>

namespace edyn {

/// A 2D vector (polygon clipping, a plane's coordinates). An aggregate: `vector2{x, y}`; its
/// members are uninitialised when default-constructed.
struct vector2 {
    scalar x, y;

    /// @var x
    /// First coordinate.
    /// @var y
    /// Second coordinate.

    /// Component by index.
    /// @param i 0 (`x`) or 1 (`y`); checked by `EDYN_ASSERT`.
    /// @return A reference to the component.
    constexpr scalar &operator[](int i) noexcept {
        EDYN_ASSERT(i >= 0 && i < 2);
        return i == 0 ? x : y;
    }
    /// Component by index.
    /// @param i 0 (`x`) or 1 (`y`); checked by `EDYN_ASSERT`.
    /// @return The component's value.
    constexpr scalar operator[](int i) const noexcept {
        EDYN_ASSERT(i >= 0 && i < 2);
        return i == 0 ? x : y;
    }
    /// Exact component-wise equality (no tolerance).
    /// @return True when both components are equal.
    constexpr bool operator==(const vector2 &) const noexcept = default;
};

/// The zero vector (0, 0).
inline constexpr vector2 vector2_zero{0, 0};
/// The vector (1, 1).
inline constexpr vector2 vector2_one{1, 1};
/// The unit vector along x, (1, 0).
inline constexpr vector2 vector2_x{1, 0};
/// The unit vector along y, (0, 1).
inline constexpr vector2 vector2_y{0, 1};

/// Component-wise sum.
/// @return `a + b`.
constexpr vector2 operator+(const vector2 &a, const vector2 &b) noexcept { return {a.x + b.x, a.y + b.y}; }
/// Component-wise difference.
/// @return `a - b`.
constexpr vector2 operator-(const vector2 &a, const vector2 &b) noexcept { return {a.x - b.x, a.y - b.y}; }
/// Negation.
/// @return `-v`.
constexpr vector2 operator-(const vector2 &v) noexcept { return {-v.x, -v.y}; }
/// Scales a vector.
/// @return `v` with each component multiplied by `s`.
constexpr vector2 operator*(const vector2 &v, scalar s) noexcept { return {v.x * s, v.y * s}; }
/// Scales a vector.
/// @return `v` with each component multiplied by `s`.
constexpr vector2 operator*(scalar s, const vector2 &v) noexcept { return v * s; }
/// Divides each component by a scalar (no check for zero).
/// @return `v` with each component divided by `s`.
constexpr vector2 operator/(const vector2 &v, scalar s) noexcept { return {v.x / s, v.y / s}; }
/// Adds `b` to `a` in place.
/// @return `a`.
constexpr vector2 &operator+=(vector2 &a, const vector2 &b) noexcept { return a = a + b; }
/// Subtracts `b` from `a` in place.
/// @return `a`.
constexpr vector2 &operator-=(vector2 &a, const vector2 &b) noexcept { return a = a - b; }
/// Scales `v` in place.
/// @return `v`.
constexpr vector2 &operator*=(vector2 &v, scalar s) noexcept { return v = v * s; }

/// Dot product.
/// @return `a.x * b.x + a.y * b.y`.
constexpr scalar dot(const vector2 &a, const vector2 &b) noexcept { return a.x * b.x + a.y * b.y; }
/// z component of the 3D cross product of (a, 0) and (b, 0): positive when `b` lies
/// counter-clockwise of `a`.
/// @return `a.x * b.y - a.y * b.x`.
constexpr scalar perp_product(const vector2 &a, const vector2 &b) noexcept { return a.x * b.y - a.y * b.x; }
/// `v` rotated by 90 degrees counter-clockwise.
/// @return (-v.y, v.x).
constexpr vector2 orthogonal(const vector2 &v) noexcept { return {-v.y, v.x}; }
/// Squared length, cheaper than `length` for comparisons.
/// @return `dot(v, v)`.
constexpr scalar length_sqr(const vector2 &v) noexcept { return dot(v, v); }
/// Euclidean length.
/// @return The length of `v`.
inline scalar length(const vector2 &v) noexcept { return std::sqrt(length_sqr(v)); }
/// Distance between two points.
/// @return The length of `a - b`.
inline scalar distance(const vector2 &a, const vector2 &b) noexcept { return length(a - b); }
/// Squared distance between two points.
/// @return The squared length of `a - b`.
inline scalar distance_sqr(const vector2 &a, const vector2 &b) noexcept { return length_sqr(a - b); }

/// The unit vector along `v`. Unchecked: a zero vector gives NaN components.
/// @param v A vector that is not the zero vector (precondition).
/// @return `v / length(v)`.
inline vector2 normalize(const vector2 &v) noexcept { return v / length(v); }

} // namespace edyn

#endif // EDYN_MATH_VECTOR2_HPP
