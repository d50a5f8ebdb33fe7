#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/math/geom.hpp"

// Polyhedron–plane: every vertex within the threshold is a point, the deepest first, so that
// add_point keeps it and the widest four of the others.
namespace edyn {

void collide(const polyhedron_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.mesh);
    const auto &mesh = *a.mesh;
    auto center_dist = distance_point_plane(b.normal, b.constant, ctx.posA);
    if (center_dist - mesh.bounding_radius > ctx.threshold) return;
    // Heights of the vertices: the centre's plus the offsets along the normal in A's space.
    auto normal_local = rotate(conjugate(ctx.ornA), b.normal);
    auto deepest = mesh.support_vertex(-normal_local);
    if (center_dist + dot(normal_local, mesh.vertices[deepest]) > ctx.threshold) return;

    auto add = [&](std::size_t i) {
        const auto &vertex = mesh.vertices[i];
        auto distance = center_dist + dot(normal_local, vertex);
        if (distance > ctx.threshold) return;
        collision_result::collision_point p;
        p.pivotA = vertex;
        // The point on the plane, in its body's object space as every pivot.
        p.pivotB = to_object_space(to_world_space(vertex, ctx.posA, ctx.ornA) - b.normal * distance, ctx.posB,
                                   ctx.ornB);
        p.normal = b.normal;
        p.distance = distance;
        result.add_point(p);
    };
    add(deepest);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        if (i != deepest) add(i);
    }
}

void collide(const plane_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
