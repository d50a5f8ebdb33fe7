#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/clip.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/matrix3x3.hpp"

// Box–box by the separating-axis test over the 15 candidate axes (3 + 3 face normals, 9 edge
// cross products), computed in A's space. Face axes give a manifold by clipping B's (or A's)
// most anti-parallel face against the reference face's side planes; edge axes a single point
// between the two supporting edges. When the boxes are apart the axis' separation only bounds
// the distance from below, so a manifold that does not reach it is replaced by the exact closest
// pair (edges of each box against the other box).
namespace edyn {

namespace {

enum class sat_kind { face_a, face_b, edge };

struct sat_axis {
    sat_kind kind{sat_kind::face_a};
    // Face axis of A or B, or, for edges, A's axis in `index` and B's in `index_b`.
    int index{0};
    int index_b{0};
    scalar separation{-large_scalar};
    // Unit axis in A's space pointing from A towards B.
    vector3 axis{vector3_x};
};

// Relative placement of B in A's space.
struct box_pair {
    vector3 ha, hb;
    vector3 c;   // B's centre.
    matrix3x3 r; // B's axes as columns.
};

struct sat_result {
    sat_axis face; // Best face axis, A's preferred.
    sat_axis edge; // Best edge axis.
    bool use_edge;
};

sat_result find_axis(const box_pair &bp) {
    const auto &r = bp.r;
    sat_axis face_a, face_b, edge;
    for (int i = 0; i < 3; ++i) {
        auto proj_b = bp.hb.x * std::abs(r[i][0]) + bp.hb.y * std::abs(r[i][1]) + bp.hb.z * std::abs(r[i][2]);
        auto sep = std::abs(bp.c[i]) - bp.ha[i] - proj_b;
        if (sep > face_a.separation) {
            vector3 axis = vector3_zero;
            axis[i] = detail::sign_of(bp.c[i]);
            face_a = {sat_kind::face_a, i, 0, sep, axis};
        }
    }
    for (int j = 0; j < 3; ++j) {
        auto col = r.column(j);
        auto cj = dot(bp.c, col);
        auto sep = std::abs(cj) - bp.hb[j] - box_projection_radius(bp.ha, col);
        if (sep > face_b.separation) {
            face_b = {sat_kind::face_b, j, j, sep, col * detail::sign_of(cj)};
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            vector3 ei = vector3_zero;
            ei[i] = 1;
            auto u = cross(ei, r.column(j));
            auto len_sqr = length_sqr(u);
            // Parallel edges: the face axes already cover that direction.
            if (len_sqr < scalar(1e-6)) continue;
            u /= std::sqrt(len_sqr);
            auto cu = dot(bp.c, u);
            auto proj_b = box_projection_radius(bp.hb, u * r);
            auto sep = std::abs(cu) - box_projection_radius(bp.ha, u) - proj_b;
            if (sep > edge.separation) {
                edge = {sat_kind::edge, i, j, sep, u * detail::sign_of(cu)};
            }
        }
    }
    auto best = detail::sat_better(face_b.separation, face_a.separation) ? face_b : face_a;
    return {best, edge, detail::sat_better(edge.separation, best.separation)};
}

// Clips the incident box's face most anti-parallel to the reference face against that face's
// side planes. Works in the reference box's space; `inc_pos`/`inc_orn` place the incident box
// there.
void face_contact(const vector3 &ref_he, unsigned ref_face, const vector3 &inc_he, const vector3 &inc_pos,
                  const quaternion &inc_orn, bool ref_is_a, const collision_context &ctx,
                  collision_result &result) {
    auto ref_normal = detail::box_face_normal(ref_face);
    auto ref_axis = detail::box_face_axis(ref_face);
    auto inc_dir = rotate(conjugate(inc_orn), -ref_normal);
    auto inc_face = detail::box_support_face(inc_dir);

    detail::clip_vertex polygon[4];
    detail::box_face_polygon(inc_he, inc_face, inc_pos, inc_orn, polygon);
    detail::clip_vertex clipped[detail::max_clip_vertices];
    auto inc_face_feature = collision_feature{box_feature::face, inc_face};
    auto count = detail::clip_polygon_box_face_sides(polygon, 4, ref_he, ref_face, inc_face_feature, clipped);

    // Normal from B towards A: the reference face's normal points from the reference box out
    // towards the incident one.
    auto ref_orn = ref_is_a ? ctx.ornA : ctx.ornB;
    auto normal = rotate(ref_orn, ref_is_a ? -ref_normal : ref_normal);
    auto ref_feature = collision_feature{box_feature::face, ref_face};
    auto inv_inc_orn = conjugate(inc_orn);

    auto add = [&](const vector3 &position, const collision_feature &inc_feature, scalar height) {
        collision_result::collision_point p;
        auto on_ref = position - ref_normal * height;
        auto on_inc = rotate(inv_inc_orn, position - inc_pos);
        p.pivotA = ref_is_a ? on_ref : on_inc;
        p.pivotB = ref_is_a ? on_inc : on_ref;
        p.featureA = ref_is_a ? ref_feature : inc_feature;
        p.featureB = ref_is_a ? inc_feature : ref_feature;
        p.normal = normal;
        p.distance = height;
        result.add_point(p);
    };

    auto added = false;
    for (std::size_t i = 0; i < count; ++i) {
        auto height = dot(ref_normal, clipped[i].position) - ref_he[ref_axis];
        if (height > ctx.threshold) continue;
        add(clipped[i].position, clipped[i].feature, height);
        added = true;
    }

    if (!added) {
        // Overlapping boxes always leave some of the incident face over the reference face;
        // should rounding clip it all away, the incident box's deepest vertex stands in.
        auto local_vertex = support_point_box(inc_he, inc_dir);
        auto vertex = inc_pos + rotate(inc_orn, local_vertex);
        auto height = dot(ref_normal, vertex) - ref_he[ref_axis];
        if (height <= 0) {
            add(vertex, {box_feature::vertex, detail::box_vertex_index(local_vertex)}, height);
        }
    }
}

// Returns false, adding nothing, when the boxes overlap but the closest points of the two
// supporting edges fall off an edge: the edges do not cross over each other, so the axis cannot
// give a point pair along it (a near tie with a face axis, left to the face).
bool edge_contact(const box_pair &bp, const sat_axis &sat, const collision_context &ctx,
                  collision_result &result) {
    auto i = sat.index, j = sat.index_b;
    // A's edge along i farthest towards B, B's edge along j farthest towards A.
    auto support_a = support_point_box(bp.ha, sat.axis);
    auto edge_a = detail::box_edge_index(i, support_a);
    vector3 a0, a1;
    detail::box_edge_vertices(bp.ha, edge_a, a0, a1);

    auto support_b = support_point_box(bp.hb, -sat.axis * bp.r);
    auto edge_b = detail::box_edge_index(j, support_b);
    vector3 b0, b1;
    detail::box_edge_vertices(bp.hb, edge_b, b0, b1);
    auto b0_in_a = bp.c + bp.r * b0;
    auto b1_in_a = bp.c + bp.r * b1;

    auto closest = closest_points_segment_segment(a0, a1, b0_in_a, b1_in_a);
    auto distance = dot(closest.pointB[0] - closest.pointA[0], sat.axis);
    auto normal = -sat.axis;
    if (distance > 0) {
        // Apart, the pair's own distance and direction: the distance exceeds the axis'
        // separation when the closest points fall off the edges, which sends the caller to the
        // exact closest pair.
        distance = std::sqrt(closest.distance_sqr);
        auto dir = closest.pointA[0] - closest.pointB[0];
        if (try_normalize(dir)) normal = dir;
    } else {
        auto interior = [](scalar s) { return s > 0 && s < 1; };
        if (!interior(closest.sA[0]) || !interior(closest.sB[0])) return false;
    }
    if (distance > ctx.threshold) return true;
    collision_result::collision_point p;
    p.pivotA = closest.pointA[0];
    p.pivotB = (closest.pointB[0] - bp.c) * bp.r;
    p.normal = rotate(ctx.ornA, normal);
    p.distance = distance;
    p.featureA = collision_feature{box_feature::edge, edge_a};
    p.featureB = collision_feature{box_feature::edge, edge_b};
    result.add_point(p);
    return true;
}

// Exact closest pair of two disjoint boxes: it always involves an edge of one of them, so the
// smallest edge-to-box distance over the 24 edges finds it.
// Feature of a point at parameter t along edge `edge` (vertex 0 at t = 0).
collision_feature edge_point_feature(unsigned edge, scalar t) noexcept {
    unsigned v0 = 0, v1 = 0;
    detail::box_edge_vertex_indices(edge, v0, v1);
    if (t <= 0) return {box_feature::vertex, v0};
    if (t >= 1) return {box_feature::vertex, v1};
    return {box_feature::edge, edge};
}

void closest_pair(const box_pair &bp, const collision_context &ctx, collision_result &result) {
    scalar best = large_scalar;
    vector3 on_a{}, on_b{}; // In A's space.
    collision_feature feature_a, feature_b;
    auto inv_r = transpose(bp.r);
    for (unsigned e = 0; e < 12; ++e) {
        vector3 v0, v1, on_seg, on_box;
        scalar t;
        // B's edge against A.
        detail::box_edge_vertices(bp.hb, e, v0, v1);
        auto d2 = closest_points_segment_box(bp.ha, bp.c + bp.r * v0, bp.c + bp.r * v1, t, on_seg, on_box);
        if (d2 < best) {
            best = d2;
            on_a = on_box;
            on_b = on_seg;
            // Clamped coordinates are exactly on the bounds, which tells the feature.
            feature_a = detail::box_feature_at(bp.ha, on_box, 0);
            feature_b = edge_point_feature(e, t);
        }
        // A's edge against B, in B's space.
        detail::box_edge_vertices(bp.ha, e, v0, v1);
        d2 = closest_points_segment_box(bp.hb, inv_r * (v0 - bp.c), inv_r * (v1 - bp.c), t, on_seg, on_box);
        if (d2 < best) {
            best = d2;
            on_a = lerp(v0, v1, t);
            on_b = bp.c + bp.r * on_box;
            feature_a = edge_point_feature(e, t);
            feature_b = detail::box_feature_at(bp.hb, on_box, 0);
        }
    }
    auto dist = std::sqrt(best);
    if (dist > ctx.threshold) return;
    auto n = on_a - on_b;
    if (!try_normalize(n)) return;
    collision_result::collision_point p;
    p.pivotA = on_a;
    p.pivotB = (on_b - bp.c) * bp.r;
    p.normal = rotate(ctx.ornA, n);
    p.distance = dist;
    p.featureA = feature_a;
    p.featureB = feature_b;
    result.add_point(p);
}

} // namespace

void collide(const box_shape &a, const box_shape &b, const collision_context &ctx, collision_result &result) {
    auto inv_orn_a = conjugate(ctx.ornA);
    auto rel_orn = inv_orn_a * ctx.ornB;
    box_pair bp{a.half_extents, b.half_extents, rotate(inv_orn_a, ctx.posB - ctx.posA),
                to_matrix3x3(rel_orn)};

    auto axes = find_axis(bp);
    auto sat = axes.use_edge ? axes.edge : axes.face;
    // The separation along any axis bounds the distance from below.
    if (sat.separation > ctx.threshold) return;

    collision_result local;
    if (axes.use_edge && !edge_contact(bp, sat, ctx, local)) {
        sat = axes.face;
    }
    if (sat.kind == sat_kind::face_a) {
        auto face = detail::box_face_index(sat.index, sat.axis[sat.index]);
        face_contact(bp.ha, face, bp.hb, bp.c, rel_orn, true, ctx, local);
    } else if (sat.kind == sat_kind::face_b) {
        // Reference B: place A in B's space.
        auto inv_rel = conjugate(rel_orn);
        auto a_in_b = rotate(inv_rel, -bp.c);
        auto dir_in_b = rotate(inv_rel, -sat.axis);
        auto face = detail::box_face_index(sat.index, dir_in_b[sat.index]);
        face_contact(bp.hb, face, bp.ha, a_in_b, inv_rel, false, ctx, local);
    }

    scalar min_distance = large_scalar;
    for (std::size_t i = 0; i < local.num_points; ++i) {
        min_distance = std::min(min_distance, local.point[i].distance);
    }
    // Apart, the manifold is the closest one only if some point reaches the axis' separation.
    constexpr auto exact_tolerance = scalar(1e-4);
    if (sat.separation > 0 && !(min_distance <= sat.separation + exact_tolerance)) {
        closest_pair(bp, ctx, result);
        return;
    }
    if (result.num_points == 0) {
        result = local;
        return;
    }
    for (std::size_t i = 0; i < local.num_points; ++i) {
        result.add_point(local.point[i]);
    }
}

} // namespace edyn
