#ifndef EDYN_MATH_VECTOR3_HPP
#define EDYN_MATH_VECTOR3_HPP

#include "edyn/config/assert.hpp"
#include "edyn/math/scalar.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

/// A 3D vector: positions (m), velocities (m/s), forces (N), axes. An aggregate:
/// `vector3{x, y, z}`; its members are uninitialised when default-constructed.
struct vector3 {
    scalar x, y, z;

    /// @var x
    /// First coordinate.
    /// @var y
    /// Second coordinate (up in the examples, which use +Y up).
    /// @var z
    /// Third coordinate.

    /// Component by index.
    /// @param i 0 (`x`), 1 (`y`) or 2 (`z`); checked by `EDYN_ASSERT`.
    /// @return A reference to the component.
    constexpr scalar &operator[](int i) noexcept {
        EDYN_ASSERT(i >= 0 && i < 3);
        return i == 0 ? x : (i == 1 ? y : z);
    }
    /// Component by index.
    /// @param i 0 (`x`), 1 (`y`) or 2 (`z`); checked by `EDYN_ASSERT`.
    /// @return The component's value.
    constexpr scalar operator[](int i) const noexcept {
        EDYN_ASSERT(i >= 0 && i < 3);
        return i == 0 ? x : (i == 1 ? y : z);
    }
    /// Exact component-wise equality (no tolerance).
    /// @return True when all three components are equal.
    constexpr bool operator==(const vector3 &) const noexcept = default;
};

/// The zero vector (0, 0, 0).
inline constexpr vector3 vector3_zero{0, 0, 0};
/// The vector (1, 1, 1).
inline constexpr vector3 vector3_one{1, 1, 1};
/// The unit vector along x, (1, 0, 0).
inline constexpr vector3 vector3_x{1, 0, 0};
/// The unit vector along y, (0, 1, 0): up in the examples.
inline constexpr vector3 vector3_y{0, 1, 0};
/// The unit vector along z, (0, 0, 1).
inline constexpr vector3 vector3_z{0, 0, 1};
/// Every component `large_scalar`, for example the lower bound of an empty box.
inline constexpr vector3 vector3_max{large_scalar, large_scalar, large_scalar};

/// Component-wise sum.
/// @return `a + b`.
constexpr vector3 operator+(const vector3 &a, const vector3 &b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
/// Component-wise difference.
/// @return `a - b`.
constexpr vector3 operator-(const vector3 &a, const vector3 &b) noexcept {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
/// Negation.
/// @return `-v`.
constexpr vector3 operator-(const vector3 &v) noexcept { return {-v.x, -v.y, -v.z}; }
/// Component-wise product (not a dot or cross product; see `dot` and `cross`).
/// @return (a.x b.x, a.y b.y, a.z b.z).
constexpr vector3 operator*(const vector3 &a, const vector3 &b) noexcept {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
/// Scales a vector.
/// @return `v` with each component multiplied by `s`.
constexpr vector3 operator*(const vector3 &v, scalar s) noexcept { return {v.x * s, v.y * s, v.z * s}; }
/// Scales a vector.
/// @return `v` with each component multiplied by `s`.
constexpr vector3 operator*(scalar s, const vector3 &v) noexcept { return v * s; }
/// Divides each component by a scalar (no check for zero).
/// @return `v` with each component divided by `s`.
constexpr vector3 operator/(const vector3 &v, scalar s) noexcept { return {v.x / s, v.y / s, v.z / s}; }
/// Component-wise quotient (no check for zero components).
/// @return (a.x / b.x, a.y / b.y, a.z / b.z).
constexpr vector3 operator/(const vector3 &a, const vector3 &b) noexcept {
    return {a.x / b.x, a.y / b.y, a.z / b.z};
}
/// Adds `b` to `a` in place.
/// @return `a`.
constexpr vector3 &operator+=(vector3 &a, const vector3 &b) noexcept { return a = a + b; }
/// Subtracts `b` from `a` in place.
/// @return `a`.
constexpr vector3 &operator-=(vector3 &a, const vector3 &b) noexcept { return a = a - b; }
/// Multiplies `a` by `b` component-wise, in place.
/// @return `a`.
constexpr vector3 &operator*=(vector3 &a, const vector3 &b) noexcept { return a = a * b; }
/// Scales `v` in place.
/// @return `v`.
constexpr vector3 &operator*=(vector3 &v, scalar s) noexcept { return v = v * s; }
/// Divides `v` by a scalar in place (no check for zero).
/// @return `v`.
constexpr vector3 &operator/=(vector3 &v, scalar s) noexcept { return v = v / s; }

/// Dot product.
/// @return `a.x * b.x + a.y * b.y + a.z * b.z`.
constexpr scalar dot(const vector3 &a, const vector3 &b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// Cross product, right-handed: `cross(vector3_x, vector3_y) == vector3_z`.
/// @return `a` × `b`.
constexpr vector3 cross(const vector3 &a, const vector3 &b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// Squared length, cheaper than `length` for comparisons.
/// @return `dot(v, v)`.
constexpr scalar length_sqr(const vector3 &v) noexcept { return dot(v, v); }
/// Euclidean length, for example a speed in m/s from a velocity.
/// @param v Any vector.
/// @return The length of `v`, in the unit of its components.
inline scalar length(const vector3 &v) noexcept { return std::sqrt(length_sqr(v)); }
/// Distance between two points.
/// @return The length of `a - b`.
inline scalar distance(const vector3 &a, const vector3 &b) noexcept { return length(a - b); }
/// Squared distance between two points.
/// @return The squared length of `a - b`.
constexpr scalar distance_sqr(const vector3 &a, const vector3 &b) noexcept { return length_sqr(a - b); }

/// The unit vector along `v`.
/// @param v A vector longer than `epsilon` (precondition, checked by `EDYN_ASSERT` only; see
/// `try_normalize` for a checked version).
/// @return `v / length(v)`.
inline vector3 normalize(const vector3 &v) noexcept {
    auto len = length(v);
    EDYN_ASSERT(len > epsilon, "normalize of a zero vector");
    return v / len;
}

/// Normalizes `v` in place when its length exceeds `epsilon`; leaves it unchanged otherwise
/// (NaN components included).
/// @param v The vector to normalize.
/// @return Whether it did.
inline bool try_normalize(vector3 &v) noexcept {
    auto len_sqr = length_sqr(v);
    if (!(len_sqr > epsilon * epsilon)) return false;
    v /= std::sqrt(len_sqr);
    return true;
}

/// Component-wise minimum.
/// @return (min(a.x, b.x), min(a.y, b.y), min(a.z, b.z)).
constexpr vector3 min(const vector3 &a, const vector3 &b) noexcept {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
/// Component-wise maximum.
/// @return (max(a.x, b.x), max(a.y, b.y), max(a.z, b.z)).
constexpr vector3 max(const vector3 &a, const vector3 &b) noexcept {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
/// Component-wise absolute value.
/// @return (|v.x|, |v.y|, |v.z|).
inline vector3 abs(const vector3 &v) noexcept { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

/// The largest component.
/// @return max(v.x, v.y, v.z).
constexpr scalar max_component(const vector3 &v) noexcept { return std::max(v.x, std::max(v.y, v.z)); }
/// The smallest component.
/// @return min(v.x, v.y, v.z).
constexpr scalar min_component(const vector3 &v) noexcept { return std::min(v.x, std::min(v.y, v.z)); }
/// Index of the largest component; the first one wins ties.
/// @return 0, 1 or 2.
constexpr int max_index(const vector3 &v) noexcept {
    return v.x >= v.y ? (v.x >= v.z ? 0 : 2) : (v.y >= v.z ? 1 : 2);
}
/// Index of the smallest component; the first one wins ties.
/// @return 0, 1 or 2.
constexpr int min_index(const vector3 &v) noexcept {
    return v.x <= v.y ? (v.x <= v.z ? 0 : 2) : (v.y <= v.z ? 1 : 2);
}

/// Whether every component is finite (neither infinite nor NaN), for validating input.
/// @return True when all three components are finite.
inline bool isfinite(const vector3 &v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Component of `v` orthogonal to the unit vector `n`: its projection on the plane through the
/// origin with normal `n`.
/// @param v Any vector.
/// @param n Unit normal (not checked).
/// @return `v - n * dot(v, n)`.
constexpr vector3 project_plane(const vector3 &v, const vector3 &n) noexcept { return v - n * dot(v, n); }

/// Turns `v` into the unit vector along its component orthogonal to the unit vector `n`, kept
/// orthogonal to `n` even when that component is short beside `v`: what one projection leaves
/// along `n` is of the order of the rounding of `v`, which normalising a short component would
/// blow up (a cylinder's support point pulled off its rim), so such a component is projected
/// again once normalised.
/// @param v Any vector; on return the unit direction, or unspecified when the function fails.
/// @param n Unit normal (not checked; rounding off unit length is tolerated).
/// @return False when the orthogonal component is too short to give a direction.
inline bool try_normalize_across(vector3 &v, const vector3 &n) noexcept {
    auto full_sqr = length_sqr(v);
    v = project_plane(v, n);
    auto len_sqr = length_sqr(v);
    if (!(len_sqr > epsilon * epsilon)) return false;
    if (len_sqr < full_sqr * scalar(0.01)) {
        v /= std::sqrt(len_sqr);
        v = project_plane(v, n);
        // What was left lay along `n` itself (rounding, or an `n` a little off unit length): not
        // a direction across it.
        len_sqr = length_sqr(v);
        if (!(len_sqr > scalar(0.25))) return false;
    }
    v /= std::sqrt(len_sqr);
    return true;
}

/// Unit vectors `t0`, `t1` completing the unit vector `n` to a right-handed orthonormal basis
/// (t0 × t1 = n), for example the friction directions of a contact. Continuous except across the
/// switch between the two branches (|n.z| = √2 / 2).
/// @param n Unit vector (not checked; a zero vector gives NaN).
/// @param t0 Receives the first tangent.
/// @param t1 Receives the second tangent.
inline void plane_space(const vector3 &n, vector3 &t0, vector3 &t1) noexcept {
    if (std::abs(n.z) > scalar(0.7071067811865476)) {
        // n lies close to z: build t0 in the y-z plane.
        auto a = n.y * n.y + n.z * n.z;
        auto k = scalar(1) / std::sqrt(a);
        t0 = {0, -n.z * k, n.y * k};
        t1 = {a * k, -n.x * t0.z, n.x * t0.y};
    } else {
        // Build t0 in the x-y plane.
        auto a = n.x * n.x + n.y * n.y;
        auto k = scalar(1) / std::sqrt(a);
        t0 = {-n.y * k, n.x * k, 0};
        t1 = {-n.z * t0.y, n.z * t0.x, a * k};
    }
}

} // namespace edyn

#endif // EDYN_MATH_VECTOR3_HPP
