#ifndef EDYN_SHAPES_SHAPE_EXTENT_HPP
#define EDYN_SHAPES_SHAPE_EXTENT_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/shapes/shapes.hpp"

namespace edyn {

/// How far a shape, turned by `orn`, reaches from its origin along a direction: the largest
/// dot(p - origin, dir) over its points p (m). This is the shape's support function.
///
/// Two shapes whose origins lie `d` apart are at least
/// dot(d, n) - shape_extent(A, ornA, n) - shape_extent(B, ornB, -n) apart, for any unit n. The
/// narrowphase takes n along the line between the origins to skip pairs this shows too far apart
/// for contact. Shapes without a bound (planes, triangle meshes, paged meshes, compounds with more
/// than `compound_shape::max_children_without_tree` children) return `large_scalar`, which never
/// rules a pair out.
///
/// @param shape The shape.
/// @param orn The shape's orientation.
/// @param dir The direction, in world space; unit length.
/// @return The extent (m), or `large_scalar`.
scalar shape_extent(const sphere_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const box_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const capsule_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const cylinder_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const polyhedron_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const compound_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const plane_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const mesh_shape &shape, const quaternion &orn, const vector3 &dir);
/// @copydoc shape_extent(const sphere_shape &, const quaternion &, const vector3 &)
scalar shape_extent(const paged_mesh_shape &shape, const quaternion &orn, const vector3 &dir);

} // namespace edyn

#endif // EDYN_SHAPES_SHAPE_EXTENT_HPP
