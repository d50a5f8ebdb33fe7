#ifndef EDYN_SHAPES_BOX_SHAPE_HPP
#define EDYN_SHAPES_BOX_SHAPE_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

/// Box centred at the origin of its object space, a shape for rigid bodies of any kind.
///
/// `box_shape{x, y, z}` and `box_shape{vector3{x, y, z}}` both give half extents x, y, z.
///
/// Features, as reported by collide() and raycasts: faces 0..5 are +x, -x, +y, -y, +z, -z (face 2
/// is the upper face); vertex i has coordinate signs (i & 1 ? - : +) x, (i & 2 ? - : +) y,
/// (i & 4 ? - : +) z; edge i (0..11) runs along axis i / 4 between the two vertices that differ in
/// that axis' sign bit, the other two sign bits given by i % 4.
struct box_shape {
    /// Half of the box's size along each object-space axis (m); each must be positive and finite
    /// (see validate_shape()).
    vector3 half_extents;
};

} // namespace edyn

#endif // EDYN_SHAPES_BOX_SHAPE_HPP
