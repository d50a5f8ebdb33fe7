#include "edyn/constraints/distance_constraint.hpp"
#include <algorithm>
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

bool current_pivot_axis(const joint_anchor &anchor, pivot_axis &axis) noexcept {
    axis.pose = anchor.pose;
    return pivot_direction(axis.pose.d, axis.direction, axis.length);
}

void warm_start_pivot_axis(const joint_anchor &anchor, scalar impulse,
                           std::span<solver_body> bodies) noexcept {
    pivot_axis axis;
    if (!current_pivot_axis(anchor, axis)) return;
    apply_impulse(bodies[anchor.body[0]], bodies[anchor.body[1]], axis.direction * impulse, axis.pose.rA,
                  axis.pose.rB);
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
    warm_start_pivot_axis(s.anchor, s.impulse, bodies);
}

void solve(distance_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    pivot_axis axis;
    if (!current_pivot_axis(s.anchor, axis)) return;
    auto row_ctx = ctx;
    if (ctx.rigid_pivots && !s.anchor.unprojected) row_ctx.use_bias = false;
    // The soft correction of the length, no faster than max_correction_speed.
    auto error = axis.length - s.distance;
    if (row_ctx.use_bias && ctx.joint.bias_rate > 0) {
        auto most = ctx.max_correction_speed / ctx.joint.bias_rate;
        error = std::clamp(error, -most, most);
    }
    solve_equality_row(linear_jacobian(axis.direction, axis.pose.rA, axis.pose.rB), error, s.impulse, a, b,
                       row_ctx);
}

void store_impulses(const distance_constraint_solver &s, distance_constraint &c) noexcept {
    c.impulse = s.impulse;
}

} // namespace edyn
