#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"

// Polyhedron–sphere in the polyhedron's space: the closest point of the solid polyhedron to the
// sphere's centre is exact (face, edge or vertex region); a centre inside leaves through the
// face of least penetration.
namespace edyn {

namespace detail {

void collide_polytope_sphere(const polytope &poly, const sphere_shape &b, const collision_context &ctx,
                             collision_result &result) noexcept {
    EDYN_ASSERT(b.radius > 0);
    auto center = to_object_space(ctx.posB, ctx.posA, ctx.ornA);
    if (length(center) - poly.bounding_radius - b.radius > ctx.threshold) return;
    auto closest = detail::closest_point_polytope(poly, center);
    auto distance = closest.distance - b.radius;
    if (distance > ctx.threshold) return;
    // closest.normal points from the polyhedron out towards the centre: from A towards B.
    auto normal = rotate(ctx.ornA, -closest.normal);
    collision_result::collision_point p;
    p.pivotA = closest.point;
    p.pivotB = rotate(conjugate(ctx.ornB), normal * b.radius);
    p.normal = normal;
    p.distance = distance;
    result.add_point(p);
}

} // namespace detail

void collide(const polyhedron_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.mesh);
    detail::collide_polytope_sphere(detail::make_polytope(*a.mesh), b, ctx, result);
}

void collide(const sphere_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
