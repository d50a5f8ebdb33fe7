#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"

// Cylinder–capsule by separating axes with exact projections: the capsule is its segment grown
// by its radius, so it projects to |dir.axis| half_length + radius. Candidate axes: the cap
// normal (a cap face against anything), the cylinder axis crossed with the segment (side against
// side, crossed), the line between the cylinder's axis segment and the capsule's segment (side
// against side, parallel), from the cylinder's axis to each capsule end (side against
// hemisphere), from each rim to each capsule end (rim against hemisphere) and the closest points
// of each rim to the segment (rim against the capsule's side).
namespace edyn {

namespace {

struct cylinder_capsule {
    detail::placed_cylinder cyl;
    detail::capsule_segment seg;
    vector3 seg_center;
    scalar half_length;
    scalar radius;
    detail::sat_result sat;

    void test(const vector3 &n) noexcept {
        auto capsule_radius = std::abs(dot(seg.axis, n)) * half_length + radius;
        sat.test(n, dot(cyl.center - seg_center, n), detail::cylinder_projection_radius(cyl, n),
                 capsule_radius);
    }

    void test_direction(vector3 d) noexcept {
        if (try_normalize(d)) test(d);
    }

    // Axes through pa (on the cylinder) and the capsule's surface points over `core` (a point of
    // its segment) nearest to and farthest from pa, kept as witnesses if closest or deepest. The
    // far side, and any `deep` pa (a far rim or side point), can only give the deepest pair, and
    // only if closer than the current depth.
    // Both pairs lie on the line from `core` through pa, so that line is their axis: taken from
    // pa - core, whose length is at least about the capsule's radius, and not from the pair's
    // points, which nearly coincide where the shapes touch.
    void test_pair(const vector3 &pa, const vector3 &core, bool deep = false) noexcept {
        auto towards = pa - core;
        auto reach = length(towards);
        if (!(reach > epsilon)) return;
        towards /= reach;
        for (auto side : {scalar(1), scalar(-1)}) {
            auto gap = reach - radius * side;
            auto len = std::abs(gap);
            if (!(len > epsilon)) {
                test(towards);
                continue;
            }
            if ((deep || side < 0) && !(len < sat.witness_tolerance - sat.distance)) continue;
            auto n = gap > 0 ? towards : -towards;
            auto capsule_radius = std::abs(dot(seg.axis, n)) * half_length + radius;
            sat.test_witness(n, len, dot(cyl.center - seg_center, n),
                             detail::cylinder_projection_radius(cyl, n), capsule_radius);
        }
    }

    // Both side points of the cylinder above the axis point `core` in the plane through `target`.
    void test_side_pairs(const vector3 &core, const vector3 &target) noexcept {
        auto radial = target - core;
        if (!try_normalize_across(radial, cyl.axis)) return;
        test_pair(core + radial * cyl.radius, target);
        test_pair(core - radial * cyl.radius, target, true);
    }
};

void test_rims(cylinder_capsule &cc) noexcept {
    const auto &cyl = cc.cyl;
    for (unsigned cap = 0; cap < 2; ++cap) {
        auto center = detail::cylinder_cap_center(cyl, cap);
        for (const auto &end : {cc.seg.p0, cc.seg.p1}) {
            auto p = closest_point_circle(center, cyl.axis, cyl.radius, end);
            cc.test_pair(p, end);
            // The farthest rim point: the other critical point, which deep overlaps can need.
            cc.test_pair(center * 2 - p, end, true);
        }
        scalar t[detail::max_circle_segment_critical];
        auto count =
            detail::circle_segment_critical_points(center, cyl.axis, cyl.radius, cc.seg.p0, cc.seg.p1, t);
        for (std::size_t i = 0; i < count; ++i) {
            auto q = lerp(cc.seg.p0, cc.seg.p1, t[i]);
            auto p = closest_point_circle(center, cyl.axis, cyl.radius, q);
            cc.test_pair(p, q);
            cc.test_pair(center * 2 - p, q, true);
        }
    }
}

} // namespace

void collide(const cylinder_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.radius > 0 && a.half_length > 0 && b.radius > 0 && b.half_length >= 0);
    cylinder_capsule cc;
    cc.cyl = detail::place_cylinder(a, ctx.posA, ctx.ornA);
    cc.seg = detail::make_capsule_segment(b, ctx.posB, ctx.ornB);
    cc.seg_center = ctx.posB;
    cc.half_length = b.half_length;
    cc.radius = b.radius;
    auto size = a.radius + a.half_length + b.radius + b.half_length;
    cc.sat.scale_to(size);
    const auto &cyl = cc.cyl;

    cc.test(cyl.axis);
    cc.test_direction(cross(cyl.axis, cc.seg.axis));
    auto a0 = cyl.center + cyl.axis * cyl.half_length, a1 = cyl.center - cyl.axis * cyl.half_length;
    auto axes = closest_points_segment_segment(a0, a1, cc.seg.p0, cc.seg.p1);
    cc.test_direction(axes.pointA[0] - axes.pointB[0]);
    cc.test_side_pairs(axes.pointA[0], axes.pointB[0]);
    for (const auto &end : {cc.seg.p0, cc.seg.p1}) {
        cc.test_side_pairs(closest_point_segment(a0, a1, end), end);
    }
    if (cc.sat.distance > ctx.threshold) return;
    test_rims(cc);
    cc.sat.finish();
    if (cc.sat.distance > ctx.threshold) return;

    auto normal = cc.sat.normal;
    auto feature_a = detail::cylinder_support_feature(cyl, -normal);
    auto feature_b = detail::capsule_support_feature(cc.seg.p0, cc.seg.p1, b.radius, normal);
    detail::build_manifold(feature_a, feature_b, normal, ctx, quaternion_identity, result);
}

void collide(const capsule_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
