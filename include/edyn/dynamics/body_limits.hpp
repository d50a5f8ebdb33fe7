#ifndef EDYN_DYNAMICS_BODY_LIMITS_HPP
#define EDYN_DYNAMICS_BODY_LIMITS_HPP

/// @file
/// The ranges make_rigidbody and set_gravity accept for a body's mass, inertia and gravity.
/// Beyond them the solver's products and inverses leave the range of a float within a few
/// steps (an infinite inverse mass, a NaN orientation), so values outside are refused up front,
/// from the program and from the network alike.

#include "edyn/math/scalar.hpp"

namespace edyn {

/// Smallest mass of a dynamic body, in kg (a milligram).
/// Masses range from a milligram to a small moon, since gravity constraints between planetoids
/// need such masses. `make_rigidbody` and `rigidbody_set_mass` throw `std::invalid_argument`
/// for a dynamic body's mass below it.
inline constexpr scalar min_body_mass = scalar(1e-6);
/// Largest mass of a dynamic body, in kg (a small moon); larger masses are refused.
inline constexpr scalar max_body_mass = scalar(1e20);
/// Smallest principal moment of an inertia tensor given explicitly, in kg·m².
/// For scale: a 1 cm, 1 g bead has about 1e-8 kg·m². Inertia computed from a shape is not
/// checked against it.
inline constexpr scalar min_body_inertia = scalar(1e-12);
/// Largest principal moment of an inertia tensor given explicitly, in kg·m².
/// For scale: a 1e20 kg body 100 km across has about 1e29 kg·m².
inline constexpr scalar max_body_inertia = scalar(1e30);
/// Largest magnitude of the world's gravity or of a body's own, in m/s² (a thousand g).
inline constexpr scalar max_gravity = scalar(1e4);

} // namespace edyn

#endif // EDYN_DYNAMICS_BODY_LIMITS_HPP
