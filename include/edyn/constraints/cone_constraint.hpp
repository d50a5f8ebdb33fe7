#ifndef EDYN_CONSTRAINTS_CONE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_CONE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/math/math.hpp"
#include <span>

namespace edyn {

/// Keeps pivot[1] of body[1] inside a cone attached to body[0]: its apex is pivot[0], its axis
/// the first column of `frame` (body[0]'s object space). The cone may be elliptical: it opens
/// by span_angle[0] towards the frame's second column and by span_angle[1] towards the third.
/// Usually paired with a point or CV joint at the apex, as a swing limit (shoulders, hips).
/// Created with make_constraint(); the user sets the pivots, frame, spans, restitution and bump
/// stops, the engine writes the impulses. Only the wall is enforced: the point may move freely
/// inside the cone, and along the axis.
struct cone_constraint {
    /// body[0] carries the cone, body[1] the point; set by make_constraint() for good.
    entity body[2]{null, null};
    /// pivot[0]: the cone's apex, in body[0]'s object space; pivot[1]: the point kept inside, in
    /// body[1]'s object space; both relative to the body's origin (m). Default: the origins.
    vector3 pivot[2]{vector3_zero, vector3_zero};
    /// Orthonormal frame of the cone in body[0]'s object space: the first column is the axis,
    /// the other two the directions of the two spans. Default: identity (axis along x).
    matrix3x3 frame{matrix3x3_identity};
    /// Half-angles of the cone in radians, each in (0, pi/2).
    /// span_angle[0] towards the frame's second column, span_angle[1] towards the third;
    /// default pi/4 each.
    scalar span_angle[2]{pi / 4, pi / 4};
    /// Restitution of the cone's wall in [0, 1]; default 0. Where a point or CV joint joins the
    /// same two bodies with its pivot on body[0] within 1 mm of the apex, the bounce is solved
    /// with that joint holding the apex, as one collision: the point leaves the wall at the
    /// restitution times its approach speed, the rest of the body turning about the apex.
    scalar restitution{0};
    /// Within bump_stop_angle of the wall, a spring of bump_stop_stiffness (Nm/rad) pushes the
    /// point back towards the axis.
    /// The width of that zone in radians; finite, not negative, default 0 (no bump stop).
    scalar bump_stop_angle{0};
    /// Stiffness of the bump stop, Nm/rad; finite, not negative, default 0 (no bump stop).
    scalar bump_stop_stiffness{0};

    /// Last step's impulses per sub-step, for warm starting: the wall's impulse (N m s, as its row
    /// measures the point's angle from the wall). Written by the engine.
    scalar impulse{0};
    /// Last step's bump stop impulse per sub-step (N m s). Written by the engine.
    scalar bump_stop_impulse{0};
};

/// Name of cone_constraint in error messages.
template<>
inline constexpr const char *constraint_type_name<cone_constraint> = "cone_constraint";

/// Checks the fields a user sets; make_constraint() calls it before creating the constraint.
/// @param c The constraint to check.
/// @throws std::invalid_argument When a pivot is not finite; `frame` is not orthonormal; a span
/// angle is not in (0, pi/2) (NaN included); `restitution` is outside [0, 1]; or
/// `bump_stop_angle` or `bump_stop_stiffness` is negative or not finite.
void validate_constraint(const cone_constraint &c);

/// A cone_constraint as the solver sees it during a step.
struct cone_constraint_solver {
    using component = cone_constraint; ///< The component this solver is made from.
    joint_anchor anchor;               ///< The apex and the point at the start of the step.
    matrix3x3 frame;                   ///< The cone's frame, world space, at the start of the step.
    scalar span_tan[2];                ///< Tangents of the two span angles.
    /// @var restitution
    /// Restitution of the wall, in [0, 1].
    /// @var bump_stop_angle
    /// Width of the bump stop zone (radians).
    /// @var bump_stop_stiffness
    /// Bump stop stiffness (N m/rad).
    scalar restitution, bump_stop_angle, bump_stop_stiffness;
    /// Rate at which the point approached the wall when the step began (negative: approaching).
    /// Measured only with restitution on.
    scalar start_rate{0};
    bool bounced{false}; ///< Whether the wall already bounced this step: a step answers one approach.
    /// Whether a point or CV joint holds body[1] at the apex (see cone_constraint::restitution).
    /// Looked for only with restitution on.
    bool apex_held{false};
    /// @var wall
    /// The wall's row at the bodies' present poses (refresh_geometry()).
    /// @var wall_angle
    /// Angle from the point's direction to the wall there (radians, positive inside).
    /// @var wall_valid
    /// False while the point is at the apex or on the axis, where there is no row.
    /// @var wall_radius
    /// The point's distance from the apex there (m): the wall's angular rate times it is the
    /// point's speed across the wall.
    jacobian wall{};
    scalar wall_angle{0};
    bool wall_valid{false};
    scalar wall_radius{0};
    /// @var impulse
    /// Wall impulse of the sub-step (N m s), not negative.
    /// @var bump_stop_impulse
    /// Bump stop impulse of the sub-step (N m s).
    scalar impulse, bump_stop_impulse;
};

/// Prepares a cone for this step's solve: apex, point and frame in world space, tangents of
/// the spans, the approach rate for restitution and last step's impulses.
/// @param registry The registry holding the constraint's bodies; with restitution their
/// `linvel` and `angvel` are read, and the constraints joining body[1] are looked through for
/// a point or CV joint at the apex.
/// @param c The constraint component.
/// @param indices The bodies' indices in the step's solver bodies.
/// @return The solver state.
cone_constraint_solver make_constraint_solver(const registry &registry, const cone_constraint &c,
                                              constraint_body_indices indices);
/// Measures the wall's row at the bodies' present poses, after they have moved.
/// @param s The solver state, its anchor's pose already refreshed.
/// @param bodies The step's solver bodies.
void refresh_geometry(cone_constraint_solver &s, std::span<const solver_body> bodies) noexcept;
/// Re-applies the accumulated impulses to the bodies, at the start of each sub-step; drops them
/// while the point is at the apex or on the axis.
/// @param s The solver state.
/// @param bodies The step's solver bodies.
void warm_start(cone_constraint_solver &s, std::span<solver_body> bodies) noexcept;
/// One pass over the cone's row: bump stop, then a bounce off the wall (once per step) or the
/// wall as a limit row. Does nothing while the point is at the apex or on the axis.
/// @param s The solver state; its impulses accumulate.
/// @param bodies The step's solver bodies.
/// @param ctx The pass (biased or relax).
void solve(cone_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
/// Writes the impulses back into the component, for next step's warm start.
/// @param s The solver state after the step.
/// @param c The constraint component.
void store_impulses(const cone_constraint_solver &s, cone_constraint &c) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONE_CONSTRAINT_HPP
