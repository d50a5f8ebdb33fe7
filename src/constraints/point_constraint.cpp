#include "edyn/constraints/point_constraint.hpp"
#include <cmath>

namespace edyn {

void validate_constraint(const point_constraint &c) {
    constexpr auto type = constraint_type_name<point_constraint>;
    check_constraint_finite(type, "pivot[0]", c.pivot[0]);
    check_constraint_finite(type, "pivot[1]", c.pivot[1]);
    check_constraint_non_negative(type, "friction_torque", c.friction_torque);
}

point_constraint_solver make_constraint_solver(const registry &registry, const point_constraint &c,
                                               constraint_body_indices indices) {
    point_constraint_solver s;
    s.anchor = make_joint_anchor(registry, c.body, c.pivot, indices);
    s.friction_torque = c.friction_torque;
    s.impulse = c.impulse;
    s.friction_impulse = c.friction_torque > 0 ? c.friction_impulse : vector3_zero;
    return s;
}

void warm_start(point_constraint_solver &s, std::span<solver_body> bodies) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    auto &pose = s.anchor.pose;
    warm_point_mass(s.anchor, a, b, pose);
    apply_impulse(a, b, s.impulse, pose.rA, pose.rB);
    // Without friction torque the friction impulse is zero (make_constraint_solver).
    if (s.friction_torque > 0) apply_angular_impulse(a, b, s.friction_impulse);
}

void solve_point_block(const joint_anchor &anchor, vector3 &impulse, solver_body &a, solver_body &b,
                       const constraint_solve_context &ctx) noexcept {
    // Solved as a block with the inverse of K, the pivots' relative velocity change per unit
    // impulse (anchor.point_mass, see update_point_mass), so the three directions do not fight.
    auto &pose = anchor.pose;
    const matrix3x3 *mass = &anchor.point_mass;
    matrix3x3 remeasured;
    if (length_sqr(pose.d) > large_point_separation_sqr) {
        // Pivots far apart move far when corrected: the mass is recomputed, not reused.
        if (!inverse_point_mass(a, b, pose, remeasured)) return;
        mass = &remeasured;
    } else if (!anchor.point_mass_valid) {
        return;
    }

    auto v = relative_velocity(a, b, pose.rA, pose.rB);
    vector3 delta;
    if (ctx.use_bias && (!ctx.rigid_pivots || anchor.unprojected)) {
        // The soft correction of the pivots' separation, no faster than max_correction_speed.
        auto bias = pose.d * ctx.joint.bias_rate;
        auto speed_sqr = length_sqr(bias);
        if (speed_sqr > ctx.max_correction_speed * ctx.max_correction_speed)
            bias *= ctx.max_correction_speed / std::sqrt(speed_sqr);
        delta = -(*mass * (v + bias)) * ctx.joint.mass_scale - impulse * ctx.joint.impulse_scale;
    } else {
        delta = -(*mass * v);
    }
    impulse += delta;
    apply_impulse(a, b, delta, pose.rA, pose.rB);
}

namespace {

// Friction torque on all three axes, bounded as a vector so that it is isotropic.
void solve_angular_friction(point_constraint_solver &s, solver_body &a, solver_body &b,
                            const constraint_solve_context &ctx) {
    auto k = a.inv_inertia + b.inv_inertia;
    if (!(std::abs(determinant(k)) > scalar(1e-12))) return;
    auto max_impulse = s.friction_torque * ctx.h;
    auto new_impulse = s.friction_impulse - inverse(k) * (a.angvel - b.angvel);
    auto len_sqr = length_sqr(new_impulse);
    if (len_sqr > max_impulse * max_impulse) new_impulse *= max_impulse / std::sqrt(len_sqr);
    apply_angular_impulse(a, b, new_impulse - s.friction_impulse);
    s.friction_impulse = new_impulse;
}

} // namespace

void solve(point_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    // Friction first: the positional constraint, solved last, has the final word.
    if (s.friction_torque > 0) solve_angular_friction(s, a, b, ctx);
    solve_point_block(s.anchor, s.impulse, a, b, ctx);
}

void store_impulses(const point_constraint_solver &s, point_constraint &c) noexcept {
    c.impulse = s.impulse;
    c.friction_impulse = s.friction_impulse;
}

} // namespace edyn
