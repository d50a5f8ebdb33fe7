#ifndef EDYN_SHAPES_COORDINATE_AXIS_HPP
#define EDYN_SHAPES_COORDINATE_AXIS_HPP

#include "edyn/math/quaternion.hpp"

namespace edyn {

/// Main axis of a cylinder or capsule, in the shape's object space.
enum class coordinate_axis : unsigned char {
    x, ///< The object-space x axis.
    y, ///< The object-space y axis.
    z  ///< The object-space z axis.
};

/// Index of the axis: 0 for x, 1 for y, 2 for z (e.g. to index a vector3).
constexpr int coordinate_axis_index(coordinate_axis axis) noexcept { return static_cast<int>(axis); }

/// Unit vector along the axis in object space.
/// @param axis The axis.
/// @return (1, 0, 0), (0, 1, 0) or (0, 0, 1).
constexpr vector3 coordinate_axis_vector(coordinate_axis axis) noexcept {
    switch (axis) {
    case coordinate_axis::x:
        return vector3_x;
    case coordinate_axis::y:
        return vector3_y;
    default:
        return vector3_z;
    }
}

/// The axis in world space for a shape at orientation `orn`.
/// @param axis The axis in object space.
/// @param orn The shape's orientation (unit quaternion).
/// @return The rotated unit vector.
constexpr vector3 coordinate_axis_vector(coordinate_axis axis, const quaternion &orn) noexcept {
    return rotate(orn, coordinate_axis_vector(axis));
}

} // namespace edyn

#endif // EDYN_SHAPES_COORDINATE_AXIS_HPP
