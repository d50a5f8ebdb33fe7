#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include <cmath>

// build_manifold() (collide_cylinder_manifold.cpp) for a polyhedron face of any number of
// vertices: the same candidate points, lifts, tolerances and fallbacks, with the quadrilateral
// loops made polygon loops. Candidates are generated twice instead of stored (once to find the
// deepest, which goes first, once to add them all), so no buffer bounds the face's size.
namespace edyn::detail {

namespace {

using kind = contact_feature_kind;

// Relative tolerance of the inside tests, so that points on a boundary survive rounding (as in
// build_manifold).
constexpr scalar inside_tolerance = scalar(1e-4);

struct polygon_manifold {
    const contact_feature &a;
    const polytope &poly;
    std::size_t face;
    vector3 normal; // Frame of ctx, from B towards A.
    const collision_context &ctx;
    vector3 world_normal;
    collision_result &result;
    // First pass: find the deepest point (added first, as build_manifold sorts by depth, so that
    // add_point keeps it and grows the area from it); second pass: add every point.
    bool emit{false};
    bool kept{false};
    scalar deepest{large_scalar};
    vector3 deepest_a{vector3_zero}, deepest_b{vector3_zero};

    std::uint32_t count() const noexcept { return poly.face_size(face); }
    const vector3 &vertex(std::size_t k) const noexcept { return poly.face_vertex(face, k % count()); }

    // x moved along the normal onto the surface through A's feature that build_manifold lifts
    // onto: a cap's plane; for a side line the plane holding it spanned with the direction
    // across it in the plane of the normal; for a point or a tilted cap's deepest rim point the
    // plane through it across the normal.
    vector3 lifted_a(const vector3 &x) const noexcept {
        scalar t;
        if (a.kind == kind::segment) {
            auto d = a.vertices[1] - a.vertices[0];
            auto len_sqr = length_sqr(d);
            auto m = len_sqr > epsilon * epsilon ? normal - d * (dot(normal, d) / len_sqr) : normal;
            auto mn = dot(m, normal);
            t = mn > epsilon ? dot(a.vertices[0] - x, m) / mn : dot(a.vertices[0] - x, normal);
        } else if (a.kind == kind::disc) {
            auto dn = dot(a.normal, normal);
            t = std::abs(dn) > epsilon ? dot(a.center - x, a.normal) / dn : dot(a.center - x, normal);
        } else {
            t = dot(a.vertices[0] - x, normal);
        }
        return x + normal * t;
    }

    // x moved along the normal onto the face's plane.
    vector3 lifted_face(const vector3 &x) const noexcept {
        const auto &n = poly.normals[face];
        auto dn = dot(n, normal);
        auto t = std::abs(dn) > epsilon ? -poly.face_distance(face, x) / dn : dot(vertex(0) - x, normal);
        return x + normal * t;
    }

    // Whether y (in the plane of a polygon whose vertices `at(k)` turn counter-clockwise about
    // orientation * plane_normal) lies inside it, up to the relative tolerance.
    template<typename At>
    bool inside(At &&at, const vector3 &plane_normal, scalar orientation, const vector3 &y) const noexcept {
        for (std::uint32_t k = 0; k < count(); ++k) {
            auto v0 = at(k);
            auto e = at(k + 1) - v0;
            if (dot(cross(e, plane_normal) * orientation, y - v0) > inside_tolerance * length_sqr(e))
                return false;
        }
        return true;
    }

    // y on the face's plane lies on the face.
    bool on_face(const vector3 &y) const noexcept {
        return inside([&](std::size_t k) { return vertex(k); }, poly.normals[face], 1, y);
    }

    bool over_face(const vector3 &y) const noexcept { return on_face(lifted_face(y)); }

    // y on A's lift surface lies on A's feature (as build_manifold decides).
    bool on_feature_a(const vector3 &y) const noexcept {
        if (a.kind == kind::segment) {
            auto tolerance_sqr =
                square(inside_tolerance) * distance_sqr(a.vertices[0], a.vertices[1]) + epsilon * epsilon;
            return distance_sqr_point_segment(a.vertices[0], a.vertices[1], y) <= tolerance_sqr;
        }
        if (a.kind == kind::disc)
            return distance_sqr(y, a.center) <= square(a.radius * (1 + inside_tolerance));
        return true;
    }

    void add_pair(const vector3 &point_a, const vector3 &point_b) {
        auto distance = dot(point_a - point_b, normal);
        if (distance > ctx.threshold) return;
        if (!emit) {
            if (distance < deepest) {
                deepest = distance;
                deepest_a = point_a;
                deepest_b = point_b;
            }
            return;
        }
        auto p = make_point(ctx, point_a, point_b, world_normal, distance);
        if (a.has_id) p.featureA = a.id;
        result.add_point(p);
    }

    // A candidate on A's feature (on_a) or on the face, lifted onto the other one; kept only
    // when both pivots lie on their features.
    void add(const vector3 &position, bool on_a) {
        auto point_a = on_a ? position : lifted_a(position);
        auto point_b = on_a ? lifted_face(position) : position;
        if (!on_feature_a(point_a) || !on_face(point_b)) return;
        kept = true;
        add_pair(point_a, point_b);
    }
};

// A cap disc against the face: the corners of their overlap (circle–edge crossings, face corners
// inside the circle) and the circle's extreme points along the face's first edge, across it and
// towards the other shape, inside the face. Worked out in the disc's plane.
void disc_polygon(polygon_manifold &pm) {
    const auto &disc = pm.a;
    auto q = [&](std::size_t k) { return pm.lifted_a(pm.vertex(k)); };
    // Lifting along the normal keeps the face's turn, seen through the two planes' normals.
    auto orientation =
        dot(pm.poly.normals[pm.face], pm.normal) * dot(disc.normal, pm.normal) < 0 ? scalar(-1) : scalar(1);
    auto r_sqr = square(disc.radius);
    for (std::uint32_t k = 0; k < pm.count(); ++k) {
        auto q0 = q(k), q1 = q(k + 1);
        if (distance_sqr(q0, disc.center) <= r_sqr) pm.add(q0, true);
        scalar t0, t1;
        if (!clip_segment_sphere(q0, q1, disc.center, disc.radius, t0, t1)) continue;
        if (t0 > 0) pm.add(lerp(q0, q1, t0), true);
        if (t1 < 1) pm.add(lerp(q0, q1, t1), true);
    }
    auto u = project_plane(q(1) - q(0), disc.normal);
    if (!try_normalize(u)) {
        vector3 t1;
        plane_space(disc.normal, u, t1);
    }
    auto v = cross(disc.normal, u);
    vector3 dirs[5] = {u, -u, v, -v, project_plane(disc.vertices[0] - disc.center, disc.normal)};
    for (auto &d : dirs) {
        if (!try_normalize(d)) continue;
        auto y = disc.center + d * disc.radius;
        if (pm.inside(q, disc.normal, orientation, y)) pm.add(y, true);
    }
}

// A tilted cap against the face: the deepest rim point, plus the rim points a quarter, half and
// three quarters of a turn away when they lie over the face.
void rim_polygon(polygon_manifold &pm) {
    const auto &rim = pm.a;
    pm.add(rim.vertices[0], true);
    auto u = (rim.vertices[0] - rim.center) / rim.radius;
    auto v = cross(rim.normal, u);
    for (const auto &dir : {v, -u, -v}) {
        auto y = rim.center + dir * rim.radius;
        if (pm.over_face(y)) pm.add(y, true);
    }
}

// A side line against the face: the part of the line over the face.
void segment_polygon(polygon_manifold &pm) {
    auto p0 = pm.lifted_face(pm.a.vertices[0]);
    auto p1 = pm.lifted_face(pm.a.vertices[1]);
    auto dir = p1 - p0;
    const auto &n = pm.poly.normals[pm.face];
    scalar t0 = 0, t1 = 1;
    for (std::uint32_t k = 0; k < pm.count(); ++k) {
        const auto &v0 = pm.vertex(k);
        auto side = cross(pm.vertex(k + 1) - v0, n);
        // Missed (the fallbacks of build_polygon_manifold take over).
        if (!clip_line_interval(p0, dir, side, dot(side, v0), t0, t1)) return;
    }
    pm.add(p0 + dir * t0, false);
    pm.add(p0 + dir * t1, false);
}

void gather(polygon_manifold &pm) {
    switch (pm.a.kind) {
    case kind::disc:
        disc_polygon(pm);
        return;
    case kind::rim:
        rim_polygon(pm);
        return;
    case kind::segment:
        segment_polygon(pm);
        return;
    case kind::point:
    case kind::polygon:
    default:
        // A vertex (or, never here, a polygon): its one point lifted onto the face.
        pm.add(pm.a.vertices[0], true);
        return;
    }
}

} // namespace

void build_polygon_manifold(const contact_feature &a, const polytope &poly, std::size_t face,
                            const vector3 &normal, const collision_context &ctx, const quaternion &to_world,
                            collision_result &result) noexcept {
    polygon_manifold pm{a, poly, face, normal, ctx, rotate(to_world, normal), result};
    gather(pm);
    if (!pm.kept) {
        // The projections missed each other: the features were taken within feature_tolerance
        // of the normal while the contact is at a support point. As build_manifold: A's support
        // on the face, else B's support (its vertex farthest along the normal) on A's feature,
        // else the two support points themselves.
        pm.emit = true;
        pm.add(a.support, true);
        if (!pm.kept) {
            auto b_support = poly.vertices[polytope_support_vertex(poly, normal)];
            pm.add(b_support, false);
            if (!pm.kept) pm.add_pair(a.support, a.support + normal * dot(b_support - a.support, normal));
        }
        return;
    }
    if (pm.deepest < large_scalar) {
        pm.emit = true;
        pm.add_pair(pm.deepest_a, pm.deepest_b);
        // The deepest point comes again below; add_point merges it with itself.
        gather(pm);
    }
}

} // namespace edyn::detail
