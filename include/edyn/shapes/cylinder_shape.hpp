#ifndef EDYN_SHAPES_CYLINDER_SHAPE_HPP
#define EDYN_SHAPES_CYLINDER_SHAPE_HPP

#include "edyn/shapes/coordinate_axis.hpp"

namespace edyn {

// Cylinder centred at the origin whose main axis is `axis`; the caps lie at +/- half_length.
// Features: cap_face (index 0 is the cap at +half_length, 1 at -half_length), side_edge, cap_edge
// (index as for cap_face), side_face.
struct cylinder_shape {
    scalar radius;
    scalar half_length;
    coordinate_axis axis{coordinate_axis::x};
};

} // namespace edyn

#endif // EDYN_SHAPES_CYLINDER_SHAPE_HPP
