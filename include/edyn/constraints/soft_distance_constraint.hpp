#ifndef EDYN_CONSTRAINTS_SOFT_DISTANCE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_SOFT_DISTANCE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <span>

namespace edyn {

/// A spring between the pivots (object space, relative to each origin) with rest length
/// `distance`, stiffness in N/m and damping in N/(m/s).
/// Created with make_constraint(); the user sets the pivots, the rest length, the stiffness and
/// the damping, the engine writes the impulse. The spring acts along the line between the
/// pivots, and both pushes and pulls.
struct soft_distance_constraint {
    entity body[2]{null, null}; ///< The two joined rigid bodies, set by make_constraint() for good.
    /// Pivot on each body, in its object space, relative to its origin (m); default: the origins.
    vector3 pivot[2]{vector3_zero, vector3_zero};
    scalar distance{0};    ///< Rest length of the spring (m), finite and not negative; default 0.
    scalar stiffness{1e6}; ///< Spring stiffness (N/m), finite and not negative; default 1e6.
    scalar damping{1e3};   ///< Damping (N/(m/s)), finite and not negative; default 1e3.
    /// Last step's spring impulse per sub-step (N s), for warm starting. Written by the engine.
    scalar impulse{0};
};

/// Name of soft_distance_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<soft_distance_constraint> = "soft_distance_constraint";

/// Checks the fields a user sets; make_constraint() calls it before creating the constraint.
/// @param c The constraint to check.
/// @throws std::invalid_argument When a pivot is not finite, or `distance`, `stiffness` or
/// `damping` is negative or not finite.
void validate_constraint(const soft_distance_constraint &c);

/// A soft_distance_constraint as the solver sees it during a step.
struct soft_distance_constraint_solver {
    using component = soft_distance_constraint; ///< The component this solver is made from.
    joint_anchor anchor;                        ///< The pivots at the start of the step.
    scalar distance{0};                         ///< Rest length (m).
    scalar stiffness{0};                        ///< Spring stiffness (N/m).
    scalar damping{0};                          ///< Damping (N/(m/s)).
    scalar impulse{0};                          ///< Spring impulse of the sub-step (N s).
};

/// Prepares a soft distance constraint for this step's solve: its pivots in world space, its
/// spring and last step's impulse.
/// @param registry The registry holding the constraint's bodies.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
soft_distance_constraint_solver make_constraint_solver(const registry &registry,
                                                       const soft_distance_constraint &c,
                                                       constraint_body_indices indices);
/// Re-applies the accumulated impulse along the current pivot direction, at the start of each
/// sub-step.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void warm_start(soft_distance_constraint_solver &s, std::span<solver_body> bodies) noexcept;
/// Applies the spring and damper along the pivots' direction (see solve_spring_row()): only in
/// the biased pass, and not while the pivots coincide.
/// @param s The solver state; its impulse accumulates.
/// @param bodies The step's solver bodies.
/// @param ctx The pass (biased or relax).
void solve(soft_distance_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Writes the impulse back into the component, for next step's warm start.
/// @param s The solver state after the step.
/// @param c The constraint component.
void store_impulses(const soft_distance_constraint_solver &s, soft_distance_constraint &c) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_SOFT_DISTANCE_CONSTRAINT_HPP
