#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"

namespace edyn {

namespace {

// Direction from B's segment to A's for segments that touch: across both axes when they cross,
// else off B's axis towards A's centre.
vector3 touching_normal(const detail::capsule_segment &sa, const detail::capsule_segment &sb,
                        const vector3 &a_minus_b) noexcept {
    auto n = cross(sa.axis, sb.axis);
    if (try_normalize(n)) {
        return dot(n, a_minus_b) < 0 ? -n : n;
    }
    return detail::orthogonal_towards(sb.axis, a_minus_b);
}

} // namespace

void collide(const capsule_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    auto sa = detail::make_capsule_segment(a, ctx.posA, ctx.ornA);
    auto sb = detail::make_capsule_segment(b, ctx.posB, ctx.ornB);
    auto closest = closest_points_segment_segment(sa.p0, sa.p1, sb.p0, sb.p1);
    auto radii = a.radius + b.radius;
    if (std::sqrt(closest.distance_sqr) - radii > ctx.threshold) return;

    for (std::size_t i = 0; i < closest.num_points; ++i) {
        auto d = closest.pointA[i] - closest.pointB[i];
        auto dist = length(d);
        auto distance = dist - radii;
        if (distance > ctx.threshold) continue;
        auto normal = dist > epsilon ? d / dist : touching_normal(sa, sb, ctx.posA - ctx.posB);
        auto on_a = closest.pointA[i] - normal * a.radius;
        auto on_b = closest.pointB[i] + normal * b.radius;
        auto p = detail::make_point(ctx, on_a, on_b, normal, distance);
        p.featureA = detail::capsule_feature_at(closest.sA[i], -normal, sa.axis);
        p.featureB = detail::capsule_feature_at(closest.sB[i], normal, sb.axis);
        result.add_point(p);
    }
}

} // namespace edyn
