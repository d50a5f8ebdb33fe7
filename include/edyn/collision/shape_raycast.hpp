#ifndef EDYN_COLLISION_SHAPE_RAYCAST_HPP
#define EDYN_COLLISION_SHAPE_RAYCAST_HPP

#include "edyn/collision/collision_feature.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/shapes/shapes.hpp"
#include <cstddef>
#include <limits>
#include <variant>

namespace edyn {

// A ray, the segment from p0 to p1 in world space, against a shape at (pos, orn).
struct raycast_context {
    vector3 pos;
    quaternion orn;
    vector3 p0;
    vector3 p1;
};

// Face 0..5 of a box: +x, -x, +y, -y, +z, -z (see box_shape).
struct box_raycast_info {
    std::size_t face_index;
};

// A cap: feature cylinder_feature::face, face_index 0 for the cap at +half_length, 1 at
// -half_length. The curved side: feature cylinder_feature::side_edge, face_index 0.
struct cylinder_raycast_info {
    cylinder_feature feature;
    std::size_t face_index;
};

// A hemisphere: capsule_feature::hemisphere, hemisphere_index 0 at +half_length, 1 at
// -half_length. The cylindrical side: capsule_feature::side, hemisphere_index 0.
struct capsule_raycast_info {
    capsule_feature feature;
    std::size_t hemisphere_index;
};

// Index into the polyhedron's mesh->faces.
struct polyhedron_raycast_info {
    std::size_t face_index;
};

using compound_child_raycast_info_variant =
    std::variant<std::monostate, box_raycast_info, cylinder_raycast_info, capsule_raycast_info,
                 polyhedron_raycast_info>;

// The child of the compound that was hit and what the child reported.
struct compound_raycast_info {
    std::size_t child_index;
    compound_child_raycast_info_variant child_info_var;
};

// Index of the mesh's triangle that was hit (triangle_mesh numbering).
struct mesh_raycast_info {
    std::size_t triangle_index;
};

// The page of a paged mesh that was hit and the triangle's index in that page's mesh.
struct paged_mesh_raycast_info {
    std::size_t submesh_index;
    std::size_t triangle_index;
};

// Spheres and planes report std::monostate.
using raycast_info_variant =
    std::variant<std::monostate, box_raycast_info, cylinder_raycast_info, capsule_raycast_info,
                 polyhedron_raycast_info, compound_raycast_info, mesh_raycast_info, paged_mesh_raycast_info>;

// Fraction of a ray that hits nothing.
inline constexpr scalar raycast_miss_fraction = std::numeric_limits<scalar>::infinity();

struct shape_raycast_result {
    // Position of the hit along the ray: lerp(p0, p1, fraction). raycast_miss_fraction (infinity)
    // when the ray misses.
    scalar fraction{raycast_miss_fraction};
    // World-space unit normal at the hit, pointing out of the shape; zero on a miss.
    vector3 normal{vector3_zero};
    raycast_info_variant info_var{};

    bool hit() const noexcept { return fraction <= 1; }
};

// First intersection of the segment [ctx.p0, ctx.p1] with a solid shape at (ctx.pos, ctx.orn).
// No call allocates memory.
//
// - Shapes are closed sets: a ray that only touches the surface (tangent to a sphere, sliding
//   along a face, through an edge) hits, to rounding. A ray parallel to a face and outside the
//   shape misses.
// - A ray starting inside a shape hits at fraction 0 with normal = -(p1 - p0) / |p1 - p0|, and
//   the info of the feature through which the ray's line enters the shape behind p0 (so the
//   info does not jump as p0 crosses the surface). A ray starting on the surface counts as
//   inside if it goes into the shape or along its surface, and misses if it leaves.
// - A zero-length ray (p0 == p1) hits nothing.
// - Planes ignore ctx.pos and ctx.orn (as planes do everywhere); the solid lies behind the
//   normal.
// - Compounds report the child hit first (the lowest child index on equal fractions).
// - Meshes are surfaces: a ray hits a triangle from either side, with the normal facing the
//   ray's start, the first triangle along the ray (the lowest index on equal fractions).
shape_raycast_result shape_raycast(const plane_shape &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const sphere_shape &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const box_shape &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const cylinder_shape &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const capsule_shape &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const polyhedron_shape &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const compound_shape &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const compound_child_shape_t &shape, const raycast_context &ctx);
shape_raycast_result shape_raycast(const mesh_shape &shape, const raycast_context &ctx);
// Only the pages that are loaded are hit.
shape_raycast_result shape_raycast(const paged_mesh_shape &shape, const raycast_context &ctx);

template<shapes_variant Variant>
shape_raycast_result shape_raycast(const Variant &shape, const raycast_context &ctx) {
    return std::visit([&](const auto &s) { return shape_raycast(s, ctx); }, shape);
}

} // namespace edyn

#endif // EDYN_COLLISION_SHAPE_RAYCAST_HPP
