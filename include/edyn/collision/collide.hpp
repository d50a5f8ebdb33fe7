#ifndef EDYN_COLLISION_COLLIDE_HPP
#define EDYN_COLLISION_COLLIDE_HPP

#include "edyn/collision/collision_result.hpp"
#include "edyn/shapes/shapes.hpp"

namespace edyn {

// Closest points between two shapes at the transforms in `ctx`, appended to `result` (which
// the caller clears). Points farther apart than ctx.threshold are not reported. Normals point
// from B towards A (see collision_result). Planes ignore posA/ornA (or posB/ornB) as static
// shapes do. No call allocates memory.

// Sphere.
void collide(const sphere_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const sphere_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const sphere_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const sphere_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const sphere_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

// Plane (only against non-plane shapes).
void collide(const plane_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const plane_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const plane_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const plane_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

// Box.
void collide(const box_shape &a, const box_shape &b, const collision_context &ctx, collision_result &result);
void collide(const box_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const box_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const box_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const box_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

// Capsule.
void collide(const capsule_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);

// Cylinder.
void collide(const cylinder_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);

// Polyhedron (SAT over face normals and edge pairs; featureA/featureB are not reported).
void collide(const polyhedron_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const polyhedron_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const polyhedron_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const polyhedron_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const polyhedron_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const polyhedron_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const sphere_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const plane_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const box_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);

// Compound: through its children (a tree over them when there are many). Features carry the
// child index in `part`; where the child's own pair reports no feature, the compound's feature is
// {std::monostate, 0, part}.
void collide(const compound_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const sphere_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const plane_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const box_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const polyhedron_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);

// Triangle mesh: every convex shape and compounds (see triangle_mesh for the one-sided triangles
// and their internal edges). Features on the mesh are triangle features whose `part` is the
// triangle index. Meshes take their body's transform (unlike planes).
void collide(const sphere_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const box_shape &a, const mesh_shape &b, const collision_context &ctx, collision_result &result);
void collide(const polyhedron_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const mesh_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const mesh_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const mesh_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const mesh_shape &a, const box_shape &b, const collision_context &ctx, collision_result &result);
void collide(const mesh_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const mesh_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);

// Paged triangle mesh: as a mesh, against the pages that are loaded (see paged_triangle_mesh).
// Feature `part` numbers the triangle across pages.
void collide(const sphere_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const capsule_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const cylinder_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const box_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const polyhedron_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const compound_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const paged_mesh_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const paged_mesh_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const paged_mesh_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const paged_mesh_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const paged_mesh_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result);
void collide(const paged_mesh_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result);

// Any two shapes of a rigid body. Two static-only shapes (planes, meshes) report nothing.
void collide(const shapes_variant_t &a, const shapes_variant_t &b, const collision_context &ctx,
             collision_result &result);

// Swaps the roles of A and B in a context, for implementing (B, A) through (A, B).
constexpr collision_context swap_context(const collision_context &ctx) noexcept {
    return {ctx.posB, ctx.ornB, ctx.posA, ctx.ornA, ctx.threshold};
}

} // namespace edyn

#endif // EDYN_COLLISION_COLLIDE_HPP
