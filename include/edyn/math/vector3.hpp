#ifndef EDYN_MATH_VECTOR3_HPP
#define EDYN_MATH_VECTOR3_HPP

#include "edyn/config/assert.hpp"
#include "edyn/math/scalar.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

struct vector3 {
    scalar x, y, z;

    constexpr scalar &operator[](int i) noexcept {
        EDYN_ASSERT(i >= 0 && i < 3);
        return i == 0 ? x : (i == 1 ? y : z);
    }
    constexpr scalar operator[](int i) const noexcept {
        EDYN_ASSERT(i >= 0 && i < 3);
        return i == 0 ? x : (i == 1 ? y : z);
    }
    constexpr bool operator==(const vector3 &) const noexcept = default;
};

inline constexpr vector3 vector3_zero{0, 0, 0};
inline constexpr vector3 vector3_one{1, 1, 1};
inline constexpr vector3 vector3_x{1, 0, 0};
inline constexpr vector3 vector3_y{0, 1, 0};
inline constexpr vector3 vector3_z{0, 0, 1};
inline constexpr vector3 vector3_max{large_scalar, large_scalar, large_scalar};

constexpr vector3 operator+(const vector3 &a, const vector3 &b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
constexpr vector3 operator-(const vector3 &a, const vector3 &b) noexcept {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
constexpr vector3 operator-(const vector3 &v) noexcept { return {-v.x, -v.y, -v.z}; }
// Component-wise product.
constexpr vector3 operator*(const vector3 &a, const vector3 &b) noexcept {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
constexpr vector3 operator*(const vector3 &v, scalar s) noexcept { return {v.x * s, v.y * s, v.z * s}; }
constexpr vector3 operator*(scalar s, const vector3 &v) noexcept { return v * s; }
constexpr vector3 operator/(const vector3 &v, scalar s) noexcept { return {v.x / s, v.y / s, v.z / s}; }
// Component-wise quotient.
constexpr vector3 operator/(const vector3 &a, const vector3 &b) noexcept {
    return {a.x / b.x, a.y / b.y, a.z / b.z};
}
constexpr vector3 &operator+=(vector3 &a, const vector3 &b) noexcept { return a = a + b; }
constexpr vector3 &operator-=(vector3 &a, const vector3 &b) noexcept { return a = a - b; }
constexpr vector3 &operator*=(vector3 &a, const vector3 &b) noexcept { return a = a * b; }
constexpr vector3 &operator*=(vector3 &v, scalar s) noexcept { return v = v * s; }
constexpr vector3 &operator/=(vector3 &v, scalar s) noexcept { return v = v / s; }

constexpr scalar dot(const vector3 &a, const vector3 &b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

constexpr vector3 cross(const vector3 &a, const vector3 &b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

constexpr scalar length_sqr(const vector3 &v) noexcept { return dot(v, v); }
inline scalar length(const vector3 &v) noexcept { return std::sqrt(length_sqr(v)); }
inline scalar distance(const vector3 &a, const vector3 &b) noexcept { return length(a - b); }
constexpr scalar distance_sqr(const vector3 &a, const vector3 &b) noexcept { return length_sqr(a - b); }

// Precondition: v is not the zero vector (see try_normalize for a checked version).
inline vector3 normalize(const vector3 &v) noexcept {
    auto len = length(v);
    EDYN_ASSERT(len > epsilon, "normalize of a zero vector");
    return v / len;
}

// Normalizes v in place when its length exceeds epsilon; returns whether it did.
inline bool try_normalize(vector3 &v) noexcept {
    auto len_sqr = length_sqr(v);
    if (!(len_sqr > epsilon * epsilon)) return false;
    v /= std::sqrt(len_sqr);
    return true;
}

constexpr vector3 min(const vector3 &a, const vector3 &b) noexcept {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
constexpr vector3 max(const vector3 &a, const vector3 &b) noexcept {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
inline vector3 abs(const vector3 &v) noexcept { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

constexpr scalar max_component(const vector3 &v) noexcept { return std::max(v.x, std::max(v.y, v.z)); }
constexpr scalar min_component(const vector3 &v) noexcept { return std::min(v.x, std::min(v.y, v.z)); }
// Index (0, 1 or 2) of the largest component; the first one wins ties.
constexpr int max_index(const vector3 &v) noexcept {
    return v.x >= v.y ? (v.x >= v.z ? 0 : 2) : (v.y >= v.z ? 1 : 2);
}
constexpr int min_index(const vector3 &v) noexcept {
    return v.x <= v.y ? (v.x <= v.z ? 0 : 2) : (v.y <= v.z ? 1 : 2);
}

inline bool isfinite(const vector3 &v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Component of v orthogonal to the unit vector n.
constexpr vector3 project_plane(const vector3 &v, const vector3 &n) noexcept { return v - n * dot(v, n); }

// Unit vectors t0, t1 completing the unit vector n to a right-handed orthonormal basis
// (t0 x t1 = n). Continuous except across the switch between the two branches.
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
