#ifndef EDYN_SHAPES_SPHERE_SHAPE_HPP
#define EDYN_SHAPES_SPHERE_SHAPE_HPP

#include "edyn/math/scalar.hpp"

namespace edyn {

struct sphere_shape {
    scalar radius;
};

} // namespace edyn

#endif // EDYN_SHAPES_SPHERE_SHAPE_HPP
