#ifndef EDYN_MATH_QUATERNION_HPP
#define EDYN_MATH_QUATERNION_HPP

#include "edyn/math/vector3.hpp"
#include <cmath>

namespace edyn {

/// Rotation quaternion, for example a body's orientation.
///
/// The members are ordered x y z w: the vector part first, then the real part. Engines that store
/// w x y z must swap when converting. Orientations must be unit quaternions (see `is_unit`); the
/// identity is `quaternion_identity`. An aggregate: `quaternion{x, y, z, w}`; its members are
/// uninitialised when default-constructed.
struct quaternion {
    scalar x, y, z, w;

    /// @var x
    /// x component of the vector part: the rotation axis times sin(angle / 2).
    /// @var y
    /// y component of the vector part.
    /// @var z
    /// z component of the vector part.
    /// @var w
    /// Real part: cos(angle / 2).

    /// Component by index, in storage order.
    /// @param i 0 (`x`), 1 (`y`), 2 (`z`) or 3 (`w`); checked by `EDYN_ASSERT`.
    /// @return A reference to the component.
    constexpr scalar &operator[](int i) noexcept {
        EDYN_ASSERT(i >= 0 && i < 4);
        return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w));
    }
    /// Component by index, in storage order.
    /// @param i 0 (`x`), 1 (`y`), 2 (`z`) or 3 (`w`); checked by `EDYN_ASSERT`.
    /// @return The component's value.
    constexpr scalar operator[](int i) const noexcept {
        EDYN_ASSERT(i >= 0 && i < 4);
        return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w));
    }
    /// Exact component-wise equality (no tolerance; `q` and `-q` are the same rotation but
    /// compare unequal).
    /// @return True when all four components are equal.
    constexpr bool operator==(const quaternion &) const noexcept = default;
};

/// The identity rotation (0, 0, 0, 1).
inline constexpr quaternion quaternion_identity{0, 0, 0, 1};

/// The vector part of a quaternion.
/// @return (q.x, q.y, q.z).
constexpr vector3 quaternion_vector(const quaternion &q) noexcept { return {q.x, q.y, q.z}; }

/// Hamilton product: rotating by (a * b) rotates by b first, then by a.
/// @return The product `a b`.
constexpr quaternion operator*(const quaternion &a, const quaternion &b) noexcept {
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}
/// Multiplies every component by a scalar (the result is not a unit quaternion in general).
/// @return (q.x s, q.y s, q.z s, q.w s).
constexpr quaternion operator*(const quaternion &q, scalar s) noexcept {
    return {q.x * s, q.y * s, q.z * s, q.w * s};
}
/// Multiplies every component by a scalar.
/// @return `q * s`.
constexpr quaternion operator*(scalar s, const quaternion &q) noexcept { return q * s; }
/// Component-wise sum (for interpolation; normalize the result to get a rotation).
/// @return `a + b`.
constexpr quaternion operator+(const quaternion &a, const quaternion &b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}
/// Negation of every component: the same rotation, on the other hemisphere.
/// @return `-q`.
constexpr quaternion operator-(const quaternion &q) noexcept { return {-q.x, -q.y, -q.z, -q.w}; }
/// Replaces `a` with the Hamilton product `a * b` (rotate by `b` first, then by the old `a`).
/// @return `a`.
constexpr quaternion &operator*=(quaternion &a, const quaternion &b) noexcept { return a = a * b; }

/// Four-dimensional dot product; for unit quaternions, cos of half the angle between them.
/// @return `a.x b.x + a.y b.y + a.z b.z + a.w b.w`.
constexpr scalar dot(const quaternion &a, const quaternion &b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}
/// Squared norm.
/// @return `dot(q, q)`.
constexpr scalar length_sqr(const quaternion &q) noexcept { return dot(q, q); }
/// Norm; 1 for a rotation.
/// @return The four-dimensional length of `q`.
inline scalar length(const quaternion &q) noexcept { return std::sqrt(length_sqr(q)); }

/// The unit quaternion along `q`, for example to remove the drift of accumulated rounding.
/// @param q A quaternion longer than `epsilon` (precondition, checked by `EDYN_ASSERT` only).
/// @return `q / length(q)`.
inline quaternion normalize(const quaternion &q) noexcept {
    auto len = length(q);
    EDYN_ASSERT(len > epsilon, "normalize of a zero quaternion");
    return q * (scalar(1) / len);
}

/// Conjugate: the inverse rotation of a unit quaternion.
/// @return (-q.x, -q.y, -q.z, q.w).
constexpr quaternion conjugate(const quaternion &q) noexcept { return {-q.x, -q.y, -q.z, q.w}; }

/// Inverse of any non-zero quaternion; equals the conjugate for unit quaternions.
/// @param q A non-zero quaternion (not checked).
/// @return `conjugate(q) / length_sqr(q)`.
constexpr quaternion inverse(const quaternion &q) noexcept {
    return conjugate(q) * (scalar(1) / length_sqr(q));
}

/// Rotates `v` by the unit quaternion `q` (q v q*), expanded to avoid two full products.
/// @param q Unit quaternion (not checked).
/// @param v The vector to rotate.
/// @return The rotated vector.
constexpr vector3 rotate(const quaternion &q, const vector3 &v) noexcept {
    auto u = quaternion_vector(q);
    auto t = cross(u, v) * scalar(2);
    return v + t * q.w + cross(u, t);
}

/// Unit quaternion for a rotation of `angle` radians about the unit vector `axis`, counter-
/// clockwise when looking down the axis towards the origin (right-hand rule).
/// @param axis Unit rotation axis (not checked: a non-unit axis gives a non-unit quaternion).
/// @param angle Rotation angle in radians.
/// @return (axis sin(angle / 2), cos(angle / 2)).
inline quaternion quaternion_axis_angle(const vector3 &axis, scalar angle) noexcept {
    auto s = std::sin(angle * scalar(0.5));
    return {axis.x * s, axis.y * s, axis.z * s, std::cos(angle * scalar(0.5))};
}

/// Rotation angle of the unit quaternion `q`.
/// @return The angle in radians, in [0, 2 pi].
inline scalar quaternion_angle(const quaternion &q) noexcept {
    return scalar(2) * std::acos(std::clamp(q.w, scalar(-1), scalar(1)));
}

/// Rotation axis of `q`.
/// @return The unit axis; `vector3_x` when `q` is (close to) the identity.
inline vector3 quaternion_axis(const quaternion &q) noexcept {
    auto v = quaternion_vector(q);
    if (!try_normalize(v)) return vector3_x;
    return v;
}

/// Shortest rotation taking unit vector `a` onto unit vector `b`. For opposite vectors, a half
/// turn about an axis orthogonal to `a`.
/// @param a Unit vector (not checked).
/// @param b Unit vector (not checked).
/// @return A unit quaternion `q` with `rotate(q, a)` ≈ `b`.
inline quaternion shortest_arc(const vector3 &a, const vector3 &b) noexcept {
    auto d = dot(a, b);
    if (d < scalar(-1) + epsilon) {
        // Opposite vectors: any axis orthogonal to a works.
        vector3 t0, t1;
        plane_space(a, t0, t1);
        return {t0.x, t0.y, t0.z, 0};
    }
    auto c = cross(a, b);
    return normalize(quaternion{c.x, c.y, c.z, scalar(1) + d});
}

/// Spherical interpolation between two orientations along the shorter arc, at constant angular
/// speed in `s`.
/// @param q0 Unit quaternion at s = 0.
/// @param q1 Unit quaternion at s = 1 (negated if needed to take the shorter arc).
/// @param s Interpolation parameter in [0, 1].
/// @return A unit quaternion between `q0` and `q1`.
inline quaternion slerp(const quaternion &q0, quaternion q1, scalar s) noexcept {
    auto c = dot(q0, q1);
    if (c < 0) {
        q1 = -q1;
        c = -c;
    }
    if (c > scalar(1) - epsilon) {
        // Nearly parallel: linear interpolation is exact to rounding and avoids 0/0.
        return normalize(q0 * (scalar(1) - s) + q1 * s);
    }
    auto theta = std::acos(c);
    auto inv_sin = scalar(1) / std::sin(theta);
    return q0 * (std::sin((scalar(1) - s) * theta) * inv_sin) + q1 * (std::sin(s * theta) * inv_sin);
}

/// Orientation after rotating `q` at angular velocity `w` for `dt` seconds.
///
/// Uses the exact exponential map, so a constant `w` gives a rotation of |w| dt about `w`.
/// @param q Unit orientation at the start.
/// @param w Angular velocity in world space, rad/s.
/// @param dt Time step, s.
/// @return The new orientation, normalized; `q` itself when |w| dt is below `epsilon`.
inline quaternion integrate(const quaternion &q, const vector3 &w, scalar dt) noexcept {
    auto len = length(w);
    if (len * dt < epsilon) return q;
    auto dq = quaternion_axis_angle(w / len, len * dt);
    return normalize(dq * q);
}

/// Angular velocity that takes `q0` to `q1` in `dt` seconds (inverse of `integrate`), along the
/// shorter way round.
/// @param q0 Unit orientation at the start.
/// @param q1 Unit orientation at the end.
/// @param dt Time, s; must not be 0 (not checked).
/// @return World-space angular velocity, rad/s.
inline vector3 angular_velocity(const quaternion &q0, const quaternion &q1, scalar dt) noexcept {
    auto dq = q1 * conjugate(q0);
    if (dq.w < 0) dq = -dq;
    auto angle = quaternion_angle(dq);
    return quaternion_axis(dq) * (angle / dt);
}

/// Whether every component is finite (neither infinite nor NaN), for validating input.
/// @return True when all four components are finite.
inline bool isfinite(const quaternion &q) noexcept {
    return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}

/// Whether `q` is unit length within a tolerance that accepts accumulated rounding; how
/// functions that take an orientation validate it.
/// @param q The quaternion to test (NaN components give false).
/// @param tolerance Largest accepted |length_sqr(q) - 1|.
/// @return True when |length_sqr(q) - 1| <= `tolerance`.
inline bool is_unit(const quaternion &q, scalar tolerance = scalar(1e-3)) noexcept {
    return std::abs(length_sqr(q) - scalar(1)) <= tolerance;
}

} // namespace edyn

#endif // EDYN_MATH_QUATERNION_HPP
