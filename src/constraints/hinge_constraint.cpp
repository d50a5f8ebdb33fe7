#include "edyn/constraints/hinge_constraint.hpp"
#include "../math/arctan2.hpp"
#include "edyn/dynamics/velocity.hpp"
#include <cmath>

namespace edyn {

void hinge_constraint::set_axes(const vector3 &axisA, const vector3 &axisB) {
    check_joint_axis("hinge_constraint::set_axes", "axisA", axisA);
    check_joint_axis("hinge_constraint::set_axes", "axisB", axisB);
    frame[0] = frame_from_axis(axisA);
    frame[1] = frame_from_axis(axisB);
}

void validate_constraint(const hinge_constraint &c) {
    constexpr auto type = constraint_type_name<hinge_constraint>;
    check_constraint_finite(type, "pivot[0]", c.pivot[0]);
    check_constraint_finite(type, "pivot[1]", c.pivot[1]);
    check_constraint_orthonormal(type, "frame[0]", c.frame[0]);
    check_constraint_orthonormal(type, "frame[1]", c.frame[1]);
    // Infinite limits are allowed (no limit); NaN, an empty range and a single angle are not
    // (a hinge that must not turn is a generic constraint with its angular axes locked).
    if (!(c.angle_min < c.angle_max)) {
        throw_constraint_error(type, "angle_min",
                               "must be smaller than angle_max, got " + std::to_string(c.angle_min) +
                                   " and " + std::to_string(c.angle_max));
    }
    check_constraint_unit_interval(type, "limit_restitution", c.limit_restitution);
    check_constraint_non_negative(type, "friction_torque", c.friction_torque);
    check_constraint_non_negative(type, "damping", c.damping);
    check_constraint_non_negative(type, "bump_stop_angle", c.bump_stop_angle);
    check_constraint_non_negative(type, "bump_stop_stiffness", c.bump_stop_stiffness);
    check_constraint_finite(type, "rest_angle", c.rest_angle);
    check_constraint_non_negative(type, "stiffness", c.stiffness);
}

scalar relative_angle(const matrix3x3 &frameA, const matrix3x3 &frameB) noexcept {
    auto axis = frameA.column(0);
    auto a1 = frameA.column(1);
    auto b1 = frameB.column(1);
    return detail::arctan2(dot(cross(a1, b1), axis), dot(a1, b1));
}

limit_hits detect_limit_hits(angular_limit &limit, const vector3 &axis, scalar angle, const solver_body &a,
                             const solver_body &b, const constraint_solve_context &ctx) noexcept {
    limit_hits hits;
    auto rate = dot(axis, b.angvel - a.angvel);
    const scalar gaps[2]{angle - limit.min, limit.max - angle};
    const scalar rates[2]{rate, -rate};
    const scalar start_rates[2]{limit.start_rate, -limit.start_rate};
    for (int i = 0; i < 2; ++i) {
        if (!std::isfinite(gaps[i]) || gaps[i] + rates[i] * ctx.h > 0) continue;
        if (limit.restitution > 0) {
            if (limit.bounced[i]) continue;
            // The approach is the faster of now and when the step began: in between, the limit
            // may have braked the motion speculatively.
            auto approach = std::min(rates[i], start_rates[i]);
            if (approach >= -ctx.restitution_threshold) continue;
            hits.rate[i] = -limit.restitution * approach;
            limit.bounced[i] = true;
        } else {
            // Approached faster than the threshold now and when the step began: a joint resting
            // on its limit, which each sub-step's gravity presses into it anew, is left to the
            // limit row.
            if (std::max(rates[i], start_rates[i]) >= -ctx.restitution_threshold) continue;
            hits.rate[i] = -std::max(gaps[i], scalar(0)) * ctx.inv_h;
        }
        hits.hit[i] = true;
    }
    return hits;
}

void solve_limit_hits(const angular_row &row, const limit_hits &hits, scalar (&impulse)[2], solver_body &a,
                      solver_body &b) noexcept {
    const angular_row rows[2]{-row, row};
    for (int i = 0; i < 2; ++i) {
        if (!hits.hit[i]) continue;
        auto mass = row_effective_mass(rows[i], a, b);
        auto new_impulse =
            std::max(impulse[i] + mass * (hits.rate[i] - row_velocity(rows[i], a, b)), scalar(0));
        apply_row_impulse(rows[i], a, b, new_impulse - impulse[i]);
        impulse[i] = new_impulse;
    }
}

void solve_angular_limit(angular_limit &limit, const angular_row &row, scalar angle, solver_body &a,
                         solver_body &b, const constraint_solve_context &ctx) noexcept {
    const angular_row rows[2]{-row, row};
    const scalar gaps[2]{angle - limit.min, limit.max - angle};
    for (int i = 0; i < 2; ++i) {
        if (!std::isfinite(gaps[i])) continue;
        if (limit.bump_angle > 0 && limit.bump_stiffness > 0) {
            // A spring that only pushes, compressed by how far the angle is into the zone.
            if (gaps[i] < limit.bump_angle) {
                solve_spring_row(rows[i], gaps[i] - limit.bump_angle, limit.bump_stiffness, 0,
                                 limit.bump_impulse[i], a, b, ctx, true);
            } else {
                limit.bump_impulse[i] = 0;
            }
        }
        solve_limit_row(rows[i], gaps[i], limit.impulse[i], a, b, ctx);
    }
}

void solve_axis_alignment(const angular_row (&rows)[2], const scalar (&errors)[2], scalar (&impulse)[2],
                          solver_body &a, solver_body &b, const constraint_solve_context &ctx) noexcept {
    for (int i = 0; i < 2; ++i)
        solve_equality_row(rows[i], errors[i], impulse[i], a, b, ctx);
}

hinge_constraint_solver make_constraint_solver(const registry &registry, const hinge_constraint &c,
                                               constraint_body_indices indices) {
    hinge_constraint_solver s;
    s.anchor = make_joint_anchor(registry, c.body, c.pivot, indices);
    s.frameA = world_frame(registry, c.body[0], c.frame[0]);
    s.frameB = world_frame(registry, c.body[1], c.frame[1]);
    s.angle = unwrap_angle(c.angle, relative_angle(s.frameA, s.frameB));
    s.friction_torque = c.friction_torque;
    s.damping = c.damping;
    s.rest_angle = c.rest_angle;
    s.stiffness = c.stiffness;
    s.limit.min = c.angle_min;
    s.limit.max = c.angle_max;
    s.limit.bump_angle = c.bump_stop_angle;
    s.limit.bump_stiffness = c.bump_stop_stiffness;
    s.limit.restitution = c.limit_restitution;
    auto axis = s.frameA.column(0);
    s.limit.start_rate =
        dot(axis, vector3(registry.get<angvel>(c.body[1])) - vector3(registry.get<angvel>(c.body[0])));
    for (int i = 0; i < 2; ++i) {
        s.limit.impulse[i] = c.limit_impulse[i];
        s.limit.bump_impulse[i] = c.bump_stop_impulse[i];
        s.align_impulse[i] = c.align_impulse[i];
    }
    s.impulse = c.impulse;
    s.friction_impulse = c.friction_impulse;
    s.spring_impulse = c.spring_impulse;
    return s;
}

namespace {

// A limit hit is solved as an isolated collision: the limit row, the axis and the pivot
// iterated together from zero impulses until they agree, so that the hinge leaves the limit
// with the rate asked for (the angular row alone does not see that the pivot constrains the
// body to turn about the hinge).
void solve_hinge_hits(hinge_constraint_solver &s, const limit_hits &hits, solver_body &a, solver_body &b,
                      const constraint_solve_context &ctx) {
    constexpr int iterations = 32;
    auto rigid = ctx;
    rigid.use_bias = false;
    const auto &row = s.axis_row;
    // A bounce answers the approach with the limit's warm-started push in it: take the push
    // back, or the limit row would remove it from the bounce once the hinge separates. A stop
    // keeps it: it may be holding a load, which taken back would be pressed in anew each
    // sub-step. The collision's impulses are not accumulated either way: warm-started in the
    // next sub-step, they would push the stopped hinge back out.
    const angular_row rows[2]{-row, row};
    for (int i = 0; i < 2; ++i) {
        if (!hits.hit[i] || s.limit.restitution <= 0) continue;
        apply_row_impulse(rows[i], a, b, -s.limit.impulse[i]);
        s.limit.impulse[i] = 0;
    }
    scalar limit_impulse[2]{0, 0}, align_impulse[2]{0, 0};
    vector3 point_impulse = vector3_zero;
    for (int k = 0; k < iterations; ++k) {
        solve_limit_hits(row, hits, limit_impulse, a, b);
        solve_axis_alignment(s.align_rows, s.align_errors, align_impulse, a, b, rigid);
        solve_point_block(s.anchor, point_impulse, a, b, rigid);
    }
}

} // namespace

void refresh_geometry(hinge_constraint_solver &s, std::span<const solver_body> bodies) noexcept {
    const auto &a = bodies[s.anchor.body[0]];
    const auto &b = bodies[s.anchor.body[1]];
    auto frameA = rotate_frame(a.delta_rotation, s.frameA);
    auto frameB = rotate_frame(b.delta_rotation, s.frameB);
    auto axisB = frameB.column(0);
    s.axis_row = make_angular_row(frameA.column(0), a, b);
    for (int i = 0; i < 2; ++i) {
        auto u = frameA.column(i + 1);
        s.align_rows[i] = make_angular_row(cross(u, axisB), a, b);
        s.align_errors[i] = dot(u, axisB);
    }
    s.present_angle = unwrap_angle(s.angle, relative_angle(frameA, frameB));
}

void warm_start(hinge_constraint_solver &s, std::span<solver_body> bodies) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    auto &pose = s.anchor.pose;
    warm_point_mass(s.anchor, a, b, pose);
    apply_impulse(a, b, s.impulse, pose.rA, pose.rB);
    // The alignment rows turn about uA_i x axisB; friction, spring and limits about the axis
    // (their rate is dot(axis, wA - wB)). One angular impulse carries them all.
    auto turn = s.axis_row.axis * (s.friction_impulse + s.spring_impulse + warm_start_impulse(s.limit));
    for (int i = 0; i < 2; ++i) {
        turn += s.align_rows[i].axis * s.align_impulse[i];
    }
    apply_angular_impulse(a, b, turn);
}

void solve(hinge_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    const auto &row = s.axis_row;
    auto angle = s.present_angle;

    // Motion-resisting rows first; the limits and the joint itself have the final word.
    if (s.friction_torque > 0) solve_friction_row(row, s.friction_torque * ctx.h, s.friction_impulse, a, b);
    if (s.stiffness > 0 || s.damping > 0) {
        // The row's rate is minus the angle's rate, so its position error is rest - angle.
        solve_spring_row(row, s.rest_angle - angle, s.stiffness, s.damping, s.spring_impulse, a, b, ctx);
    }
    if (auto hits = detect_limit_hits(s.limit, row.axis, angle, a, b, ctx); hits.any()) {
        solve_hinge_hits(s, hits, a, b, ctx);
    }
    solve_angular_limit(s.limit, row, angle, a, b, ctx);
    solve_axis_alignment(s.align_rows, s.align_errors, s.align_impulse, a, b, ctx);
    solve_point_block(s.anchor, s.impulse, a, b, ctx);
    if (!ctx.use_bias) s.angle = angle;
}

void store_impulses(const hinge_constraint_solver &s, hinge_constraint &c) noexcept {
    c.angle = s.angle;
    c.impulse = s.impulse;
    for (int i = 0; i < 2; ++i) {
        c.align_impulse[i] = s.align_impulse[i];
        c.limit_impulse[i] = s.limit.impulse[i];
        c.bump_stop_impulse[i] = s.limit.bump_impulse[i];
    }
    c.friction_impulse = s.friction_impulse;
    c.spring_impulse = s.spring_impulse;
}

} // namespace edyn
