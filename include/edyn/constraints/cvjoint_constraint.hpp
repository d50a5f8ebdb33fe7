#ifndef EDYN_CONSTRAINTS_CVJOINT_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_CVJOINT_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include "edyn/constraints/hinge_constraint.hpp"
#include "edyn/constraints/point_constraint.hpp"
#include <span>

namespace edyn {

// Constant-velocity joint: the pivots are kept together and the bodies may bend freely, but
// their twist is transmitted whatever the bend, like a car's drive shaft joint. Each body's
// axis is the first column of its frame (object space); the twist is the angle of body[1]'s
// second column from body[0]'s once body[0]'s frame is swung onto body[1]'s axis along the
// shortest arc. Spinning one body about its axis spins the other about its own at the same
// rate.
struct cvjoint_constraint {
    entity body[2]{null, null};
    vector3 pivot[2]{vector3_zero, vector3_zero};
    matrix3x3 frame[2]{matrix3x3_identity, matrix3x3_identity};
    // Twist limits (radians), twist_min <= twist_max. Equal limits lock the twist (the
    // default), infinite ones leave it free.
    scalar twist_min{0};
    scalar twist_max{0};
    // Restitution of a twist limit in [0, 1].
    scalar twist_restitution{0};
    // Torque opposing twisting, Nm.
    scalar twist_friction_torque{0};
    // Torque per twist rate, Nm/(rad/s).
    scalar twist_damping{0};
    // Torque opposing bending (relative rotation about any axis across the twist axis), Nm: what
    // lets a swinging joint, such as a rag doll's shoulder, come to rest.
    scalar bend_friction_torque{0};
    // A spring of twist_stiffness (Nm/rad) pulls the twist towards twist_rest_angle.
    scalar twist_rest_angle{0};
    scalar twist_stiffness{0};
    // Within twist_bump_stop_angle of a limit, a spring of twist_bump_stop_stiffness (Nm/rad)
    // pushes back.
    scalar twist_bump_stop_angle{0};
    scalar twist_bump_stop_stiffness{0};
    // The twist at the end of the last step, unwrapped past half a turn.
    scalar twist_angle{0};

    // Last step's impulses per sub-step, for warm starting.
    vector3 impulse{vector3_zero};
    scalar twist_impulse{0};
    scalar limit_impulse[2]{0, 0};
    scalar bump_stop_impulse[2]{0, 0};
    scalar friction_impulse{0};
    scalar spring_impulse{0};
    vector3 bend_friction_impulse{vector3_zero};

    // Sets both frames from each body's axis (object space), completing each into an
    // orthonormal basis.
    void set_axes(const vector3 &axisA, const vector3 &axisB);
};

template<>
inline constexpr const char *constraint_type_name<cvjoint_constraint> = "cvjoint_constraint";

void validate_constraint(const cvjoint_constraint &c);

// Twist of frame B relative to frame A (world space) about B's axis, after swinging A's axis
// onto B's along the shortest arc.
scalar cvjoint_twist(const matrix3x3 &frameA, const matrix3x3 &frameB) noexcept;

// The twist's rate is dot(axis, wB - wA) with axis = (a + b) / (1 + a.b) for the unit axes a
// and b of the two frames: spinning either body about its own axis twists at its spin rate,
// and bending (about a x b) does not twist at all.
vector3 cvjoint_twist_axis(const vector3 &axisA, const vector3 &axisB) noexcept;

struct cvjoint_constraint_solver {
    using component = cvjoint_constraint;
    joint_anchor anchor;
    matrix3x3 frameA, frameB; // world space, at the start of the step
    scalar twist{0};
    bool locked{true};
    scalar friction_torque, damping, rest_angle, stiffness;
    scalar bend_friction_torque;
    angular_limit limit;
    vector3 impulse;
    scalar twist_impulse;
    scalar friction_impulse;
    scalar spring_impulse;
    vector3 bend_friction_impulse;
};

cvjoint_constraint_solver make_constraint_solver(const registry &registry, const cvjoint_constraint &c,
                                                 constraint_body_indices indices);
void warm_start(cvjoint_constraint_solver &s, std::span<solver_body> bodies) noexcept;
void solve(cvjoint_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
void store_impulses(const cvjoint_constraint_solver &s, cvjoint_constraint &c) noexcept;
inline void project_positions(cvjoint_constraint_solver &s, std::span<solver_body> bodies, scalar fraction,
                              scalar inv_h) noexcept {
    project_point(s.anchor, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]], fraction, inv_h);
}

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CVJOINT_CONSTRAINT_HPP
