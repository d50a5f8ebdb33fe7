#ifndef EDYN_SHAPES_CAPSULE_SHAPE_HPP
#define EDYN_SHAPES_CAPSULE_SHAPE_HPP

#include "edyn/shapes/coordinate_axis.hpp"

namespace edyn {

// Segment from -half_length to +half_length along `axis`, swept by a sphere of `radius`.
// Features: hemisphere (index 0 at +half_length, 1 at -half_length) and side.
struct capsule_shape {
    scalar radius;
    scalar half_length;
    coordinate_axis axis{coordinate_axis::x};
};

} // namespace edyn

#endif // EDYN_SHAPES_CAPSULE_SHAPE_HPP
