#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/geom.hpp"

// Cylinder–plane. The plane lives in world space (it ignores its body's transform); its pivot is
// the point on the plane in its body's object space, as every pivot. The points are chosen for a resting
// cylinder to be stable: lying on its side, the two ends of the lowest side line; otherwise four points of
// the lower cap's rim, the deepest one and those a quarter, half and three quarters of a turn away, so that a
// cylinder standing on a cap gets four points and a tilted one its deepest rim point plus whichever others
// come within the threshold.
namespace edyn {

void collide(const cylinder_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.radius > 0 && a.half_length > 0);
    auto cyl = detail::place_cylinder(a, ctx.posA, ctx.ornA);
    auto feature = detail::cylinder_support_feature(cyl, -b.normal);
    vector3 points[4];
    std::size_t count = 0;
    if (feature.kind == detail::contact_feature_kind::segment) {
        points[count++] = feature.vertices[0];
        points[count++] = feature.vertices[1];
    } else {
        // Disc or rim: vertices[0] is the deepest rim point.
        auto u = feature.vertices[0] - feature.center;
        auto v = cross(feature.normal, u);
        points[count++] = feature.vertices[0];
        points[count++] = feature.center + v;
        points[count++] = feature.center - u;
        points[count++] = feature.center - v;
    }
    for (std::size_t i = 0; i < count; ++i) {
        auto distance = distance_point_plane(b.normal, b.constant, points[i]);
        if (distance > ctx.threshold) continue;
        collision_result::collision_point p;
        p.pivotA = to_object_space(points[i], ctx.posA, ctx.ornA);
        p.pivotB = to_object_space(points[i] - b.normal * distance, ctx.posB, ctx.ornB);
        p.normal = b.normal;
        p.distance = distance;
        p.featureA = feature.id;
        result.add_point(p);
    }
}

void collide(const plane_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
