#ifndef EDYN_SHAPES_PLANE_SHAPE_HPP
#define EDYN_SHAPES_PLANE_SHAPE_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

// Infinite plane of the points p with dot(normal, p) == constant; solid behind the normal.
// Static bodies only; it ignores the body's position and orientation.
struct plane_shape {
    vector3 normal;
    scalar constant;
};

} // namespace edyn

#endif // EDYN_SHAPES_PLANE_SHAPE_HPP
