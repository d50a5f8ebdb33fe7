#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/transform.hpp"

// Cylinder–box by separating axes in the box's space, with exact projections. Candidate axes:
// the box's face normals and the cap normal (faces against anything), the cylinder axis crossed
// with the box's edge directions (side against edge), the directions from the cylinder's axis to
// each box vertex (side against vertex), from each rim to each vertex (rim against vertex) and
// the closest points of each rim to each box edge (rim against edge, through the quartic in
// circle_segment_critical_points). Rim–edge pairs that cannot hold the closest points are
// skipped: while the shapes are apart the rim must reach the edge's Voronoi region; while they
// overlap it must come closer to the edge than the current depth.
namespace edyn {

namespace {

struct cylinder_box {
    detail::placed_cylinder cyl; // In the box's space.
    vector3 he;
    detail::sat_result sat;

    void test(const vector3 &n) noexcept {
        sat.test(n, dot(cyl.center, n), detail::cylinder_projection_radius(cyl, n),
                 box_projection_radius(he, n));
    }

    void test_direction(vector3 d) noexcept {
        if (try_normalize(d)) test(d);
    }

    // Axis through pa (on the cylinder) and pb (on the box), kept as a witness if they are
    // closest or deepest. A `deep` pair (a far rim or side point) can only be the deepest pair,
    // and only if it is closer than the current depth.
    void test_pair(const vector3 &pa, const vector3 &pb, bool deep = false) noexcept {
        auto d = pa - pb;
        auto len = length(d);
        if (!(len > epsilon)) return;
        if (deep && !(len < sat.witness_tolerance - sat.distance)) return;
        auto n = d / len;
        sat.test_witness(n, len, dot(cyl.center, n), detail::cylinder_projection_radius(cyl, n),
                         box_projection_radius(he, n));
    }
};

// Whether the circle (center, unit normal, radius) has a point in the Voronoi region of box edge
// `edge`: beyond both faces that meet there and within the edge's length.
bool circle_reaches_edge_region(const vector3 &he, unsigned edge, const vector3 &center,
                                const vector3 &normal, scalar radius, scalar margin) noexcept {
    auto axis = detail::box_edge_axis(edge);
    vector3 v0, v1;
    detail::box_edge_vertices(he, edge, v0, v1);
    for (int k = 0; k < 3; ++k) {
        auto spread = radius * length_across_axis(normal, k);
        if (k == axis) {
            if (std::abs(center[k]) - spread > he[k] + margin) return false;
        } else {
            auto sign = detail::sign_of(v0[k]);
            if (center[k] * sign + spread < he[k] - margin) return false;
        }
    }
    return true;
}

// Lower bound of the distance between the box edge [v0, v1] and the circle.
scalar edge_circle_distance_bound(const vector3 &v0, const vector3 &v1, const vector3 &center,
                                  const vector3 &normal, scalar radius) noexcept {
    auto bound = std::sqrt(distance_sqr_point_segment(v0, v1, center)) - radius;
    auto h0 = dot(v0 - center, normal), h1 = dot(v1 - center, normal);
    if ((h0 > 0) == (h1 > 0)) bound = std::max(bound, std::min(std::abs(h0), std::abs(h1)));
    return bound;
}

// Whether the box (centred at `center`, `half` its half extents) reaches the Voronoi region of
// vertex `v`: the octant beyond it.
bool reaches_vertex_region(const vector3 &he, const vector3 &v, const vector3 &center, const vector3 &half,
                           scalar margin) noexcept {
    for (int k = 0; k < 3; ++k) {
        if (center[k] * detail::sign_of(v[k]) + half[k] < he[k] - margin) return false;
    }
    return true;
}

void test_vertices(cylinder_box &cb, scalar margin) noexcept {
    const auto &cyl = cb.cyl;
    auto depth = -cb.sat.distance - cb.sat.bias;
    // Extents of the cylinder's and of a rim's bounding boxes.
    vector3 rim_half, cyl_half;
    for (int k = 0; k < 3; ++k) {
        rim_half[k] = cyl.radius * length_across_axis(cyl.axis, k);
        cyl_half[k] = rim_half[k] + cyl.half_length * std::abs(cyl.axis[k]);
    }
    auto a0 = cyl.center + cyl.axis * cyl.half_length, a1 = cyl.center - cyl.axis * cyl.half_length;
    for (unsigned i = 0; i < 8; ++i) {
        auto v = detail::box_vertex(cb.he, i);
        // Apart, a pair counts only if it reaches the vertex's region; overlapping, only if it
        // comes closer than the current depth.
        auto core = closest_point_segment(a0, a1, v);
        auto off_axis = distance(core, v);
        if (reaches_vertex_region(cb.he, v, cyl.center, cyl_half, margin) ||
            (depth > 0 && std::abs(off_axis - cyl.radius) < depth)) {
            auto radial = v - cyl.center;
            if (try_normalize_across(radial, cyl.axis)) {
                // A vertex touching the side: the side's normal is the pair's axis.
                auto side = core + radial * cyl.radius;
                if (distance(side, v) < cb.sat.coincident) cb.test(radial);
                cb.test_pair(side, v);
                cb.test_pair(core - radial * cyl.radius, v, true);
            }
        }
        for (unsigned cap = 0; cap < 2; ++cap) {
            auto center = detail::cylinder_cap_center(cyl, cap);
            auto w = v - center;
            auto bound = std::max(length(w) - cyl.radius, std::abs(dot(w, cyl.axis)));
            if (!reaches_vertex_region(cb.he, v, center, rim_half, margin) && !(depth > 0 && bound < depth))
                continue;
            auto p = closest_point_circle(center, cyl.axis, cyl.radius, v);
            cb.test_pair(p, v);
            // The farthest rim point: the other critical point, which deep overlaps can need.
            cb.test_pair(center * 2 - p, v, true);
        }
    }
}

void test_edges(cylinder_box &cb, scalar margin) noexcept {
    const auto &cyl = cb.cyl;
    for (unsigned cap = 0; cap < 2; ++cap) {
        auto center = detail::cylinder_cap_center(cyl, cap);
        for (unsigned edge = 0; edge < 12; ++edge) {
            vector3 v0, v1;
            detail::box_edge_vertices(cb.he, edge, v0, v1);
            auto apart = circle_reaches_edge_region(cb.he, edge, center, cyl.axis, cyl.radius, margin);
            // Overlapping, the pair can only win by coming closer than the current depth.
            auto overlapping =
                cb.sat.distance < 0 && edge_circle_distance_bound(v0, v1, center, cyl.axis, cyl.radius) <
                                           -cb.sat.distance - cb.sat.bias;
            if (!apart && !overlapping) continue;
            scalar t[detail::max_circle_segment_critical];
            auto count = detail::circle_segment_critical_points(center, cyl.axis, cyl.radius, v0, v1, t);
            for (std::size_t i = 0; i < count; ++i) {
                auto q = lerp(v0, v1, t[i]);
                auto p = closest_point_circle(center, cyl.axis, cyl.radius, q);
                cb.test_pair(p, q);
                // A rim that touches the edge crosses it there: the axis across the rim's tangent
                // and the edge is the pair's.
                if (distance(p, q) < cb.sat.coincident)
                    cb.test_direction(cross(cross(cyl.axis, p - center), v1 - v0));
                cb.test_pair(center * 2 - p, q, true);
            }
        }
    }
}

} // namespace

void collide(const cylinder_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.radius > 0 && a.half_length > 0);
    EDYN_ASSERT(b.half_extents.x > 0 && b.half_extents.y > 0 && b.half_extents.z > 0);
    // Everything happens in the box's space; `local` maps that space to each shape's own.
    auto orn_b_inv = conjugate(ctx.ornB);
    collision_context local{to_object_space(ctx.posA, ctx.posB, ctx.ornB), orn_b_inv * ctx.ornA, vector3_zero,
                            quaternion_identity, ctx.threshold};
    cylinder_box cb;
    cb.cyl = detail::place_cylinder(a, local.posA, local.ornA);
    cb.he = b.half_extents;
    auto size = a.radius + a.half_length + b.half_extents.x + b.half_extents.y + b.half_extents.z;
    cb.sat.scale_to(size);

    cb.test(vector3_x);
    cb.test(vector3_y);
    cb.test(vector3_z);
    cb.test(cb.cyl.axis);
    cb.test_direction(cross(cb.cyl.axis, vector3_x));
    cb.test_direction(cross(cb.cyl.axis, vector3_y));
    cb.test_direction(cross(cb.cyl.axis, vector3_z));
    if (cb.sat.distance > ctx.threshold) return;
    test_vertices(cb, scalar(1e-4) * size);
    if (cb.sat.distance > ctx.threshold) return;
    test_edges(cb, scalar(1e-4) * size);
    cb.sat.finish();
    if (cb.sat.distance > ctx.threshold) return;

    auto normal = cb.sat.normal;
    auto feature_a = detail::cylinder_support_feature(cb.cyl, -normal);
    auto feature_b = detail::box_support_feature(cb.he, normal);
    detail::build_manifold(feature_a, feature_b, normal, local, ctx.ornB, result);
}

void collide(const box_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
