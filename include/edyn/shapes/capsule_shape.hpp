#ifndef EDYN_SHAPES_CAPSULE_SHAPE_HPP
#define EDYN_SHAPES_CAPSULE_SHAPE_HPP

#include "edyn/shapes/coordinate_axis.hpp"

namespace edyn {

/// Capsule: the segment from -half_length to +half_length along `axis`, swept by a sphere of
/// `radius`, centred at the origin of its object space.
///
/// Features: capsule_feature::hemisphere (index 0 at +half_length, 1 at -half_length) and
/// capsule_feature::side.
struct capsule_shape {
    /// Radius of the swept sphere (m); positive and finite.
    scalar radius;
    /// Half the length of the inner segment, without the hemispheres (m); positive and finite.
    scalar half_length;
    coordinate_axis axis{coordinate_axis::x}; ///< Main axis in object space; x by default.
};

} // namespace edyn

#endif // EDYN_SHAPES_CAPSULE_SHAPE_HPP
