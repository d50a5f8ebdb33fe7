#ifndef EDYN_DYNAMICS_VELOCITY_HPP
#define EDYN_DYNAMICS_VELOCITY_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

/// Component: linear velocity of the centre of mass, world space, m/s.
/// Written by make_rigidbody (rigidbody_def::linvel; zero for static bodies) and by every step.
/// The program may set it with `replace` or `patch` (a kinematic body follows it).
struct linvel : vector3 {
    linvel() = default;
    /// Makes the velocity from a vector.
    /// @param v World-space velocity, in m/s.
    constexpr linvel(const vector3 &v) noexcept
        : vector3(v) {}
    /// Makes the velocity from its world-space coordinates, in m/s.
    /// @param x Velocity along the world's x axis.
    /// @param y Velocity along the world's y axis.
    /// @param z Velocity along the world's z axis.
    constexpr linvel(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

/// Component: angular velocity, world space, rad/s.
/// The vector is the rotation axis scaled by the rate. Written by make_rigidbody
/// (rigidbody_def::angvel; zero for static bodies) and by every step. The program may set it
/// with `replace` or `patch` (a kinematic body follows it).
struct angvel : vector3 {
    angvel() = default;
    /// Makes the angular velocity from a vector.
    /// @param v World-space angular velocity, in rad/s.
    constexpr angvel(const vector3 &v) noexcept
        : vector3(v) {}
    /// Makes the angular velocity from its world-space coordinates, in rad/s.
    /// @param x Rate about the world's x axis.
    /// @param y Rate about the world's y axis.
    /// @param z Rate about the world's z axis.
    constexpr angvel(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

/// Component: per-body gravitational acceleration, overriding the world's (see set_gravity),
/// in m/s².
/// Emplaced by make_rigidbody on a dynamic body whose rigidbody_def::gravity is set; bodies
/// without it fall with the world's gravity. Static and kinematic bodies ignore it.
struct gravity : vector3 {
    gravity() = default;
    /// Makes the acceleration from a vector.
    /// @param v World-space acceleration, in m/s².
    constexpr gravity(const vector3 &v) noexcept
        : vector3(v) {}
    /// Makes the acceleration from its world-space coordinates, in m/s².
    /// @param x Acceleration along the world's x axis.
    /// @param y Acceleration along the world's y axis.
    /// @param z Acceleration along the world's z axis.
    constexpr gravity(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

} // namespace edyn

#endif // EDYN_DYNAMICS_VELOCITY_HPP
