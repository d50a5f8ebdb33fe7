#ifndef EDYN_CONSTRAINTS_POINT_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_POINT_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <span>

namespace edyn {

/// Ball joint: pivot[0] on body[0] and pivot[1] on body[1] (object space, relative to each
/// origin) are kept at the same point in space.
/// Created with make_constraint(); the user sets the pivots and the friction torque, the engine
/// writes the impulses.
struct point_constraint {
    entity body[2]{null, null}; ///< The two joined rigid bodies, set by make_constraint() for good.
    /// Pivot on each body, in its object space, relative to its origin (m); default: the origins.
    vector3 pivot[2]{vector3_zero, vector3_zero};
    /// Torque opposing the relative angular velocity of the bodies, Nm; 0 (the default) for none.
    /// Keeps a pendulum from swinging forever. Must be finite and not negative.
    scalar friction_torque{0};
    /// Last step's impulses per sub-step, for warm starting: the linear impulse holding the
    /// pivots together (N s, world space). Written by the engine.
    vector3 impulse{vector3_zero};
    /// Last step's angular friction impulse per sub-step (N m s, world space). Written by the
    /// engine.
    vector3 friction_impulse{vector3_zero};
};

/// Name of point_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<point_constraint> = "point_constraint";

/// Checks the fields a user sets; make_constraint() calls it before creating the constraint.
/// @param c The constraint to check.
/// @throws std::invalid_argument When a pivot is not finite, or `friction_torque` is negative or
/// not finite.
void validate_constraint(const point_constraint &c);

/// A point_constraint as the solver sees it during a step: its pivots measured from the bodies'
/// centres of mass, world space, and its impulses.
struct point_constraint_solver {
    using component = point_constraint; ///< The component this solver is made from.
    joint_anchor anchor;                ///< The pivots at the start of the step.
    scalar friction_torque{0};          ///< Friction torque (N m), from the component.
    vector3 impulse{vector3_zero};      ///< Linear impulse of the sub-step (N s), accumulated.
    /// Angular friction impulse of the sub-step (N m s), accumulated; bounded in magnitude by
    /// `friction_torque` times the sub-step.
    vector3 friction_impulse{vector3_zero};
};

/// Prepares a point constraint for this step's solve: its pivots in world space and last step's
/// impulses (the friction impulse only while friction is on).
/// @param registry The registry holding the constraint's bodies.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
point_constraint_solver make_constraint_solver(const registry &registry, const point_constraint &c,
                                               constraint_body_indices indices);
/// Re-applies the accumulated impulses to the bodies, at the start of each sub-step.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void warm_start(point_constraint_solver &s, std::span<solver_body> bodies) noexcept;
/// One pass over the joint's rows: angular friction first, then the pivots as a 3x3 block.
/// @param s The solver state; its impulses accumulate.
/// @param bodies The step's solver bodies.
/// @param ctx The pass (biased or relax).
void solve(point_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Writes the impulses back into the component, for next step's warm start.
/// @param s The solver state after the step.
/// @param c The constraint component.
void store_impulses(const point_constraint_solver &s, point_constraint &c) noexcept;
/// The pivots position projection brings together after a sub-step's integration (see
/// joint_path_set).
/// @param s The solver state.
/// @return Its anchor.
inline joint_anchor *projected_pivots(point_constraint_solver &s) noexcept { return &s.anchor; }

/// Solves the 3x3 block keeping the pivots together (shared by the joints that contain a ball
/// joint): impulse accumulates the linear impulse of the sub-step.
/// Carries no position bias when `ctx.rigid_pivots` is set (position projection corrects the
/// drift instead); does nothing when the block cannot be inverted.
/// @param anchor The joint's pivots, its pose refreshed since the bodies last moved.
/// @param impulse The block's linear impulse of the sub-step (N s, world space), updated.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param ctx The pass (biased or relax).
void solve_point_block(const joint_anchor &anchor, vector3 &impulse, solver_body &a, solver_body &b,
                       const constraint_solve_context &ctx) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_POINT_CONSTRAINT_HPP
