#ifndef EDYN_CONSTRAINTS_GENERIC_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_GENERIC_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include <cstdint>
#include <limits>
#include <span>

namespace edyn {

/// How a degree of freedom of a generic constraint moves.
enum class dof_mode : std::uint8_t {
    free,    ///< Unconstrained (springs, damping and friction still act).
    locked,  ///< Held at zero (the coordinate, not `rest`); the default.
    limited, ///< Kept within [min, max]; an infinite bound is no bound.
};

/// One degree of freedom. Linear ones are in metres (forces in N), angular ones in radians
/// (torques in Nm).
/// Set by the user in generic_constraint::linear and generic_constraint::angular.
struct generic_dof {
    dof_mode mode{dof_mode::locked}; ///< How the coordinate moves; default: locked.
    /// Lower bound of the coordinate (m or rad), used when `mode` is limited; default: minus
    /// infinity (none). Must not be NaN nor exceed `max` when limited.
    scalar min{-std::numeric_limits<scalar>::infinity()};
    /// Upper bound of the coordinate (m or rad), used when `mode` is limited; default: infinity
    /// (none).
    scalar max{std::numeric_limits<scalar>::infinity()};
    /// A spring of `stiffness` (N/m or Nm/rad) pulls the coordinate towards `rest`.
    /// Finite, not negative; default 0 (no spring). It acts in every mode.
    scalar stiffness{0};
    /// The coordinate the spring pulls towards (m or rad, finite); default 0.
    scalar rest{0};
    /// Force or torque per unit rate (N/(m/s) or Nm/(rad/s)).
    /// Finite, not negative; default 0. It acts in every mode.
    scalar damping{0};
    /// Force or torque opposing motion along the axis (N or Nm).
    /// Finite, not negative; default 0. It acts in every mode.
    scalar friction{0};
};

/// Six degrees of freedom between two bodies, each free, locked or limited. The coordinates are
/// measured in body[0]'s frame (frame[0], object space, at pivot[0]): linear[i] is the offset of
/// pivot[1] from pivot[0] along frame[0]'s column i; angular[i] is the rotation of frame[1]
/// from frame[0] about column i (the components of the rotation vector taking frame[0] to
/// frame[1], exact for rotations about a single axis). Every degree of freedom is locked by
/// default: a weld.
/// Created with make_constraint(); the user sets the pivots, frames and degrees of freedom, the
/// engine writes the impulses.
struct generic_constraint {
    entity body[2]{null, null}; ///< The two joined rigid bodies, set by make_constraint() for good.
    /// Pivot on each body, in its object space, relative to its origin (m); default: the origins.
    vector3 pivot[2]{vector3_zero, vector3_zero};
    /// Orthonormal frame of each body, in its object space; the coordinates are measured along
    /// and about frame[0]'s columns. Default: identity.
    matrix3x3 frame[2]{matrix3x3_identity, matrix3x3_identity};
    generic_dof linear[3]{};  ///< Translations along frame[0]'s three columns (m).
    generic_dof angular[3]{}; ///< Rotations about frame[0]'s three columns (radians).

    /// Last step's impulses per sub-step, for warm starting: rows 0-2 linear, 3-5 angular.
    /// Three locked linear (or angular) degrees of freedom are solved as one block, whose
    /// impulse (world space) is kept instead of the rows'.
    /// This member holds the linear block's impulse (N s). All impulses are written by the
    /// engine.
    vector3 linear_block_impulse{vector3_zero};
    /// The angular block's impulse (N m s, world space).
    vector3 angular_block_impulse{vector3_zero};
    /// Impulses of the locked rows not solved as a block (N s or N m s).
    scalar impulse[6]{0, 0, 0, 0, 0, 0};
    /// Impulses of the lower and upper limits of each limited row (N s or N m s).
    scalar limit_impulse[6][2]{};
    /// Impulses of each row's spring and damper (N s or N m s).
    scalar spring_impulse[6]{0, 0, 0, 0, 0, 0};
    /// Impulses of each row's friction (N s or N m s).
    scalar friction_impulse[6]{0, 0, 0, 0, 0, 0};
};

/// Name of generic_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<generic_constraint> = "generic_constraint";

/// Checks the fields a user sets; make_constraint() calls it before creating the constraint.
/// @param c The constraint to check.
/// @throws std::invalid_argument When a pivot is not finite; a frame is not orthonormal; or, for
/// any degree of freedom, `mode` is not one of the enumerators, a limited one has a NaN bound
/// or `min > max`, `stiffness`, `damping` or `friction` is negative or not finite, or `rest` is
/// not finite. The message names the field, e.g. "angular[2].min".
void validate_constraint(const generic_constraint &c);

/// Each degree of freedom's coordinate and the row whose velocity is its rate, at the bodies'
/// present poses (refresh_geometry()).
struct generic_rows {
    jacobian j[6];    ///< The rows, linear then angular.
    scalar q[6];      ///< The coordinates (m, then radians in frame A's axes).
    vector3 rotation; ///< World space rotation vector taking frame A to frame B.
};

/// A generic_constraint as the solver sees it during a step; rows 0-2 are linear, 3-5 angular.
struct generic_constraint_solver {
    using component = generic_constraint; ///< The component this solver is made from.
    joint_anchor anchor;                  ///< The pivots at the start of the step.
    /// @var frameA
    /// Body A's frame in world space, at the start of the step.
    /// @var frameB
    /// Body B's frame in world space, at the start of the step.
    matrix3x3 frameA, frameB;
    generic_dof dof[6]; ///< The degrees of freedom, linear then angular, from the component.
    /// @var linear_block
    /// All three linear degrees of freedom locked: solved as a block (as a ball joint).
    /// @var angular_block
    /// All three angular degrees of freedom locked: solved as a block.
    bool linear_block{false}, angular_block{false};
    /// @var linear_block_impulse
    /// The linear block's impulse of the sub-step (N s, world space).
    /// @var angular_block_impulse
    /// The angular block's impulse of the sub-step (N m s, world space).
    vector3 linear_block_impulse, angular_block_impulse;
    scalar impulse[6];          ///< Impulses of the locked rows outside a block.
    scalar limit_impulse[6][2]; ///< Impulses of the lower and upper limits of each row.
    scalar spring_impulse[6];   ///< Impulses of each row's spring and damper.
    scalar friction_impulse[6]; ///< Impulses of each row's friction.
    generic_rows rows{};        ///< The rows at the bodies' present poses (refresh_geometry()).
    /// Rate of each coordinate when the step began (m/s or rad/s): a limit approached faster
    /// than the restitution threshold both then and now is stopped as a collision (solve()).
    scalar start_rate[6]{0, 0, 0, 0, 0, 0};
};

/// Prepares a generic constraint for this step's solve: pivots and frames in world space,
/// which blocks apply, and last step's impulses (those of rows not in use dropped).
/// @param registry The registry holding the constraint's bodies.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
generic_constraint_solver make_constraint_solver(const registry &registry, const generic_constraint &c,
                                                 constraint_body_indices indices);
/// Measures the rows and coordinates at the bodies' present poses, after they have moved.
/// @param s The solver state, its anchor's pose already refreshed.
/// @param bodies The step's solver bodies.
void refresh_geometry(generic_constraint_solver &s, std::span<const solver_body> bodies) noexcept;
/// Re-applies the accumulated impulses to the bodies, at the start of each sub-step.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void warm_start(generic_constraint_solver &s, std::span<solver_body> bodies) noexcept;
/// One pass over the rows: angular ones first, then linear ones, which have the final word;
/// for each, friction, spring and damper, then the lock or the limits.
/// @param s The solver state; its impulses accumulate.
/// @param bodies The step's solver bodies.
/// @param ctx The pass (biased or relax).
void solve(generic_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Writes the impulses back into the component, for next step's warm start.
/// @param s The solver state after the step.
/// @param c The constraint component.
void store_impulses(const generic_constraint_solver &s, generic_constraint &c) noexcept;
/// The pivots position projection brings together after a sub-step's integration (see
/// joint_path_set): with all three linear degrees of freedom locked, they are held as a ball
/// joint's.
/// @param s The solver state.
/// @return Its anchor, or null when a linear axis is free or limited.
inline joint_anchor *projected_pivots(generic_constraint_solver &s) noexcept {
    return s.linear_block ? &s.anchor : nullptr;
}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_GENERIC_CONSTRAINT_HPP
