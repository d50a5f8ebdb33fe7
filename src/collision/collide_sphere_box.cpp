#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"

namespace edyn {

void collide(const sphere_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    auto &he = b.half_extents;
    auto center = to_object_space(ctx.posA, ctx.posB, ctx.ornB);
    auto on_box = closest_point_box(he, center);
    auto d = center - on_box;
    auto dist_sqr = length_sqr(d);

    vector3 normal_local;
    scalar distance;
    collision_feature feature_b;
    if (dist_sqr > epsilon * epsilon) {
        auto dist = std::sqrt(dist_sqr);
        normal_local = d / dist;
        distance = dist - a.radius;
        // Clamped coordinates sit exactly on the bounds, which tells the feature.
        feature_b = detail::box_feature_at(he, on_box, 0);
    } else {
        // Centre inside: leave through the nearest face.
        scalar sign, depth;
        auto axis = nearest_box_face(he, center, sign, depth);
        normal_local = vector3_zero;
        normal_local[axis] = sign;
        on_box = center;
        on_box[axis] = sign * he[axis];
        distance = -depth - a.radius;
        feature_b = {box_feature::face, detail::box_face_index(axis, sign)};
    }
    if (distance > ctx.threshold) return;

    auto normal = rotate(ctx.ornB, normal_local);
    collision_result::collision_point p;
    p.pivotA = rotate(conjugate(ctx.ornA), -normal * a.radius);
    p.pivotB = on_box;
    p.normal = normal;
    p.distance = distance;
    p.featureB = feature_b;
    result.add_point(p);
}

void collide(const box_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
