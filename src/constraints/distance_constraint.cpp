#include "edyn/constraints/distance_constraint.hpp"
#include <cmath>

namespace edyn {

void validate_constraint(const distance_constraint &c) {
    constexpr auto type = constraint_type_name<distance_constraint>;
    check_constraint_finite(type, "pivot[0]", c.pivot[0]);
    check_constraint_finite(type, "pivot[1]", c.pivot[1]);
    check_constraint_non_negative(type, "distance", c.distance);
}

bool pivot_direction(const vector3 &d, vector3 &direction, scalar &length) noexcept {
    length = edyn::length(d);
    if (!(length > scalar(1e-9))) return false;
    direction = d / length;
    return true;
}

distance_constraint_solver make_constraint_solver(const registry &registry, const distance_constraint &c,
                                                  constraint_body_indices indices) {
    distance_constraint_solver s;
    s.anchor = make_joint_anchor(registry, c.body, c.pivot, indices);
    s.distance = c.distance;
    s.impulse = c.impulse;
    return s;
}

void warm_start(distance_constraint_solver &s, std::span<solver_body> bodies) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    auto pose = current_pose(s.anchor, a, b);
    vector3 n;
    scalar len;
    if (!pivot_direction(pose.d, n, len)) return;
    apply_impulse(a, b, n * s.impulse, pose.rA, pose.rB);
}

void solve(distance_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    auto pose = current_pose(s.anchor, a, b);
    vector3 n;
    scalar len;
    if (!pivot_direction(pose.d, n, len)) return;
    auto row_ctx = ctx;
    if (ctx.rigid_pivots) row_ctx.use_bias = false;
    solve_equality_row(linear_jacobian(n, pose.rA, pose.rB), len - s.distance, s.impulse, a, b, row_ctx);
}

void store_impulses(const distance_constraint_solver &s, distance_constraint &c) noexcept {
    c.impulse = s.impulse;
}

} // namespace edyn
