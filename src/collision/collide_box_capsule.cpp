#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"

// Box–capsule in the box's space. While the capsule's segment stays outside the box the exact
// segment–box closest points decide (plus the ends of the segment over a face, or along a
// parallel edge, for a stable manifold). Once the segment enters the box, a separating-axis test
// over the box's face normals and the cross products of its edges with the segment finds the
// least penetration.
namespace edyn {

namespace {

// 1 - cosine of the angle below which a direction counts as a face normal.
constexpr scalar face_normal_tolerance = scalar(1e-6);

struct box_capsule {
    vector3 he;
    detail::capsule_segment seg; // In the box's space.
    scalar radius;
    quaternion orn_a;  // Box orientation, to bring normals to world space.
    quaternion orn_ab; // Capsule orientation in the box's space.
    vector3 pos_ab;    // Capsule position in the box's space.
};

// Adds the pair (on_box, on_segment + normal * radius) where `normal` (box space, B towards A)
// is the direction from the capsule's segment to the box.
void add_pair(const box_capsule &bc, const vector3 &on_box, const vector3 &on_segment, scalar s,
              const vector3 &normal, scalar distance, const collision_feature &feature_a,
              collision_result &result) {
    collision_result::collision_point p;
    p.pivotA = on_box;
    p.pivotB = rotate(conjugate(bc.orn_ab), on_segment + normal * bc.radius - bc.pos_ab);
    p.normal = rotate(bc.orn_a, normal);
    p.distance = distance;
    p.featureA = feature_a;
    p.featureB = detail::capsule_feature_at(s, normal, bc.seg.axis);
    result.add_point(p);
}

// Points where the part of the segment over face `face` ends, at their height above the face
// less the radius. The capsule's pivot is the segment point moved by the radius against the face
// normal: on the surface at a segment end or for a segment parallel to the face, slightly inside
// the capsule where a tilted segment is cut by a side plane (the usual clipped-capsule manifold).
void face_points(const box_capsule &bc, unsigned face, scalar threshold, collision_result &result) {
    auto axis = detail::box_face_axis(face);
    auto face_normal = detail::box_face_normal(face);
    auto dir = bc.seg.p1 - bc.seg.p0;
    scalar t0 = 0, t1 = 1;
    for (int k = 1; k < 3; ++k) {
        auto side = (axis + k) % 3;
        vector3 n = vector3_zero;
        n[side] = 1;
        if (!clip_line_interval(bc.seg.p0, dir, n, bc.he[side], t0, t1) ||
            !clip_line_interval(bc.seg.p0, dir, -n, bc.he[side], t0, t1)) {
            return;
        }
    }
    auto feature = collision_feature{box_feature::face, face};
    for (auto t : {t0, t1}) {
        auto on_segment = bc.seg.p0 + dir * t;
        auto height = dot(face_normal, on_segment) - bc.he[axis];
        auto distance = height - bc.radius;
        if (distance > threshold) continue;
        add_pair(bc, on_segment - face_normal * height, on_segment, t, -face_normal, distance, feature,
                 result);
    }
}

// The segment does not reach the box: exact closest pair, widened to a face's or a parallel
// edge's extent.
void separated(const box_capsule &bc, const vector3 &on_segment, const vector3 &on_box, scalar s, scalar dist,
               scalar threshold, collision_result &result) {
    auto normal = (on_box - on_segment) / dist;
    auto feature = detail::box_feature_at(bc.he, on_box, 0);
    auto box_kind = std::get<box_feature>(feature.feature);
    // Facing a face (also when the pair found lies on the face's border, as it may for a
    // segment parallel to the face), the ends of the stretch of segment over the face; the
    // exact pair is added too and merges with one of them unless the segment leans past the
    // face's border.
    auto normal_axis = max_index(abs(normal));
    if (box_kind == box_feature::face) {
        face_points(bc, feature.index, threshold, result);
    } else if (std::abs(normal[normal_axis]) >= scalar(1) - face_normal_tolerance) {
        face_points(bc, detail::box_face_index(normal_axis, -normal[normal_axis]), threshold, result);
    }
    add_pair(bc, on_box, on_segment, s, normal, dist - bc.radius, feature, result);

    if (box_kind == box_feature::edge) {
        auto axis = detail::box_edge_axis(feature.index);
        auto along = bc.seg.axis[axis];
        if (scalar(1) - along * along > segment_parallel_tolerance * segment_parallel_tolerance) return;
        // Parallel to the edge: also the ends of the stretch of segment alongside it.
        auto dir = bc.seg.p1 - bc.seg.p0;
        vector3 n = vector3_zero;
        n[axis] = 1;
        scalar t0 = 0, t1 = 1;
        if (!clip_line_interval(bc.seg.p0, dir, n, bc.he[axis], t0, t1) ||
            !clip_line_interval(bc.seg.p0, dir, -n, bc.he[axis], t0, t1)) {
            return;
        }
        for (auto t : {t0, t1}) {
            auto point = bc.seg.p0 + dir * t;
            auto box_point = closest_point_box(bc.he, point);
            auto d = box_point - point;
            auto len = length(d);
            if (len <= epsilon || len - bc.radius > threshold) continue;
            add_pair(bc, box_point, point, t, d / len, len - bc.radius,
                     detail::box_feature_at(bc.he, box_point, 0), result);
        }
    }
}

// The segment meets the box: least penetration over the candidate axes.
void penetrating(const box_capsule &bc, scalar threshold, collision_result &result) {
    auto center = (bc.seg.p0 + bc.seg.p1) * scalar(0.5);
    auto half = (bc.seg.p0 - bc.seg.p1) * scalar(0.5);
    int face_axis = 0;
    auto face_sep = -large_scalar;
    for (int k = 0; k < 3; ++k) {
        auto sep = std::abs(center[k]) - bc.he[k] - std::abs(half[k]) - bc.radius;
        if (sep > face_sep) {
            face_sep = sep;
            face_axis = k;
        }
    }
    auto edge_sep = -large_scalar;
    int edge_axis = 0;
    vector3 edge_dir{};
    for (int k = 0; k < 3; ++k) {
        vector3 ek = vector3_zero;
        ek[k] = 1;
        auto u = cross(ek, bc.seg.axis);
        auto len_sqr = length_sqr(u);
        if (len_sqr < scalar(1e-6)) continue;
        u /= std::sqrt(len_sqr);
        auto cu = dot(center, u);
        auto sep = std::abs(cu) - box_projection_radius(bc.he, u) - bc.radius;
        if (sep > edge_sep) {
            edge_sep = sep;
            edge_axis = k;
            edge_dir = u * detail::sign_of(cu);
        }
    }

    if (!detail::sat_better(edge_sep, face_sep)) {
        // Part of the segment is inside the box, hence over the face and below the threshold.
        auto face = detail::box_face_index(face_axis, center[face_axis]);
        face_points(bc, face, threshold, result);
        return;
    }
    // Edge of the box along `edge_axis` farthest towards the capsule against the segment.
    auto edge = detail::box_edge_index(edge_axis, support_point_box(bc.he, edge_dir));
    vector3 e0, e1;
    detail::box_edge_vertices(bc.he, edge, e0, e1);
    auto closest = closest_points_segment_segment(e0, e1, bc.seg.p0, bc.seg.p1);
    auto distance = dot(closest.pointB[0] - closest.pointA[0], edge_dir) - bc.radius;
    if (distance > threshold) return;
    add_pair(bc, closest.pointA[0], closest.pointB[0], closest.sB[0], -edge_dir, distance,
             {box_feature::edge, edge}, result);
}

} // namespace

void collide(const box_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    auto inv_orn_a = conjugate(ctx.ornA);
    auto pos_ab = rotate(inv_orn_a, ctx.posB - ctx.posA);
    auto orn_ab = inv_orn_a * ctx.ornB;
    box_capsule bc{
        a.half_extents, detail::make_capsule_segment(b, pos_ab, orn_ab), b.radius, ctx.ornA, orn_ab, pos_ab};

    scalar s;
    vector3 on_segment, on_box;
    auto dist_sqr = closest_points_segment_box(bc.he, bc.seg.p0, bc.seg.p1, s, on_segment, on_box);
    auto dist = std::sqrt(dist_sqr);
    if (dist - b.radius > ctx.threshold) return;
    // Below a micrometre the direction between the closest points is rounding noise.
    if (dist > scalar(1e-6)) {
        separated(bc, on_segment, on_box, s, dist, ctx.threshold, result);
    } else {
        penetrating(bc, ctx.threshold, result);
    }
}

void collide(const capsule_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
