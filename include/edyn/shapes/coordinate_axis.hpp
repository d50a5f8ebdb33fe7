#ifndef EDYN_SHAPES_COORDINATE_AXIS_HPP
#define EDYN_SHAPES_COORDINATE_AXIS_HPP

#include "edyn/math/quaternion.hpp"

namespace edyn {

// Main axis of a cylinder or capsule, in the shape's object space.
enum class coordinate_axis : unsigned char { x, y, z };

constexpr int coordinate_axis_index(coordinate_axis axis) noexcept { return static_cast<int>(axis); }

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

// The axis in world space for a shape at orientation `orn`.
constexpr vector3 coordinate_axis_vector(coordinate_axis axis, const quaternion &orn) noexcept {
    return rotate(orn, coordinate_axis_vector(axis));
}

} // namespace edyn

#endif // EDYN_SHAPES_COORDINATE_AXIS_HPP
