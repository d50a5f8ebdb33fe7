#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"

namespace edyn {

// Every vertex within the threshold is a candidate; add_point keeps the deepest and the widest
// four when a thin box brings more than four under the threshold.
void collide(const box_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(std::abs(length_sqr(b.normal) - 1) < scalar(1e-3), "plane normal must be unit length");
    // Vertices in the plane's frame along the normal: centre height plus the rotated offsets.
    auto normal_local = rotate(conjugate(ctx.ornA), b.normal);
    auto center_dist = distance_point_plane(b.normal, b.constant, ctx.posA);
    // Early out: the lowest vertex is too far.
    if (center_dist - box_projection_radius(a.half_extents, normal_local) > ctx.threshold) return;

    for (unsigned i = 0; i < 8; ++i) {
        auto vertex = detail::box_vertex(a.half_extents, i);
        auto distance = center_dist + dot(normal_local, vertex);
        if (distance > ctx.threshold) continue;
        auto world = to_world_space(vertex, ctx.posA, ctx.ornA);
        collision_result::collision_point p;
        p.pivotA = vertex;
        p.pivotB = to_object_space(world - b.normal * distance, ctx.posB, ctx.ornB);
        p.normal = b.normal;
        p.distance = distance;
        p.featureA = collision_feature{box_feature::vertex, i};
        result.add_point(p);
    }
}

void collide(const plane_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
