#ifndef EDYN_COLLISION_DETAIL_TRIANGLE_MESH_COLLISION_HPP
#define EDYN_COLLISION_DETAIL_TRIANGLE_MESH_COLLISION_HPP

#include "edyn/collision/collision_result.hpp"
#include "edyn/shapes/shapes.hpp"

// Convex shapes against a triangle mesh placed at ctx.posB/ornB: the body of collide(X,
// mesh_shape) (collide_mesh.cpp), shared with the paged meshes' sub-meshes. Features on B are
// triangle features with the triangle index in `part`.
namespace edyn::detail {

void collide_triangle_mesh(const sphere_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result);
void collide_triangle_mesh(const capsule_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result);
void collide_triangle_mesh(const cylinder_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result);
void collide_triangle_mesh(const box_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result);
void collide_triangle_mesh(const polyhedron_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result);

} // namespace edyn::detail

#endif // EDYN_COLLISION_DETAIL_TRIANGLE_MESH_COLLISION_HPP
