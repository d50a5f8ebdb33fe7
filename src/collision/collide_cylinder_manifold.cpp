#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include <algorithm>
#include <cmath>
#include <optional>

// Manifolds for the pairs with a cylinder. The two supporting features are intersected in
// projection along the contact normal; every candidate point lies on one of them and is lifted
// along the normal onto the other, so the pivots of a point differ by exactly its distance along
// the normal. Caps are handled as true discs: the circle is intersected analytically with
// polygon edges, segments and the other cap's rim.
namespace edyn::detail {

namespace {

using kind = contact_feature_kind;

// Room for a disc against a quadrilateral: 8 edge crossings, 4 corners, 5 rim points.
constexpr std::size_t max_candidates = 20;

// Relative tolerance of the inside tests, so that points on a boundary survive rounding.
constexpr scalar inside_tolerance = scalar(1e-4);

// How much shallower than the shapes' separation along the normal (as a fraction of the
// threshold: 0.2 mm at the default 2 cm) a manifold's deepest point may be before the support
// points are added to it.
constexpr scalar deepest_point_tolerance = scalar(0.01);

struct candidate {
    vector3 position;
    bool on_a; // Lies on A's feature (else on B's).
};

struct candidate_list {
    candidate items[max_candidates];
    std::size_t count{0};

    void add(const vector3 &p, bool on_a) noexcept {
        if (count < max_candidates) items[count++] = {p, on_a};
    }
};

// Parameter t such that x + normal * t lies on the surface through the feature that the lift
// uses: the plane of a disc or polygon; for a segment the plane holding it and spanned with the
// in-plane direction across it; for a point, or a tilted cap's deepest rim point, the plane
// through it normal to `normal`.
scalar lift(const contact_feature &f, const vector3 &normal, const vector3 &x) noexcept {
    switch (f.kind) {
    case kind::point:
    case kind::rim:
        return dot(f.vertices[0] - x, normal);
    case kind::segment: {
        auto d = f.vertices[1] - f.vertices[0];
        auto len_sqr = length_sqr(d);
        if (len_sqr <= epsilon * epsilon) return dot(f.vertices[0] - x, normal);
        auto m = normal - d * (dot(normal, d) / len_sqr);
        auto mn = dot(m, normal);
        if (mn <= epsilon) return dot(f.vertices[0] - x, normal);
        return dot(f.vertices[0] - x, m) / mn;
    }
    case kind::polygon: {
        auto dn = dot(f.normal, normal);
        if (std::abs(dn) <= epsilon) return dot(f.vertices[0] - x, normal);
        return dot(f.vertices[0] - x, f.normal) / dn;
    }
    case kind::disc:
    default: {
        auto dn = dot(f.normal, normal);
        if (std::abs(dn) <= epsilon) return dot(f.center - x, normal);
        return dot(f.center - x, f.normal) / dn;
    }
    }
}

vector3 lifted(const contact_feature &f, const vector3 &normal, const vector3 &x) noexcept {
    return x + normal * lift(f, normal, x);
}

bool inside_disc(const contact_feature &disc, const vector3 &normal, const vector3 &x) noexcept {
    auto r = disc.radius * (scalar(1) + inside_tolerance);
    return distance_sqr(lifted(disc, normal, x), disc.center) <= r * r;
}

// A convex quadrilateral's edges as half-planes, for repeated inside tests: `outward[k]` is the
// unit outward normal of the edge from v[k] to v[k + 1] within the plane of unit normal
// `plane_normal`; the vertices turn counter-clockwise about orientation * plane_normal.
struct quad_sides {
    vector3 v[4];
    vector3 outward[4];
    scalar slack[4]; // Tolerance of the inside test per edge.

    quad_sides(const vector3 *vertices, const vector3 &plane_normal, scalar orientation) noexcept {
        for (std::size_t k = 0; k < 4; ++k) {
            v[k] = vertices[k];
            auto edge = vertices[(k + 1) % 4] - vertices[k];
            auto len = length(edge);
            outward[k] = len > epsilon ? cross(edge, plane_normal) * (orientation / len) : vector3_zero;
            slack[k] = inside_tolerance * len;
        }
    }

    bool contains(const vector3 &y) const noexcept {
        for (std::size_t k = 0; k < 4; ++k) {
            if (dot(outward[k], y - v[k]) > slack[k]) return false;
        }
        return true;
    }
};

// A cap disc against a box face: the corners of their overlap (circle-edge crossings, face
// corners inside the circle) and the circle's extreme points along the face's edges and towards
// the other shape, inside the face. Worked out in the disc's plane.
void disc_polygon(const contact_feature &disc, bool disc_is_a, const contact_feature &poly,
                  const vector3 &normal, candidate_list &out) noexcept {
    vector3 q[4];
    for (int k = 0; k < 4; ++k) {
        q[k] = lifted(disc, normal, poly.vertices[k]);
    }
    auto orientation = dot(cross(q[1] - q[0], q[2] - q[1]), disc.normal) < 0 ? scalar(-1) : scalar(1);
    quad_sides sides(q, disc.normal, orientation);
    for (std::size_t k = 0; k < 4; ++k) {
        const auto &q0 = q[k];
        const auto &q1 = q[(k + 1) % 4];
        if (distance_sqr(q0, disc.center) <= square(disc.radius)) out.add(q0, disc_is_a);
        scalar t0, t1;
        if (!clip_segment_sphere(q0, q1, disc.center, disc.radius, t0, t1)) continue;
        if (t0 > 0) out.add(lerp(q0, q1, t0), disc_is_a);
        if (t1 < 1) out.add(lerp(q0, q1, t1), disc_is_a);
    }
    vector3 dirs[5] = {q[1] - q[0], q[0] - q[1], q[2] - q[1], q[1] - q[2], disc.vertices[0] - disc.center};
    for (auto &d : dirs) {
        d = project_plane(d, disc.normal);
        if (!try_normalize(d)) continue;
        auto y = disc.center + d * disc.radius;
        if (sides.contains(y)) out.add(y, disc_is_a);
    }
}

// Newton's method on the angle of a point of disc A's rim so that its lift onto disc B's plane
// lands on B's rim: makes the crossings of two tilted caps' outlines exact.
vector3 refine_rim_crossing(const contact_feature &a, const contact_feature &b, const vector3 &normal,
                            const vector3 &u, const vector3 &v, scalar angle) noexcept {
    auto dn = dot(b.normal, normal);
    for (int iteration = 0; iteration < 4; ++iteration) {
        auto c = std::cos(angle), s = std::sin(angle);
        auto p = a.center + (u * c + v * s) * a.radius;
        auto dp = (v * c - u * s) * a.radius;
        auto y = lifted(b, normal, p) - b.center;
        auto dy = dp - normal * (dot(dp, b.normal) / dn);
        auto g = dot(y, y) - b.radius * b.radius;
        auto dg = 2 * dot(y, dy);
        if (std::abs(dg) <= epsilon * b.radius * b.radius) break;
        angle -= g / dg;
    }
    return a.center + (u * std::cos(angle) + v * std::sin(angle)) * a.radius;
}

// Rim points of disc `d` along the line of centres (towards `other_center`), across it, and at
// its deepest point, that lie over disc `other`.
void rim_points_over(const contact_feature &d, bool d_is_a, const contact_feature &other,
                     const vector3 &other_center, const vector3 &normal, candidate_list &out) noexcept {
    auto u = project_plane(other_center - d.center, d.normal);
    if (!try_normalize(u)) {
        vector3 t1;
        plane_space(d.normal, u, t1);
    }
    auto v = cross(d.normal, u);
    vector3 dirs[5] = {u, -u, v, -v, project_plane(d.vertices[0] - d.center, d.normal)};
    for (auto &dir : dirs) {
        if (!try_normalize(dir)) continue;
        auto y = d.center + dir * d.radius;
        if (inside_disc(other, normal, y)) out.add(y, d_is_a);
    }
}

// Cap on cap: the crossings of the two outlines plus each rim's points over the other disc (a
// lens gives its two corners and two tips; nested discs give the inner rim).
void disc_disc(const contact_feature &a, const contact_feature &b, const vector3 &normal,
               candidate_list &out) noexcept {
    auto b_center = lifted(a, normal, b.center);
    auto a_center = lifted(b, normal, a.center);
    auto u = b_center - a.center;
    auto d = length(u);
    if (d > epsilon * a.radius && d < a.radius + b.radius && d > std::abs(a.radius - b.radius)) {
        u /= d;
        auto v = cross(a.normal, u);
        auto cos_angle = (d * d + a.radius * a.radius - b.radius * b.radius) / (2 * d * a.radius);
        auto angle = std::acos(std::clamp(cos_angle, scalar(-1), scalar(1)));
        out.add(refine_rim_crossing(a, b, normal, u, v, angle), true);
        out.add(refine_rim_crossing(a, b, normal, u, v, -angle), true);
    }
    rim_points_over(a, true, b, b_center, normal, out);
    rim_points_over(b, false, a, a_center, normal, out);
}

// A tilted cap against a face: the deepest rim point, plus the rim points a quarter, half and
// three quarters of a turn away when they lie over the face (the threshold drops those too
// high).
void rim_face(const contact_feature &rim, bool rim_is_a, const contact_feature &face, const vector3 &normal,
              candidate_list &out) noexcept {
    out.add(rim.vertices[0], rim_is_a);
    auto u = (rim.vertices[0] - rim.center) / rim.radius;
    auto v = cross(rim.normal, u);
    vector3 others[3] = {v, -u, -v};
    for (const auto &dir : others) {
        auto y = rim.center + dir * rim.radius;
        bool over = false;
        if (face.kind == kind::disc) {
            over = inside_disc(face, normal, y);
        } else {
            // Box faces turn counter-clockwise about their outward normal.
            over = quad_sides(face.vertices, face.normal, 1).contains(lifted(face, normal, y));
        }
        if (over) out.add(y, rim_is_a);
    }
}

// A side line against a cap disc: the part of the line over the disc.
void segment_disc(const contact_feature &seg, const contact_feature &disc, bool disc_is_a,
                  const vector3 &normal, candidate_list &out) noexcept {
    auto p0 = lifted(disc, normal, seg.vertices[0]);
    auto p1 = lifted(disc, normal, seg.vertices[1]);
    scalar t0, t1;
    if (clip_segment_sphere(p0, p1, disc.center, disc.radius, t0, t1)) {
        out.add(lerp(p0, p1, t0), disc_is_a);
        out.add(lerp(p0, p1, t1), disc_is_a);
    }
}

// A side line or edge against a box face: the part of the line over the face.
void segment_polygon(const contact_feature &seg, const contact_feature &poly, bool poly_is_a,
                     const vector3 &normal, candidate_list &out) noexcept {
    auto p0 = lifted(poly, normal, seg.vertices[0]);
    auto p1 = lifted(poly, normal, seg.vertices[1]);
    auto dir = p1 - p0;
    scalar t0 = 0, t1 = 1;
    for (std::size_t k = 0; k < 4; ++k) {
        auto o = cross(poly.vertices[(k + 1) % 4] - poly.vertices[k], poly.normal);
        if (!clip_line_interval(p0, dir, o, dot(o, poly.vertices[k]), t0, t1)) return;
    }
    out.add(p0 + dir * t0, poly_is_a);
    out.add(p0 + dir * t1, poly_is_a);
}

// Two lines across the normal (side lines, edges): the crossing of their projections on the
// contact plane, or the ends of their overlap when parallel. Working in projection keeps a pair
// that only nearly crosses (an edge taken for a vertex within feature_tolerance) on the line
// through the true contact.
void segment_segment(const contact_feature &s, bool s_is_a, const contact_feature &other,
                     const vector3 &normal, candidate_list &out) noexcept {
    auto flat = [&](const vector3 &p) { return project_plane(p, normal); };
    auto closest =
        closest_points_segment_segment(flat(s.vertices[0]), flat(s.vertices[1]), flat(other.vertices[0]),
                                       flat(other.vertices[1]), feature_tolerance);
    for (std::size_t i = 0; i < closest.num_points; ++i) {
        out.add(lerp(s.vertices[0], s.vertices[1], closest.sA[i]), s_is_a);
    }
}

// Whether the lifted point y (on the feature's lift surface) lies on the feature itself;
// `sides` holds a polygon feature's half-planes.
bool on_feature(const contact_feature &f, const quad_sides *sides, const vector3 &y) noexcept {
    switch (f.kind) {
    case kind::segment: {
        auto len_sqr = distance_sqr(f.vertices[0], f.vertices[1]);
        auto tolerance_sqr = square(inside_tolerance) * len_sqr + epsilon * epsilon;
        return distance_sqr_point_segment(f.vertices[0], f.vertices[1], y) <= tolerance_sqr;
    }
    case kind::polygon:
        return sides->contains(y);
    case kind::disc:
        return distance_sqr(y, f.center) <= square(f.radius * (1 + inside_tolerance));
    case kind::point:
    case kind::rim:
    default:
        // Reached only through the support point itself.
        return true;
    }
}

// Rank of a feature kind: the lower-ranked feature of a pair drives the clipping.
int rank(kind k) noexcept {
    switch (k) {
    case kind::point:
        return 0;
    case kind::rim:
        return 1;
    case kind::segment:
        return 2;
    case kind::disc:
        return 3;
    case kind::polygon:
    default:
        return 4;
    }
}

void gather(const contact_feature &a, const contact_feature &b, const vector3 &normal,
            candidate_list &out) noexcept {
    auto a_first = rank(a.kind) <= rank(b.kind);
    const auto &f1 = a_first ? a : b;
    const auto &f2 = a_first ? b : a;
    auto f1_is_a = a_first;

    switch (f1.kind) {
    case kind::point:
        out.add(f1.vertices[0], f1_is_a);
        return;
    case kind::rim:
        if (f2.kind == kind::disc || f2.kind == kind::polygon) {
            rim_face(f1, f1_is_a, f2, normal, out);
        } else {
            out.add(f1.vertices[0], f1_is_a);
        }
        return;
    case kind::segment:
        if (f2.kind == kind::segment) {
            segment_segment(f1, f1_is_a, f2, normal, out);
        } else if (f2.kind == kind::disc) {
            segment_disc(f1, f2, !f1_is_a, normal, out);
        } else {
            segment_polygon(f1, f2, !f1_is_a, normal, out);
        }
        return;
    case kind::disc:
        if (f2.kind == kind::disc) {
            disc_disc(a, b, normal, out);
        } else {
            disc_polygon(f1, f1_is_a, f2, normal, out);
        }
        return;
    case kind::polygon:
    default:
        // Two faces never meet here: no pair with a cylinder has two polygonal shapes.
        EDYN_ASSERT(false, "build_manifold: polygon against polygon");
        out.add(f1.vertices[0], f1_is_a);
        return;
    }
}

} // namespace

void build_manifold(const contact_feature &a, const contact_feature &b, const vector3 &normal,
                    const collision_context &ctx, const quaternion &to_world,
                    collision_result &result) noexcept {
    candidate_list candidates;
    gather(a, b, normal, candidates);

    // The candidates and the three support-point fallbacks below.
    collision_result::collision_point points[max_candidates + 3];
    std::size_t count = 0;
    auto world_normal = rotate(to_world, normal);
    auto deepest = large_scalar;
    auto add = [&](const vector3 &on_a, const vector3 &on_b) {
        auto distance = dot(on_a - on_b, normal);
        if (distance > ctx.threshold) return false;
        auto &p = points[count++];
        p = make_point(ctx, on_a, on_b, world_normal, distance);
        if (a.has_id) p.featureA = a.id;
        if (b.has_id) p.featureB = b.id;
        deepest = std::min(deepest, distance);
        return true;
    };
    // Box faces turn counter-clockwise about their outward normal.
    std::optional<quad_sides> sides_a, sides_b;
    if (a.kind == kind::polygon) sides_a.emplace(a.vertices, a.normal, 1);
    if (b.kind == kind::polygon) sides_b.emplace(b.vertices, b.normal, 1);
    // Keeps a candidate whose pivots both lie on their features.
    auto try_add = [&](const vector3 &position, bool on_a_feature) {
        auto on_a = on_a_feature ? position : lifted(a, normal, position);
        auto on_b = on_a_feature ? lifted(b, normal, position) : position;
        if (!on_feature(a, sides_a ? &*sides_a : nullptr, on_a) ||
            !on_feature(b, sides_b ? &*sides_b : nullptr, on_b)) {
            return false;
        }
        return add(on_a, on_b);
    };
    for (std::size_t i = 0; i < candidates.count; ++i) {
        try_add(candidates.items[i].position, candidates.items[i].on_a);
    }
    // The supports lie exactly as far apart along the normal as the shapes. When no candidate
    // comes that deep, the projections missed each other where the shapes touch: the features
    // were taken within feature_tolerance of the normal, or the deepest point of one lies just
    // beyond the other's outline (two rims crossing). The contact is then at a support point.
    auto gap = dot(a.support - b.support, normal);
    auto missed = [&] { return !(deepest <= gap + ctx.threshold * deepest_point_tolerance); };
    if (missed()) try_add(a.support, true);
    if (missed()) try_add(b.support, false);
    if (missed()) add(a.support, a.support - normal * gap);
    // Deepest first, so that add_point's reduction to four keeps it and grows the area from it.
    std::sort(points, points + count, [](const auto &p, const auto &q) { return p.distance < q.distance; });
    for (std::size_t i = 0; i < count; ++i) {
        result.add_point(points[i]);
    }
}

} // namespace edyn::detail
