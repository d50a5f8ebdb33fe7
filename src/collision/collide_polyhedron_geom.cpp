#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include <algorithm>
#include <cmath>

namespace edyn::detail {

namespace {

// The box's faces, edges and adjacency in the index conventions of box_features.hpp, laid out
// as convex_mesh lays out a polyhedron.
struct box_topology {
    std::array<std::uint32_t, 24> indices{};
    std::array<convex_mesh::face_range, 6> faces{};
    std::array<vector3, 6> normals{};
    std::array<std::array<std::uint32_t, 2>, 12> edges{};
    std::array<std::array<std::uint32_t, 2>, 12> edge_faces{};
    std::array<vector3, 3> directions{vector3_x, vector3_y, vector3_z};
};

constexpr box_topology make_box_topology() noexcept {
    box_topology topo;
    for (unsigned f = 0; f < 6; ++f) {
        unsigned idx[4]{};
        box_face_vertex_indices(f, idx);
        for (unsigned k = 0; k < 4; ++k)
            topo.indices[f * 4 + k] = idx[k];
        topo.faces[f] = {f * 4, 4};
        topo.normals[f] = box_face_normal(f);
    }
    for (unsigned e = 0; e < 12; ++e) {
        unsigned v0 = 0, v1 = 0;
        box_edge_vertex_indices(e, v0, v1);
        topo.edges[e] = {v0, v1};
        // As in convex_mesh: the face that runs v0 -> v1 counter-clockwise first.
        for (unsigned f = 0; f < 6; ++f) {
            for (unsigned k = 0; k < 4; ++k) {
                auto from = topo.indices[f * 4 + k], to = topo.indices[f * 4 + (k + 1) % 4];
                if (from == v0 && to == v1) topo.edge_faces[e][0] = f;
                if (from == v1 && to == v0) topo.edge_faces[e][1] = f;
            }
        }
    }
    return topo;
}

constexpr box_topology box_topo = make_box_topology();

polytope_feature edge_point_feature(const polytope &poly, std::uint32_t edge, scalar s) noexcept {
    if (s <= 0) return {polyhedron_feature::vertex, poly.edges[edge][0]};
    if (s >= 1) return {polyhedron_feature::vertex, poly.edges[edge][1]};
    return {polyhedron_feature::edge, edge};
}

} // namespace

polytope make_polytope(const convex_mesh &mesh) noexcept {
    polytope p;
    p.vertices = mesh.vertices;
    p.indices = mesh.indices;
    p.faces = mesh.faces;
    p.normals = mesh.normals;
    p.plane_constants = mesh.plane_constants;
    p.edges = mesh.edges;
    p.edge_faces = mesh.edge_faces;
    p.unique_edge_directions = mesh.unique_edge_directions;
    p.bounding_radius = mesh.bounding_radius;
    return p;
}

box_polytope::box_polytope(const vector3 &he) noexcept
    : half_extents(he) {
    for (unsigned i = 0; i < 8; ++i)
        vertices[i] = box_vertex(he, i);
    for (unsigned f = 0; f < 6; ++f)
        plane_constants[f] = he[box_face_axis(f)];
}

polytope box_polytope::view() const noexcept {
    polytope p;
    p.vertices = vertices;
    p.indices = box_topo.indices;
    p.faces = box_topo.faces;
    p.normals = box_topo.normals;
    p.plane_constants = plane_constants;
    p.edges = box_topo.edges;
    p.edge_faces = box_topo.edge_faces;
    p.unique_edge_directions = box_topo.directions;
    p.bounding_radius = length(half_extents);
    p.box_half_extents = &half_extents;
    return p;
}

void polytope_interval(const polytope &poly, const vector3 &dir, scalar &lo, scalar &hi) noexcept {
    lo = large_scalar;
    hi = -large_scalar;
    for (const auto &v : poly.vertices) {
        auto d = dot(v, dir);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
}

scalar polytope_min_projection(const polytope &poly, const vector3 &dir) noexcept {
    auto lo = large_scalar;
    for (const auto &v : poly.vertices)
        lo = std::min(lo, dot(v, dir));
    return lo;
}

std::uint32_t polytope_support_vertex(const polytope &poly, const vector3 &dir) noexcept {
    std::uint32_t best = 0;
    auto best_proj = -large_scalar;
    for (std::uint32_t i = 0; i < poly.vertices.size(); ++i) {
        auto proj = dot(poly.vertices[i], dir);
        if (proj > best_proj) {
            best_proj = proj;
            best = i;
        }
    }
    return best;
}

bool point_over_face(const polytope &poly, std::size_t face, const vector3 &p, scalar tolerance) noexcept {
    const auto &n = poly.normals[face];
    auto count = poly.face_size(face);
    auto prev = poly.face_vertex(face, count - 1);
    for (std::uint32_t i = 0; i < count; ++i) {
        const auto &curr = poly.face_vertex(face, i);
        auto edge = curr - prev;
        // Outward across the edge for a counter-clockwise face, as long as the edge.
        auto d = dot(cross(edge, n), p - prev);
        if (tolerance == 0 ? d > 0 : d > tolerance * length(edge)) return false;
        prev = curr;
    }
    return true;
}

std::optional<collision_feature> reported_feature(const polytope &poly, const polytope_feature &f) noexcept {
    if (!poly.box_half_extents) return std::nullopt;
    switch (f.kind) {
    case polyhedron_feature::vertex:
        return collision_feature{box_feature::vertex, f.index};
    case polyhedron_feature::edge:
        return collision_feature{box_feature::edge, f.index};
    case polyhedron_feature::face:
    default:
        return collision_feature{box_feature::face, f.index};
    }
}

polytope_closest_point closest_point_polytope(const polytope &poly, const vector3 &p) noexcept {
    std::uint32_t best_face = 0;
    auto best = -large_scalar;
    for (std::uint32_t f = 0; f < poly.faces.size(); ++f) {
        auto s = poly.face_distance(f, p);
        if (s > best) {
            best = s;
            best_face = f;
        }
    }
    const auto &face_normal = poly.normals[best_face];
    if (best <= 0) {
        // Inside: every face plane is at least -best away, so the nearest plane's foot is on the
        // surface.
        return {p - face_normal * best, face_normal, best, {polyhedron_feature::face, best_face}};
    }

    // Outside: a face whose prism holds p is the answer (its plane bounds the distance from
    // below); else the nearest point lies on the boundary of a face that p sees.
    if (point_over_face(poly, best_face, p)) {
        return {p - face_normal * best, face_normal, best, {polyhedron_feature::face, best_face}};
    }
    for (std::uint32_t f = 0; f < poly.faces.size(); ++f) {
        if (f == best_face) continue;
        auto s = poly.face_distance(f, p);
        if (s > 0 && point_over_face(poly, f, p)) {
            return {p - poly.normals[f] * s, poly.normals[f], s, {polyhedron_feature::face, f}};
        }
    }
    auto best_sqr = large_scalar;
    polytope_closest_point r{p, face_normal, best, {polyhedron_feature::face, best_face}};
    for (std::uint32_t e = 0; e < poly.edges.size(); ++e) {
        const auto &faces = poly.edge_faces[e];
        if (poly.face_distance(faces[0], p) <= 0 && poly.face_distance(faces[1], p) <= 0) continue;
        scalar t;
        auto q =
            closest_point_segment(poly.vertices[poly.edges[e][0]], poly.vertices[poly.edges[e][1]], p, t);
        auto d2 = distance_sqr(p, q);
        if (d2 < best_sqr) {
            best_sqr = d2;
            r.point = q;
            r.feature = edge_point_feature(poly, e, t);
        }
    }
    auto d = p - r.point;
    r.distance = std::sqrt(best_sqr);
    if (r.distance > epsilon * std::max(scalar(1), poly.bounding_radius)) {
        r.normal = d / r.distance;
    }
    return r;
}

segment_polytope_closest closest_points_segment_polytope(const polytope &poly, const vector3 &p0,
                                                         const vector3 &p1) noexcept {
    segment_polytope_closest r;
    auto dir = p1 - p0;
    scalar t0 = 0, t1 = 1;
    auto inside = true;
    for (std::size_t f = 0; f < poly.faces.size() && inside; ++f) {
        inside = clip_line_interval(p0, dir, poly.normals[f], poly.plane_constants[f], t0, t1);
    }
    if (inside) {
        r.intersects = true;
        r.t = (t0 + t1) * scalar(0.5);
        r.on_segment = r.on_polytope = p0 + dir * r.t;
        return r;
    }

    // Apart: the closest pair holds an end of the segment, or a point of an edge that the
    // segment sees (a face-interior pair with the segment parallel is matched by either).
    auto c0 = closest_point_polytope(poly, p0);
    auto c1 = closest_point_polytope(poly, p1);
    auto best_sqr = square(c0.distance);
    r.t = 0;
    r.on_segment = p0;
    r.on_polytope = c0.point;
    r.feature = c0.feature;
    if (square(c1.distance) < best_sqr) {
        best_sqr = square(c1.distance);
        r.t = 1;
        r.on_segment = p1;
        r.on_polytope = c1.point;
        r.feature = c1.feature;
    }
    for (std::uint32_t e = 0; e < poly.edges.size(); ++e) {
        const auto &faces = poly.edge_faces[e];
        auto sees = [&](std::uint32_t f) {
            return poly.face_distance(f, p0) > 0 || poly.face_distance(f, p1) > 0;
        };
        if (!sees(faces[0]) && !sees(faces[1])) continue;
        auto closest = closest_points_segment_segment(p0, p1, poly.vertices[poly.edges[e][0]],
                                                      poly.vertices[poly.edges[e][1]]);
        for (std::size_t i = 0; i < closest.num_points; ++i) {
            auto d2 = distance_sqr(closest.pointA[i], closest.pointB[i]);
            if (d2 < best_sqr) {
                best_sqr = d2;
                r.t = closest.sA[i];
                r.on_segment = closest.pointA[i];
                r.on_polytope = closest.pointB[i];
                r.feature = edge_point_feature(poly, e, closest.sB[i]);
            }
        }
    }
    r.distance = std::sqrt(best_sqr);
    return r;
}

polytope_closest_pair closest_pair_polytopes(const polytope &a, const polytope &b,
                                             const polytope_placement &place, const vector3 &axis,
                                             scalar reach) noexcept {
    // Heights along the axis: a closest pair at most `reach` apart lies within `reach` of A's top
    // and of B's bottom, and so does every feature that holds one of its points.
    scalar a_lo, a_hi, b_lo, b_hi;
    polytope_interval(a, axis, a_lo, a_hi);
    auto axis_b = axis * place.r;
    auto offset = dot(axis, place.t);
    polytope_interval(b, axis_b, b_lo, b_hi);
    auto a_min = a_hi - reach;
    auto b_max = b_lo + offset + reach;
    auto near_a = [&](std::uint32_t i) { return dot(axis, a.vertices[i]) >= a_min; };
    auto near_b = [&](std::uint32_t j) { return dot(axis_b, b.vertices[j]) + offset <= b_max; };

    polytope_closest_pair r;
    for (std::uint32_t i = 0; i < a.vertices.size(); ++i) {
        if (!near_a(i)) continue;
        auto p = place.to_b(a.vertices[i]);
        for (std::uint32_t g = 0; g < b.faces.size(); ++g) {
            auto s = b.face_distance(g, p);
            if (s > 0 && s * s < r.distance_sqr && point_over_face(b, g, p)) {
                r = {s * s,
                     a.vertices[i],
                     place.to_a(p - b.normals[g] * s),
                     {polyhedron_feature::vertex, i},
                     {polyhedron_feature::face, g}};
            }
        }
    }
    for (std::uint32_t j = 0; j < b.vertices.size(); ++j) {
        if (!near_b(j)) continue;
        auto q = place.to_a(b.vertices[j]);
        for (std::uint32_t f = 0; f < a.faces.size(); ++f) {
            auto s = a.face_distance(f, q);
            if (s > 0 && s * s < r.distance_sqr && point_over_face(a, f, q)) {
                r = {s * s,
                     q - a.normals[f] * s,
                     q,
                     {polyhedron_feature::face, f},
                     {polyhedron_feature::vertex, j}};
            }
        }
    }
    for (std::uint32_t ea = 0; ea < a.edges.size(); ++ea) {
        auto ia0 = a.edges[ea][0], ia1 = a.edges[ea][1];
        if (!near_a(ia0) && !near_a(ia1)) continue;
        for (std::uint32_t eb = 0; eb < b.edges.size(); ++eb) {
            auto ib0 = b.edges[eb][0], ib1 = b.edges[eb][1];
            if (!near_b(ib0) && !near_b(ib1)) continue;
            auto closest = closest_points_segment_segment(
                a.vertices[ia0], a.vertices[ia1], place.to_a(b.vertices[ib0]), place.to_a(b.vertices[ib1]));
            for (std::size_t k = 0; k < closest.num_points; ++k) {
                auto d2 = distance_sqr(closest.pointA[k], closest.pointB[k]);
                if (d2 < r.distance_sqr) {
                    r = {d2, closest.pointA[k], closest.pointB[k], edge_point_feature(a, ea, closest.sA[k]),
                         edge_point_feature(b, eb, closest.sB[k])};
                }
            }
        }
    }
    return r;
}

polytope_feature polytope_support_feature(const polytope &poly, const vector3 &dir) noexcept {
    std::uint32_t best_face = 0;
    auto best_dot = -large_scalar;
    for (std::uint32_t f = 0; f < poly.faces.size(); ++f) {
        auto d = dot(poly.normals[f], dir);
        if (d > best_dot) {
            best_dot = d;
            best_face = f;
        }
    }
    if (best_dot > 0 && scalar(1) - best_dot * best_dot <= square(feature_tolerance)) {
        return {polyhedron_feature::face, best_face};
    }
    auto vertex = polytope_support_vertex(poly, dir);
    auto best_cos = feature_tolerance;
    auto found = false;
    std::uint32_t best_edge = 0;
    for (std::uint32_t e = 0; e < poly.edges.size(); ++e) {
        if (poly.edges[e][0] != vertex && poly.edges[e][1] != vertex) continue;
        auto d = poly.vertices[poly.edges[e][1]] - poly.vertices[poly.edges[e][0]];
        auto c = std::abs(dot(d, dir)) / length(d);
        if (c <= best_cos) {
            best_cos = c;
            best_edge = e;
            found = true;
        }
    }
    if (found) return {polyhedron_feature::edge, best_edge};
    return {polyhedron_feature::vertex, vertex};
}

scalar segment_circle_distance_bound(const vector3 &p0, const vector3 &p1, const vector3 &center,
                                     const vector3 &normal, scalar radius) noexcept {
    auto bound = std::sqrt(distance_sqr_point_segment(p0, p1, center)) - radius;
    auto h0 = dot(p0 - center, normal), h1 = dot(p1 - center, normal);
    if ((h0 > 0) == (h1 > 0)) bound = std::max(bound, std::min(std::abs(h0), std::abs(h1)));
    return bound;
}

} // namespace edyn::detail
