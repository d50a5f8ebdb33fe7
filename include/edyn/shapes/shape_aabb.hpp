#ifndef EDYN_SHAPES_SHAPE_AABB_HPP
#define EDYN_SHAPES_SHAPE_AABB_HPP

#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/shapes.hpp"

namespace edyn {

/// Half size of the box given to a plane (m): finite, so that box arithmetic (areas in the
/// broadphase) stays finite, and far beyond any simulated world.
inline constexpr scalar plane_aabb_half_size = scalar(1e15);

/// World-space AABB of a plane.
///
/// Ignores `pos` and `orn`; the box it gets is described below.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const plane_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a sphere.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const sphere_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a box.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const box_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a cylinder.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const cylinder_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a capsule.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const capsule_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a polyhedron.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const polyhedron_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a compound.
///
/// The union of its children's tight AABBs.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const compound_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of any shape a compound can hold.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const compound_child_shape_t &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a triangle mesh.
///
/// The mesh's bounds in its object space, placed at (pos, orn): tight when orn is the identity.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const mesh_shape &shape, const vector3 &pos, const quaternion &orn);
/// World-space AABB of a paged triangle mesh.
///
/// The bounds of all pages in the mesh's space, placed at (pos, orn), as for a triangle mesh.
///
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
AABB shape_aabb(const paged_mesh_shape &shape, const vector3 &pos, const quaternion &orn);

/// World-space AABB of a shape at position `pos` and orientation `orn`, whatever its type.
///
/// Tight for every shape but meshes: boxes and polyhedra bound their rotated vertices; cylinders
/// use, per world axis i, |a_i| half_length + radius sqrt(1 - a_i^2) with a the world-space main
/// axis; capsules |a_i| half_length + radius; compounds are the union of their children's tight
/// AABBs.
///
/// A plane ignores pos and orn (as planes do everywhere) and gets the cube of half size
/// plane_aabb_half_size around the origin, cut at the plane where its normal is exactly a
/// coordinate axis: the ground plane {normal (0, 1, 0), constant 0} gives max.y == 0. A mesh's
/// bounds in its object space are placed at (pos, orn): tight when orn is the identity.
///
/// The engine keeps each body's AABB component up to date with it.
/// @param shape The shape.
/// @param pos Position of the shape's origin in world space (m).
/// @param orn Orientation of the shape (unit quaternion, x y z w).
/// @return The box in world space (m).
template<shapes_variant Variant>
AABB shape_aabb(const Variant &shape, const vector3 &pos, const quaternion &orn) {
    return std::visit([&](const auto &s) { return shape_aabb(s, pos, orn); }, shape);
}

} // namespace edyn

#endif // EDYN_SHAPES_SHAPE_AABB_HPP
