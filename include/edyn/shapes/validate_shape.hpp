#ifndef EDYN_SHAPES_VALIDATE_SHAPE_HPP
#define EDYN_SHAPES_VALIDATE_SHAPE_HPP

#include "edyn/shapes/shapes.hpp"

namespace edyn {

/// Checks a plane given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const plane_shape &shape);
/// Checks a sphere given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const sphere_shape &shape);
/// Checks a box given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const box_shape &shape);
/// Checks a cylinder given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const cylinder_shape &shape);
/// Checks a capsule given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const capsule_shape &shape);
/// Checks a polyhedron given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const polyhedron_shape &shape);
/// Checks a compound given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const compound_shape &shape);
/// Checks any shape a compound can hold given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const compound_child_shape_t &shape);
/// Checks a triangle mesh shape given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const mesh_shape &shape);
/// Checks a paged triangle mesh shape given by the user.
///
/// Rules as listed for the shapes_variant_t overload.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value.
void validate_shape(const paged_mesh_shape &shape);

/// Checks a shape given by the user, whatever its type; make_rigidbody(),
/// rigidbody_set_shape() and compound_shape::add_shape() call it.
///
/// The rules, by shape:
///  - sphere, cylinder, capsule: radius (and half_length) positive and finite; axis one of
///    coordinate_axis::x, y, z.
///  - box: every half extent positive and finite.
///  - plane: normal finite and unit length (|length^2 - 1| <= 1e-3; it is not normalised for
///    you), constant finite.
///  - polyhedron: a mesh is present and passes validate_convex_mesh().
///  - compound: at least one child, finish() called after the last add_shape(), every child
///    valid with a finite position and a unit orientation.
///  - mesh: a triangle mesh is present and initialized.
///  - paged mesh: a paged triangle mesh is present.
/// @param shape The shape to check.
/// @throws std::invalid_argument Naming the shape, the field and the value, e.g.
///         "box_shape: half_extents.y must be positive and finite, got -1".
template<shapes_variant Variant>
void validate_shape(const Variant &shape) {
    std::visit([](const auto &s) { validate_shape(s); }, shape);
}

} // namespace edyn

#endif // EDYN_SHAPES_VALIDATE_SHAPE_HPP
