#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/transform.hpp"
#include <algorithm>

// Cylinder–sphere in the cylinder's space: the closest point of the solid cylinder to the
// sphere's centre is exact (clamp along the axis, clamp the radial offset). A centre inside the
// cylinder leaves through the nearer of its cap and its side.
namespace edyn {

namespace {

struct closest_on_cylinder {
    vector3 point;   // On the cylinder's surface, cylinder space.
    vector3 normal;  // Cylinder space, from the sphere's centre towards the cylinder (B to A).
    scalar distance; // Signed, between the centre and `point` along `normal`.
    collision_feature feature;
};

closest_on_cylinder closest_to_point(const cylinder_shape &cyl, const vector3 &p) noexcept {
    auto k = coordinate_axis_index(cyl.axis);
    auto axis = coordinate_axis_vector(cyl.axis);
    auto along = p[k];
    auto off_axis = p - axis * along;
    auto rho = length(off_axis);
    unsigned cap = along < 0 ? 1 : 0;
    auto cap_sign = along < 0 ? scalar(-1) : scalar(1);
    auto beyond_cap = std::abs(along) > cyl.half_length;
    auto beyond_side = rho > cyl.radius;
    closest_on_cylinder r;

    if (beyond_cap || beyond_side) {
        auto clamped_along = std::clamp(along, -cyl.half_length, cyl.half_length);
        auto radial = beyond_side ? off_axis * (cyl.radius / rho) : off_axis;
        r.point = radial + axis * clamped_along;
        auto w = r.point - p;
        r.distance = length(w);
        if (r.distance > epsilon * (cyl.radius + cyl.half_length)) {
            r.normal = w / r.distance;
            if (beyond_cap && beyond_side) {
                r.feature = {cylinder_feature::cap_edge, cap};
            } else if (beyond_cap) {
                r.feature = {cylinder_feature::face, cap};
            } else {
                r.feature = {cylinder_feature::side_edge, 0};
            }
            return r;
        }
    }

    // Inside (or on the surface): out through the nearer boundary.
    auto depth_cap = cyl.half_length - std::abs(along);
    auto depth_side = cyl.radius - rho;
    if (depth_cap <= depth_side) {
        r.point = off_axis + axis * (cyl.half_length * cap_sign);
        r.normal = -axis * cap_sign;
        r.distance = -depth_cap;
        r.feature = {cylinder_feature::face, cap};
    } else {
        auto radial = off_axis;
        if (!try_normalize(radial)) {
            vector3 t1;
            plane_space(axis, radial, t1);
        }
        r.point = radial * cyl.radius + axis * along;
        r.normal = -radial;
        r.distance = -depth_side;
        r.feature = {cylinder_feature::side_edge, 0};
    }
    return r;
}

} // namespace

void collide(const cylinder_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.radius > 0 && a.half_length > 0 && b.radius > 0);
    auto center = to_object_space(ctx.posB, ctx.posA, ctx.ornA);
    auto closest = closest_to_point(a, center);
    auto distance = closest.distance - b.radius;
    if (distance > ctx.threshold) return;
    auto normal = rotate(ctx.ornA, closest.normal);
    auto on_a = to_world_space(closest.point, ctx.posA, ctx.ornA);
    auto on_b = ctx.posB + normal * b.radius;
    auto p = detail::make_point(ctx, on_a, on_b, normal, distance);
    p.featureA = closest.feature;
    result.add_point(p);
}

void collide(const sphere_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
