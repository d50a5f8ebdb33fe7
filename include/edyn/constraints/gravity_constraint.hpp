#ifndef EDYN_CONSTRAINTS_GRAVITY_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_GRAVITY_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <span>

namespace edyn {

/// Newton's universal gravitational constant, m^3 / (kg s^2).
inline constexpr scalar gravitational_constant = scalar(6.674e-11);

/// Newtonian attraction G mA mB / r^2 between the centres of mass of the two bodies.
/// Created with make_constraint(); it has nothing to set but its bodies. The masses are read
/// from the bodies' `mass` components at the start of every step. Static and kinematic bodies
/// carry `large_scalar` as their mass, so make_constraint() refuses them: both bodies must be
/// dynamic. While a body made static or kinematic later (rigidbody_set_kind) is not dynamic,
/// the attraction is off.
struct gravity_constraint {
    entity body[2]{null, null}; ///< The two attracting rigid bodies, set by make_constraint() for good.
};

/// Name of gravity_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<gravity_constraint> = "gravity_constraint";

/// Checks a gravity_constraint's fields: it has none a user sets, so it never throws.
inline void validate_constraint(const gravity_constraint &) noexcept {}

/// A gravity_constraint as the solver sees it during a step.
struct gravity_constraint_solver {
    using component = gravity_constraint; ///< The component this solver is made from.
    solver_body_index body[2]{0, 0};      ///< Indices of the two bodies in the step's solver bodies.
    /// Centre of mass B minus centre of mass A when the step began (m, world space).
    vector3 separation{vector3_zero};
    /// G mA mB (N m^2); 0, which turns the attraction off, when either body is not dynamic or
    /// either mass is missing or not finite.
    scalar strength{0};
};

/// Prepares a gravity constraint for this step's solve: the separation of the centres of mass
/// and the strength G mA mB from the bodies' masses.
/// @param registry The registry holding the constraint's bodies.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
gravity_constraint_solver make_constraint_solver(const registry &registry, const gravity_constraint &c,
                                                 constraint_body_indices indices);
/// Does nothing: the attraction is a force, recomputed in every sub-step, with no impulse to
/// carry over.
inline void warm_start(gravity_constraint_solver &, std::span<solver_body>) noexcept {}
/// Applies the attraction's impulse over the sub-step (biased pass only: it is a force, and
/// must act once per sub-step).
/// The distance is measured from the bodies' motion since the step began; nothing is applied
/// while the centres of mass (nearly) coincide.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
/// @param ctx The pass; only its sub-step `h` and `use_bias` are read.
void solve(gravity_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Does nothing: a gravity constraint stores no impulses.
inline void store_impulses(const gravity_constraint_solver &, gravity_constraint &) noexcept {}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_GRAVITY_CONSTRAINT_HPP
