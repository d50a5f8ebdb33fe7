#ifndef EDYN_SHAPES_SHAPE_BOUNDING_RADIUS_HPP
#define EDYN_SHAPES_SHAPE_BOUNDING_RADIUS_HPP

#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/shapes.hpp"
#include <algorithm>

namespace edyn {

/// The radius of a sphere about the shape's origin that holds the whole shape, in any
/// orientation: the largest distance of a point of the shape from its origin (m).
///
/// Two shapes whose origins lie farther apart than the sum of their radii do not touch; the
/// narrowphase skips such pairs. Shapes without a useful bound (planes, triangle meshes, paged
/// meshes, compounds) return `large_scalar`, which never rules a pair out.
///
/// @param shape The shape.
/// @return The radius (m), or `large_scalar`.
scalar shape_bounding_radius(const sphere_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const box_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const capsule_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const cylinder_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const polyhedron_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const compound_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const plane_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const mesh_shape &shape);
/// @copydoc shape_bounding_radius(const sphere_shape &)
scalar shape_bounding_radius(const paged_mesh_shape &shape);

/// How far any point of a shape reaches from `point`, bounded by its AABB: the half diagonal
/// plus the distance from the AABB's centre to `point` (m).
/// @param aabb The shape's AABB.
/// @param point Where the reach is measured from (a centre of mass, m).
inline scalar aabb_reach(const AABB &aabb, const vector3 &point) {
    return length(aabb_half_extents(aabb)) + distance(aabb_center(aabb), point);
}

/// How far any point of a shape reaches from `point`: the smaller of the AABB's bound
/// (aabb_reach) and the bounding sphere's, its radius plus the distance from `point` to the
/// shape's origin. Neither alone will do: the AABB's is up to 1.67 times the sphere's for a
/// turned cube, and meshes have no finite sphere.
/// @param aabb The shape's AABB.
/// @param point Where the reach is measured from (a centre of mass, m).
/// @param radius The shape's shape_bounding_radius (m).
/// @param origin_distance Distance from `point` to the shape's origin (m).
inline scalar shape_reach(const AABB &aabb, const vector3 &point, scalar radius, scalar origin_distance) {
    return std::min(radius + origin_distance, aabb_reach(aabb, point));
}

} // namespace edyn

#endif // EDYN_SHAPES_SHAPE_BOUNDING_RADIUS_HPP
