#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"

namespace edyn {

// Planes live in world space (they ignore their body's transform); the plane's pivot is the
// point on the plane given, as every pivot, in its body's object space.
void collide(const sphere_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(std::abs(length_sqr(b.normal) - 1) < scalar(1e-3), "plane normal must be unit length");
    auto center_dist = distance_point_plane(b.normal, b.constant, ctx.posA);
    auto distance = center_dist - a.radius;
    if (distance > ctx.threshold) return;
    collision_result::collision_point p;
    p.pivotA = rotate(conjugate(ctx.ornA), -b.normal * a.radius);
    p.pivotB = to_object_space(ctx.posA - b.normal * center_dist, ctx.posB, ctx.ornB);
    p.normal = b.normal;
    p.distance = distance;
    result.add_point(p);
}

void collide(const plane_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
