#include "edyn/constraints/generic_constraint.hpp"
#include "../math/arctan2.hpp"
#include "edyn/dynamics/velocity.hpp"
#include <cmath>
#include <string>

namespace edyn {

void validate_constraint(const generic_constraint &c) {
    constexpr auto type = constraint_type_name<generic_constraint>;
    check_constraint_finite(type, "pivot[0]", c.pivot[0]);
    check_constraint_finite(type, "pivot[1]", c.pivot[1]);
    check_constraint_orthonormal(type, "frame[0]", c.frame[0]);
    check_constraint_orthonormal(type, "frame[1]", c.frame[1]);
    const char *names[6]{"linear[0]", "linear[1]", "linear[2]", "angular[0]", "angular[1]", "angular[2]"};
    for (int i = 0; i < 6; ++i) {
        auto &d = i < 3 ? c.linear[i] : c.angular[i - 3];
        auto field = std::string(names[i]);
        if (d.mode != dof_mode::free && d.mode != dof_mode::locked && d.mode != dof_mode::limited) {
            throw_constraint_error(type, (field + ".mode").c_str(), "must be free, locked or limited");
        }
        if (d.mode == dof_mode::limited) {
            if (std::isnan(d.min) || std::isnan(d.max) || d.min > d.max) {
                throw_constraint_error(type, (field + ".min").c_str(),
                                       "must not exceed " + field + ".max, got " + std::to_string(d.min) +
                                           " > " + std::to_string(d.max));
            }
        }
        check_constraint_non_negative(type, (field + ".stiffness").c_str(), d.stiffness);
        check_constraint_finite(type, (field + ".rest").c_str(), d.rest);
        check_constraint_non_negative(type, (field + ".damping").c_str(), d.damping);
        check_constraint_non_negative(type, (field + ".friction").c_str(), d.friction);
    }
}

namespace {

generic_rows current_rows(const generic_constraint_solver &s, const solver_body &a,
                          const solver_body &b) noexcept {
    generic_rows rows{};
    auto &pose = s.anchor.pose;
    auto frameA = rotate_frame(a.delta_rotation, s.frameA);
    auto frameB = rotate_frame(b.delta_rotation, s.frameB);
    // Linear: q = dot(pB - pA, e) with e turning with A, so A's lever reaches pivot B.
    for (int i = 0; i < 3; ++i) {
        auto e = frameA.column(i);
        rows.q[i] = dot(-pose.d, e);
        rows.j[i] = linear_jacobian(-e, pose.rA - pose.d, pose.rB);
    }
    // Angular: the rotation vector of frameB relative to frameA, in frameA's axes; its rate
    // about each axis is dot(e, wB - wA) to first order.
    auto rel = transpose(frameA) * frameB;
    auto q = to_quaternion(rel);
    if (q.w < 0) q = -q;
    auto v = quaternion_vector(q);
    auto sin_half = length(v);
    vector3 rotation = vector3_zero;
    if (sin_half > scalar(1e-9)) rotation = v * (2 * detail::arctan2(sin_half, q.w) / sin_half);
    rows.rotation = frameA * rotation;
    for (int i = 0; i < 3; ++i) {
        rows.q[3 + i] = rotation[i];
        rows.j[3 + i] = angular_jacobian(-frameA.column(i));
    }
    return rows;
}

} // namespace

generic_constraint_solver make_constraint_solver(const registry &registry, const generic_constraint &c,
                                                 constraint_body_indices indices) {
    generic_constraint_solver s;
    s.anchor = make_joint_anchor(registry, c.body, c.pivot, indices);
    s.frameA = world_frame(registry, c.body[0], c.frame[0]);
    s.frameB = world_frame(registry, c.body[1], c.frame[1]);
    auto all_locked = [](const generic_dof(&d)[3]) {
        return d[0].mode == dof_mode::locked && d[1].mode == dof_mode::locked &&
               d[2].mode == dof_mode::locked;
    };
    s.linear_block = all_locked(c.linear);
    s.angular_block = all_locked(c.angular);
    s.linear_block_impulse = s.linear_block ? c.linear_block_impulse : vector3_zero;
    s.angular_block_impulse = s.angular_block ? c.angular_block_impulse : vector3_zero;
    for (int i = 0; i < 6; ++i) {
        s.dof[i] = i < 3 ? c.linear[i] : c.angular[i - 3];
        bool in_block = i < 3 ? s.linear_block : s.angular_block;
        s.impulse[i] = s.dof[i].mode == dof_mode::locked && !in_block ? c.impulse[i] : 0;
        for (int k = 0; k < 2; ++k)
            s.limit_impulse[i][k] = s.dof[i].mode == dof_mode::limited ? c.limit_impulse[i][k] : 0;
        s.spring_impulse[i] = c.spring_impulse[i];
        s.friction_impulse[i] = c.friction_impulse[i];
    }
    bool limited = false;
    for (auto &d : s.dof)
        limited = limited || d.mode == dof_mode::limited;
    if (limited) {
        solver_body a, b;
        a.linvel = registry.get<linvel>(c.body[0]);
        a.angvel = registry.get<angvel>(c.body[0]);
        b.linvel = registry.get<linvel>(c.body[1]);
        b.angvel = registry.get<angvel>(c.body[1]);
        // The pose at the start of the step, which the step's first refresh measures again.
        refresh_pose(s.anchor, a, b);
        auto rows = current_rows(s, a, b);
        for (int i = 0; i < 6; ++i)
            s.start_rate[i] = row_velocity(rows.j[i], a, b);
    }
    return s;
}

namespace {

// Three locked angular degrees of freedom: the relative angular velocity wB - wA and the
// rotation are driven to zero together, with K = IA^-1 + IB^-1.
void solve_angular_block(const vector3 &rotation, vector3 &impulse, solver_body &a, solver_body &b,
                         const constraint_solve_context &ctx) noexcept {
    auto k = a.inv_inertia + b.inv_inertia;
    if (!(std::abs(determinant(k)) > scalar(1e-12))) return;
    scalar mass_scale = 1, impulse_scale = 0;
    vector3 bias = vector3_zero;
    if (ctx.use_bias) {
        bias = rotation * ctx.joint.bias_rate;
        mass_scale = ctx.joint.mass_scale;
        impulse_scale = ctx.joint.impulse_scale;
    }
    // An angular impulse L (+L to A, -L to B) changes wB - wA by -K L.
    auto delta = (inverse(k) * (b.angvel - a.angvel + bias)) * mass_scale - impulse * impulse_scale;
    impulse += delta;
    apply_angular_impulse(a, b, delta);
}

} // namespace

void refresh_geometry(generic_constraint_solver &s, std::span<const solver_body> bodies) noexcept {
    s.rows = current_rows(s, bodies[s.anchor.body[0]], bodies[s.anchor.body[1]]);
}

void warm_start(generic_constraint_solver &s, std::span<solver_body> bodies) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    auto &rows = s.rows;
    auto &pose = s.anchor.pose;
    if (s.linear_block) warm_point_mass(s.anchor, a, b, pose);
    apply_impulse(a, b, s.linear_block_impulse, pose.rA, pose.rB);
    apply_angular_impulse(a, b, s.angular_block_impulse);
    for (int i = 0; i < 6; ++i) {
        auto lambda = s.impulse[i] + s.limit_impulse[i][0] - s.limit_impulse[i][1] + s.spring_impulse[i] +
                      s.friction_impulse[i];
        apply_row_impulse(rows.j[i], a, b, lambda);
    }
}

namespace {

// The upper limit's row: the coordinate's row turned around.
jacobian reversed(const jacobian &j) noexcept { return {-j.linA, -j.angA, -j.linB, -j.angB}; }

// A limit approached faster than the restitution threshold, now and when the step began, by a
// motion that would carry the coordinate past it within the sub-step, is stopped as an isolated
// collision: its row and the locked rows iterated together from zero impulses until they agree.
// The limit row alone moves a body about its centre of mass, which the locked rows move back,
// and the approach that one pass leaves was pushed out as a rebound (0.35 rad/s out of 2 for a
// bar swung into an angular limit). A joint resting on its limit is left to the limit rows.
void stop_limit_hits(generic_constraint_solver &s, solver_body &a, solver_body &b,
                     const constraint_solve_context &ctx) noexcept {
    constexpr int iterations = 16;
    const auto &rows = s.rows;
    scalar target[6][2];
    bool hit[6][2]{};
    bool any = false;
    for (int i = 0; i < 6; ++i) {
        auto &d = s.dof[i];
        if (d.mode != dof_mode::limited) continue;
        auto rate = row_velocity(rows.j[i], a, b);
        const scalar gaps[2]{rows.q[i] - d.min, d.max - rows.q[i]};
        const scalar rates[2]{rate, -rate};
        const scalar start_rates[2]{s.start_rate[i], -s.start_rate[i]};
        for (int k = 0; k < 2; ++k) {
            if (!std::isfinite(gaps[k]) || gaps[k] + rates[k] * ctx.h > 0 ||
                std::max(rates[k], start_rates[k]) >= -ctx.restitution_threshold)
                continue;
            hit[i][k] = any = true;
            target[i][k] = -std::max(gaps[k], scalar(0)) * ctx.inv_h;
        }
    }
    if (!any) return;
    auto rigid = ctx;
    rigid.use_bias = false;
    scalar limit_impulse[6][2]{}, locked_impulse[6]{};
    vector3 point_impulse = vector3_zero, turn_impulse = vector3_zero;
    for (int n = 0; n < iterations; ++n) {
        for (int i = 0; i < 6; ++i) {
            for (int k = 0; k < 2; ++k) {
                if (!hit[i][k]) continue;
                auto j = k == 0 ? rows.j[i] : reversed(rows.j[i]);
                auto mass = row_effective_mass(j, a, b);
                auto next =
                    std::max(limit_impulse[i][k] + mass * (target[i][k] - row_velocity(j, a, b)), scalar(0));
                apply_row_impulse(j, a, b, next - limit_impulse[i][k]);
                limit_impulse[i][k] = next;
            }
        }
        for (int i = 0; i < 6; ++i) {
            if (s.dof[i].mode != dof_mode::locked) continue;
            if (i < 3 && s.linear_block) {
                if (i == 2) solve_point_block(s.anchor, point_impulse, a, b, rigid);
            } else if (i >= 3 && s.angular_block) {
                if (i == 5) solve_angular_block(rows.rotation, turn_impulse, a, b, rigid);
            } else {
                solve_equality_row(rows.j[i], rows.q[i], locked_impulse[i], a, b, rigid);
            }
        }
    }
}

} // namespace

void solve(generic_constraint_solver &s, std::span<solver_body> bodies,
           const constraint_solve_context &ctx) noexcept {
    auto &a = bodies[s.anchor.body[0]];
    auto &b = bodies[s.anchor.body[1]];
    stop_limit_hits(s, a, b, ctx);
    // The rows depend on the bodies' poses only, which solving velocities does not change.
    const auto &rows = s.rows;
    // Angular rows first, then linear: the pivots have the final word.
    for (int n = 0; n < 6; ++n) {
        auto i = (n + 3) % 6;
        auto &j = rows.j[i];
        auto q = rows.q[i];
        auto &d = s.dof[i];
        if (d.friction > 0) solve_friction_row(j, d.friction * ctx.h, s.friction_impulse[i], a, b);
        if (d.stiffness > 0 || d.damping > 0) {
            solve_spring_row(j, q - d.rest, d.stiffness, d.damping, s.spring_impulse[i], a, b, ctx);
        }
        if (d.mode == dof_mode::locked) {
            if (i < 3 && s.linear_block) {
                if (i == 2) solve_point_block(s.anchor, s.linear_block_impulse, a, b, ctx);
            } else if (i >= 3 && s.angular_block) {
                if (i == 5) solve_angular_block(rows.rotation, s.angular_block_impulse, a, b, ctx);
            } else {
                solve_equality_row(j, q, s.impulse[i], a, b, ctx);
            }
        } else if (d.mode == dof_mode::limited) {
            if (std::isfinite(d.min)) solve_limit_row(j, q - d.min, s.limit_impulse[i][0], a, b, ctx);
            if (std::isfinite(d.max)) {
                solve_limit_row(reversed(j), d.max - q, s.limit_impulse[i][1], a, b, ctx);
            }
        }
    }
}

void store_impulses(const generic_constraint_solver &s, generic_constraint &c) noexcept {
    c.linear_block_impulse = s.linear_block_impulse;
    c.angular_block_impulse = s.angular_block_impulse;
    for (int i = 0; i < 6; ++i) {
        c.impulse[i] = s.impulse[i];
        for (int k = 0; k < 2; ++k)
            c.limit_impulse[i][k] = s.limit_impulse[i][k];
        c.spring_impulse[i] = s.spring_impulse[i];
        c.friction_impulse[i] = s.friction_impulse[i];
    }
}

} // namespace edyn
