#ifndef EDYN_SRC_SHAPES_VALIDATE_COMPOUND_CHILD_HPP
#define EDYN_SRC_SHAPES_VALIDATE_COMPOUND_CHILD_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/shapes/compound_shape.hpp"

// The check of one child of a compound, shared by add_shape(), validate_shape() and the
// refresh of a compound changed in place. Private to src/.
namespace edyn::detail {

// Throws std::invalid_argument when the child's shape is invalid ("shape: " and the shape's
// problem), its position is not finite ("position must be finite, got ...") or its orientation
// is not a unit quaternion. The caller puts the compound and the child's name in front.
void validate_compound_child(const compound_child_shape_t &shape, const vector3 &position,
                             const quaternion &orientation);

} // namespace edyn::detail

#endif // EDYN_SRC_SHAPES_VALIDATE_COMPOUND_CHILD_HPP
