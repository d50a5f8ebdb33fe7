#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"

namespace edyn {

// The capsule's closest points to a plane are on its end hemispheres: one point per end within
// the threshold, two when it lies flat.
void collide(const capsule_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(std::abs(length_sqr(b.normal) - 1) < scalar(1e-3), "plane normal must be unit length");
    auto seg = detail::make_capsule_segment(a, ctx.posA, ctx.ornA);
    const vector3 ends[2] = {seg.p0, seg.p1};
    for (unsigned i = 0; i < 2; ++i) {
        auto center_dist = distance_point_plane(b.normal, b.constant, ends[i]);
        auto distance = center_dist - a.radius;
        if (distance > ctx.threshold) continue;
        collision_result::collision_point p;
        p.pivotA = to_object_space(ends[i] - b.normal * a.radius, ctx.posA, ctx.ornA);
        p.pivotB = to_object_space(ends[i] - b.normal * center_dist, ctx.posB, ctx.ornB);
        p.normal = b.normal;
        p.distance = distance;
        p.featureA = detail::capsule_feature_at(scalar(i), -b.normal, seg.axis);
        result.add_point(p);
    }
}

void collide(const plane_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
