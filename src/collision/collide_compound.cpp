#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/transform.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include <variant>

// A compound collides through its children: each child that can be within the threshold runs
// the convex pair at the child's world transform into a fixed-size collision_result, whose points
// are then moved into the compound's object space and merged into the output with add_point
// (which keeps the deepest point and the widest four). Every point's feature on the compound
// carries the child index in `part`; when the child pair reports no feature (polyhedra, spheres),
// the feature is {std::monostate, 0, part} so that contact matching can still tell children
// apart. Compound against compound goes through the convex-against-compound overloads, so both
// features carry their child index.

namespace edyn {

namespace {

struct frame {
    vector3 pos;
    quaternion orn;
};

// Transform of the shape at (posB, ornB) expressed in the object space of (posA, ornA).
frame relative_frame(const collision_context &ctx) noexcept {
    return {to_object_space(ctx.posB, ctx.posA, ctx.ornA), conjugate(ctx.ornA) * ctx.ornB};
}

AABB inflate(const AABB &aabb, scalar threshold) noexcept { return inset(aabb, vector3_one * threshold); }

// Bounds of the box `local` (object space of `f`) in the space `f` is given in.
AABB transform_aabb(const AABB &local, const frame &f) noexcept {
    auto basis = to_matrix3x3(f.orn);
    auto he = aabb_half_extents(local);
    auto extent = vector3{dot(abs(basis[0]), he), dot(abs(basis[1]), he), dot(abs(basis[2]), he)};
    auto center = to_world_space(aabb_center(local), f.pos, f.orn);
    return {center - extent, center + extent};
}

// Bounds of all children in the compound's object space: the tree's root when there is one.
AABB local_bounds(const compound_shape &shape) noexcept {
    EDYN_ASSERT(!shape.children.empty(), "compound_shape without children");
    if (!shape.tree.empty()) return shape.tree.root_aabb();
    auto aabb = shape.children[0].aabb;
    for (const auto &child : shape.children) {
        aabb = enclosing_aabb(aabb, child.aabb);
    }
    return aabb;
}

collision_feature child_feature(const std::optional<collision_feature> &feature, std::size_t index) noexcept {
    auto f = feature ? *feature : collision_feature{};
    f.part = static_cast<std::int32_t>(index);
    return f;
}

// Runs child `index` of `a` (the compound at posA/ornA in ctx) against `b` and merges the points
// into `result`. `scratch` is the caller's per-child result, reused to avoid re-constructing it.
template<typename Other>
void collide_child(const compound_shape &a, std::size_t index, const Other &b, const collision_context &ctx,
                   collision_result &scratch, collision_result &result) {
    const auto &child = a.children[index];
    auto child_ctx = collision_context{to_world_space(child.position, ctx.posA, ctx.ornA),
                                       ctx.ornA * child.orientation, ctx.posB, ctx.ornB, ctx.threshold};
    scratch.num_points = 0;
    std::visit([&](const auto &shape) { collide(shape, b, child_ctx, scratch); }, child.shape);

    for (std::size_t k = 0; k < scratch.num_points; ++k) {
        auto p = scratch.point[k];
        p.pivotA = to_world_space(p.pivotA, child.position, child.orientation);
        p.featureA = child_feature(p.featureA, index);
        result.add_point(p);
    }
}

// Every child whose AABB overlaps `b_local` (the other shape's bounds in the compound's object
// space, inflated by the threshold) against `b`.
template<typename Other>
void collide_children(const compound_shape &a, const Other &b, const AABB &b_local,
                      const collision_context &ctx, collision_result &result) {
    collision_result scratch;
    a.visit(b_local, [&](std::size_t index) { collide_child(a, index, b, ctx, scratch, result); });
}

template<typename Shape>
void collide_compound_convex(const compound_shape &a, const Shape &b, const collision_context &ctx,
                             collision_result &result) {
    auto rel = relative_frame(ctx);
    auto b_local = inflate(shape_aabb(b, rel.pos, rel.orn), ctx.threshold);
    collide_children(a, b, b_local, ctx, result);
}

} // namespace

void collide(const compound_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    // A's children are culled against B's bounds (B's tree root, rotated into A's space); each
    // remaining child then culls B's children with B's tree against the child's own AABB in B's
    // space (collide(child, compound)), so only pairs of overlapping child AABBs run.
    auto b_local = inflate(transform_aabb(local_bounds(b), relative_frame(ctx)), ctx.threshold);
    collide_children(a, b, b_local, ctx, result);
}

void collide(const compound_shape &a, const plane_shape &b, const collision_context &ctx,
             collision_result &result) {
    // The plane in the compound's object space: dot(normal_local, p) == constant_local. A child
    // whose AABB lies entirely farther than the threshold in front of it is skipped. Planes are
    // infinite, so there is no bounding box to give the tree: every child is tested.
    auto normal_local = rotate(conjugate(ctx.ornA), b.normal);
    auto constant_local = b.constant - dot(b.normal, ctx.posA);
    auto abs_normal = abs(normal_local);
    collision_result scratch;
    for (std::size_t i = 0; i < a.children.size(); ++i) {
        const auto &aabb = a.children[i].aabb;
        auto lowest = dot(normal_local, aabb_center(aabb)) - dot(abs_normal, aabb_half_extents(aabb));
        if (lowest - constant_local > ctx.threshold) continue;
        collide_child(a, i, b, ctx, scratch, result);
    }
}

void collide(const compound_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_compound_convex(a, b, ctx, result);
}

void collide(const compound_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_compound_convex(a, b, ctx, result);
}

void collide(const compound_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_compound_convex(a, b, ctx, result);
}

void collide(const compound_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_compound_convex(a, b, ctx, result);
}

void collide(const compound_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_compound_convex(a, b, ctx, result);
}

void collide(const compound_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_compound_convex(a, b, ctx, result);
}

void collide(const compound_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_compound_convex(a, b, ctx, result);
}

// The other argument order runs the routines above with A and B exchanged, so that both orders
// give the same points.

void collide(const sphere_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const plane_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const box_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const capsule_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const cylinder_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const polyhedron_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const mesh_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const paged_mesh_shape &a, const compound_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
