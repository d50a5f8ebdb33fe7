#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"

// Polytope–polytope (polyhedron–polyhedron, polyhedron–box) by the separating-axis test in A's
// space, structured as box–box: A's face normals, B's face normals (rotated into A's space once
// per call), then the cross products of edge pairs that span a face of the Minkowski difference
// (the Gauss-map test skips all others). Face axes give a manifold by clipping B's (or A's)
// incident face against the reference face; edge axes a single point between the two edges.
// When the polytopes are apart the axis' separation only bounds the distance from below, so a
// manifold that does not reach it is replaced by the exact closest pair.
namespace edyn {

namespace {

using detail::polytope;
using detail::polytope_placement;

// B's face normals in A's space, and the cross products of each edge's two face normals, are
// cached on the stack for meshes of up to this many faces and edges (about 9 KiB in single
// precision); a mesh with more computes them where they are used, with the same results.
constexpr std::size_t max_cached_faces = 256;
constexpr std::size_t max_cached_edges = 384;

enum class sat_kind { face_a, face_b, edge };

struct sat_axis {
    sat_kind kind{sat_kind::face_a};
    // A's face, B's face, or A's edge in `index` and B's in `index_b`.
    std::uint32_t index{0};
    std::uint32_t index_b{0};
    scalar separation{-large_scalar};
    // Unit axis in A's space pointing from A towards B.
    vector3 axis{vector3_y};
};

struct polytope_pair {
    const polytope &a;
    const polytope &b;
    polytope_placement place;
    // When cached: B's normals in A's space, and for each edge of B the cross product of its
    // faces' normals (in that order) in A's space.
    const vector3 *normals_b{nullptr};
    const vector3 *edge_crosses_b{nullptr};

    vector3 normal_b(std::size_t face) const noexcept {
        return normals_b ? normals_b[face] : place.r * b.normals[face];
    }
};

void test_faces_a(const polytope_pair &pp, sat_axis &best) noexcept {
    const auto &a = pp.a;
    for (std::uint32_t f = 0; f < a.faces.size(); ++f) {
        const auto &n = a.normals[f];
        auto lo = detail::polytope_min_projection(pp.b, n * pp.place.r);
        auto sep = lo + dot(n, pp.place.t) - a.plane_constants[f];
        if (sep > best.separation) best = {sat_kind::face_a, f, 0, sep, n};
    }
}

void test_faces_b(const polytope_pair &pp, sat_axis &best) noexcept {
    const auto &b = pp.b;
    for (std::uint32_t g = 0; g < b.faces.size(); ++g) {
        auto n = pp.normal_b(g);
        auto lo = detail::polytope_min_projection(pp.a, n);
        auto sep = lo - b.plane_constants[g] - dot(n, pp.place.t);
        if (sep > best.separation) best = {sat_kind::face_b, g, g, sep, -n};
    }
}

// Separation along the cross product of edge i of A and edge j of B, which span a face of the
// Minkowski difference.
void test_edge_pair(const polytope_pair &pp, std::uint32_t i, std::uint32_t j, sat_axis &best) noexcept {
    const auto &a = pp.a;
    const auto &b = pp.b;
    const auto &pa0 = a.vertices[a.edges[i][0]];
    auto da = a.vertices[a.edges[i][1]] - pa0;
    auto pb0 = pp.place.to_a(b.vertices[b.edges[j][0]]);
    auto db = pp.place.r * (b.vertices[b.edges[j][1]] - b.vertices[b.edges[j][0]]);
    auto axis = cross(da, db);
    auto len_sqr = length_sqr(axis);
    // Parallel edges: the face axes already cover that direction.
    if (len_sqr < scalar(1e-6) * length_sqr(da) * length_sqr(db)) return;
    axis /= std::sqrt(len_sqr);
    // Outwards from A's edge, into the arc of its faces' normals.
    if (dot(axis, a.normals[a.edge_faces[i][0]] + a.normals[a.edge_faces[i][1]]) < 0) axis = -axis;
    auto sep = dot(axis, pb0 - pa0);
    if (sep > best.separation) best = {sat_kind::edge, i, j, sep, axis};
}

void test_edges(const polytope_pair &pp, sat_axis &best) noexcept {
    const auto &a = pp.a;
    const auto &b = pp.b;
    const auto *edge_faces_b = b.edge_faces.data();
    auto num_edges_b = b.edges.size();
    // Sides of B's face normals relative to the great circle of A's current edge, once per face:
    // most pairs then cost two loads and a product.
    scalar sides[max_cached_faces];
    for (std::uint32_t i = 0; i < a.edges.size(); ++i) {
        const auto &na0 = a.normals[a.edge_faces[i][0]];
        const auto &na1 = a.normals[a.edge_faces[i][1]];
        auto n_a = cross(na0, na1);
        if (pp.normals_b) {
            for (std::size_t g = 0; g < b.faces.size(); ++g)
                sides[g] = dot(pp.normals_b[g], n_a);
            for (std::uint32_t j = 0; j < num_edges_b; ++j) {
                auto g0 = edge_faces_b[j][0], g1 = edge_faces_b[j][1];
                auto s0 = sides[g0], s1 = sides[g1];
                if (!(s0 * s1 < 0)) continue;
                if (detail::is_minkowski_face(na0, na1, pp.normals_b[g0], pp.normals_b[g1], s0, s1,
                                              pp.edge_crosses_b[j])) {
                    test_edge_pair(pp, i, j, best);
                }
            }
        } else {
            for (std::uint32_t j = 0; j < num_edges_b; ++j) {
                auto nb0 = pp.normal_b(edge_faces_b[j][0]), nb1 = pp.normal_b(edge_faces_b[j][1]);
                auto s0 = dot(nb0, n_a), s1 = dot(nb1, n_a);
                if (!(s0 * s1 < 0)) continue;
                if (detail::is_minkowski_face(na0, na1, nb0, nb1, s0, s1, cross(nb0, nb1))) {
                    test_edge_pair(pp, i, j, best);
                }
            }
        }
    }
}

// Whether face `face` of `poly` holds vertex `vertex`.
bool face_has_vertex(const polytope &poly, std::uint32_t face, std::uint32_t vertex) noexcept {
    for (std::uint32_t k = 0; k < poly.face_size(face); ++k) {
        if (poly.face_vertex_index(face, k) == vertex) return true;
    }
    return false;
}

// Among the faces around the incident polytope's deepest vertex along -ref_normal, the one most
// anti-parallel to the reference face: it holds the deepest point, so clipping it reaches the
// separation whenever that point lies over the reference face. `dir` is -ref_normal in the
// incident polytope's space.
std::uint32_t incident_face(const polytope &inc, const vector3 &dir, std::uint32_t &deepest) noexcept {
    deepest = detail::polytope_support_vertex(inc, dir);
    std::uint32_t best = 0;
    auto best_dot = -large_scalar;
    for (std::uint32_t g = 0; g < inc.faces.size(); ++g) {
        auto d = dot(inc.normals[g], dir);
        if (d > best_dot && face_has_vertex(inc, g, deepest)) {
            best_dot = d;
            best = g;
        }
    }
    return best;
}

struct face_clip {
    const polytope &ref;
    const polytope &inc;
    polytope_placement place; // Incident space to reference space.
    std::uint32_t ref_face;
    bool ref_is_a;
    vector3 normal; // World, from B towards A.
    std::optional<collision_feature> ref_feature;
    collision_result &result;
    bool added{false};

    // A point of the incident face at `position` (reference space) at `height` above the
    // reference face.
    void add(const vector3 &position, scalar height, const std::optional<collision_feature> &inc_feature) {
        collision_result::collision_point p;
        auto on_ref = position - ref.normals[ref_face] * height;
        auto on_inc = place.to_b(position);
        p.pivotA = ref_is_a ? on_ref : on_inc;
        p.pivotB = ref_is_a ? on_inc : on_ref;
        p.featureA = ref_is_a ? ref_feature : inc_feature;
        p.featureB = ref_is_a ? inc_feature : ref_feature;
        p.normal = normal;
        p.distance = height;
        result.add_point(p);
        added = true;
    }
};

// The part of each incident edge over the reference face, clipped by the reference face's side
// planes: together with the reference corners over the incident face (below), the corners of
// the two faces' overlap. Edge by edge, so no buffer bounds the faces' sizes.
void clip_incident_edges(face_clip &fc, std::uint32_t inc_face, scalar threshold) {
    const auto &ref = fc.ref;
    const auto &n = ref.normals[fc.ref_face];
    auto d = ref.plane_constants[fc.ref_face];
    auto ref_count = ref.face_size(fc.ref_face);
    auto count = fc.inc.face_size(inc_face);
    auto is_box = fc.inc.box_half_extents != nullptr;
    for (std::uint32_t k = 0; k < count; ++k) {
        auto i0 = fc.inc.face_vertex_index(inc_face, k);
        auto i1 = fc.inc.face_vertex_index(inc_face, (k + 1) % count);
        auto p0 = fc.place.to_a(fc.inc.vertices[i0]);
        auto dir = fc.place.to_a(fc.inc.vertices[i1]) - p0;
        scalar t0 = 0, t1 = 1;
        auto inside = true;
        for (std::uint32_t j = 0; j < ref_count && inside; ++j) {
            const auto &r0 = ref.face_vertex(fc.ref_face, j);
            auto side = cross(ref.face_vertex(fc.ref_face, (j + 1) % ref_count) - r0, n);
            inside = clip_line_interval(p0, dir, side, dot(side, r0), t0, t1);
        }
        if (!inside) continue;
        std::optional<collision_feature> edge_feature;
        if (is_box) edge_feature = collision_feature{box_feature::edge, detail::box_edge_between(i0, i1)};
        auto start = p0 + dir * t0;
        auto height = dot(n, start) - d;
        if (height <= threshold) {
            auto feature = edge_feature;
            if (is_box && t0 == 0) feature = collision_feature{box_feature::vertex, i0};
            fc.add(start, height, feature);
        }
        if (t1 < 1) {
            auto end = p0 + dir * t1;
            height = dot(n, end) - d;
            if (height <= threshold) fc.add(end, height, edge_feature);
        }
    }
}

// Reference corners whose lift along the reference normal lands on the incident face.
void clip_reference_corners(face_clip &fc, std::uint32_t inc_face, scalar threshold) {
    const auto &ref = fc.ref;
    const auto &n = ref.normals[fc.ref_face];
    auto m = fc.place.r * fc.inc.normals[inc_face];
    auto mn = dot(m, n);
    // A face turned across the reference one meets it only along its edges.
    if (mn > -scalar(1e-3)) return;
    auto e = fc.inc.plane_constants[inc_face] + dot(m, fc.place.t);
    std::optional<collision_feature> inc_feature;
    if (fc.inc.box_half_extents) inc_feature = collision_feature{box_feature::face, inc_face};
    for (std::uint32_t j = 0; j < ref.face_size(fc.ref_face); ++j) {
        const auto &corner = ref.face_vertex(fc.ref_face, j);
        auto height = (e - dot(m, corner)) / mn;
        if (height > threshold) continue;
        auto q = corner + n * height;
        if (!detail::point_over_face(fc.inc, inc_face, fc.place.to_b(q))) continue;
        fc.add(q, height, inc_feature);
    }
}

void face_contact(const polytope &ref, const polytope &inc, const polytope_placement &place,
                  std::uint32_t ref_face, bool ref_is_a, bool last_resort, const collision_context &ctx,
                  collision_result &result) {
    const auto &n = ref.normals[ref_face];
    std::uint32_t deepest;
    auto inc_face = incident_face(inc, -n * place.r, deepest);
    auto ref_orn = ref_is_a ? ctx.ornA : ctx.ornB;
    std::optional<collision_feature> ref_feature;
    if (ref.box_half_extents) ref_feature = collision_feature{box_feature::face, ref_face};
    face_clip fc{ref,         inc,   place, ref_face, ref_is_a, rotate(ref_orn, ref_is_a ? -n : n),
                 ref_feature, result};
    clip_incident_edges(fc, inc_face, ctx.threshold);
    clip_reference_corners(fc, inc_face, ctx.threshold);

    if (!fc.added && last_resort) {
        // Overlapping polytopes leave some incident face over the reference face of some axis;
        // should rounding clip it all away, the incident polytope's deepest vertex stands in.
        auto vertex = place.to_a(inc.vertices[deepest]);
        auto height = dot(n, vertex) - ref.plane_constants[ref_face];
        if (height <= 0)
            fc.add(vertex, height, detail::reported_feature(inc, {polyhedron_feature::vertex, deepest}));
    }
}

// Closest points of the two edges; returns their distance for the exactness check. Apart, the
// point's normal and distance are those of the closest points (the axis' separation is only a
// bound when they lie at the edges' ends). Adds nothing when overlapping edges do not cross.
scalar edge_contact(const polytope_pair &pp, const sat_axis &sat, const collision_context &ctx,
                    collision_result &result) {
    const auto &ea = pp.a.edges[sat.index];
    const auto &eb = pp.b.edges[sat.index_b];
    auto closest = closest_points_segment_segment(pp.a.vertices[ea[0]], pp.a.vertices[ea[1]],
                                                  pp.place.to_a(pp.b.vertices[eb[0]]),
                                                  pp.place.to_a(pp.b.vertices[eb[1]]));
    const auto &on_a = closest.pointA[0];
    const auto &on_b = closest.pointB[0];
    auto normal = -sat.axis;
    auto distance = dot(on_b - on_a, sat.axis);
    if (sat.separation > 0) {
        auto d = on_a - on_b;
        distance = length(d);
        if (distance > epsilon) normal = d / distance;
    } else if (!(closest.sA[0] > 0 && closest.sA[0] < 1 && closest.sB[0] > 0 && closest.sB[0] < 1)) {
        // Overlapping, the edges must cross over each other for the axis to give a pair along
        // it; otherwise (a near tie kept by the bias) the next axis serves.
        return large_scalar;
    }
    if (distance > ctx.threshold) return distance;
    collision_result::collision_point p;
    p.pivotA = on_a;
    p.pivotB = pp.place.to_b(on_b);
    p.normal = rotate(ctx.ornA, normal);
    p.distance = distance;
    p.featureA = detail::reported_feature(pp.a, {polyhedron_feature::edge, sat.index});
    p.featureB = detail::reported_feature(pp.b, {polyhedron_feature::edge, sat.index_b});
    result.add_point(p);
    return distance;
}

void closest_pair(const polytope_pair &pp, const sat_axis &sat, const collision_context &ctx,
                  collision_result &result) {
    auto reach = ctx.threshold - sat.separation + scalar(1e-4);
    auto cp = detail::closest_pair_polytopes(pp.a, pp.b, pp.place, sat.axis, reach);
    auto dist = std::sqrt(cp.distance_sqr);
    if (dist > ctx.threshold) return;
    auto n = cp.on_a - cp.on_b;
    if (!try_normalize(n)) n = -sat.axis;
    collision_result::collision_point p;
    p.pivotA = cp.on_a;
    p.pivotB = pp.place.to_b(cp.on_b);
    p.normal = rotate(ctx.ornA, n);
    p.distance = dist;
    p.featureA = detail::reported_feature(pp.a, cp.feature_a);
    p.featureB = detail::reported_feature(pp.b, cp.feature_b);
    result.add_point(p);
}

// The candidate axes in order of preference: the best face (A's unless B's separates by more
// than the bias), the edge axis if it beats that by more than the bias, then the others by
// separation. Later ones serve when an earlier one gives no manifold: a face kept by the bias
// over a slightly better edge axis may have nothing of the incident polytope over it.
struct sat_search {
    sat_axis axes[3];
    std::size_t count{0};
};

sat_search find_axes(const polytope_pair &pp, scalar threshold) noexcept {
    sat_search search;
    sat_axis face_a, face_b, edge;
    test_faces_a(pp, face_a);
    if (face_a.separation > threshold) {
        search.axes[search.count++] = face_a;
        return search;
    }
    test_faces_b(pp, face_b);
    if (face_b.separation > threshold) {
        search.axes[search.count++] = face_b;
        return search;
    }
    test_edges(pp, edge);
    auto b_first = detail::sat_better(face_b.separation, face_a.separation);
    sat_axis order[3] = {b_first ? face_b : face_a, b_first ? face_a : face_b, edge};
    if (detail::sat_better(edge.separation, order[0].separation)) {
        std::swap(order[0], order[2]);
        std::swap(order[1], order[2]);
    } else if (edge.separation > order[1].separation) {
        std::swap(order[1], order[2]);
    }
    for (const auto &axis : order) {
        // No edge pair spans a face of the Minkowski difference: no edge axis.
        if (axis.separation > -large_scalar) search.axes[search.count++] = axis;
    }
    return search;
}

} // namespace

namespace detail {

void collide_polytopes(const polytope &a, const polytope &b, const collision_context &ctx,
                       collision_result &result) noexcept {
    auto inv_orn_a = conjugate(ctx.ornA);
    auto t = rotate(inv_orn_a, ctx.posB - ctx.posA);
    if (length(t) - a.bounding_radius - b.bounding_radius > ctx.threshold) return;
    auto rel_orn = inv_orn_a * ctx.ornB;
    polytope_pair pp{a, b, {to_matrix3x3(rel_orn), t}};

    vector3 normals_b[max_cached_faces];
    vector3 edge_crosses_b[max_cached_edges];
    if (b.faces.size() <= max_cached_faces && b.edges.size() <= max_cached_edges) {
        for (std::size_t g = 0; g < b.faces.size(); ++g)
            normals_b[g] = pp.place.r * b.normals[g];
        for (std::size_t j = 0; j < b.edges.size(); ++j) {
            edge_crosses_b[j] = cross(normals_b[b.edge_faces[j][0]], normals_b[b.edge_faces[j][1]]);
        }
        pp.normals_b = normals_b;
        pp.edge_crosses_b = edge_crosses_b;
    }

    auto search = find_axes(pp, ctx.threshold);
    // The separation along any axis bounds the distance from below.
    if (search.axes[0].separation > ctx.threshold) return;

    collision_result local;
    auto reached = large_scalar;
    auto manifold = [&](const sat_axis &sat, bool last_resort) {
        if (sat.kind == sat_kind::edge) {
            reached = edge_contact(pp, sat, ctx, local);
            return;
        }
        if (sat.kind == sat_kind::face_a) {
            face_contact(a, b, pp.place, sat.index, true, last_resort, ctx, local);
        } else {
            // Reference B: place A in B's space.
            auto r_inv = transpose(pp.place.r);
            face_contact(b, a, {r_inv, -(r_inv * t)}, sat.index, false, last_resort, ctx, local);
        }
        for (std::size_t i = 0; i < local.num_points; ++i)
            reached = std::min(reached, local.point[i].distance);
    };
    std::size_t used = 0;
    while (used < search.count) {
        manifold(search.axes[used], false);
        if (local.num_points > 0) break;
        ++used;
    }
    if (used == search.count) {
        // Nothing from any axis: only rounding gets here with the polytopes overlapping, and the
        // preferred axis' deepest vertex stands in.
        used = 0;
        manifold(search.axes[0], true);
    }

    // Apart, the manifold is the closest one only if some point reaches the axis' separation
    // (to rounding).
    auto exact_tolerance = scalar(1e-6) * std::max(scalar(1), a.bounding_radius + b.bounding_radius);
    const auto &sat = search.axes[used];
    if (sat.separation > 0 && !(reached <= sat.separation + exact_tolerance)) {
        closest_pair(pp, sat, ctx, result);
        return;
    }
    for (std::size_t i = 0; i < local.num_points; ++i) {
        result.add_point(local.point[i]);
    }
}

} // namespace detail

void collide(const polyhedron_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.mesh && b.mesh);
    detail::collide_polytopes(detail::make_polytope(*a.mesh), detail::make_polytope(*b.mesh), ctx, result);
}

void collide(const polyhedron_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(a.mesh);
    detail::box_polytope box(b.half_extents);
    detail::collide_polytopes(detail::make_polytope(*a.mesh), box.view(), ctx, result);
}

void collide(const box_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(b.mesh);
    detail::box_polytope box(a.half_extents);
    detail::collide_polytopes(box.view(), detail::make_polytope(*b.mesh), ctx, result);
}

} // namespace edyn
