#ifndef EDYN_DYNAMICS_SHAPE_INDEX_HPP
#define EDYN_DYNAMICS_SHAPE_INDEX_HPP

#include <cstddef>

namespace edyn {

/// Component: which shape component a body has, as the index of its type in shapes_variant_t.
/// The shape itself is stored as a component of its own type (box_shape, sphere_shape, ...), so
/// that a program can read and patch it directly. Written by make_rigidbody and
/// rigidbody_set_shape; absent on amorphous bodies. visit_shape uses it to reach the shape.
struct shape_index {
    std::size_t value; ///< Index of the shape's type in shapes_variant_t.
};

} // namespace edyn

#endif // EDYN_DYNAMICS_SHAPE_INDEX_HPP
