#include "edyn/constraints/soft_distance_constraint.hpp"
#include "edyn/constraints/distance_constraint.hpp"

namespace edyn {

void validate_constraint(const soft_distance_constraint &c) {
    constexpr auto type = constraint_type_name<soft_distance_constraint>;
    check_constraint_finite(type, "pivot[0]", c.pivot[0]);
    check_constraint_finite(type, "pivot[1]", c.pivot[1]);
    check_constraint_non_negative(type, "distance", c.distance);
    check_constraint_non_negative(type, "stiffness", c.stiffness);
    check_constraint_non_negative(type, "damping", c.damping);
}

soft_distance_constraint_solver make_constraint_solver(const registry &registry,
                                                       const soft_distance_constraint &c,
                                                       constraint_body_indices indices) {
    soft_distance_constraint_solver s;
    s.anchor = make_joint_anchor(registry, c.body, c.pivot, indices);
    s.distance = c.distance;
    s.stiffness = c.stiffness;
    s.damping = c.damping;
    s.impulse = c.impulse;
    return s;
}

void warm_start(soft_distance_constraint_solver &s, std::span<solver_body> bodies) noexcept {
    warm_start_pivot_axis(s.anchor, s.impulse, bodies);
}

void solve(soft_distance_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    pivot_axis axis;
    if (!current_pivot_axis(s.anchor, axis)) return;
    solve_spring_row(linear_jacobian(axis.direction, axis.pose.rA, axis.pose.rB), axis.length - s.distance,
                     s.stiffness, s.damping, s.impulse, a, b, ctx);
}

void store_impulses(const soft_distance_constraint_solver &s, soft_distance_constraint &c) noexcept {
    c.impulse = s.impulse;
}

} // namespace edyn
