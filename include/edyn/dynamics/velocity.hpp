#ifndef EDYN_DYNAMICS_VELOCITY_HPP
#define EDYN_DYNAMICS_VELOCITY_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

// Linear velocity of the centre of mass, world space, m/s.
struct linvel : vector3 {
    linvel() = default;
    constexpr linvel(const vector3 &v) noexcept
        : vector3(v) {}
    constexpr linvel(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

// Angular velocity, world space, rad/s.
struct angvel : vector3 {
    angvel() = default;
    constexpr angvel(const vector3 &v) noexcept
        : vector3(v) {}
    constexpr angvel(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

// Per-body gravitational acceleration, overriding the world's (see set_gravity).
struct gravity : vector3 {
    gravity() = default;
    constexpr gravity(const vector3 &v) noexcept
        : vector3(v) {}
    constexpr gravity(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

} // namespace edyn

#endif // EDYN_DYNAMICS_VELOCITY_HPP
