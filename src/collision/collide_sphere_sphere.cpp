#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"

namespace edyn {

void collide(const sphere_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    auto d = ctx.posA - ctx.posB;
    auto dist = length(d);
    auto distance = dist - a.radius - b.radius;
    if (distance > ctx.threshold) return;
    // Concentric spheres separate equally in every direction: +y, the usual up.
    auto normal = dist > epsilon ? d / dist : vector3_y;
    auto on_a = ctx.posA - normal * a.radius;
    auto on_b = ctx.posB + normal * b.radius;
    result.add_point(detail::make_point(ctx, on_a, on_b, normal, distance));
}

} // namespace edyn
