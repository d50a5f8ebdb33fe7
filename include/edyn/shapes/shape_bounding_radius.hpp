#ifndef EDYN_SHAPES_SHAPE_BOUNDING_RADIUS_HPP
#define EDYN_SHAPES_SHAPE_BOUNDING_RADIUS_HPP

#include "edyn/shapes/shapes.hpp"

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

} // namespace edyn

#endif // EDYN_SHAPES_SHAPE_BOUNDING_RADIUS_HPP
