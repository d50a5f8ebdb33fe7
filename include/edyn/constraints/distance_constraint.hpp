#ifndef EDYN_CONSTRAINTS_DISTANCE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_DISTANCE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <cmath>
#include <span>

namespace edyn {

/// Keeps the pivots (object space, relative to each origin) `distance` apart, like a rigid rod
/// with ball joints at both ends.
/// Created with make_constraint(); the user sets the pivots and the distance, the engine writes
/// the impulse.
struct distance_constraint {
    entity body[2]{null, null}; ///< The two joined rigid bodies, set by make_constraint() for good.
    /// Pivot on each body, in its object space, relative to its origin (m); default: the origins.
    vector3 pivot[2]{vector3_zero, vector3_zero};
    /// Length kept between the pivots (m), finite and not negative; default 0.
    scalar distance{0};
    /// Last step's impulse per sub-step along the pivots' direction (N s), for warm starting.
    /// Written by the engine.
    scalar impulse{0};
};

/// Name of distance_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<distance_constraint> = "distance_constraint";

/// Checks the fields a user sets; make_constraint() calls it before creating the constraint.
/// @param c The constraint to check.
/// @throws std::invalid_argument When a pivot is not finite, or `distance` is negative or not
/// finite.
void validate_constraint(const distance_constraint &c);

/// A distance_constraint as the solver sees it during a step.
struct distance_constraint_solver {
    using component = distance_constraint; ///< The component this solver is made from.
    joint_anchor anchor;                   ///< The pivots at the start of the step.
    scalar distance{0};                    ///< Length kept between the pivots (m).
    scalar impulse{0};                     ///< Impulse of the sub-step along the pivots (N s).
};

/// Prepares a distance constraint for this step's solve: its pivots in world space and last
/// step's impulse.
/// @param registry The registry holding the constraint's bodies.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
distance_constraint_solver make_constraint_solver(const registry &registry, const distance_constraint &c,
                                                  constraint_body_indices indices);
/// Re-applies the accumulated impulse along the current pivot direction, at the start of each
/// sub-step.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void warm_start(distance_constraint_solver &s, std::span<solver_body> bodies) noexcept;
/// One pass over the joint's row: the pivots' distance is held at `distance`. With rigid pivots
/// (position projection on) the row carries no position bias, unless the joint was left out of
/// the projection (joint_anchor::unprojected). Does nothing while the pivots
/// coincide, as no direction exists.
/// @param s The solver state; its impulse accumulates.
/// @param bodies The step's solver bodies.
/// @param ctx The pass (biased or relax).
void solve(distance_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Writes the impulse back into the component, for next step's warm start.
/// @param s The solver state after the step.
/// @param c The constraint component.
void store_impulses(const distance_constraint_solver &s, distance_constraint &c) noexcept;
/// How far the joint's length is off at the start of the step (m), which decides whether the
/// position projection takes it (constraint_solver_settings::max_projected_gap).
/// @param s The solver state, as made this step.
inline scalar projection_gap(const distance_constraint_solver &s) noexcept {
    return std::abs(length(s.anchor.separation) - s.distance);
}
/// Position projection along the pivots' direction after a sub-step's integration (see
/// project_distance()); nothing for a joint left out of the projection this step
/// (joint_anchor::unprojected).
/// @param s The solver state.
/// @param bodies The step's solver bodies.
/// @param fraction Share of the length error removed, in [0, 1].
/// @param inv_h 1 / h of the sub-step (1/s).
inline void project_positions(distance_constraint_solver &s, std::span<solver_body> bodies, scalar fraction,
                              scalar inv_h) noexcept {
    if (s.anchor.unprojected) return;
    project_distance(s.anchor, s.distance, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]], fraction,
                     inv_h);
}

/// Direction and length of d; false when the pivots coincide and no direction exists.
/// @param d Pivot A minus pivot B (m).
/// @param direction Set to d / |d| when the function returns true; untouched otherwise.
/// @param length Always set to |d| (m).
/// @return Whether |d| exceeds 1e-9 m, so that a direction exists.
bool pivot_direction(const vector3 &d, vector3 &direction, scalar &length) noexcept;

/// The pivots of a distance-like joint now, and the unit direction and length between them.
struct pivot_axis {
    joint_pose pose;   ///< The current pivots.
    vector3 direction; ///< Unit direction from pivot B to pivot A, world space.
    scalar length;     ///< Distance between the pivots (m).
};

/// The pivots of a distance-like joint at the bodies' present poses (`anchor.pose`), with their
/// direction and distance. False when the pivots coincide and no direction exists.
/// @param anchor The joint's pivots, its pose refreshed since the bodies last moved.
/// @param axis Receives the pose and length; the direction only when the function returns true.
/// @return Whether a direction exists.
bool current_pivot_axis(const joint_anchor &anchor, pivot_axis &axis) noexcept;

/// Re-applies an impulse along the current direction between the pivots (distance and soft
/// distance joints).
/// Does nothing while the pivots coincide.
/// @param anchor The joint's pivots, its pose refreshed since the bodies last moved.
/// @param impulse The impulse along the direction from pivot B to pivot A (N s).
/// @param bodies The step's solver bodies.
void warm_start_pivot_axis(const joint_anchor &anchor, scalar impulse,
                           std::span<solver_body> bodies) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_DISTANCE_CONSTRAINT_HPP
