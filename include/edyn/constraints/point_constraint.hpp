#ifndef EDYN_CONSTRAINTS_POINT_CONSTRAINT_HPP
#define EDYN_CONSTRAINTS_POINT_CONSTRAINT_HPP

#include "edyn/constraints/constraint_base.hpp"
#include <span>

namespace edyn {

// Ball joint: pivot[0] on body[0] and pivot[1] on body[1] (object space, relative to each
// origin) are kept at the same point in space.
struct point_constraint {
    entity body[2]{null, null};
    vector3 pivot[2]{vector3_zero, vector3_zero};
    // Torque opposing the relative angular velocity of the bodies, Nm.
    scalar friction_torque{0};
    // Last step's impulses per sub-step, for warm starting.
    vector3 impulse{vector3_zero};
    vector3 friction_impulse{vector3_zero};
};

template<>
inline constexpr const char *constraint_type_name<point_constraint> = "point_constraint";

void validate_constraint(const point_constraint &c);

struct point_constraint_solver {
    using component = point_constraint;
    joint_anchor anchor;
    scalar friction_torque{0};
    vector3 impulse{vector3_zero};
    vector3 friction_impulse{vector3_zero};
};

point_constraint_solver make_constraint_solver(const registry &registry, const point_constraint &c,
                                               constraint_body_indices indices);
void warm_start(point_constraint_solver &s, std::span<solver_body> bodies) noexcept;
void solve(point_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept;
void store_impulses(const point_constraint_solver &s, point_constraint &c) noexcept;
inline void project_positions(point_constraint_solver &s, std::span<solver_body> bodies, scalar fraction,
                              scalar inv_h) noexcept {
    project_point(s.anchor, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]], fraction, inv_h);
}

// Solves the 3x3 block keeping the pivots together (shared by the joints that contain a ball
// joint): impulse accumulates the linear impulse of the sub-step.
void solve_point_block(const joint_anchor &anchor, vector3 &impulse, solver_body &a, solver_body &b,
                       const constraint_solve_context &ctx) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_POINT_CONSTRAINT_HPP
