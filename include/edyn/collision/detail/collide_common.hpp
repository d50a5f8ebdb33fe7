#ifndef EDYN_COLLISION_DETAIL_COLLIDE_COMMON_HPP
#define EDYN_COLLISION_DETAIL_COLLIDE_COMMON_HPP

#include "edyn/collision/collision_result.hpp"
#include "edyn/math/transform.hpp"
#include "edyn/shapes/capsule_shape.hpp"

// Constants and small helpers shared by the collide() implementations.
namespace edyn::detail {

// Two points of one manifold whose pivots on A, or on B, are closer than this are one contact
// (the same spot of one of the shapes): collision_result::add_point keeps the deeper. 1 mm: below what a
// solver can tell apart for bodies of centimetre size and up, and far above the rounding of clipping.
inline constexpr scalar contact_merge_distance = scalar(1e-3);

// Separating-axis tests prefer face axes (and A's faces over B's): a candidate axis replaces the
// current one only when its separation is larger by more than this bias. It keeps manifolds
// from flipping between near-equal axes (e.g. a box resting face on face), at the cost of a
// penetration depth larger than the minimum by at most the bias.
inline constexpr scalar sat_bias_absolute = scalar(1e-3);
inline constexpr scalar sat_bias_relative = scalar(0.02);

constexpr bool sat_better(scalar candidate, scalar current) noexcept {
    auto magnitude = current < 0 ? -current : current;
    return candidate > current + sat_bias_absolute + sat_bias_relative * magnitude;
}

// Builds a point from world-space points on A and B, their world normal (B towards A) and the
// distance, expressing the pivots in each shape's object space.
inline collision_result::collision_point make_point(const collision_context &ctx, const vector3 &world_on_a,
                                                    const vector3 &world_on_b, const vector3 &normal,
                                                    scalar distance) noexcept {
    collision_result::collision_point p;
    p.pivotA = to_object_space(world_on_a, ctx.posA, ctx.ornA);
    p.pivotB = to_object_space(world_on_b, ctx.posB, ctx.ornB);
    p.normal = normal;
    p.distance = distance;
    return p;
}

// Runs `collide_ba(b, a, swapped context, tmp)` and appends its points to `result` with the
// roles of A and B exchanged: one routine serves both argument orders.
template<typename Fn, typename A, typename B>
void collide_swapped(Fn &&collide_ba, const A &a, const B &b, const collision_context &ctx,
                     collision_result &result) {
    collision_result swapped;
    collide_ba(b, a, collision_context{ctx.posB, ctx.ornB, ctx.posA, ctx.ornA, ctx.threshold}, swapped);
    swapped.swap();
    for (std::size_t i = 0; i < swapped.num_points; ++i) {
        result.add_point(swapped.point[i]);
    }
}

// Capsule segment in the frame of (pos, orn): p0 is the centre of hemisphere 0 (at
// +half_length), p1 that of hemisphere 1; `axis` is the unit vector from p1 to p0.
struct capsule_segment {
    vector3 p0;
    vector3 p1;
    vector3 axis;
};

inline capsule_segment make_capsule_segment(const capsule_shape &capsule, const vector3 &pos,
                                            const quaternion &orn) noexcept {
    auto axis = coordinate_axis_vector(capsule.axis, orn);
    auto half = axis * capsule.half_length;
    return {pos + half, pos - half, axis};
}

// Cosine between the outward surface direction and the capsule axis above which a point at a
// segment end lies on the hemisphere rather than on the rim where it meets the side.
inline constexpr scalar capsule_hemisphere_cosine = scalar(1e-4);

// Feature of a capsule surface point whose segment parameter is s (0 at p0, 1 at p1) and whose
// outward direction (from the segment) is `surface_dir`; `axis` as in capsule_segment, same frame.
inline collision_feature capsule_feature_at(scalar s, const vector3 &surface_dir,
                                            const vector3 &axis) noexcept {
    auto c = dot(surface_dir, axis);
    if (s <= 0 && c > capsule_hemisphere_cosine) return {capsule_feature::hemisphere, 0};
    if (s >= 1 && c < -capsule_hemisphere_cosine) return {capsule_feature::hemisphere, 1};
    return {capsule_feature::side, 0};
}

// A unit vector orthogonal to `axis`, oriented towards `towards` when that has a component off
// the axis: the separating direction for shapes whose cores touch or coincide.
inline vector3 orthogonal_towards(const vector3 &axis, const vector3 &towards) noexcept {
    auto v = project_plane(towards, axis);
    if (try_normalize(v)) return v;
    vector3 t0, t1;
    plane_space(axis, t0, t1);
    return t0;
}

} // namespace edyn::detail

#endif // EDYN_COLLISION_DETAIL_COLLIDE_COMMON_HPP
