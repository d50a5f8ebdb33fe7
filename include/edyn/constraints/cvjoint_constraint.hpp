#ifndef EDYN_CONSTRAINTS_CVJOINT_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_CVJOINT_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/hinge_constraint.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include <span>

namespace edyn {

/// Constant-velocity joint: the pivots are kept together and the bodies may bend freely, but
/// their twist is transmitted whatever the bend, like a car's drive shaft joint. Each body's
/// axis is the first column of its frame (object space); the twist is the angle of body[1]'s
/// second column from body[0]'s once body[0]'s frame is swung onto body[1]'s axis along the
/// shortest arc. Spinning one body about its axis spins the other about its own at the same
/// rate.
/// Shoulders, hips and spines of rag dolls, usually with a cone_constraint limiting the bend.
/// Created with make_constraint(); the user sets the pivots, frames (or calls set_axes()),
/// twist limits, friction, damping and springs, the engine writes `twist_angle` and the
/// impulses.
struct cvjoint_constraint {
    entity body[2]{null, null}; ///< The two joined rigid bodies, set by make_constraint() for good.
    /// Pivot on each body, in its object space, relative to its origin (m); default: the origins.
    vector3 pivot[2]{vector3_zero, vector3_zero};
    /// Orthonormal frame of each body, in its object space: the first column is the body's
    /// twist axis, the second measures the twist. Default: identity (the x axes).
    matrix3x3 frame[2]{matrix3x3_identity, matrix3x3_identity};
    /// Twist limits (radians), twist_min <= twist_max. Equal limits lock the twist (the
    /// default) and must then be finite; an infinite limit is not enforced, so that
    /// (-inf, +inf) leaves the twist free.
    /// The lower limit; default 0.
    scalar twist_min{0};
    /// The upper limit, not below `twist_min`; default 0.
    scalar twist_max{0};
    /// Restitution of a twist limit in [0, 1]; default 0. Unused while the twist is locked.
    scalar twist_restitution{0};
    /// Torque opposing twisting, Nm; finite, not negative, default 0. Unused while the twist is
    /// locked.
    scalar twist_friction_torque{0};
    /// Torque per twist rate, Nm/(rad/s); finite, not negative, default 0. Unused while the
    /// twist is locked.
    scalar twist_damping{0};
    /// Torque opposing bending (relative rotation about any axis across the twist axis), Nm: what
    /// lets a swinging joint, such as a rag doll's shoulder, come to rest.
    /// Finite, not negative, default 0.
    scalar bend_friction_torque{0};
    /// A spring of twist_stiffness (Nm/rad) pulls the twist towards twist_rest_angle.
    /// The twist the spring pulls towards (radians, finite); default 0.
    scalar twist_rest_angle{0};
    /// Stiffness of the twist spring, Nm/rad; finite, not negative, default 0 (no spring).
    /// Unused while the twist is locked.
    scalar twist_stiffness{0};
    /// Within twist_bump_stop_angle of a limit, a spring of twist_bump_stop_stiffness (Nm/rad)
    /// pushes back.
    /// The width of that zone in radians; finite, not negative, default 0 (no bump stops).
    scalar twist_bump_stop_angle{0};
    /// Stiffness of the twist bump stops, Nm/rad; finite, not negative, default 0.
    scalar twist_bump_stop_stiffness{0};
    /// The twist at the end of the last step, unwrapped past half a turn.
    /// Written by the engine.
    scalar twist_angle{0};

    /// Last step's impulses per sub-step, for warm starting: the linear impulse holding the
    /// pivots together (N s, world space). All impulses are written by the engine.
    vector3 impulse{vector3_zero};
    scalar twist_impulse{0};           ///< Impulse of the locked twist (N m s).
    scalar limit_impulse[2]{0, 0};     ///< Impulses of the lower and upper twist limits (N m s).
    scalar bump_stop_impulse[2]{0, 0}; ///< Impulses of the lower and upper bump stops (N m s).
    scalar friction_impulse{0};        ///< Impulse of the twist friction (N m s).
    scalar spring_impulse{0};          ///< Impulse of the twist spring and damper (N m s).
    /// Impulse of the bend friction (N m s, world space, across the twist axis).
    vector3 bend_friction_impulse{vector3_zero};

    /// Sets both frames from each body's axis (object space), completing each into an
    /// orthonormal basis.
    /// The completions come from plane_space(), so twist limits and `twist_rest_angle` are
    /// measured from a direction that depends on the axis; set `frame` instead to choose it.
    /// @param axisA The twist axis in body[0]'s object space; need not be unit length.
    /// @param axisB The twist axis in body[1]'s object space; need not be unit length.
    /// @throws std::invalid_argument When an axis is not finite or is zero; the frames are left
    /// as they were.
    void set_axes(const vector3 &axisA, const vector3 &axisB);
};

/// Name of cvjoint_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<cvjoint_constraint> = "cvjoint_constraint";

/// Checks the fields a user sets; make_constraint() calls it before creating the constraint.
/// @param c The constraint to check.
/// @throws std::invalid_argument When a pivot is not finite; a frame is not orthonormal; a twist
/// limit is NaN or `twist_min > twist_max`; both twist limits are the same infinity (+inf or
/// -inf, which would lock the twist at no angle); `twist_restitution` is outside [0, 1];
/// `twist_friction_torque`, `twist_damping`, `bend_friction_torque`, `twist_stiffness`,
/// `twist_bump_stop_angle` or `twist_bump_stop_stiffness` is negative or not finite; or
/// `twist_rest_angle` is not finite.
void validate_constraint(const cvjoint_constraint &c);

/// Twist of frame B relative to frame A (world space) about B's axis, after swinging A's axis
/// onto B's along the shortest arc.
/// @param frameA Body A's frame, world space (first column: its axis).
/// @param frameB Body B's frame, world space (first column: its axis).
/// @return The twist in radians, in [-pi, pi].
scalar cvjoint_twist(const matrix3x3 &frameA, const matrix3x3 &frameB) noexcept;

/// The twist's rate is dot(axis, wB - wA) with axis = (a + b) / (1 + a.b) for the unit axes a
/// and b of the two frames: spinning either body about its own axis twists at its spin rate,
/// and bending (about a x b) does not twist at all.
/// The denominator is kept at 1e-3 or more, so that the axis stays bounded when the joint is
/// bent by nearly half a turn.
/// @param axisA Body A's unit axis, world space.
/// @param axisB Body B's unit axis, world space.
/// @return The twist rate axis (not unit length in general).
vector3 cvjoint_twist_axis(const vector3 &axisA, const vector3 &axisB) noexcept;

/// A cvjoint_constraint as the solver sees it during a step.
struct cvjoint_constraint_solver {
    using component = cvjoint_constraint; ///< The component this solver is made from.
    joint_anchor anchor;                  ///< The pivots at the start of the step.
    /// @var frameA
    /// Body A's frame in world space, at the start of the step.
    /// @var frameB
    /// Body B's frame in world space, at the start of the step.
    matrix3x3 frameA, frameB;
    scalar twist{0}; ///< Twist (radians, unwrapped), updated after each relax pass.
    /// @var twist_row
    /// The row about the axis of the twist's rate at the bodies' present poses
    /// (refresh_geometry()).
    /// @var present_twist
    /// Twist at the bodies' present poses (radians, unwrapped from `twist`).
    angular_row twist_row{vector3_zero, 0};
    scalar present_twist{0};
    bool locked{true}; ///< Whether the twist limits are equal, so that the twist is held.
    /// @var friction_torque
    /// Twist friction torque (N m).
    /// @var damping
    /// Twist damping (N m/(rad/s)).
    /// @var rest_angle
    /// Twist the spring pulls towards (radians).
    /// @var stiffness
    /// Twist spring stiffness (N m/rad).
    scalar friction_torque, damping, rest_angle, stiffness;
    scalar bend_friction_torque;   ///< Bend friction torque (N m).
    angular_limit limit;           ///< The twist's limits, bump stops and restitution.
    vector3 impulse;               ///< Linear impulse holding the pivots together (N s).
    scalar twist_impulse;          ///< Impulse of the locked twist (N m s).
    scalar friction_impulse;       ///< Twist friction impulse (N m s).
    scalar spring_impulse;         ///< Twist spring and damper impulse (N m s).
    vector3 bend_friction_impulse; ///< Bend friction impulse (N m s, world space).
    /// Inverse of IA^-1 + IB^-1, the bend friction's mass (kg m^2), measured at each sub-step's
    /// warm start when the joint has bend friction.
    matrix3x3 bend_mass{matrix3x3_zero};
    /// Whether `bend_mass` holds an inverse: false when neither body can turn.
    bool bend_mass_valid{false};
};

/// Prepares a CV joint for this step's solve: pivots and frames in world space, the unwrapped
/// twist, its rate for restitution and last step's impulses (those of rows not in use dropped).
/// @param registry The registry holding the constraint's bodies; their `angvel` is read.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
cvjoint_constraint_solver make_constraint_solver(const registry &registry, const cvjoint_constraint &c,
                                                 constraint_body_indices indices);
/// Measures the twist and its axis at the bodies' present poses, after they have moved.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void refresh_geometry(cvjoint_constraint_solver &s, std::span<const solver_body> bodies) noexcept;
/// Re-applies the accumulated impulses to the bodies, at the start of each sub-step.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void warm_start(cvjoint_constraint_solver &s, std::span<solver_body> bodies) noexcept;
/// One pass over the joint's rows: bend friction; then either the locked twist or the twist's
/// friction, spring, limit bounces, limits and bump stops; then the pivots, which have the
/// final word.
/// @param s The solver state; its impulses accumulate.
/// @param bodies The step's solver bodies.
/// @param ctx The pass (biased or relax).
void solve(cvjoint_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Writes the twist and the impulses back into the component, for the next step.
/// @param s The solver state after the step.
/// @param c The constraint component.
void store_impulses(const cvjoint_constraint_solver &s, cvjoint_constraint &c) noexcept;
/// The pivots position projection brings together after a sub-step's integration (see
/// joint_path_set).
/// @param s The solver state.
/// @return Its anchor.
inline joint_anchor *projected_pivots(cvjoint_constraint_solver &s) noexcept { return &s.anchor; }

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CVJOINT_CONSTRAINT_HPP
