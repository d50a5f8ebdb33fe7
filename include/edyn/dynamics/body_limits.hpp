#ifndef EDYN_DYNAMICS_BODY_LIMITS_HPP
#define EDYN_DYNAMICS_BODY_LIMITS_HPP

// The ranges make_rigidbody and set_gravity accept for a body's mass, inertia and gravity.
// Beyond them the solver's products and inverses leave the range of a float within a few
// steps (an infinite inverse mass, a NaN orientation), so values outside are refused up front,
// from the program and from the network alike.

#include "edyn/math/scalar.hpp"

namespace edyn {

// kg: from a milligram to a small moon (gravity constraints between planetoids need such masses).
inline constexpr scalar min_body_mass = scalar(1e-6);
inline constexpr scalar max_body_mass = scalar(1e20);
// kg·m², for an inertia given explicitly: its smallest and largest principal moments (a 1 cm,
// 1 g bead has 1e-8; a 1e20 kg body 100 km across about 1e29).
inline constexpr scalar min_body_inertia = scalar(1e-12);
inline constexpr scalar max_body_inertia = scalar(1e30);
// m/s², the magnitude of the world's gravity or a body's: a thousand g.
inline constexpr scalar max_gravity = scalar(1e4);

} // namespace edyn

#endif // EDYN_DYNAMICS_BODY_LIMITS_HPP
