#include "edyn/shapes/shape_extent.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/scalar.hpp"
#include <algorithm>
#include <variant>

namespace edyn {

scalar shape_extent(const sphere_shape &shape, const quaternion &, const vector3 &) { return shape.radius; }

scalar shape_extent(const box_shape &shape, const quaternion &orn, const vector3 &dir) {
    return box_projection_radius(shape.half_extents, rotate(conjugate(orn), dir));
}

scalar shape_extent(const capsule_shape &shape, const quaternion &orn, const vector3 &dir) {
    return shape.radius + shape.half_length * std::abs(dot(coordinate_axis_vector(shape.axis, orn), dir));
}

scalar shape_extent(const cylinder_shape &shape, const quaternion &orn, const vector3 &dir) {
    return cylinder_projection_radius(coordinate_axis_vector(shape.axis, orn), shape.half_length,
                                      shape.radius, dir);
}

scalar shape_extent(const polyhedron_shape &shape, const quaternion &orn, const vector3 &dir) {
    if (!shape.mesh || shape.mesh->vertices.empty()) return large_scalar;
    auto local = rotate(conjugate(orn), dir);
    return dot(shape.mesh->vertices[shape.mesh->support_vertex(local)], local);
}

// The farthest child: its origin's offset along `dir` plus its own extent. A compound large
// enough for a tree over its children gets no bound: a pass over all of them could cost more
// than the collision it would spare, which the tree keeps to the children nearby.
scalar shape_extent(const compound_shape &shape, const quaternion &orn, const vector3 &dir) {
    if (shape.children.empty() || shape.children.size() > compound_shape::max_children_without_tree)
        return large_scalar;
    auto extent = -large_scalar;
    for (const auto &child : shape.children) {
        auto child_orn = orn * child.orientation;
        auto reach = std::visit([&](const auto &s) { return shape_extent(s, child_orn, dir); }, child.shape);
        extent = std::max(extent, dot(rotate(orn, child.position), dir) + reach);
    }
    return extent;
}

scalar shape_extent(const plane_shape &, const quaternion &, const vector3 &) { return large_scalar; }

scalar shape_extent(const mesh_shape &, const quaternion &, const vector3 &) { return large_scalar; }

scalar shape_extent(const paged_mesh_shape &, const quaternion &, const vector3 &) { return large_scalar; }

} // namespace edyn
