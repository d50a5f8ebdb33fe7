#ifndef EDYN_DYNAMICS_ORIENTATION_HPP
#define EDYN_DYNAMICS_ORIENTATION_HPP

#include "edyn/math/quaternion.hpp"

namespace edyn {

// World-space orientation of a rigid body (x y z w). Use present_orientation for rendering.
struct orientation : quaternion {
    orientation() = default;
    constexpr orientation(const quaternion &q) noexcept
        : quaternion(q) {}
    constexpr orientation(scalar x, scalar y, scalar z, scalar w) noexcept
        : quaternion{x, y, z, w} {}
};

// Orientation interpolated to the time of the last update(), for rendering.
struct present_orientation : quaternion {
    present_orientation() = default;
    constexpr present_orientation(const quaternion &q) noexcept
        : quaternion(q) {}
    constexpr present_orientation(scalar x, scalar y, scalar z, scalar w) noexcept
        : quaternion{x, y, z, w} {}
};

} // namespace edyn

#endif // EDYN_DYNAMICS_ORIENTATION_HPP
