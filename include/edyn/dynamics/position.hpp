#ifndef EDYN_DYNAMICS_POSITION_HPP
#define EDYN_DYNAMICS_POSITION_HPP

#include "edyn/math/vector3.hpp"

namespace edyn {

// Components that are a vector3 or a quaternion convert from one and from its coordinates, so
// that `registry.get<linvel>(e) = {0, 5, 0}` and `= some_vector` both read as they should.

// World-space position of a rigid body's centre of mass (not its origin when the centre of
// mass is shifted; see get_rigidbody_origin). Use present_position for rendering.
struct position : vector3 {
    position() = default;
    constexpr position(const vector3 &v) noexcept
        : vector3(v) {}
    constexpr position(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

// Position interpolated to the time of the last update(), for rendering.
struct present_position : vector3 {
    present_position() = default;
    constexpr present_position(const vector3 &v) noexcept
        : vector3(v) {}
    constexpr present_position(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

} // namespace edyn

#endif // EDYN_DYNAMICS_POSITION_HPP
