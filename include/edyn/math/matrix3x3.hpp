#ifndef EDYN_MATH_MATRIX3X3_HPP
#define EDYN_MATH_MATRIX3X3_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include <algorithm>
#include <limits>
#include <utility>

namespace edyn {

/// 3x3 matrix stored as three rows: rotations, inertia tensors (kg·m²), frames.
///
/// Frames (a hinge's, a body's basis) are read by column: column i is the i-th axis of the frame
/// expressed in the parent space. An aggregate: `matrix3x3{{r0, r1, r2}}`.
struct matrix3x3 {
    vector3 row[3]; ///< The rows, top to bottom.

    /// Row by index.
    /// @param i 0, 1 or 2 (not checked).
    /// @return A reference to the row.
    constexpr vector3 &operator[](int i) noexcept { return row[i]; }
    /// Row by index.
    /// @param i 0, 1 or 2 (not checked).
    /// @return A reference to the row.
    constexpr const vector3 &operator[](int i) const noexcept { return row[i]; }
    /// Column by index, for example an axis of a frame.
    /// @param i 0, 1 or 2.
    /// @return A copy of the column.
    constexpr vector3 column(int i) const noexcept { return {row[0][i], row[1][i], row[2][i]}; }
    /// Exact element-wise equality (no tolerance).
    /// @return True when all nine elements are equal.
    constexpr bool operator==(const matrix3x3 &) const noexcept = default;
};

/// The identity matrix.
inline constexpr matrix3x3 matrix3x3_identity{{vector3_x, vector3_y, vector3_z}};
/// The matrix of zeros.
inline constexpr matrix3x3 matrix3x3_zero{{vector3_zero, vector3_zero, vector3_zero}};

/// Builds a matrix from its rows.
/// @param r0 First row.
/// @param r1 Second row.
/// @param r2 Third row.
/// @return The matrix.
constexpr matrix3x3 matrix3x3_rows(const vector3 &r0, const vector3 &r1, const vector3 &r2) noexcept {
    return {{r0, r1, r2}};
}

/// Builds a matrix from its columns, for example a frame from its three axes.
/// @param c0 First column (the frame's x axis).
/// @param c1 Second column (y axis).
/// @param c2 Third column (z axis).
/// @return The matrix.
constexpr matrix3x3 matrix3x3_columns(const vector3 &c0, const vector3 &c1, const vector3 &c2) noexcept {
    return {{{c0.x, c1.x, c2.x}, {c0.y, c1.y, c2.y}, {c0.z, c1.z, c2.z}}};
}

/// Diagonal matrix, for example an inertia tensor in its principal axes.
/// @param d The diagonal elements.
/// @return The matrix with `d` on its diagonal and zeros elsewhere.
constexpr matrix3x3 diagonal_matrix(const vector3 &d) noexcept {
    return {{{d.x, 0, 0}, {0, d.y, 0}, {0, 0, d.z}}};
}

/// The diagonal of a matrix.
/// @return (m[0][0], m[1][1], m[2][2]).
constexpr vector3 get_diagonal(const matrix3x3 &m) noexcept { return {m[0][0], m[1][1], m[2][2]}; }

/// Matrix form of the cross product: skew_matrix(a) * b == cross(a, b).
/// @param v The left operand of the cross product.
/// @return The skew-symmetric matrix of `v`.
constexpr matrix3x3 skew_matrix(const vector3 &v) noexcept {
    return {{{0, -v.z, v.y}, {v.z, 0, -v.x}, {-v.y, v.x, 0}}};
}

/// Transpose; the inverse of a rotation matrix.
/// @return The matrix with rows and columns swapped.
constexpr matrix3x3 transpose(const matrix3x3 &m) noexcept { return matrix3x3_columns(m[0], m[1], m[2]); }

/// Element-wise sum.
/// @return `a + b`.
constexpr matrix3x3 operator+(const matrix3x3 &a, const matrix3x3 &b) noexcept {
    return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
}
/// Element-wise difference.
/// @return `a - b`.
constexpr matrix3x3 operator-(const matrix3x3 &a, const matrix3x3 &b) noexcept {
    return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
/// Scales every element.
/// @return `m` with each element multiplied by `s`.
constexpr matrix3x3 operator*(const matrix3x3 &m, scalar s) noexcept {
    return {{m[0] * s, m[1] * s, m[2] * s}};
}
/// Scales every element.
/// @return `m * s`.
constexpr matrix3x3 operator*(scalar s, const matrix3x3 &m) noexcept { return m * s; }

/// Matrix times column vector, for example a vector transformed by a rotation matrix.
/// @return `m v`.
constexpr vector3 operator*(const matrix3x3 &m, const vector3 &v) noexcept {
    return {dot(m[0], v), dot(m[1], v), dot(m[2], v)};
}

/// Row vector times matrix, that is, transpose(m) * v without building the transpose.
/// @return `v^T m` as a vector.
constexpr vector3 operator*(const vector3 &v, const matrix3x3 &m) noexcept {
    return m[0] * v.x + m[1] * v.y + m[2] * v.z;
}

/// Matrix product: applying `a * b` to a vector applies `b` first, then `a`.
/// @return `a b`.
constexpr matrix3x3 operator*(const matrix3x3 &a, const matrix3x3 &b) noexcept {
    return {{a[0] * b, a[1] * b, a[2] * b}};
}

/// Adds `b` to `a` in place.
/// @return `a`.
constexpr matrix3x3 &operator+=(matrix3x3 &a, const matrix3x3 &b) noexcept { return a = a + b; }
/// Replaces `a` with the product `a * b`.
/// @return `a`.
constexpr matrix3x3 &operator*=(matrix3x3 &a, const matrix3x3 &b) noexcept { return a = a * b; }

/// Determinant; 1 for a rotation matrix.
/// @return The scalar triple product of the rows.
constexpr scalar determinant(const matrix3x3 &m) noexcept { return dot(m[0], cross(m[1], m[2])); }

/// Inverse through the adjugate, for example of an inertia tensor; use `transpose` for rotations.
/// A matrix of finite entries whose determinant overflows, or falls below the smallest normal
/// scalar, or whose adjugate overflows (an asteroid's inertia, a sand grain's: in single
/// precision, entries past about 1e12 or below about 1e-13) is inverted scaled by its largest
/// entry, then scaled back; any other is inverted as it is.
/// @param m A matrix with a non-zero determinant (precondition, checked by `EDYN_ASSERT` only).
/// @return The inverse of `m`.
constexpr matrix3x3 inverse(const matrix3x3 &m) noexcept {
    auto adjugate_inverse = [](const matrix3x3 &n) {
        auto c0 = cross(n[1], n[2]);
        auto c1 = cross(n[2], n[0]);
        auto c2 = cross(n[0], n[1]);
        return std::pair{matrix3x3_columns(c0, c1, c2), dot(n[0], c0)};
    };
    auto [adjugate, det] = adjugate_inverse(m);
    auto magnitude = det < 0 ? -det : det;
    if (magnitude >= std::numeric_limits<scalar>::min() && magnitude <= std::numeric_limits<scalar>::max())
        return adjugate * (scalar(1) / det);
    scalar largest = 0;
    bool finite = true;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            auto entry = m[i][j] < 0 ? -m[i][j] : m[i][j];
            finite = finite && entry <= std::numeric_limits<scalar>::max();
            largest = std::max(largest, entry);
        }
    }
    // Entries that are infinite or NaN give what the adjugate gives.
    if (!finite) return adjugate * (scalar(1) / det);
    EDYN_ASSERT(largest > scalar(0), "inverse of a singular matrix");
    auto scale = scalar(1) / largest;
    auto [scaled_adjugate, scaled_det] = adjugate_inverse(m * scale);
    EDYN_ASSERT(scaled_det != scalar(0), "inverse of a singular matrix");
    return scaled_adjugate * (scale / scaled_det);
}

/// Rotation matrix equal to the unit quaternion `q`; its columns are the rotated axes.
/// @param q Unit quaternion (not checked).
/// @return The rotation matrix.
constexpr matrix3x3 to_matrix3x3(const quaternion &q) noexcept {
    auto xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    auto xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    auto wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return {{{1 - 2 * (yy + zz), 2 * (xy - wz), 2 * (xz + wy)},
             {2 * (xy + wz), 1 - 2 * (xx + zz), 2 * (yz - wx)},
             {2 * (xz - wy), 2 * (yz + wx), 1 - 2 * (xx + yy)}}};
}

/// Unit quaternion of the rotation matrix `m`; the inverse of `to_matrix3x3`.
/// @param m Orthonormal matrix with determinant 1 (not checked).
/// @return The unit quaternion, normalized.
inline quaternion to_quaternion(const matrix3x3 &m) noexcept {
    auto trace = m[0][0] + m[1][1] + m[2][2];
    quaternion q;
    // Pick the largest of w, x, y, z to divide by, for accuracy.
    if (trace > 0) {
        auto s = std::sqrt(trace + scalar(1)) * 2;
        q = {(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4};
    } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
        auto s = std::sqrt(scalar(1) + m[0][0] - m[1][1] - m[2][2]) * 2;
        q = {s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s};
    } else if (m[1][1] > m[2][2]) {
        auto s = std::sqrt(scalar(1) + m[1][1] - m[0][0] - m[2][2]) * 2;
        q = {(m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s};
    } else {
        auto s = std::sqrt(scalar(1) + m[2][2] - m[0][0] - m[1][1]) * 2;
        q = {(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4, (m[1][0] - m[0][1]) / s};
    }
    return normalize(q);
}

/// R diag(d) R^T for a rotation R: a diagonal tensor (inertia) expressed in another frame.
/// @param r Rotation matrix from the tensor's principal frame to the target frame.
/// @param d The diagonal of the tensor in its principal frame (for example kg·m²).
/// @return The full tensor in the target frame.
constexpr matrix3x3 rotate_diagonal(const matrix3x3 &r, const vector3 &d) noexcept {
    return r * diagonal_matrix(d) * transpose(r);
}

/// Whether every element is finite (neither infinite nor NaN), for validating input.
/// @return True when all nine elements are finite.
inline bool isfinite(const matrix3x3 &m) noexcept {
    return isfinite(m[0]) && isfinite(m[1]) && isfinite(m[2]);
}

} // namespace edyn

#endif // EDYN_MATH_MATRIX3X3_HPP
