#ifndef EDYN_COLLISION_SHAPE_RAYCAST_HPP
#define EDYN_COLLISION_SHAPE_RAYCAST_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/shapes/shapes.hpp"
#include <cstddef>
#include <limits>
#include <variant>

namespace edyn {

/// A ray, the segment from p0 to p1 in world space, against a shape at (pos, orn): the input of
/// shape_raycast().
struct raycast_context {
    vector3 pos;    ///< Position of the shape's origin in world space (m).
    quaternion orn; ///< Orientation of the shape (unit quaternion, x y z w).
    vector3 p0;     ///< Start of the ray in world space (m).
    vector3 p1;     ///< End of the ray in world space (m).
};

/// Which face of a box_shape a ray hit.
struct box_raycast_info {
    /// Face 0..5 of the box: +x, -x, +y, -y, +z, -z (see box_shape).
    std::size_t face_index;
};

/// Which part of a cylinder_shape a ray hit.
///
/// A cap: feature cylinder_feature::face, face_index 0 for the cap at +half_length, 1 at
/// -half_length. The curved side: feature cylinder_feature::side_edge, face_index 0.
struct cylinder_raycast_info {
    cylinder_feature feature; ///< cylinder_feature::face for a cap, side_edge for the side.
    std::size_t face_index;   ///< The cap (0 at +half_length, 1 at -half_length); 0 for the side.
};

/// Which part of a capsule_shape a ray hit.
///
/// A hemisphere: capsule_feature::hemisphere, hemisphere_index 0 at +half_length, 1 at
/// -half_length. The cylindrical side: capsule_feature::side, hemisphere_index 0.
struct capsule_raycast_info {
    /// capsule_feature::hemisphere or capsule_feature::side.
    capsule_feature feature;
    /// The hemisphere (0 at +half_length, 1 at -half_length); 0 for the side.
    std::size_t hemisphere_index;
};

/// Which face of a polyhedron_shape a ray hit.
struct polyhedron_raycast_info {
    /// Index into the polyhedron's `mesh->faces` (and `mesh->normals`).
    std::size_t face_index;
};

/// What a ray hit on a compound's child: nothing more for a sphere (`std::monostate`), else the
/// info of the child's shape type.
using compound_child_raycast_info_variant =
    std::variant<std::monostate, box_raycast_info, cylinder_raycast_info, capsule_raycast_info,
                 polyhedron_raycast_info>;

/// The child of a compound_shape that a ray hit and what the child reported.
struct compound_raycast_info {
    std::size_t child_index;                            ///< Index into compound_shape::children.
    compound_child_raycast_info_variant child_info_var; ///< The child's own raycast info.
};

/// Which triangle of a mesh_shape a ray hit.
struct mesh_raycast_info {
    /// Index of the triangle (triangle_mesh numbering).
    std::size_t triangle_index;
};

/// Which triangle of a paged_mesh_shape a ray hit: the page and the triangle's index in that
/// page's mesh.
struct paged_mesh_raycast_info {
    std::size_t submesh_index;  ///< Index of the page.
    std::size_t triangle_index; ///< Index of the triangle within the page's triangle_mesh.
};

/// Extra information on a ray hit, by type of shape hit. Spheres and planes report
/// std::monostate.
using raycast_info_variant =
    std::variant<std::monostate, box_raycast_info, cylinder_raycast_info, capsule_raycast_info,
                 polyhedron_raycast_info, compound_raycast_info, mesh_raycast_info, paged_mesh_raycast_info>;

/// Fraction of a ray that hits nothing (infinity).
inline constexpr scalar raycast_miss_fraction = std::numeric_limits<scalar>::infinity();

/// Result of shape_raycast(): where along the ray the shape was hit, the normal there and
/// shape-specific information.
struct shape_raycast_result {
    /// Position of the hit along the ray: lerp(p0, p1, fraction). raycast_miss_fraction (infinity)
    /// when the ray misses, the default.
    scalar fraction{raycast_miss_fraction};
    /// World-space unit normal at the hit, pointing out of the shape; zero on a miss.
    vector3 normal{vector3_zero};
    /// Which feature was hit, by shape type (see raycast_info_variant); std::monostate by default.
    raycast_info_variant info_var{};

    /// Whether the ray hit the shape (the fraction is at most 1).
    bool hit() const noexcept { return fraction <= 1; }
};

/// Ray against a plane; the plane ignores ctx.pos and ctx.orn and its solid lies behind the
/// normal.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const plane_shape &shape, const raycast_context &ctx);
/// Ray against a sphere; the info is std::monostate.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const sphere_shape &shape, const raycast_context &ctx);
/// Ray against a box; the info is a box_raycast_info.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const box_shape &shape, const raycast_context &ctx);
/// Ray against a cylinder; the info is a cylinder_raycast_info.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const cylinder_shape &shape, const raycast_context &ctx);
/// Ray against a capsule; the info is a capsule_raycast_info.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const capsule_shape &shape, const raycast_context &ctx);
/// Ray against a polyhedron; the info is a polyhedron_raycast_info.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const polyhedron_shape &shape, const raycast_context &ctx);
/// Ray against a compound; the info is a compound_raycast_info naming the child hit first (the
/// lowest child index on equal fractions).
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const compound_shape &shape, const raycast_context &ctx);
/// Ray against any shape a compound can hold, as the overload for its type.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const compound_child_shape_t &shape, const raycast_context &ctx);
/// Ray against a triangle mesh; the info is a mesh_raycast_info.
///
/// Meshes are surfaces: a ray hits a triangle from either side, with the normal facing the ray's
/// start, the first triangle along the ray (the lowest index on equal fractions).
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const mesh_shape &shape, const raycast_context &ctx);
/// Ray against a paged triangle mesh; the info is a paged_mesh_raycast_info.
///
/// Only the pages that are loaded are hit; otherwise as against a mesh_shape.
///
/// First intersection of the segment [ctx.p0, ctx.p1] with the solid shape at (ctx.pos,
/// ctx.orn); a ray starting inside hits at fraction 0. No call allocates memory. Rules as for
/// the shapes_variant_t overload.
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
shape_raycast_result shape_raycast(const paged_mesh_shape &shape, const raycast_context &ctx);

/// First intersection of the segment [ctx.p0, ctx.p1] with a solid shape at (ctx.pos, ctx.orn),
/// whatever the shape's type.
///
/// No call allocates memory; it can be called from any thread on shapes nobody modifies
/// meanwhile. It tests one shape; to cast a ray through a world, use raycast().
///
/// - Shapes are closed sets: a ray that only touches the surface (tangent to a sphere, sliding
///   along a face, through an edge) hits, to rounding. A ray parallel to a face and outside the
///   shape misses.
/// - A ray starting inside a shape hits at fraction 0 with normal = -(p1 - p0) / |p1 - p0|, and
///   the info of the feature through which the ray's line enters the shape behind p0 (so the
///   info does not jump as p0 crosses the surface). A ray starting on the surface counts as
///   inside if it goes into the shape or along its surface, and misses if it leaves.
/// - A zero-length ray (p0 == p1) hits nothing.
/// - Planes ignore ctx.pos and ctx.orn (as planes do everywhere); the solid lies behind the
///   normal.
/// - Compounds report the child hit first (the lowest child index on equal fractions).
/// - Meshes are surfaces: a ray hits a triangle from either side, with the normal facing the
///   ray's start, the first triangle along the ray (the lowest index on equal fractions).
/// @param shape The shape, in its object space.
/// @param ctx The shape's transform and the ray's end points, in world space (m).
/// @return The hit, or a result whose hit() is false.
template<shapes_variant Variant>
shape_raycast_result shape_raycast(const Variant &shape, const raycast_context &ctx) {
    return std::visit([&](const auto &s) { return shape_raycast(s, ctx); }, shape);
}

} // namespace edyn

#endif // EDYN_COLLISION_SHAPE_RAYCAST_HPP
