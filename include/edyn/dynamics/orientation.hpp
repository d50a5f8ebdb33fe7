#ifndef EDYN_DYNAMICS_ORIENTATION_HPP
#define EDYN_DYNAMICS_ORIENTATION_HPP

#include "edyn/math/quaternion.hpp"

namespace edyn {

// World-space orientation of a rigid body (x y z w). Use present_orientation for rendering.
struct orientation : quaternion {
    orientation &operator=(const quaternion &q) noexcept {
        quaternion::operator=(q);
        return *this;
    }
};

// Orientation interpolated to the time of the last update(), for rendering.
struct present_orientation : quaternion {
    present_orientation &operator=(const quaternion &q) noexcept {
        quaternion::operator=(q);
        return *this;
    }
};

} // namespace edyn

#endif // EDYN_DYNAMICS_ORIENTATION_HPP
