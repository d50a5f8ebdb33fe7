#include "edyn/constraints/constraint_row.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

softness make_spring_softness(scalar k, scalar c, scalar mass, scalar h) noexcept {
    // Implicit Euler of m x'' = -k x - c x': the impulse over h is
    // -(h d / (1 + h d / m)) (x' + (k / d) x) with d = c + h k.
    auto d = c + h * k;
    if (!(d > 0) || !(mass > 0)) return {0, 0, 1};
    auto a = h * d / mass;
    return {k / d, a / (1 + a), 1 / (1 + a)};
}

template<constraint_row Row>
void solve_equality_row(const Row &j, scalar C, scalar &impulse, solver_body &a, solver_body &b,
                        const constraint_solve_context &ctx) noexcept {
    auto mass = row_effective_mass(j, a, b);
    if (mass == 0) return;
    scalar bias = 0, mass_scale = 1, impulse_scale = 0;
    if (ctx.use_bias) {
        bias = ctx.joint.bias_rate * C;
        mass_scale = ctx.joint.mass_scale;
        impulse_scale = ctx.joint.impulse_scale;
    }
    auto v = row_velocity(j, a, b);
    auto delta = -mass * mass_scale * (v + bias) - impulse_scale * impulse;
    impulse += delta;
    apply_row_impulse(j, a, b, delta);
}

template<constraint_row Row>
void solve_limit_row(const Row &j, scalar C, scalar &impulse, solver_body &a, solver_body &b,
                     const constraint_solve_context &ctx, scalar max_correction) noexcept {
    // An open limit holding no impulse, which the motion does not close within the sub-step,
    // has nothing to do (the common case, far from the limit): its effective mass is not needed.
    if (C > 0 && impulse == 0 && row_velocity(j, a, b) + C * ctx.inv_h >= 0) return;
    auto mass = row_effective_mass(j, a, b);
    if (mass == 0) return;
    scalar bias = 0, mass_scale = 1, impulse_scale = 0;
    if (C > 0) {
        // Speculative: the gap may close within this sub-step, no more.
        bias = C * ctx.inv_h;
    } else if (ctx.use_bias) {
        bias = std::max(ctx.joint.bias_rate * C, -max_correction);
        mass_scale = ctx.joint.mass_scale;
        impulse_scale = ctx.joint.impulse_scale;
    }
    auto v = row_velocity(j, a, b);
    auto delta = -mass * mass_scale * (v + bias) - impulse_scale * impulse;
    auto new_impulse = std::max(impulse + delta, scalar(0));
    delta = new_impulse - impulse;
    impulse = new_impulse;
    apply_row_impulse(j, a, b, delta);
}

template<constraint_row Row>
void solve_friction_row(const Row &j, scalar max_impulse, scalar &impulse, solver_body &a,
                        solver_body &b) noexcept {
    auto mass = row_effective_mass(j, a, b);
    if (mass == 0) return;
    auto v = row_velocity(j, a, b);
    auto new_impulse = std::clamp(impulse - mass * v, -max_impulse, max_impulse);
    auto delta = new_impulse - impulse;
    impulse = new_impulse;
    apply_row_impulse(j, a, b, delta);
}

template<constraint_row Row>
void solve_spring_row(const Row &j, scalar C, scalar k, scalar c, scalar &impulse, solver_body &a,
                      solver_body &b, const constraint_solve_context &ctx, bool unilateral) noexcept {
    // A spring is a force of the model: applied once per sub-step, in the biased pass. Solving
    // it again in the relax pass would integrate it twice and damp it.
    if (!ctx.use_bias) return;
    auto mass = row_effective_mass(j, a, b);
    if (mass == 0) return;
    auto soft = make_spring_softness(k, c, mass, ctx.h);
    auto v = row_velocity(j, a, b);
    auto delta = -mass * soft.mass_scale * (v + soft.bias_rate * C) - soft.impulse_scale * impulse;
    auto new_impulse = unilateral ? std::max(impulse + delta, scalar(0)) : impulse + delta;
    delta = new_impulse - impulse;
    impulse = new_impulse;
    apply_row_impulse(j, a, b, delta);
}

// The rows the joints use: full jacobians and angular rows.
#define EDYN_INSTANTIATE_ROW_SOLVERS(Row)                                                                    \
    template void solve_equality_row(const Row &, scalar, scalar &, solver_body &, solver_body &,            \
                                     const constraint_solve_context &) noexcept;                             \
    template void solve_limit_row(const Row &, scalar, scalar &, solver_body &, solver_body &,               \
                                  const constraint_solve_context &, scalar) noexcept;                        \
    template void solve_friction_row(const Row &, scalar, scalar &, solver_body &, solver_body &) noexcept;  \
    template void solve_spring_row(const Row &, scalar, scalar, scalar, scalar &, solver_body &,             \
                                   solver_body &, const constraint_solve_context &, bool) noexcept;
EDYN_INSTANTIATE_ROW_SOLVERS(jacobian)
EDYN_INSTANTIATE_ROW_SOLVERS(angular_row)
#undef EDYN_INSTANTIATE_ROW_SOLVERS

namespace {

// Pivots within a tenth of a micrometre, the rounding of a float position a metre from the
// origin, are left as they are: a resting joint needs no correction.
constexpr scalar projection_tolerance_sqr = scalar(1e-14);

// The orientation q turned by the small rotation vector dw (radians): the first-order update
// q + (dw, 0) q / 2, normalised, which is the exact rotation to within |dw|^3 / 12 rad. Position
// corrections turn bodies by a fraction of a joint's error over its lever arm, well under
// 0.1 rad; larger turns take the exact exponential.
quaternion turn(const quaternion &q, const vector3 &dw) noexcept {
    if (length_sqr(dw) > scalar(0.01)) return integrate(q, dw, 1);
    auto dq = quaternion{dw.x, dw.y, dw.z, 0} * q;
    auto r = quaternion{q.x + scalar(0.5) * dq.x, q.y + scalar(0.5) * dq.y, q.z + scalar(0.5) * dq.z,
                        q.w + scalar(0.5) * dq.w};
    // Within 2^-12 of unit length, one Newton step from 1 gives 1 / sqrt(n) to within
    // 3/8 (n - 1)^2 < 2^-25, finer than the scalar's rounding, without a square root.
    auto n = length_sqr(r);
    if (std::abs(n - 1) < scalar(1) / 4096) return r * ((3 - n) * scalar(0.5));
    return normalize(r);
}

// -[r] I [r] for a symmetric I: entry (i, j) is (e_i x r) . I (e_j x r), symmetric, built from
// the rows of [r] without a full matrix product.
matrix3x3 lever_inertia(const vector3 &r, const matrix3x3 &inv_inertia) noexcept {
    const vector3 s[3]{{0, -r.z, r.y}, {r.z, 0, -r.x}, {-r.y, r.x, 0}};
    const vector3 u[3]{inv_inertia * s[0], inv_inertia * s[1], inv_inertia * s[2]};
    auto k00 = dot(s[0], u[0]), k01 = dot(s[0], u[1]), k02 = dot(s[0], u[2]);
    auto k11 = dot(s[1], u[1]), k12 = dot(s[1], u[2]), k22 = dot(s[2], u[2]);
    return {{{k00, k01, k02}, {k01, k11, k12}, {k02, k12, k22}}};
}

} // namespace

void move_body(solver_body &body, const vector3 &dv, const vector3 &dw, scalar inv_h) noexcept {
    if (!moves(body)) return;
    body.delta_position += dv;
    body.delta_rotation = turn(body.delta_rotation, dw);
    body.linvel += dv * inv_h;
    body.angvel += dw * inv_h;
}

void apply_position_impulse(solver_body &a, solver_body &b, const vector3 &p, const vector3 &rA,
                            const vector3 &rB, scalar inv_h) noexcept {
    move_body(a, p * a.inv_mass, a.inv_inertia * cross(rA, p), inv_h);
    move_body(b, -p * b.inv_mass, b.inv_inertia * cross(rB, -p), inv_h);
}

matrix3x3 point_mass_matrix(const solver_body &a, const solver_body &b, const joint_pose &pose) noexcept {
    return diagonal_matrix(vector3_one * (a.inv_mass + b.inv_mass)) + lever_inertia(pose.rA, a.inv_inertia) +
           lever_inertia(pose.rB, b.inv_inertia);
}

namespace {

bool invert_point_mass(const matrix3x3 &k, matrix3x3 &inverse_k) noexcept {
    // The inverse from the cofactors, whose first dot product is the determinant.
    auto c0 = cross(k[1], k[2]), c1 = cross(k[2], k[0]), c2 = cross(k[0], k[1]);
    auto det = dot(k[0], c0);
    bool valid = std::abs(det) > scalar(1e-12);
    inverse_k = valid ? matrix3x3_columns(c0, c1, c2) * (scalar(1) / det) : matrix3x3_zero;
    return valid;
}

} // namespace

bool inverse_point_mass(const solver_body &a, const solver_body &b, const joint_pose &pose,
                        matrix3x3 &inverse_k) noexcept {
    return invert_point_mass(point_mass_matrix(a, b, pose), inverse_k);
}

void update_point_mass(joint_anchor &anchor, const solver_body &a, const solver_body &b,
                       const joint_pose &pose) noexcept {
    anchor.point_mass_valid = inverse_point_mass(a, b, pose, anchor.point_mass);
}

namespace {

// Whether K no longer fits the pivots: it was never measured (or is singular), or either lever arm
// has turned by more than max_point_mass_turn of its length since the step began. The inertia is
// fixed for the step, so K changes only with the lever arms.
bool point_mass_stale(const joint_anchor &anchor, const joint_pose &pose) noexcept {
    if (!anchor.point_mass_valid) return true;
    constexpr auto turn_sqr = max_point_mass_turn * max_point_mass_turn;
    return length_sqr(pose.rA - anchor.rA) > turn_sqr * length_sqr(anchor.rA) ||
           length_sqr(pose.rB - anchor.rB) > turn_sqr * length_sqr(anchor.rB);
}

} // namespace

void warm_point_mass(joint_anchor &anchor, const solver_body &a, const solver_body &b,
                     const joint_pose &pose) noexcept {
    if (!anchor.point_mass_current && point_mass_stale(anchor, pose)) update_point_mass(anchor, a, b, pose);
    anchor.point_mass_current = false;
}

void project_point(joint_anchor &anchor, solver_body &a, solver_body &b, scalar fraction,
                   scalar inv_h) noexcept {
    auto pose = current_pose(anchor, a, b);
    // A separation past a centimetre means large corrections, which turn the bodies enough to
    // make the reused mass diverge: it is recomputed for such a joint.
    auto separation_sqr = length_sqr(pose.d);
    if (separation_sqr > large_point_separation_sqr) update_point_mass(anchor, a, b, pose);
    if (!anchor.point_mass_valid || separation_sqr <= projection_tolerance_sqr) return;
    apply_position_impulse(a, b, -(anchor.point_mass * pose.d) * fraction, pose.rA, pose.rB, inv_h);
}

void project_distance(const joint_anchor &anchor, scalar distance, solver_body &a, solver_body &b,
                      scalar fraction, scalar inv_h) noexcept {
    auto pose = current_pose(anchor, a, b);
    auto len = length(pose.d);
    if (!(len > scalar(1e-9))) return;
    auto n = pose.d / len;
    auto mass = row_effective_mass(linear_jacobian(n, pose.rA, pose.rB), a, b);
    apply_position_impulse(a, b, n * (-mass * (len - distance) * fraction), pose.rA, pose.rB, inv_h);
}

} // namespace edyn
