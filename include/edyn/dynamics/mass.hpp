#ifndef EDYN_DYNAMICS_MASS_HPP
#define EDYN_DYNAMICS_MASS_HPP

#include "edyn/math/matrix3x3.hpp"

namespace edyn {

// Mass in kg; infinite (large_scalar) for static and kinematic bodies, whose mass_inv is 0.
struct mass {
    scalar s;
    constexpr operator scalar() const noexcept { return s; }
};

struct mass_inv {
    scalar s;
    constexpr operator scalar() const noexcept { return s; }
};

// Inertia tensor about the centre of mass, in object space.
struct inertia : matrix3x3 {
    inertia &operator=(const matrix3x3 &m) noexcept {
        matrix3x3::operator=(m);
        return *this;
    }
};

// Inverse of the object-space inertia tensor (zero for static and kinematic bodies).
struct inertia_inv : matrix3x3 {
    inertia_inv &operator=(const matrix3x3 &m) noexcept {
        matrix3x3::operator=(m);
        return *this;
    }
};

// Inverse inertia in world space, R I^-1 R^T, refreshed after every integration.
struct inertia_world_inv : matrix3x3 {
    inertia_world_inv &operator=(const matrix3x3 &m) noexcept {
        matrix3x3::operator=(m);
        return *this;
    }
};

// Offset of the centre of mass from the body's origin, in object space. Only present on
// bodies whose centre of mass differs from the origin.
struct center_of_mass : vector3 {
    center_of_mass() = default;
    constexpr center_of_mass(const vector3 &v) noexcept
        : vector3(v) {}
    constexpr center_of_mass(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

// Mass and inertia a dynamic body had before rigidbody_set_kind made it static or kinematic,
// so that it gets them back when it becomes dynamic again.
struct rigidbody_dynamic_mass {
    scalar mass;
    matrix3x3 inertia;
};

} // namespace edyn

#endif // EDYN_DYNAMICS_MASS_HPP
