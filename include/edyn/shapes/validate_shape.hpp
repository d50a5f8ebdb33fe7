#ifndef EDYN_SHAPES_VALIDATE_SHAPE_HPP
#define EDYN_SHAPES_VALIDATE_SHAPE_HPP

#include "edyn/shapes/shapes.hpp"

namespace edyn {

// Checks a shape given by the user; throws std::invalid_argument naming the shape, the field
// and the value, e.g. "box_shape: half_extents.y must be positive and finite, got -1".
//  - sphere, cylinder, capsule: radius (and half_length) positive and finite; axis one of
//    coordinate_axis::x, y, z.
//  - box: every half extent positive and finite.
//  - plane: normal finite and unit length (|length^2 - 1| <= 1e-3; it is not normalised for
//    you), constant finite.
//  - polyhedron: a mesh is present and passes validate_convex_mesh.
//  - compound: at least one child, finish() called after the last add_shape(), every child
//    valid with a finite position and a unit orientation.
void validate_shape(const plane_shape &shape);
void validate_shape(const sphere_shape &shape);
void validate_shape(const box_shape &shape);
void validate_shape(const cylinder_shape &shape);
void validate_shape(const capsule_shape &shape);
void validate_shape(const polyhedron_shape &shape);
void validate_shape(const compound_shape &shape);
void validate_shape(const compound_child_shape_t &shape);
//  - mesh: a triangle mesh is present and initialized.
void validate_shape(const mesh_shape &shape);
//  - paged mesh: a paged triangle mesh is present.
void validate_shape(const paged_mesh_shape &shape);

template<shapes_variant Variant>
void validate_shape(const Variant &shape) {
    std::visit([](const auto &s) { validate_shape(s); }, shape);
}

} // namespace edyn

#endif // EDYN_SHAPES_VALIDATE_SHAPE_HPP
