#ifndef EDYN_CONSTRAINTS_HINGE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_HINGE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include "edyn/math/math.hpp"
#include <limits>
#include <span>

namespace edyn {

/// Keeps the pivots together and lets the bodies turn only about the hinge axis: the first
/// column of each body's frame (object space). The other columns measure the hinge angle: the
/// angle of body[1]'s second column from body[0]'s, about the axis, positive counterclockwise.
/// Doors, wheel bearings, elbows and knees. Created with make_constraint(); the user sets the
/// pivots, frames (or calls set_axes()), limits, friction, damping and springs, the engine
/// writes `angle` and the impulses.
struct hinge_constraint {
    entity body[2]{null, null}; ///< The two joined rigid bodies, set by make_constraint() for good.
    /// Pivot on each body, in its object space, relative to its origin (m): a point of the hinge
    /// axis. Default: the origins.
    vector3 pivot[2]{vector3_zero, vector3_zero};
    /// Orthonormal frame of each body, in its object space: the first column is the hinge axis,
    /// the second measures the hinge angle (the third completes the basis). Default: identity,
    /// so the hinge axis is each body's x axis.
    matrix3x3 frame[2]{matrix3x3_identity, matrix3x3_identity};
    /// Lower limit of the hinge angle (radians); infinite for a free hinge. angle_min < angle_max.
    /// Default: minus infinity (no lower limit).
    scalar angle_min{-std::numeric_limits<scalar>::infinity()};
    /// Upper limit of the hinge angle (radians), above `angle_min`; default: infinity (no
    /// upper limit).
    scalar angle_max{std::numeric_limits<scalar>::infinity()};
    /// Restitution of a limit in [0, 1]: the share of the approach speed a limit hit faster than
    /// the solver's restitution threshold bounces back with. Default 0: such a hit stops dead.
    scalar limit_restitution{0};
    /// Torque opposing rotation about the axis, Nm; finite, not negative, default 0.
    scalar friction_torque{0};
    /// Torque per angular velocity about the axis, Nm/(rad/s); finite, not negative, default 0.
    scalar damping{0};
    /// Within bump_stop_angle of a limit, a spring of bump_stop_stiffness (Nm/rad) pushes back.
    /// The width of that zone in radians; finite, not negative, default 0 (no bump stops).
    scalar bump_stop_angle{0};
    /// Stiffness of the bump stops, Nm/rad; finite, not negative, default 0 (no bump stops).
    scalar bump_stop_stiffness{0};
    /// A spring of `stiffness` (Nm/rad) pulls the hinge towards rest_angle.
    /// The angle the spring pulls towards (radians, finite); default 0.
    scalar rest_angle{0};
    /// Stiffness of the spring towards `rest_angle`, Nm/rad; finite, not negative, default 0
    /// (no spring).
    scalar stiffness{0};
    /// The hinge angle at the end of the last step, unwrapped so that limits beyond half a turn
    /// work.
    /// Written by the engine. The frames' angle is unwrapped towards it, so setting it chooses
    /// which turn a hinge starts in.
    scalar angle{0};

    /// Last step's impulses per sub-step, for warm starting: the linear impulse holding the
    /// pivots together (N s, world space). All impulses are written by the engine.
    vector3 impulse{vector3_zero};
    /// Impulses of the two angular rows keeping the axes parallel (N m s).
    scalar align_impulse[2]{0, 0};
    /// Impulses of the lower and upper limits (N m s).
    scalar limit_impulse[2]{0, 0};
    /// Impulses of the lower and upper bump stops (N m s).
    scalar bump_stop_impulse[2]{0, 0};
    /// Impulse of the friction torque (N m s).
    scalar friction_impulse{0};
    /// Impulse of the spring and damper (N m s).
    scalar spring_impulse{0};

    /// Sets both frames from the hinge axis in each body's object space, completing each into an
    /// orthonormal basis. The angle is then measured between those completions.
    /// The completions come from plane_space(), so limits and `rest_angle` are measured from a
    /// direction that depends on the axis; set `frame` instead to choose it.
    /// @param axisA The hinge axis in body[0]'s object space; need not be unit length.
    /// @param axisB The hinge axis in body[1]'s object space; need not be unit length.
    /// @throws std::invalid_argument When an axis is not finite or is zero; the frames are left
    /// as they were.
    void set_axes(const vector3 &axisA, const vector3 &axisB);
};

/// Name of hinge_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<hinge_constraint> = "hinge_constraint";

/// Checks the fields a user sets; make_constraint() calls it before creating the constraint.
/// Infinite limits mean no limit; angle_min must be smaller than angle_max.
/// @param c The constraint to check.
/// @throws std::invalid_argument When a pivot is not finite; a frame is not orthonormal; a limit
/// is NaN or `angle_min >= angle_max`; `limit_restitution` is outside [0, 1]; `friction_torque`,
/// `damping`, `bump_stop_angle`, `bump_stop_stiffness` or `stiffness` is negative or not
/// finite; or `rest_angle` is not finite.
void validate_constraint(const hinge_constraint &c);

/// Angle of frame B's second column from frame A's about A's first column.
/// @param frameA Frame of body A, world space (first column: the hinge axis).
/// @param frameB Frame of body B, world space.
/// @return The angle in radians, in [-pi, pi], positive counterclockwise about A's axis.
scalar relative_angle(const matrix3x3 &frameA, const matrix3x3 &frameB) noexcept;

/// Rotation about the axis is measured against the value it had at the start of the step so
/// that an angle past half a turn stays continuous.
/// @param previous The unwrapped angle it continues (radians).
/// @param raw The angle measured now, in [-pi, pi].
/// @return The angle equal to `raw` modulo a full turn that is closest to `previous`.
inline scalar unwrap_angle(scalar previous, scalar raw) noexcept {
    // Within half a turn of the previous angle, the common case, the raw angle itself.
    auto change = raw - previous;
    if (change >= -pi && change < pi) return raw;
    return previous + normalize_angle(change);
}

/// Limits, bump stops and limit restitution of an angle whose rate is dot(axis, wB - wA)
/// (shared by the hinge angle and the CV joint's twist).
/// Part of a joint's solver state; index 0 is the lower limit, 1 the upper.
struct angular_limit {
    /// @var min
    /// Lower limit (radians); minus infinity for none.
    /// @var max
    /// Upper limit (radians); infinity for none.
    scalar min{0}, max{0};
    /// @var bump_angle
    /// Width of the bump stop zone inside each limit (radians); 0 for none.
    /// @var bump_stiffness
    /// Stiffness of the bump stops (N m/rad); 0 for none.
    scalar bump_angle{0}, bump_stiffness{0};
    scalar restitution{0}; ///< Restitution of the limits, in [0, 1].
    /// Rate of the angle when the step began: a limit approached faster than the threshold
    /// bounces, with the speed it had before the solver started braking it (rad/s).
    scalar start_rate{0};
    /// Whether each limit already bounced this step: a step answers one approach.
    bool bounced[2]{false, false};
    scalar impulse[2]{0, 0};      ///< Impulses of the two limits over the sub-step (N m s), not negative.
    scalar bump_impulse[2]{0, 0}; ///< Impulses of the two bump stops over the sub-step (N m s).
};

/// The accumulated impulses of the limits and bump stops as one angular impulse about +axis
/// (N m s), which each sub-step's warm start re-applies with the joint's other angular impulses:
/// the lower limit and its bump stop push along -axis (raising the angle), the upper ones along
/// +axis.
/// @param limit The limits and their impulses.
/// @return The upper impulses minus the lower ones.
inline scalar warm_start_impulse(const angular_limit &limit) noexcept {
    return (limit.impulse[1] + limit.bump_impulse[1]) - (limit.impulse[0] + limit.bump_impulse[0]);
}
/// One pass over the rows of the finite limits and, where both bump stop values are positive,
/// their bump stops (a spring that only pushes, within `bump_angle` of a limit).
/// @param limit The limits; their impulses accumulate.
/// @param row The row about the axis about which the angle turns, world space (the lower limit's
/// row is the same about -axis).
/// @param angle The angle now (radians, unwrapped).
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param ctx The pass (biased or relax).
void solve_angular_limit(angular_limit &limit, const angular_row &row, scalar angle, solver_body &a,
                         solver_body &b, const constraint_solve_context &ctx) noexcept;
/// The limits a sub-step hits, and the rate of the angle each must leave its limit with.
struct limit_hits {
    bool hit[2]{false, false}; ///< Whether the lower and the upper limit are hit.
    /// Rate each hit limit must open with (rad/s, positive away from the limit): the bounce of
    /// a limit with restitution; for one without, minus its gap over the sub-step (the motion
    /// closes the gap, no more) and 0 once the angle is at or past the limit.
    scalar rate[2]{0, 0};
    /// Whether either limit is hit.
    /// @return hit[0] or hit[1].
    bool any() const noexcept { return hit[0] || hit[1]; }
};

/// The limits hit in the coming sub-step by an approach faster than the threshold. A hit is
/// solved as an isolated collision of the limit and the rows that hold the joint together,
/// whose rate the limit row alone cannot stop: an angular impulse that turns a body about its
/// centre of mass moves the pivot, which the pivot rows then move back, and the approach that
/// few passes leave is what the limit's position correction turns into a rebound.
/// A limit with restitution bounces once per step, with the faster of the rates now and at the
/// start of the step (marked in `bounced`); one without is stopped at the limit, in each
/// sub-step whose approach would carry the angle past it, when both the rates now and at the
/// start of the step are faster than the threshold (a joint resting on its limit, which each
/// sub-step's gravity presses into it anew, is left to the limit row). Infinite limits are
/// never hit.
/// @param limit The limits; `bounced` is updated.
/// @param axis The axis about which the angle turns, world space.
/// @param angle The angle now (radians, unwrapped).
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param ctx The pass: its sub-step and restitution threshold are read.
/// @return The limits hit and the rates they must leave with.
limit_hits detect_limit_hits(angular_limit &limit, const vector3 &axis, scalar angle, const solver_body &a,
                             const solver_body &b, const constraint_solve_context &ctx) noexcept;
/// Drives the rate of each hit limit to the rate it must leave with (impulses that only push),
/// as one row of an isolated collision solve.
/// @param row The row about the axis about which the angle turns, world space.
/// @param hits The limits hit and their rates; the others are skipped.
/// @param impulse The impulses of the two limits (N m s), accumulated and not negative.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
void solve_limit_hits(const angular_row &row, const limit_hits &hits, scalar (&impulse)[2], solver_body &a,
                      solver_body &b) noexcept;

/// A hinge_constraint as the solver sees it during a step.
struct hinge_constraint_solver {
    using component = hinge_constraint; ///< The component this solver is made from.
    joint_anchor anchor;                ///< The pivots at the start of the step.
    /// @var frameA
    /// Body A's frame in world space, at the start of the step.
    /// @var frameB
    /// Body B's frame in world space, at the start of the step.
    matrix3x3 frameA, frameB;
    scalar angle{0}; ///< Hinge angle (radians, unwrapped), updated after each relax pass.
    /// @var axis_row
    /// The row about A's hinge axis at the bodies' present poses (refresh_geometry()): friction,
    /// spring and limits act on its rate.
    /// @var align_rows
    /// The two rows keeping B's axis parallel to A's there, about uA_i x axisB for A's other two
    /// frame axes uA_i.
    /// @var align_errors
    /// Their errors there, dot(uA_i, axisB).
    /// @var present_angle
    /// The hinge angle there (radians, unwrapped from `angle`).
    angular_row axis_row{vector3_zero, 0};
    angular_row align_rows[2]{{vector3_zero, 0}, {vector3_zero, 0}};
    scalar align_errors[2]{0, 0};
    scalar present_angle{0};
    /// @var friction_torque
    /// Friction torque about the axis (N m).
    /// @var damping
    /// Damping about the axis (N m/(rad/s)).
    /// @var rest_angle
    /// Angle the spring pulls towards (radians).
    /// @var stiffness
    /// Spring stiffness (N m/rad).
    scalar friction_torque, damping, rest_angle, stiffness;
    angular_limit limit;     ///< The angle's limits, bump stops and restitution.
    vector3 impulse;         ///< Linear impulse holding the pivots together (N s).
    scalar align_impulse[2]; ///< Impulses keeping the axes parallel (N m s).
    scalar friction_impulse; ///< Friction impulse (N m s).
    scalar spring_impulse;   ///< Spring and damper impulse (N m s).
};

/// Prepares a hinge for this step's solve: pivots and frames in world space, the unwrapped
/// angle, the angle's rate for restitution and last step's impulses.
/// @param registry The registry holding the constraint's bodies; their `angvel` is read.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
hinge_constraint_solver make_constraint_solver(const registry &registry, const hinge_constraint &c,
                                               constraint_body_indices indices);
/// Measures the hinge's frame, axis and angle at the bodies' present poses, after they have moved.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void refresh_geometry(hinge_constraint_solver &s, std::span<const solver_body> bodies) noexcept;
/// Re-applies the accumulated impulses to the bodies, at the start of each sub-step.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void warm_start(hinge_constraint_solver &s, std::span<solver_body> bodies) noexcept;
/// One pass over the hinge's rows: friction, spring and damper, limit bounces, limits and bump
/// stops, axis alignment, then the pivots, which have the final word.
/// @param s The solver state; its impulses accumulate.
/// @param bodies The step's solver bodies.
/// @param ctx The pass (biased or relax).
void solve(hinge_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Writes the angle and the impulses back into the component, for the next step.
/// @param s The solver state after the step.
/// @param c The constraint component.
void store_impulses(const hinge_constraint_solver &s, hinge_constraint &c) noexcept;
/// The pivots position projection brings together after a sub-step's integration (see
/// joint_path_set).
/// @param s The solver state.
/// @return Its anchor.
inline joint_anchor *projected_pivots(hinge_constraint_solver &s) noexcept { return &s.anchor; }

/// Shared with the other joints that align an axis: two angular rows keeping axisB parallel to
/// axisA, measured against A's two other axes uA_i (frame columns 1 and 2): the error of each is
/// C_i = dot(uA_i, axisB), its rate dot(uA_i x axisB, wA - wB).
/// @param rows The rows about uA_i x axisB, world space, from make_angular_row().
/// @param errors The errors C_i now.
/// @param impulse Impulses of the two rows over the sub-step (N m s), updated.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param ctx The pass (biased or relax).
void solve_axis_alignment(const angular_row (&rows)[2], const scalar (&errors)[2], scalar (&impulse)[2],
                          solver_body &a, solver_body &b, const constraint_solve_context &ctx) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_HINGE_CONSTRAINT_HPP
