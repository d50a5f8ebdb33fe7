#ifndef EDYN_DYNAMICS_MASS_HPP
#define EDYN_DYNAMICS_MASS_HPP

#include "edyn/math/matrix3x3.hpp"

namespace edyn {

/// Component: a rigid body's mass.
/// Mass in kg; infinite (`large_scalar`) for static and kinematic bodies, whose mass_inv is 0.
/// Written by make_rigidbody, rigidbody_set_mass and rigidbody_set_kind; change it through
/// rigidbody_set_mass, which keeps mass_inv and the inertia in step.
struct mass {
    scalar s; ///< The mass, in kg.
    /// Reads the component as a plain scalar (kg).
    constexpr operator scalar() const noexcept { return s; }
};

/// Component: the inverse of a rigid body's mass, in 1/kg.
/// Zero for static and kinematic bodies, which impulses do not move. Kept in step with mass by
/// the functions that write it.
struct mass_inv {
    scalar s; ///< The inverse mass, in 1/kg.
    /// Reads the component as a plain scalar (1/kg).
    constexpr operator scalar() const noexcept { return s; }
};

/// Component: inertia tensor about the centre of mass, in object space, in kg·m².
/// Computed from the shape and mass, or given in rigidbody_def::inertia. Static and kinematic
/// bodies have a diagonal of the largest scalar.
struct inertia : matrix3x3 {
    /// Assigns a tensor given as a plain matrix (kg·m²).
    /// @param m The new tensor.
    /// @return This component.
    inertia &operator=(const matrix3x3 &m) noexcept {
        matrix3x3::operator=(m);
        return *this;
    }
};

/// Component: inverse of the object-space inertia tensor, in 1/(kg·m²).
/// Zero for static and kinematic bodies.
struct inertia_inv : matrix3x3 {
    /// Assigns an inverse tensor given as a plain matrix (1/(kg·m²)).
    /// @param m The new inverse tensor.
    /// @return This component.
    inertia_inv &operator=(const matrix3x3 &m) noexcept {
        matrix3x3::operator=(m);
        return *this;
    }
};

/// Component: inverse inertia in world space, `R I^-1 R^T`, in 1/(kg·m²).
/// Written by the engine: refreshed after every integration and by update_inertia_world.
/// Zero for static and kinematic bodies.
struct inertia_world_inv : matrix3x3 {
    /// Assigns an inverse tensor given as a plain matrix (1/(kg·m²)).
    /// @param m The new world-space inverse tensor.
    /// @return This component.
    inertia_world_inv &operator=(const matrix3x3 &m) noexcept {
        matrix3x3::operator=(m);
        return *this;
    }
};

/// Component: offset of the centre of mass from the body's origin, in object space, in metres.
/// Only present on bodies whose centre of mass differs from the origin. Set by make_rigidbody
/// (rigidbody_def::center_of_mass, or the shape's centroid) and by set_center_of_mass, which is
/// the way to change it.
struct center_of_mass : vector3 {
    center_of_mass() = default;
    /// Makes the offset from a vector.
    /// @param v Offset from the origin, in object space, in metres.
    constexpr center_of_mass(const vector3 &v) noexcept
        : vector3(v) {}
    /// Makes the offset from its coordinates, in object space, in metres.
    /// @param x Offset along the body's x axis.
    /// @param y Offset along the body's y axis.
    /// @param z Offset along the body's z axis.
    constexpr center_of_mass(scalar x, scalar y, scalar z) noexcept
        : vector3{x, y, z} {}
};

/// Component: the mass and inertia of a dynamic body turned static or kinematic.
/// Written by rigidbody_set_kind when it makes a dynamic body static or kinematic, so that the
/// body gets them back when it becomes dynamic again. rigidbody_set_shape and
/// set_center_of_mass recompute the inertia for the new shape or centre, keeping the mass.
struct rigidbody_dynamic_mass {
    scalar mass;       ///< The mass it had, in kg.
    matrix3x3 inertia; ///< The inertia tensor it had, about its centre of mass in object space, in kg·m².
};

} // namespace edyn

#endif // EDYN_DYNAMICS_MASS_HPP
