#ifndef EDYN_DYNAMICS_SHAPE_INDEX_HPP
#define EDYN_DYNAMICS_SHAPE_INDEX_HPP

#include <cstddef>

namespace edyn {

// Which shape component a body has, as the index of its type in shapes_variant_t. The shape
// itself is stored as a component of its own type (box_shape, sphere_shape, ...), so that a
// program can read and patch it directly.
struct shape_index {
    std::size_t value;
};

} // namespace edyn

#endif // EDYN_DYNAMICS_SHAPE_INDEX_HPP
