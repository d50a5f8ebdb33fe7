#ifndef EDYN_DYNAMICS_ORIENTATION_HPP
#define EDYN_DYNAMICS_ORIENTATION_HPP

#include "edyn/math/quaternion.hpp"

namespace edyn {

/// Component: world-space orientation of a rigid body, a unit quaternion (x y z w).
/// Written by make_rigidbody and by every step. The program may assign one (a kinematic body,
/// a teleport) with `replace` or `patch`, so that the simulation sees it. Use
/// present_orientation for rendering.
struct orientation : quaternion {
    orientation() = default;
    /// Makes the orientation from a quaternion.
    /// @param q A unit quaternion (x y z w).
    constexpr orientation(const quaternion &q) noexcept
        : quaternion(q) {}
    /// Makes the orientation from its coordinates, in x y z w order.
    /// @param x Vector part, x.
    /// @param y Vector part, y.
    /// @param z Vector part, z.
    /// @param w Scalar part.
    constexpr orientation(scalar x, scalar y, scalar z, scalar w) noexcept
        : quaternion{x, y, z, w} {}
};

/// Component: orientation interpolated to the time of the last update(), for rendering.
/// Written by the engine in update(): between the last two steps' orientations, so that
/// motion looks smooth whatever the frame rate (in asynchronous mode one update behind the
/// sequential mode's).
struct present_orientation : quaternion {
    present_orientation() = default;
    /// Makes the orientation from a quaternion.
    /// @param q A unit quaternion (x y z w).
    constexpr present_orientation(const quaternion &q) noexcept
        : quaternion(q) {}
    /// Makes the orientation from its coordinates, in x y z w order.
    /// @param x Vector part, x.
    /// @param y Vector part, y.
    /// @param z Vector part, z.
    /// @param w Scalar part.
    constexpr present_orientation(scalar x, scalar y, scalar z, scalar w) noexcept
        : quaternion{x, y, z, w} {}
};

} // namespace edyn

#endif // EDYN_DYNAMICS_ORIENTATION_HPP
