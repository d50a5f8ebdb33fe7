#ifndef EDYN_DYNAMICS_VELOCITY_HPP
#define EDYN_DYNAMICS_VELOCITY_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

// Linear velocity of the centre of mass, world space, m/s.
struct linvel : vector3 {
    linvel &operator=(const vector3 &v) noexcept {
        vector3::operator=(v);
        return *this;
    }
};

// Angular velocity, world space, rad/s.
struct angvel : vector3 {
    angvel &operator=(const vector3 &v) noexcept {
        vector3::operator=(v);
        return *this;
    }
};

// Per-body gravitational acceleration, overriding the world's (see set_gravity).
struct gravity : vector3 {
    gravity &operator=(const vector3 &v) noexcept {
        vector3::operator=(v);
        return *this;
    }
};

} // namespace edyn

#endif // EDYN_DYNAMICS_VELOCITY_HPP
