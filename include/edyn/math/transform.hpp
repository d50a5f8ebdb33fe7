#ifndef EDYN_MATH_TRANSFORM_HPP
#define EDYN_MATH_TRANSFORM_HPP

#include "edyn/math/quaternion.hpp"

namespace edyn {

/// Point `p` given in the object space of a body at (pos, orn) expressed in world space.
/// @param p Point in object space, m.
/// @param pos Position of the body's origin in world space, m.
/// @param orn Orientation of the body, unit quaternion.
/// @return The point in world space, m.
constexpr vector3 to_world_space(const vector3 &p, const vector3 &pos, const quaternion &orn) noexcept {
    return pos + rotate(orn, p);
}

/// World-space point `p` expressed in the object space of a body at (pos, orn); the inverse of
/// `to_world_space`.
/// @param p Point in world space, m.
/// @param pos Position of the body's origin in world space, m.
/// @param orn Orientation of the body, unit quaternion.
/// @return The point in object space, m.
constexpr vector3 to_object_space(const vector3 &p, const vector3 &pos, const quaternion &orn) noexcept {
    return rotate(conjugate(orn), p - pos);
}

} // namespace edyn

#endif // EDYN_MATH_TRANSFORM_HPP
