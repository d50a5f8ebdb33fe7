#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"

namespace edyn {

void collide(const sphere_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    auto seg = detail::make_capsule_segment(b, ctx.posB, ctx.ornB);
    scalar s;
    auto on_segment = closest_point_segment(seg.p0, seg.p1, ctx.posA, s);
    auto d = ctx.posA - on_segment;
    auto dist = length(d);
    auto distance = dist - a.radius - b.radius;
    if (distance > ctx.threshold) return;
    auto normal = dist > epsilon ? d / dist : detail::orthogonal_towards(seg.axis, vector3_y);
    auto on_a = ctx.posA - normal * a.radius;
    auto on_b = on_segment + normal * b.radius;
    auto p = detail::make_point(ctx, on_a, on_b, normal, distance);
    p.featureB = detail::capsule_feature_at(s, normal, seg.axis);
    result.add_point(p);
}

void collide(const capsule_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
