#ifndef EDYN_DYNAMICS_POSITION_HPP
#define EDYN_DYNAMICS_POSITION_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

/// @file
/// The position components of rigid bodies.
/// Components that are a vector3 or a quaternion convert from one and from its coordinates, so
/// that `registry.get<linvel>(e) = {0, 5, 0}` and `= some_vector` both read as they should.

/// Component: world-space position of a rigid body's centre of mass, in metres.
/// Not its origin when the centre of mass is shifted; see get_rigidbody_origin. Written by
/// make_rigidbody and by every step; the program may assign one (a kinematic body, a teleport)
/// with `replace` or `patch`, so that the simulation sees it. Use present_position for
/// rendering.
struct position : vector3 {
    position() = default;
    /// Makes the position from a vector.
    /// @param v World-space position, in metres.
    constexpr position(const vector3 &v) noexcept
        : vector3(v) {}
    /// Makes the position from its world-space coordinates, in metres.
    /// @param x Coordinate along the world's x axis.
    /// @param y Coordinate along the world's y axis.
    /// @param z Coordinate along the world's z axis.
    constexpr position(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

/// Component: position interpolated to the time of the last update(), for rendering, in metres.
/// Written by the engine in update(): between the last two steps' positions of the centre of
/// mass, so that motion looks smooth whatever the frame rate (in asynchronous mode one update
/// behind the sequential mode's).
struct present_position : vector3 {
    present_position() = default;
    /// Makes the position from a vector.
    /// @param v World-space position, in metres.
    constexpr present_position(const vector3 &v) noexcept
        : vector3(v) {}
    /// Makes the position from its world-space coordinates, in metres.
    /// @param x Coordinate along the world's x axis.
    /// @param y Coordinate along the world's y axis.
    /// @param z Coordinate along the world's z axis.
    constexpr present_position(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

} // namespace edyn

#endif // EDYN_DYNAMICS_POSITION_HPP
