#include "edyn/constraints/cvjoint_constraint.hpp"
#include "../math/arctan2.hpp"
#include "edyn/dynamics/velocity.hpp"
#include <cmath>
#include <string>

namespace edyn {

void cvjoint_constraint::set_axes(const vector3 &axisA, const vector3 &axisB) {
    check_joint_axis("cvjoint_constraint::set_axes", "axisA", axisA);
    check_joint_axis("cvjoint_constraint::set_axes", "axisB", axisB);
    frame[0] = frame_from_axis(axisA);
    frame[1] = frame_from_axis(axisB);
}

void validate_constraint(const cvjoint_constraint &c) {
    constexpr auto type = constraint_type_name<cvjoint_constraint>;
    check_constraint_finite(type, "pivot[0]", c.pivot[0]);
    check_constraint_finite(type, "pivot[1]", c.pivot[1]);
    check_constraint_orthonormal(type, "frame[0]", c.frame[0]);
    check_constraint_orthonormal(type, "frame[1]", c.frame[1]);
    if (std::isnan(c.twist_min) || std::isnan(c.twist_max) || c.twist_min > c.twist_max) {
        throw_constraint_error(type, "twist_min",
                               "must not exceed twist_max, got " + std::to_string(c.twist_min) + " > " +
                                   std::to_string(c.twist_max));
    }
    // Equal limits lock the twist at that angle, which must then be finite; apart, an infinite
    // limit is simply not enforced (the pair -inf, +inf leaves the twist free).
    if (c.twist_min == c.twist_max && !std::isfinite(c.twist_min)) {
        throw_constraint_error(type, "twist_min",
                               "must be finite when equal to twist_max (a locked twist), got " +
                                   std::to_string(c.twist_min));
    }
    check_constraint_unit_interval(type, "twist_restitution", c.twist_restitution);
    check_constraint_non_negative(type, "twist_friction_torque", c.twist_friction_torque);
    check_constraint_non_negative(type, "twist_damping", c.twist_damping);
    check_constraint_non_negative(type, "bend_friction_torque", c.bend_friction_torque);
    check_constraint_finite(type, "twist_rest_angle", c.twist_rest_angle);
    check_constraint_non_negative(type, "twist_stiffness", c.twist_stiffness);
    check_constraint_non_negative(type, "twist_bump_stop_angle", c.twist_bump_stop_angle);
    check_constraint_non_negative(type, "twist_bump_stop_stiffness", c.twist_bump_stop_stiffness);
}

namespace {

// The twist from the frames' first two columns, all the third column would add: the axes and
// the reference directions whose angle about B's axis the twist is.
scalar twist_of(const vector3 &axisA, const vector3 &refA, const vector3 &axisB,
                const vector3 &refB) noexcept {
    auto p = rotate(shortest_arc(axisA, axisB), refA);
    return detail::arctan2(dot(cross(p, refB), axisB), dot(p, refB));
}

} // namespace

scalar cvjoint_twist(const matrix3x3 &frameA, const matrix3x3 &frameB) noexcept {
    return twist_of(frameA.column(0), frameA.column(1), frameB.column(0), frameB.column(1));
}

vector3 cvjoint_twist_axis(const vector3 &axisA, const vector3 &axisB) noexcept {
    // Bent by nearly half a turn the twist is undefined; keep the row bounded.
    auto c = std::max(1 + dot(axisA, axisB), scalar(1e-3));
    return (axisA + axisB) / c;
}

namespace {

// The normal of the plane the joint bends in: the twist axis, made unit. Bent by exactly half a
// turn the twist axis vanishes (a + b = 0) and every plane through the shafts is a bend plane;
// body A's axis stands in for it.
vector3 bend_plane_normal(const vector3 &twist_axis, const vector3 &axisA) noexcept {
    auto len_sqr = length_sqr(twist_axis);
    return len_sqr > epsilon * epsilon ? twist_axis / std::sqrt(len_sqr) : axisA;
}

} // namespace

cvjoint_constraint_solver make_constraint_solver(const registry &registry, const cvjoint_constraint &c,
                                                 constraint_body_indices indices) {
    cvjoint_constraint_solver s;
    s.anchor = make_joint_anchor(registry, c.body, c.pivot, indices);
    s.frameA = world_frame(registry, c.body[0], c.frame[0]);
    s.frameB = world_frame(registry, c.body[1], c.frame[1]);
    s.twist = unwrap_angle(c.twist_angle, cvjoint_twist(s.frameA, s.frameB));
    s.locked = c.twist_min == c.twist_max;
    s.friction_torque = c.twist_friction_torque;
    s.damping = c.twist_damping;
    s.rest_angle = c.twist_rest_angle;
    s.stiffness = c.twist_stiffness;
    s.limit.min = c.twist_min;
    s.limit.max = c.twist_max;
    s.limit.bump_angle = c.twist_bump_stop_angle;
    s.limit.bump_stiffness = c.twist_bump_stop_stiffness;
    s.limit.restitution = c.twist_restitution;
    auto axis = cvjoint_twist_axis(s.frameA.column(0), s.frameB.column(0));
    s.limit.start_rate =
        dot(axis, vector3(registry.get<angvel>(c.body[1])) - vector3(registry.get<angvel>(c.body[0])));
    for (int i = 0; i < 2; ++i) {
        s.limit.impulse[i] = s.locked ? 0 : c.limit_impulse[i];
        s.limit.bump_impulse[i] = s.locked ? 0 : c.bump_stop_impulse[i];
    }
    s.impulse = c.impulse;
    s.twist_impulse = s.locked ? c.twist_impulse : 0;
    s.friction_impulse = c.friction_impulse;
    s.spring_impulse = c.spring_impulse;
    s.bend_friction_torque = c.bend_friction_torque;
    // The bend plane has turned since the impulse was stored: keep only what still bends.
    s.bend_friction_impulse =
        c.bend_friction_torque > 0
            ? project_plane(c.bend_friction_impulse, bend_plane_normal(axis, s.frameA.column(0)))
            : vector3_zero;
    return s;
}

void refresh_geometry(cvjoint_constraint_solver &s, std::span<const solver_body> bodies) noexcept {
    // The frames' first two columns turned with the bodies: the twist needs no more.
    const auto &a = bodies[s.anchor.body[0]];
    const auto &b = bodies[s.anchor.body[1]];
    const auto &qA = a.delta_rotation;
    const auto &qB = b.delta_rotation;
    auto axisA = rotate(qA, s.frameA.column(0)), refA = rotate(qA, s.frameA.column(1));
    auto axisB = rotate(qB, s.frameB.column(0)), refB = rotate(qB, s.frameB.column(1));
    s.twist_row = make_angular_row(cvjoint_twist_axis(axisA, axisB), a, b);
    s.present_twist = unwrap_angle(s.twist, twist_of(axisA, refA, axisB, refB));
}

namespace {

// A twist limit hit, solved as an isolated collision of the limit and the pivot, iterated from
// zero impulses until they agree (the warm-started push taken back for a bounce only, as
// the hinge's).
void solve_twist_hits(cvjoint_constraint_solver &s, const limit_hits &hits, solver_body &a, solver_body &b,
                      const constraint_solve_context &ctx) {
    constexpr int iterations = 16;
    auto rigid = ctx;
    rigid.use_bias = false;
    const auto &row = s.twist_row;
    const angular_row rows[2]{-row, row};
    for (int i = 0; i < 2; ++i) {
        if (!hits.hit[i] || s.limit.restitution <= 0) continue;
        apply_row_impulse(rows[i], a, b, -s.limit.impulse[i]);
        s.limit.impulse[i] = 0;
    }
    scalar limit_impulse[2]{0, 0};
    vector3 point_impulse = vector3_zero;
    for (int k = 0; k < iterations; ++k) {
        solve_limit_hits(row, hits, limit_impulse, a, b);
        solve_point_block(s.anchor, point_impulse, a, b, rigid);
    }
}

// Friction torque across the twist axis, bounded as a vector so that it is the same in every
// direction of bending.
void solve_bend_friction(cvjoint_constraint_solver &s, const vector3 &twist_axis, solver_body &a,
                         solver_body &b, const constraint_solve_context &ctx) noexcept {
    if (!s.bend_mass_valid) return;
    auto u = bend_plane_normal(twist_axis, s.frameA.column(0));
    auto max_impulse = s.bend_friction_torque * ctx.h;
    auto bend_rate = project_plane(a.angvel - b.angvel, u);
    auto new_impulse = project_plane(s.bend_friction_impulse - s.bend_mass * bend_rate, u);
    auto len_sqr = length_sqr(new_impulse);
    if (len_sqr > max_impulse * max_impulse) new_impulse *= max_impulse / std::sqrt(len_sqr);
    apply_angular_impulse(a, b, new_impulse - s.bend_friction_impulse);
    s.bend_friction_impulse = new_impulse;
}

} // namespace

void warm_start(cvjoint_constraint_solver &s, std::span<solver_body> bodies) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    auto &pose = s.anchor.pose;
    warm_point_mass(s.anchor, a, b, pose);
    if (s.bend_friction_torque > 0) {
        // The bodies' inertia is the step's: the bend friction's mass is measured once a sub-step
        // for its velocity passes.
        auto k = a.inv_inertia + b.inv_inertia;
        s.bend_mass_valid = std::abs(determinant(k)) > scalar(1e-12);
        if (s.bend_mass_valid) s.bend_mass = inverse(k);
    }
    apply_impulse(a, b, s.impulse, pose.rA, pose.rB);
    // The locked twist's row turns about -axis; friction, spring and limits about the axis;
    // bend friction across it. One angular impulse carries them all.
    const auto &axis = s.twist_row.axis;
    apply_angular_impulse(
        a, b,
        axis * (s.friction_impulse + s.spring_impulse + warm_start_impulse(s.limit) - s.twist_impulse) +
            s.bend_friction_impulse);
}

void solve(cvjoint_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    const auto &row = s.twist_row; // its rate is minus the twist rate
    const auto twist = s.present_twist;

    if (s.bend_friction_torque > 0) solve_bend_friction(s, row.axis, a, b, ctx);
    if (s.locked) {
        solve_equality_row(-row, twist - s.limit.min, s.twist_impulse, a, b, ctx);
    } else {
        if (s.friction_torque > 0)
            solve_friction_row(row, s.friction_torque * ctx.h, s.friction_impulse, a, b);
        if (s.stiffness > 0 || s.damping > 0) {
            solve_spring_row(row, s.rest_angle - twist, s.stiffness, s.damping, s.spring_impulse, a, b, ctx);
        }
        if (auto hits = detect_limit_hits(s.limit, row.axis, twist, a, b, ctx); hits.any()) {
            solve_twist_hits(s, hits, a, b, ctx);
        }
        solve_angular_limit(s.limit, row, twist, a, b, ctx);
    }
    solve_point_block(s.anchor, s.impulse, a, b, ctx);
    if (!ctx.use_bias) s.twist = twist;
}

void store_impulses(const cvjoint_constraint_solver &s, cvjoint_constraint &c) noexcept {
    c.twist_angle = s.twist;
    c.impulse = s.impulse;
    c.twist_impulse = s.twist_impulse;
    for (int i = 0; i < 2; ++i) {
        c.limit_impulse[i] = s.limit.impulse[i];
        c.bump_stop_impulse[i] = s.limit.bump_impulse[i];
    }
    c.friction_impulse = s.friction_impulse;
    c.spring_impulse = s.spring_impulse;
    c.bend_friction_impulse = s.bend_friction_impulse;
}

} // namespace edyn
