#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include <utility>

// Cylinder–cylinder by separating axes with exact projections. The candidate axes are those
// along which two features can be closest: either cap normal (a cap face against anything), the
// cross product of the axes (side against side, crossed), the line between the axis segments
// (side against side, parallel), the closest points of each cap rim to the other's axis (rim
// against side) and of each rim to each rim of the other (solved numerically, see
// circle_circle_local_minima). Deep overlaps also need the far rim and side points of those
// pairs. Axes from point pairs are kept as witnesses (see sat_result). Axes that cannot beat the
// best one found are skipped: while the shapes are apart a rim pair counts only if each rim
// reaches the other's Voronoi region; while they overlap, only if the rims come closer than the
// current depth. While they are apart, the search ends at the first witness, which is then the
// closest pair (sat_result::closest_pair_found); to find one early, each cap facing the other
// shape gets a witness of its own and the rims are taken nearest first.
namespace edyn {

namespace {

using detail::placed_cylinder;

struct cylinder_pair {
    placed_cylinder a, b;
    vector3 delta; // a.center - b.center
    detail::sat_result sat;

    void test(const vector3 &n) noexcept {
        sat.test(n, dot(delta, n), detail::cylinder_projection_radius(a, n),
                 detail::cylinder_projection_radius(b, n));
    }

    void test_direction(vector3 d) noexcept {
        if (try_normalize(d)) test(d);
    }

    // Axis through pa (in A) and pb (in B), kept as a witness if they are closest or deepest.
    // A `deep` pair (far rim or far side points) can only be the deepest pair, and only if it is
    // closer than the current depth.
    void test_pair(const vector3 &pa, const vector3 &pb, bool deep = false) noexcept {
        auto d = pa - pb;
        auto len = length(d);
        if (!(len > epsilon)) return;
        if (deep && !(len < sat.witness_tolerance - sat.distance)) return;
        auto n = d / len;
        sat.test_witness(n, len, dot(delta, n), detail::cylinder_projection_radius(a, n),
                         detail::cylinder_projection_radius(b, n));
    }
};

// The side points of `cyl` above the axis point `core` in the plane through `target`: the nearer
// to it first. The farther one is the deepest in overlaps where `target` has passed the axis.
// Returns the side's outward normal at the nearer point (zero when `target` lies on the axis).
vector3 side_points(const placed_cylinder &cyl, const vector3 &core, const vector3 &target,
                    vector3 (&out)[2]) noexcept {
    auto radial = target - core;
    if (!try_normalize_across(radial, cyl.axis)) {
        out[0] = out[1] = core;
        return vector3_zero;
    }
    out[0] = core + radial * cyl.radius;
    out[1] = core - radial * cyl.radius;
    return radial;
}

// Whether some point of the circle (center, unit normal, radius) lies beyond cap `cap` of `cyl`
// and outside its side: the Voronoi region of that cap's rim, which a rim of the other shape
// must reach to hold the closest point while the shapes are apart.
bool circle_reaches_rim_region(const vector3 &center, const vector3 &normal, scalar radius,
                               const placed_cylinder &cyl, unsigned cap, scalar margin) noexcept {
    auto w = center - cyl.center;
    auto along = dot(w, cyl.axis) * detail::cylinder_cap_sign(cap);
    auto spread = radius * length(cross(normal, cyl.axis));
    if (along + spread < cyl.half_length - margin) return false;
    auto off_axis = length(project_plane(w, cyl.axis));
    return off_axis + radius >= cyl.radius - margin;
}

// A lower bound of the distance between two circles: from the centres, and from each circle to
// the other's plane.
scalar circle_circle_distance_bound(const vector3 &ca, const vector3 &na, scalar ra, const vector3 &cb,
                                    const vector3 &nb, scalar rb) noexcept {
    auto bound = distance(ca, cb) - ra - rb;
    auto tilt = length(cross(na, nb));
    bound = std::max(bound, std::abs(dot(cb - ca, na)) - rb * tilt);
    bound = std::max(bound, std::abs(dot(ca - cb, nb)) - ra * tilt);
    return bound;
}

// Rim `cap` of `rims` against the axis segment of `other`: where the rim runs past the other's side.
void test_rim_against_axis(cylinder_pair &pair, const placed_cylinder &rims, unsigned cap,
                           const placed_cylinder &other, bool rims_are_a) {
    auto p0 = other.center + other.axis * other.half_length;
    auto p1 = other.center - other.axis * other.half_length;
    auto center = detail::cylinder_cap_center(rims, cap);
    scalar t[detail::max_circle_segment_critical];
    auto count = detail::circle_segment_critical_points(center, rims.axis, rims.radius, p0, p1, t);
    for (std::size_t i = 0; i < count; ++i) {
        auto q = lerp(p0, p1, t[i]);
        auto p = closest_point_circle(center, rims.axis, rims.radius, q);
        // The closest rim point, and the farthest (the other critical point: deep overlaps).
        vector3 rim_points[2] = {p, center * 2 - p};
        for (int r = 0; r < 2; ++r) {
            vector3 sides[2];
            auto side_normal = side_points(other, q, rim_points[r], sides);
            // Where the rim touches the side, the side's normal is the pair's axis.
            if (r == 0 && side_normal != vector3_zero &&
                distance(rim_points[0], sides[0]) < pair.sat.coincident) {
                pair.test(side_normal);
            }
            for (int k = 0; k < 2; ++k) {
                auto deep = r + k > 0;
                if (rims_are_a) {
                    pair.test_pair(rim_points[r], sides[k], deep);
                } else {
                    pair.test_pair(sides[k], rim_points[r], deep);
                }
            }
        }
    }
}

// The four rims against the other's axis, nearest rim first, until a closest pair is known.
void test_rims_against_axes(cylinder_pair &pair) {
    struct rim {
        const placed_cylinder *rims, *other;
        unsigned cap;
        bool rims_are_a;
        scalar centre_distance_sqr; // from the cap's centre to the other's centre: the order
    };
    rim order[4];
    std::size_t n = 0;
    for (unsigned cap = 0; cap < 2; ++cap) {
        order[n++] = {&pair.a, &pair.b, cap, true,
                      distance_sqr(detail::cylinder_cap_center(pair.a, cap), pair.b.center)};
        order[n++] = {&pair.b, &pair.a, cap, false,
                      distance_sqr(detail::cylinder_cap_center(pair.b, cap), pair.a.center)};
    }
    for (std::size_t i = 1; i < n; ++i) {
        for (auto j = i; j > 0 && order[j].centre_distance_sqr < order[j - 1].centre_distance_sqr; --j)
            std::swap(order[j], order[j - 1]);
    }
    for (auto &r : order) {
        if (pair.sat.closest_pair_found()) return;
        test_rim_against_axis(pair, *r.rims, r.cap, *r.other, r.rims_are_a);
    }
}

// A witness for the cap of `cyl` that faces `other`: the point of `other` nearest to the cap's
// plane and its projection on the cap, when that falls on the cap. Then, if the two are apart,
// they are the closest pair, which the cap's axis alone cannot show.
void test_cap_witness(cylinder_pair &pair, const placed_cylinder &cyl, const placed_cylinder &other,
                      bool cyl_is_a) {
    auto n = cyl.axis;
    if (dot(other.center - cyl.center, n) < 0) n = -n;
    auto cap_center = cyl.center + n * cyl.half_length;
    // The part of `other` lowest along n: its support point, or, when its cap lies flat (any
    // point of the cap is one), the cap's point nearest to above this cap's centre.
    vector3 near;
    if (length_sqr(project_plane(n, other.axis)) > scalar(1e-12)) {
        near = detail::cylinder_support_point(other, -n);
    } else {
        auto end = detail::cylinder_cap_center(other, dot(other.axis, n) > 0 ? 1 : 0);
        near = closest_point_disc(end, other.axis, other.radius, cap_center);
    }
    auto height = dot(near - cap_center, n);
    if (!(height > 0)) return;
    auto on_cap = near - n * height;
    if (distance_sqr(on_cap, cap_center) > cyl.radius * cyl.radius) return;
    if (cyl_is_a) {
        pair.test_pair(on_cap, near);
    } else {
        pair.test_pair(near, on_cap);
    }
}

void test_rim_pairs(cylinder_pair &pair, scalar margin) {
    const auto &a = pair.a;
    const auto &b = pair.b;
    for (unsigned i = 0; i < 2; ++i) {
        auto ca = detail::cylinder_cap_center(a, i);
        for (unsigned j = 0; j < 2; ++j) {
            auto cb = detail::cylinder_cap_center(b, j);
            auto apart = circle_reaches_rim_region(ca, a.axis, a.radius, b, j, margin) &&
                         circle_reaches_rim_region(cb, b.axis, b.radius, a, i, margin);
            // Overlapping, the pair can only win by coming closer than the current depth.
            auto overlapping = pair.sat.distance < 0 &&
                               circle_circle_distance_bound(ca, a.axis, a.radius, cb, b.axis, b.radius) <
                                   -pair.sat.distance - pair.sat.bias;
            if (!apart && !overlapping) continue;
            vector3 on_a[detail::max_circle_circle_minima], on_b[detail::max_circle_circle_minima];
            auto count =
                detail::circle_circle_local_minima(ca, a.axis, a.radius, cb, b.axis, b.radius, on_a, on_b);
            for (std::size_t k = 0; k < count; ++k) {
                pair.test_pair(on_a[k], on_b[k]);
                // Rims that touch cross there: the axis across both tangents is the pair's.
                if (distance(on_a[k], on_b[k]) < pair.sat.coincident) {
                    pair.test_direction(cross(cross(a.axis, on_a[k] - ca), cross(b.axis, on_b[k] - cb)));
                }
            }
        }
    }
}

} // namespace

void collide(const cylinder_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.radius > 0 && a.half_length > 0 && b.radius > 0 && b.half_length > 0);
    cylinder_pair pair;
    pair.a = detail::place_cylinder(a, ctx.posA, ctx.ornA);
    pair.b = detail::place_cylinder(b, ctx.posB, ctx.ornB);
    pair.delta = pair.a.center - pair.b.center;
    auto size = a.radius + a.half_length + b.radius + b.half_length;
    pair.sat.scale_to(size);

    pair.test(pair.a.axis);
    pair.test(pair.b.axis);
    pair.test_direction(cross(pair.a.axis, pair.b.axis));
    auto a0 = pair.a.center + pair.a.axis * a.half_length, a1 = pair.a.center - pair.a.axis * a.half_length;
    auto b0 = pair.b.center + pair.b.axis * b.half_length, b1 = pair.b.center - pair.b.axis * b.half_length;
    auto axes = closest_points_segment_segment(a0, a1, b0, b1);
    pair.test_direction(axes.pointA[0] - axes.pointB[0]);
    vector3 sides_a[2], sides_b[2];
    side_points(pair.a, axes.pointA[0], axes.pointB[0], sides_a);
    side_points(pair.b, axes.pointB[0], axes.pointA[0], sides_b);
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j)
            pair.test_pair(sides_a[i], sides_b[j], i + j > 0);
    }
    if (pair.sat.distance > ctx.threshold) return;

    // A cap's witness can only hold where its axis already shows the shapes apart.
    if (pair.sat.distance > 0) {
        test_cap_witness(pair, pair.a, pair.b, true);
        test_cap_witness(pair, pair.b, pair.a, false);
    }
    test_rims_against_axes(pair);
    if (pair.sat.distance > ctx.threshold) return;
    if (!pair.sat.closest_pair_found()) test_rim_pairs(pair, scalar(1e-4) * size);
    pair.sat.finish();
    if (pair.sat.distance > ctx.threshold) return;

    auto normal = pair.sat.normal;
    auto feature_a = detail::cylinder_support_feature(pair.a, -normal);
    auto feature_b = detail::cylinder_support_feature(pair.b, normal);
    detail::build_manifold(feature_a, feature_b, normal, ctx, quaternion_identity, result);
}

} // namespace edyn
