#ifndef EDYN_SHAPES_AABB_HPP
#define EDYN_SHAPES_AABB_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

/// Axis-aligned bounding box, in world space when it is a body's component.
///
/// Every rigid body with a shape has one; the engine computes it from the shape and the body's
/// transform (shape_aabb()) after every step, and the broadphase reads it. Elsewhere (shape
/// trees, meshes, queries) the space is the one of the surrounding object.
struct AABB {
    vector3 min; ///< Lowest corner (m).
    vector3 max; ///< Highest corner (m).

    /// Two boxes are equal when both corners are.
    constexpr bool operator==(const AABB &) const noexcept = default;
};

/// Whether a and b overlap; touching boxes count as overlapping.
/// @param a One box.
/// @param b The other box.
constexpr bool intersect(const AABB &a, const AABB &b) noexcept {
    return a.min.x <= b.max.x && a.max.x >= b.min.x && a.min.y <= b.max.y && a.max.y >= b.min.y &&
           a.min.z <= b.max.z && a.max.z >= b.min.z;
}

/// Whether `outer` fully contains `inner` (shared boundaries count as contained).
/// @param outer The enclosing box.
/// @param inner The enclosed box.
constexpr bool contains(const AABB &outer, const AABB &inner) noexcept {
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
           outer.max.x >= inner.max.x && outer.max.y >= inner.max.y && outer.max.z >= inner.max.z;
}

/// Whether the point `p` lies in the box (on its boundary counts).
/// @param aabb The box.
/// @param p The point, in the box's space (m).
constexpr bool contains(const AABB &aabb, const vector3 &p) noexcept {
    return aabb.min.x <= p.x && aabb.min.y <= p.y && aabb.min.z <= p.z && aabb.max.x >= p.x &&
           aabb.max.y >= p.y && aabb.max.z >= p.z;
}

/// Smallest box enclosing both.
/// @param a One box.
/// @param b The other box.
/// @return The union's bounds.
constexpr AABB enclosing_aabb(const AABB &a, const AABB &b) noexcept {
    return {min(a.min, b.min), max(a.max, b.max)};
}

/// Grows (positive `amount`) or shrinks (negative) the box by `amount` on every side.
/// @param aabb The box.
/// @param amount Growth along each axis, applied to both sides (m).
/// @return The grown box; shrinking past the centre gives an inverted box.
constexpr AABB inset(const AABB &aabb, const vector3 &amount) noexcept {
    return {aabb.min - amount, aabb.max + amount};
}

/// Centre of the box.
constexpr vector3 aabb_center(const AABB &aabb) noexcept { return (aabb.min + aabb.max) * scalar(0.5); }
/// Half of the box's size along each axis (m).
constexpr vector3 aabb_half_extents(const AABB &aabb) noexcept { return (aabb.max - aabb.min) * scalar(0.5); }

/// Surface area (m²); the cost measure of the broadphase tree.
constexpr scalar aabb_area(const AABB &aabb) noexcept {
    auto d = aabb.max - aabb.min;
    return scalar(2) * (d.x * d.y + d.y * d.z + d.z * d.x);
}

/// Whether the segment [p0, p1] touches the box (slab test; touching counts).
/// @param aabb The box.
/// @param p0 Start of the segment, in the box's space (m).
/// @param p1 End of the segment (m).
constexpr bool intersect_segment(const AABB &aabb, const vector3 &p0, const vector3 &p1) noexcept {
    scalar t0 = 0, t1 = 1;
    for (int i = 0; i < 3; ++i) {
        auto d = p1[i] - p0[i];
        if (d == 0) {
            if (p0[i] < aabb.min[i] || p0[i] > aabb.max[i]) return false;
            continue;
        }
        auto ta = (aabb.min[i] - p0[i]) / d;
        auto tb = (aabb.max[i] - p0[i]) / d;
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
        if (t0 > t1) return false;
    }
    return true;
}

} // namespace edyn

#endif // EDYN_SHAPES_AABB_HPP
