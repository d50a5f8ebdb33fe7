#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/transform.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

AABB shape_aabb(const plane_shape &shape, const vector3 &, const quaternion &) {
    constexpr auto h = plane_aabb_half_size;
    AABB aabb{{-h, -h, -h}, {h, h, h}};
    const auto &n = shape.normal;
    for (int i = 0; i < 3; ++i) {
        auto j = (i + 1) % 3, k = (i + 2) % 3;
        if (n[i] == 0 || n[j] != 0 || n[k] != 0) continue;
        // The solid half-space n_i x_i <= constant.
        auto bound = std::clamp(shape.constant / n[i], -h, h);
        if (n[i] > 0) {
            aabb.max[i] = bound;
        } else {
            aabb.min[i] = bound;
        }
    }
    return aabb;
}

namespace {

AABB placed_aabb(const AABB &local, const vector3 &pos, const quaternion &orn) {
    auto basis = to_matrix3x3(orn);
    auto he = (local.max - local.min) * scalar(0.5);
    auto center = pos + basis * aabb_center(local);
    auto extent = vector3{dot(abs(basis[0]), he), dot(abs(basis[1]), he), dot(abs(basis[2]), he)};
    return {center - extent, center + extent};
}

} // namespace

AABB shape_aabb(const mesh_shape &shape, const vector3 &pos, const quaternion &orn) {
    EDYN_ASSERT(shape.trimesh && shape.trimesh->initialized());
    return placed_aabb(shape.trimesh->get_aabb(), pos, orn);
}

AABB shape_aabb(const paged_mesh_shape &shape, const vector3 &pos, const quaternion &orn) {
    EDYN_ASSERT(shape.trimesh);
    return placed_aabb(shape.trimesh->get_aabb(), pos, orn);
}

AABB shape_aabb(const sphere_shape &shape, const vector3 &pos, const quaternion &) {
    auto r = vector3{shape.radius, shape.radius, shape.radius};
    return {pos - r, pos + r};
}

AABB shape_aabb(const box_shape &shape, const vector3 &pos, const quaternion &orn) {
    // Extent along world axis i: sum over the box axes j of |R_ij| h_j.
    auto basis = to_matrix3x3(orn);
    auto he = shape.half_extents;
    auto extent = vector3{dot(abs(basis[0]), he), dot(abs(basis[1]), he), dot(abs(basis[2]), he)};
    return {pos - extent, pos + extent};
}

AABB shape_aabb(const cylinder_shape &shape, const vector3 &pos, const quaternion &orn) {
    // The caps are discs of normal a: along unit direction e a disc of radius r reaches
    // r sqrt(1 - (a.e)^2) from its centre, taken from a's other components.
    auto a = coordinate_axis_vector(shape.axis, orn);
    vector3 extent;
    for (int i = 0; i < 3; ++i) {
        extent[i] = std::abs(a[i]) * shape.half_length + shape.radius * length_across_axis(a, i);
    }
    return {pos - extent, pos + extent};
}

AABB shape_aabb(const capsule_shape &shape, const vector3 &pos, const quaternion &orn) {
    auto a = coordinate_axis_vector(shape.axis, orn);
    auto extent = abs(a) * shape.half_length + vector3_one * shape.radius;
    return {pos - extent, pos + extent};
}

AABB shape_aabb(const polyhedron_shape &shape, const vector3 &pos, const quaternion &orn) {
    EDYN_ASSERT(shape.mesh && !shape.mesh->vertices.empty());
    auto basis = to_matrix3x3(orn);
    auto lo = basis * shape.mesh->vertices[0];
    auto hi = lo;
    for (const auto &v : shape.mesh->vertices) {
        auto p = basis * v;
        lo = min(lo, p);
        hi = max(hi, p);
    }
    return {pos + lo, pos + hi};
}

AABB shape_aabb(const compound_shape &shape, const vector3 &pos, const quaternion &orn) {
    EDYN_ASSERT(!shape.children.empty());
    AABB result{vector3_max, -vector3_max};
    for (const auto &child : shape.children) {
        auto child_pos = to_world_space(child.position, pos, orn);
        auto child_orn = orn * child.orientation;
        result = enclosing_aabb(result, shape_aabb(child.shape, child_pos, child_orn));
    }
    return result;
}

AABB shape_aabb(const compound_child_shape_t &shape, const vector3 &pos, const quaternion &orn) {
    return std::visit([&](const auto &s) { return shape_aabb(s, pos, orn); }, shape);
}

} // namespace edyn
