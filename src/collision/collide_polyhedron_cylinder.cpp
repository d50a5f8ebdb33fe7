#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/transform.hpp"

// Cylinder–polyhedron by separating axes in the polyhedron's space with exact projections,
// structured as cylinder–box. Candidate axes: the polyhedron's face normals and the cap normal
// (faces against anything), the cylinder axis crossed with the unique edge directions (side
// against edge), the directions from the cylinder's axis to each vertex (side against vertex),
// from each rim to each vertex (rim against vertex) and the closest points of each rim to each
// edge (rim against edge, through the quartic in circle_segment_critical_points). Rim–edge pairs
// that cannot hold the closest points are skipped: they must come within the threshold while the
// shapes are apart, and closer than the current depth while they overlap. The manifold clips the
// cylinder's supporting feature (cap disc, side line, rim point) against the polyhedron's (face
// polygon, edge, vertex) without approximating the cap.
namespace edyn {

namespace {

struct cylinder_polytope {
    detail::placed_cylinder cyl; // In the polyhedron's space.
    detail::polytope poly;
    detail::sat_result sat;

    void test(const vector3 &n) noexcept {
        scalar lo, hi;
        detail::polytope_interval(poly, n, lo, hi);
        auto mid = (lo + hi) * scalar(0.5);
        sat.test(n, dot(cyl.center, n) - mid, detail::cylinder_projection_radius(cyl, n),
                 (hi - lo) * scalar(0.5));
    }

    void test_direction(vector3 d) noexcept {
        if (try_normalize(d)) test(d);
    }

    // Axis through pa (on the cylinder) and pb (on the polyhedron), kept as a witness if they
    // are closest or deepest.
    void test_pair(const vector3 &pa, const vector3 &pb) noexcept {
        auto d = pa - pb;
        auto len = length(d);
        if (!(len > epsilon)) return;
        auto n = d / len;
        scalar lo, hi;
        detail::polytope_interval(poly, n, lo, hi);
        sat.test_witness(n, len, dot(cyl.center, n) - (lo + hi) * scalar(0.5),
                         detail::cylinder_projection_radius(cyl, n), (hi - lo) * scalar(0.5));
    }

    // A face's outward side only: its plane bounds the polyhedron, so no projection is needed.
    void test_face(std::uint32_t face) noexcept {
        const auto &n = poly.normals[face];
        auto sep =
            dot(cyl.center, n) - detail::cylinder_projection_radius(cyl, n) - poly.plane_constants[face];
        if (sep > sat.distance + sat.bias) {
            sat.distance = sep;
            sat.normal = n;
        }
    }
};

void test_vertices(cylinder_polytope &cp) noexcept {
    const auto &cyl = cp.cyl;
    auto top = cyl.center + cyl.axis * cyl.half_length, bottom = cyl.center - cyl.axis * cyl.half_length;
    for (const auto &v : cp.poly.vertices) {
        auto radial = v - cyl.center;
        cp.test_direction(project_plane(radial, cyl.axis));
        if (try_normalize_across(radial, cyl.axis)) {
            auto core = closest_point_segment(top, bottom, v);
            // A vertex touching the side: the side's normal is the pair's axis.
            auto side = core + radial * cyl.radius;
            if (distance(side, v) < cp.sat.coincident) cp.test(radial);
            cp.test_pair(side, v);
            cp.test_pair(core - radial * cyl.radius, v);
        }
        for (unsigned cap = 0; cap < 2; ++cap) {
            auto center = detail::cylinder_cap_center(cyl, cap);
            auto p = closest_point_circle(center, cyl.axis, cyl.radius, v);
            cp.test_pair(p, v);
            // The farthest rim point: the other critical point, which deep overlaps can need.
            cp.test_pair(center * 2 - p, v);
        }
    }
}

void test_edges(cylinder_polytope &cp, scalar threshold, scalar margin) noexcept {
    const auto &cyl = cp.cyl;
    const auto &poly = cp.poly;
    for (unsigned cap = 0; cap < 2; ++cap) {
        auto center = detail::cylinder_cap_center(cyl, cap);
        for (const auto &edge : poly.edges) {
            const auto &v0 = poly.vertices[edge[0]];
            const auto &v1 = poly.vertices[edge[1]];
            // Apart, a rim–edge pair beyond the threshold does not matter; overlapping, one
            // farther apart than the current depth cannot lessen it.
            auto reach = std::max(threshold, -cp.sat.distance) + margin;
            if (detail::segment_circle_distance_bound(v0, v1, center, cyl.axis, cyl.radius) > reach) continue;
            scalar t[detail::max_circle_segment_critical];
            auto count = detail::circle_segment_critical_points(center, cyl.axis, cyl.radius, v0, v1, t);
            for (std::size_t i = 0; i < count; ++i) {
                auto q = lerp(v0, v1, t[i]);
                auto p = closest_point_circle(center, cyl.axis, cyl.radius, q);
                cp.test_pair(p, q);
                // A rim that touches the edge crosses it there: the axis across the rim's tangent
                // and the edge is the pair's.
                if (distance(p, q) < cp.sat.coincident)
                    cp.test_direction(cross(cross(cyl.axis, p - center), v1 - v0));
                cp.test_pair(center * 2 - p, q);
            }
        }
    }
}

// The polyhedron's supporting edge or vertex as a contact feature for build_manifold().
detail::contact_feature point_or_segment(const detail::polytope &poly, const detail::polytope_feature &f,
                                         const vector3 &dir) noexcept {
    detail::contact_feature c;
    c.support = poly.vertices[detail::polytope_support_vertex(poly, dir)];
    if (f.kind == polyhedron_feature::edge) {
        c.kind = detail::contact_feature_kind::segment;
        c.vertices[0] = poly.vertices[poly.edges[f.index][0]];
        c.vertices[1] = poly.vertices[poly.edges[f.index][1]];
    } else {
        c.kind = detail::contact_feature_kind::point;
        c.vertices[0] = poly.vertices[f.index];
    }
    return c;
}

} // namespace

namespace detail {

void collide_cylinder_polytope(const cylinder_shape &a, const polytope &poly, const collision_context &ctx,
                               collision_result &result) noexcept {
    EDYN_ASSERT(a.radius > 0 && a.half_length > 0);
    // Everything happens in the polyhedron's space; `local` maps that space to each shape's own.
    auto orn_b_inv = conjugate(ctx.ornB);
    collision_context local{to_object_space(ctx.posA, ctx.posB, ctx.ornB), orn_b_inv * ctx.ornA, vector3_zero,
                            quaternion_identity, ctx.threshold};
    cylinder_polytope cp;
    cp.cyl = detail::place_cylinder(a, local.posA, local.ornA);
    cp.poly = poly;
    auto cyl_reach = std::sqrt(a.radius * a.radius + a.half_length * a.half_length);
    if (length(cp.cyl.center) - cyl_reach - cp.poly.bounding_radius > ctx.threshold) return;
    auto size = a.radius + a.half_length + cp.poly.bounding_radius;
    cp.sat.scale_to(size);

    for (std::uint32_t f = 0; f < cp.poly.faces.size(); ++f)
        cp.test_face(f);
    cp.test(cp.cyl.axis);
    for (const auto &u : cp.poly.unique_edge_directions)
        cp.test_direction(cross(cp.cyl.axis, u));
    if (cp.sat.distance > ctx.threshold) return;
    test_vertices(cp);
    if (cp.sat.distance > ctx.threshold) return;
    test_edges(cp, ctx.threshold, scalar(1e-4) * size);
    cp.sat.finish();
    if (cp.sat.distance > ctx.threshold) return;

    auto normal = cp.sat.normal;
    auto feature_a = detail::cylinder_support_feature(cp.cyl, -normal);
    auto feature_b = detail::polytope_support_feature(cp.poly, normal);
    if (feature_b.kind == polyhedron_feature::face) {
        detail::build_polygon_manifold(feature_a, cp.poly, feature_b.index, normal, local, ctx.ornB, result);
    } else {
        detail::build_manifold(feature_a, point_or_segment(cp.poly, feature_b, normal), normal, local,
                               ctx.ornB, result);
    }
}

} // namespace detail

void collide(const cylinder_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(b.mesh);
    detail::collide_cylinder_polytope(a, detail::make_polytope(*b.mesh), ctx, result);
}

void collide(const polyhedron_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
