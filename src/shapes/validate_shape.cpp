#include "edyn/shapes/validate_shape.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "invalid_argument.hpp"
#include "validate_compound_child.hpp"
#include <cmath>
#include <string>

namespace edyn {

namespace {

using detail::positive_finite;
using detail::throw_invalid_argument;

void check_positive(const char *shape, const char *field, scalar value) {
    if (!positive_finite(value)) {
        throw_invalid_argument(shape, ": ", field, " must be positive and finite, got ", value);
    }
}

void check_axis(const char *shape, coordinate_axis axis) {
    auto value = static_cast<unsigned>(axis);
    if (value > static_cast<unsigned>(coordinate_axis::z)) {
        throw_invalid_argument(shape, ": axis must be coordinate_axis::x, y or z, got ", value);
    }
}

} // namespace

void validate_shape(const mesh_shape &shape) {
    if (!shape.trimesh) throw_invalid_argument("mesh_shape: trimesh is null");
    if (!shape.trimesh->initialized()) {
        throw_invalid_argument("mesh_shape: trimesh is not initialized; call triangle_mesh::initialize()");
    }
}

void validate_shape(const paged_mesh_shape &shape) {
    if (!shape.trimesh) throw_invalid_argument("paged_mesh_shape: trimesh is null");
}

void validate_shape(const plane_shape &shape) {
    if (!isfinite(shape.normal)) {
        throw_invalid_argument("plane_shape: normal must be finite, got ", shape.normal);
    }
    auto len_sqr = length_sqr(shape.normal);
    if (!(std::abs(len_sqr - 1) <= scalar(1e-3))) {
        throw_invalid_argument("plane_shape: normal must be a unit vector, got ", shape.normal, " of length ",
                               std::sqrt(len_sqr));
    }
    if (!std::isfinite(shape.constant)) {
        throw_invalid_argument("plane_shape: constant must be finite, got ", shape.constant);
    }
}

void validate_shape(const sphere_shape &shape) { check_positive("sphere_shape", "radius", shape.radius); }

void validate_shape(const box_shape &shape) {
    check_positive("box_shape", "half_extents.x", shape.half_extents.x);
    check_positive("box_shape", "half_extents.y", shape.half_extents.y);
    check_positive("box_shape", "half_extents.z", shape.half_extents.z);
}

void validate_shape(const cylinder_shape &shape) {
    check_positive("cylinder_shape", "radius", shape.radius);
    check_positive("cylinder_shape", "half_length", shape.half_length);
    check_axis("cylinder_shape", shape.axis);
}

void validate_shape(const capsule_shape &shape) {
    check_positive("capsule_shape", "radius", shape.radius);
    check_positive("capsule_shape", "half_length", shape.half_length);
    check_axis("capsule_shape", shape.axis);
}

void validate_shape(const polyhedron_shape &shape) {
    if (!shape.mesh) {
        throw_invalid_argument("polyhedron_shape: mesh is null (default-constructed shape)");
    }
    validate_convex_mesh(*shape.mesh);
}

void validate_shape(const compound_child_shape_t &shape) {
    std::visit([](const auto &s) { validate_shape(s); }, shape);
}

void detail::validate_compound_child(const compound_child_shape_t &shape, const vector3 &position,
                                     const quaternion &orientation) {
    try {
        validate_shape(shape);
    } catch (const std::invalid_argument &e) {
        throw_invalid_argument("shape: ", e.what());
    }
    if (!isfinite(position)) {
        throw_invalid_argument("position must be finite, got ", position);
    }
    if (!isfinite(orientation) || !is_unit(orientation)) {
        throw_invalid_argument("orientation must be a unit quaternion, got ", orientation, " of length ",
                               length(orientation));
    }
}

void validate_shape(const compound_shape &shape) {
    if (shape.children.empty()) {
        throw_invalid_argument("compound_shape: children is empty; add shapes with add_shape()");
    }
    if (!shape.finished) {
        throw_invalid_argument("compound_shape: finish() was not called after the last add_shape()");
    }
    for (std::size_t i = 0; i < shape.children.size(); ++i) {
        const auto &child = shape.children[i];
        try {
            detail::validate_compound_child(child.shape, child.position, child.orientation);
        } catch (const std::invalid_argument &e) {
            throw_invalid_argument("compound_shape: children[", i, "].", e.what());
        }
        if (child.aabb != shape_aabb(child.shape, child.position, child.orientation)) {
            throw_invalid_argument("compound_shape: children[", i,
                                   "] changed since finish(), which takes its bounds; call finish() again");
        }
    }
    // Every child a leaf of the tree, and no other, when there is one.
    std::size_t leaves = 0;
    auto beyond = false;
    for (const auto &node : shape.tree.nodes) {
        if (!node.leaf) continue;
        ++leaves;
        beyond = beyond || node.index >= shape.children.size();
    }
    auto tree_children =
        shape.children.size() > compound_shape::max_children_without_tree ? shape.children.size() : 0;
    if (leaves != tree_children || beyond) {
        throw_invalid_argument(
            "compound_shape: children were added or removed since finish(), which builds its tree; "
            "call finish() again");
    }
}

} // namespace edyn
