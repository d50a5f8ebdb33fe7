#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"

// Polyhedron–capsule in the polyhedron's space, structured as box–capsule. While the capsule's
// segment stays outside the polyhedron the exact segment–polyhedron closest points decide (plus
// the ends of the segment over a face it lies along, or along a parallel edge, for a stable
// manifold). Once the segment enters the polyhedron, a separating-axis test over the face normals
// and the cross products of the unique edge directions with the segment finds the least
// penetration.
namespace edyn {

namespace {

struct polyhedron_capsule {
    detail::polytope poly;
    detail::capsule_segment seg; // In the polyhedron's space.
    scalar radius;
    quaternion orn_a;  // Polyhedron orientation, to bring normals to world space.
    quaternion orn_ab; // Capsule orientation in the polyhedron's space.
    vector3 pos_ab;    // Capsule position in the polyhedron's space.
};

// Adds the pair (on_poly, on_segment + normal * radius) where `normal` (polyhedron space, B
// towards A) is the direction from the capsule's segment to the polyhedron.
void add_pair(const polyhedron_capsule &pc, const vector3 &on_poly, const vector3 &on_segment, scalar s,
              const vector3 &normal, scalar distance, collision_result &result) {
    collision_result::collision_point p;
    p.pivotA = on_poly;
    p.pivotB = rotate(conjugate(pc.orn_ab), on_segment + normal * pc.radius - pc.pos_ab);
    p.normal = rotate(pc.orn_a, normal);
    p.distance = distance;
    p.featureB = detail::capsule_feature_at(s, normal, pc.seg.axis);
    result.add_point(p);
}

// Points where the part of the segment over face `face` ends, at their height above the face.
// Returns whether the segment has a part over the face.
bool face_points(const polyhedron_capsule &pc, std::uint32_t face, scalar threshold,
                 collision_result &result) {
    const auto &poly = pc.poly;
    const auto &n = poly.normals[face];
    auto dir = pc.seg.p1 - pc.seg.p0;
    scalar t0 = 0, t1 = 1;
    auto count = poly.face_size(face);
    for (std::uint32_t k = 0; k < count; ++k) {
        const auto &v0 = poly.face_vertex(face, k);
        auto side = cross(poly.face_vertex(face, (k + 1) % count) - v0, n);
        if (!clip_line_interval(pc.seg.p0, dir, side, dot(side, v0), t0, t1)) return false;
    }
    for (auto t : {t0, t1}) {
        auto on_segment = pc.seg.p0 + dir * t;
        auto height = poly.face_distance(face, on_segment);
        auto distance = height - pc.radius;
        if (distance > threshold) continue;
        add_pair(pc, on_segment - n * height, on_segment, t, -n, distance, result);
    }
    return true;
}

// The ends of the stretch of segment alongside edge `edge` when they are parallel.
void parallel_edge_points(const polyhedron_capsule &pc, std::uint32_t edge, scalar threshold,
                          collision_result &result) {
    const auto &e0 = pc.poly.vertices[pc.poly.edges[edge][0]];
    const auto &e1 = pc.poly.vertices[pc.poly.edges[edge][1]];
    auto u = e1 - e0;
    if (!try_normalize(u)) return;
    auto along = dot(u, pc.seg.axis);
    if (scalar(1) - along * along > segment_parallel_tolerance * segment_parallel_tolerance) return;
    auto dir = pc.seg.p1 - pc.seg.p0;
    scalar t0 = 0, t1 = 1;
    if (!clip_line_interval(pc.seg.p0, dir, u, dot(u, e1), t0, t1) ||
        !clip_line_interval(pc.seg.p0, dir, -u, -dot(u, e0), t0, t1)) {
        return;
    }
    for (auto t : {t0, t1}) {
        auto point = pc.seg.p0 + dir * t;
        auto on_edge = closest_point_segment(e0, e1, point);
        auto d = on_edge - point;
        auto len = length(d);
        if (len <= epsilon || len - pc.radius > threshold) continue;
        add_pair(pc, on_edge, point, t, d / len, len - pc.radius, result);
    }
}

// The segment does not reach the polyhedron: exact closest pair, widened to the segment's
// stretch over a face it lies along or beside a parallel edge.
void separated(const polyhedron_capsule &pc, const detail::segment_polytope_closest &closest,
               scalar threshold, collision_result &result) {
    const auto &poly = pc.poly;
    auto normal = (closest.on_polytope - closest.on_segment) / closest.distance;
    if (closest.feature.kind == polyhedron_feature::face) {
        face_points(pc, closest.feature.index, threshold, result);
        return;
    }
    add_pair(pc, closest.on_polytope, closest.on_segment, closest.t, normal, closest.distance - pc.radius,
             result);

    // Lying along a face whose boundary holds the closest point: the ends over that face too.
    std::uint32_t face = 0;
    auto best_dot = -large_scalar;
    for (std::uint32_t f = 0; f < poly.faces.size(); ++f) {
        auto d = -dot(poly.normals[f], normal);
        if (d > best_dot) {
            best_dot = d;
            face = f;
        }
    }
    auto across = dot(poly.normals[face], pc.seg.axis);
    if (scalar(1) - best_dot * best_dot <= square(detail::feature_tolerance) &&
        std::abs(across) <= detail::feature_tolerance) {
        face_points(pc, face, threshold, result);
    }
    if (closest.feature.kind == polyhedron_feature::edge) {
        parallel_edge_points(pc, closest.feature.index, threshold, result);
    }
}

// Edge of the polyhedron parallel to unique direction `u` that lies farthest along `dir`.
std::uint32_t support_edge(const detail::polytope &poly, const vector3 &u, const vector3 &dir) noexcept {
    std::uint32_t best = 0;
    auto best_height = -large_scalar;
    for (std::uint32_t e = 0; e < poly.edges.size(); ++e) {
        const auto &v0 = poly.vertices[poly.edges[e][0]];
        const auto &v1 = poly.vertices[poly.edges[e][1]];
        auto d = v1 - v0;
        if (length_sqr(cross(d, u)) > scalar(1e-6) * length_sqr(d)) continue;
        auto height = dot(dir, v0 + v1);
        if (height > best_height) {
            best_height = height;
            best = e;
        }
    }
    return best;
}

// The segment meets the polyhedron: least penetration over the candidate axes.
void penetrating(const polyhedron_capsule &pc, scalar threshold, collision_result &result) {
    const auto &poly = pc.poly;
    std::uint32_t face = 0;
    auto face_sep = -large_scalar;
    for (std::uint32_t f = 0; f < poly.faces.size(); ++f) {
        auto low = std::min(poly.face_distance(f, pc.seg.p0), poly.face_distance(f, pc.seg.p1));
        auto sep = low - pc.radius;
        if (sep > face_sep) {
            face_sep = sep;
            face = f;
        }
    }
    auto edge_sep = -large_scalar;
    vector3 edge_dir{}, edge_u{};
    for (const auto &u : poly.unique_edge_directions) {
        auto axis = cross(u, pc.seg.axis);
        auto len_sqr = length_sqr(axis);
        if (len_sqr < scalar(1e-6)) continue;
        axis /= std::sqrt(len_sqr);
        scalar lo, hi;
        detail::polytope_interval(poly, axis, lo, hi);
        // The axis is across the segment: all of it projects to one value.
        auto c = dot(axis, pc.seg.p0);
        auto above = c - pc.radius - hi;
        auto below = lo - c - pc.radius;
        auto sep = std::max(above, below);
        if (sep > edge_sep) {
            edge_sep = sep;
            edge_u = u;
            edge_dir = above >= below ? axis : -axis;
        }
    }

    if (!detail::sat_better(edge_sep, face_sep)) {
        if (face_points(pc, face, threshold, result)) return;
        // No part of the segment over the face (a thin polyhedron pierced near a side): the
        // deepest end stands in.
        const auto &n = poly.normals[face];
        auto h0 = poly.face_distance(face, pc.seg.p0), h1 = poly.face_distance(face, pc.seg.p1);
        auto t = h0 <= h1 ? scalar(0) : scalar(1);
        auto end = t == 0 ? pc.seg.p0 : pc.seg.p1;
        auto height = std::min(h0, h1);
        if (height - pc.radius <= threshold)
            add_pair(pc, end - n * height, end, t, -n, height - pc.radius, result);
        return;
    }
    auto edge = support_edge(poly, edge_u, edge_dir);
    const auto &e0 = poly.vertices[poly.edges[edge][0]];
    const auto &e1 = poly.vertices[poly.edges[edge][1]];
    auto closest = closest_points_segment_segment(e0, e1, pc.seg.p0, pc.seg.p1);
    auto distance = dot(closest.pointB[0] - closest.pointA[0], edge_dir) - pc.radius;
    if (distance > threshold) return;
    add_pair(pc, closest.pointA[0], closest.pointB[0], closest.sB[0], -edge_dir, distance, result);
}

} // namespace

namespace detail {

void collide_polytope_capsule(const polytope &poly, const capsule_shape &b, const collision_context &ctx,
                              collision_result &result, segment_polytope_closest_fn closest_fn) noexcept {
    EDYN_ASSERT(b.radius > 0 && b.half_length >= 0);
    auto inv_orn_a = conjugate(ctx.ornA);
    auto pos_ab = rotate(inv_orn_a, ctx.posB - ctx.posA);
    auto orn_ab = inv_orn_a * ctx.ornB;
    polyhedron_capsule pc{poly,  detail::make_capsule_segment(b, pos_ab, orn_ab), b.radius, ctx.ornA, orn_ab,
                          pos_ab};
    if (length(pos_ab) - pc.poly.bounding_radius - b.half_length - b.radius > ctx.threshold) return;

    auto closest = closest_fn(pc.poly, pc.seg.p0, pc.seg.p1);
    if (!closest.intersects && closest.distance - b.radius > ctx.threshold) return;
    // Below a micrometre the direction between the closest points is rounding noise.
    if (!closest.intersects && closest.distance > scalar(1e-6)) {
        separated(pc, closest, ctx.threshold, result);
    } else {
        penetrating(pc, ctx.threshold, result);
    }
}

} // namespace detail

void collide(const polyhedron_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.mesh);
    detail::collide_polytope_capsule(detail::make_polytope(*a.mesh), b, ctx, result);
}

void collide(const capsule_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](const auto &x, const auto &y, const auto &c, auto &r) { collide(x, y, c, r); },
                            a, b, ctx, result);
}

} // namespace edyn
