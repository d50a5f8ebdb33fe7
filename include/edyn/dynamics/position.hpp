#ifndef EDYN_DYNAMICS_POSITION_HPP
#define EDYN_DYNAMICS_POSITION_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

// World-space position of a rigid body's centre of mass (not its origin when the centre of
// mass is shifted; see get_rigidbody_origin). Use present_position for rendering.
struct position : vector3 {
    position &operator=(const vector3 &v) noexcept {
        vector3::operator=(v);
        return *this;
    }
};

// Position interpolated to the time of the last update(), for rendering.
struct present_position : vector3 {
    present_position &operator=(const vector3 &v) noexcept {
        vector3::operator=(v);
        return *this;
    }
};

} // namespace edyn

#endif // EDYN_DYNAMICS_POSITION_HPP
