#ifndef EDYN_CONSTRAINTS_HINGE_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_HINGE_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include "edyn/math/math.hpp"
#include <limits>
#include <span>

namespace edyn {

// Keeps the pivots together and lets the bodies turn only about the hinge axis: the first
// column of each body's frame (object space). The other columns measure the hinge angle: the
// angle of body[1]'s second column from body[0]'s, about the axis, positive counterclockwise.
struct hinge_constraint {
    entity body[2]{null, null};
    vector3 pivot[2]{vector3_zero, vector3_zero};
    matrix3x3 frame[2]{matrix3x3_identity, matrix3x3_identity};
    // Limits of the hinge angle (radians); infinite for a free hinge. angle_min <= angle_max.
    scalar angle_min{-std::numeric_limits<scalar>::infinity()};
    scalar angle_max{std::numeric_limits<scalar>::infinity()};
    // Restitution of a limit in [0, 1].
    scalar limit_restitution{0};
    // Torque opposing rotation about the axis, Nm.
    scalar friction_torque{0};
    // Torque per angular velocity about the axis, Nm/(rad/s).
    scalar damping{0};
    // Within bump_stop_angle of a limit, a spring of bump_stop_stiffness (Nm/rad) pushes back.
    scalar bump_stop_angle{0};
    scalar bump_stop_stiffness{0};
    // A spring of `stiffness` (Nm/rad) pulls the hinge towards rest_angle.
    scalar rest_angle{0};
    scalar stiffness{0};
    // The hinge angle at the end of the last step, unwrapped so that limits beyond half a turn
    // work.
    scalar angle{0};

    // Last step's impulses per sub-step, for warm starting.
    vector3 impulse{vector3_zero};
    scalar align_impulse[2]{0, 0};
    scalar limit_impulse[2]{0, 0};
    scalar bump_stop_impulse[2]{0, 0};
    scalar friction_impulse{0};
    scalar spring_impulse{0};

    // Sets both frames from the hinge axis in each body's object space, completing each into an
    // orthonormal basis. The angle is then measured between those completions.
    void set_axes(const vector3 &axisA, const vector3 &axisB);
};

template<>
inline constexpr const char *constraint_type_name<hinge_constraint> = "hinge_constraint";

void validate_constraint(const hinge_constraint &c);

// Angle of frame B's second column from frame A's about A's first column.
scalar relative_angle(const matrix3x3 &frameA, const matrix3x3 &frameB) noexcept;

// Rotation about the axis is measured against the value it had at the start of the step so
// that an angle past half a turn stays continuous.
inline scalar unwrap_angle(scalar previous, scalar raw) noexcept {
    return previous + normalize_angle(raw - previous);
}

// Limits, bump stops and limit restitution of an angle whose rate is dot(axis, wB - wA)
// (shared by the hinge angle and the CV joint's twist).
struct angular_limit {
    scalar min{0}, max{0};
    scalar bump_angle{0}, bump_stiffness{0};
    scalar restitution{0};
    // Rate of the angle when the step began: a limit approached faster than the threshold
    // bounces, with the speed it had before the solver started braking it.
    scalar start_rate{0};
    // Whether each limit already bounced this step: a step answers one approach.
    bool bounced[2]{false, false};
    scalar impulse[2]{0, 0};
    scalar bump_impulse[2]{0, 0};
};

void warm_start_angular_limit(const angular_limit &limit, const vector3 &axis, solver_body &a,
                              solver_body &b) noexcept;
void solve_angular_limit(angular_limit &limit, const vector3 &axis, scalar angle, solver_body &a,
                         solver_body &b, const constraint_solve_context &ctx) noexcept;
// Separating velocity for each limit hit in the coming sub-step faster than the threshold (0 for
// the others); marks them as bounced. Returns whether any was hit.
bool detect_limit_hits(angular_limit &limit, const vector3 &axis, scalar angle, const solver_body &a,
                       const solver_body &b, const constraint_solve_context &ctx,
                       scalar (&bounce)[2]) noexcept;
// Drives the rate of each hit limit to its bounce velocity (impulses that only push), as one
// row of an isolated collision solve.
void solve_limit_bounce(const vector3 &axis, const scalar (&bounce)[2], scalar (&impulse)[2], solver_body &a,
                        solver_body &b) noexcept;

struct hinge_constraint_solver {
    using component = hinge_constraint;
    joint_anchor anchor;
    matrix3x3 frameA, frameB; // world space, at the start of the step
    scalar angle{0};
    scalar friction_torque, damping, rest_angle, stiffness;
    angular_limit limit;
    vector3 impulse;
    scalar align_impulse[2];
    scalar friction_impulse;
    scalar spring_impulse;
};

hinge_constraint_solver make_constraint_solver(const registry &registry, const hinge_constraint &c,
                                               constraint_body_indices indices);
void warm_start(hinge_constraint_solver &s, std::span<solver_body> bodies) noexcept;
void solve(hinge_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
void store_impulses(const hinge_constraint_solver &s, hinge_constraint &c) noexcept;
inline void project_positions(hinge_constraint_solver &s, std::span<solver_body> bodies, scalar fraction,
                              scalar inv_h) noexcept {
    project_point(s.anchor, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]], fraction, inv_h);
}

// Shared with the other joints that align an axis: two angular rows keeping axisB parallel to
// axisA, measured against A's two other axes (frame columns 1 and 2).
void solve_axis_alignment(const matrix3x3 &frameA, const vector3 &axisB, scalar (&impulse)[2], solver_body &a,
                          solver_body &b, const constraint_solve_context &ctx) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_HINGE_CONSTRAINT_HPP
