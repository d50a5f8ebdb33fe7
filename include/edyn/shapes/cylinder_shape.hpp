#ifndef EDYN_SHAPES_CYLINDER_SHAPE_HPP
#define EDYN_SHAPES_CYLINDER_SHAPE_HPP

#include "edyn/shapes/coordinate_axis.hpp"

namespace edyn {

/// Cylinder centred at the origin of its object space whose main axis is `axis`; the caps lie
/// at +/- half_length.
///
/// Features (cylinder_feature): face, a cap (index 0 is the cap at +half_length, 1 at
/// -half_length); cap_edge, a cap's rim (index as for face); side_edge, the curved side (index 0).
struct cylinder_shape {
    scalar radius;      ///< Radius of the caps (m); positive and finite.
    scalar half_length; ///< Half the distance between the caps (m); positive and finite.
    coordinate_axis axis{coordinate_axis::x}; ///< Main axis in object space; x by default.
};

} // namespace edyn

#endif // EDYN_SHAPES_CYLINDER_SHAPE_HPP
