#ifndef EDYN_CONSTRAINTS_CONSTRAINT_ROW_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_ROW_HPP

#include "edyn/dynamics/solver_body.hpp"
#include "edyn/math/quaternion.hpp"

namespace edyn {

// How rows of joints are solved in one pass of the soft-step solver. Rigid rows are soft
// springs in the biased pass (a stiff, well damped correction of their position error) and
// purely rigid velocity constraints in the relax pass.
struct constraint_solve_context {
    scalar h{0};     // sub-step
    scalar inv_h{0}; // 1 / h
    softness joint{};
    bool use_bias{false};
    // Pivots are kept together by position projection after each sub-step, so their velocity
    // rows are rigid and carry no bias: a soft pivot would sag under the load of a chain.
    bool rigid_pivots{false};
    // A limit reached slower than this does not bounce, so that resting limits stay quiet.
    scalar restitution_threshold{0};
};

// A joint's pivots as seen when the step begins. Every sub-step recovers the current pivots
// from the bodies' accumulated motion, so errors are measured exactly without the registry.
struct joint_anchor {
    solver_body_index body[2]{0, 0};
    vector3 rA{vector3_zero}, rB{vector3_zero}; // pivots relative to each centre of mass, world
    vector3 separation{vector3_zero};           // pivot A minus pivot B, world
};

// Current pivots: lever arms from the centres of mass and d = pivot A - pivot B.
struct joint_pose {
    vector3 rA, rB, d;
};

inline joint_pose current_pose(const joint_anchor &j, const solver_body &a, const solver_body &b) noexcept {
    auto rA = rotate(a.delta_rotation, j.rA);
    auto rB = rotate(b.delta_rotation, j.rB);
    auto d = j.separation + (a.delta_position - b.delta_position) + (rA - j.rA) - (rB - j.rB);
    return {rA, rB, d};
}

// One row of a constraint: its velocity is dot(linA, vA) + dot(angA, wA) + dot(linB, vB) +
// dot(angB, wB), and an impulse `lambda` along the row changes the bodies' velocities by
// M^-1 J^T lambda.
struct jacobian {
    vector3 linA, angA, linB, angB;
};

// Row along the world direction n at the pivots: its velocity is the velocity of pivot A
// relative to pivot B along n.
inline jacobian linear_jacobian(const vector3 &n, const vector3 &rA, const vector3 &rB) noexcept {
    return {n, cross(rA, n), -n, -cross(rB, n)};
}

// Row about the world axis: its velocity is the angular velocity of A relative to B about it.
inline jacobian angular_jacobian(const vector3 &axis) noexcept {
    return {vector3_zero, axis, vector3_zero, -axis};
}

inline scalar row_velocity(const jacobian &j, const solver_body &a, const solver_body &b) noexcept {
    return dot(j.linA, a.linvel) + dot(j.angA, a.angvel) + dot(j.linB, b.linvel) + dot(j.angB, b.angvel);
}

// Inverse of J M^-1 J^T, or zero when neither body can move along the row.
inline scalar row_effective_mass(const jacobian &j, const solver_body &a, const solver_body &b) noexcept {
    auto k = a.inv_mass * length_sqr(j.linA) + dot(j.angA, a.inv_inertia * j.angA) +
             b.inv_mass * length_sqr(j.linB) + dot(j.angB, b.inv_inertia * j.angB);
    return k > 0 ? scalar(1) / k : scalar(0);
}

inline void apply_row_impulse(const jacobian &j, solver_body &a, solver_body &b, scalar lambda) noexcept {
    if (moves(a)) {
        a.linvel += j.linA * (a.inv_mass * lambda);
        a.angvel += a.inv_inertia * (j.angA * lambda);
    }
    if (moves(b)) {
        b.linvel += j.linB * (b.inv_mass * lambda);
        b.angvel += b.inv_inertia * (j.angB * lambda);
    }
}

// Soft coefficients of an implicit spring of stiffness k and damping c acting on a row of
// effective mass `mass` over the sub-step h (the rigid softness formula expressed in physical
// units, so that the spring's frequency is sqrt(k / mass) whatever the sub-step).
softness make_spring_softness(scalar k, scalar c, scalar mass, scalar h) noexcept;

// Bilateral row keeping C at zero: soft in the biased pass, rigid in the relax pass.
void solve_equality_row(const jacobian &j, scalar C, scalar &impulse, solver_body &a, solver_body &b,
                        const constraint_solve_context &ctx) noexcept;

// Unilateral row keeping C >= 0 (impulse >= 0). A gap (C > 0) may close within the sub-step
// but no further. `bounce_velocity`, when positive, is the separating velocity the row must
// reach (restitution); it replaces the soft correction.
void solve_limit_row(const jacobian &j, scalar C, scalar &impulse, solver_body &a, solver_body &b,
                     const constraint_solve_context &ctx, scalar bounce_velocity = 0) noexcept;

// Row driving its velocity to zero with an impulse bounded by max_impulse per sub-step.
void solve_friction_row(const jacobian &j, scalar max_impulse, scalar &impulse, solver_body &a,
                        solver_body &b) noexcept;

// Spring and damper pulling C towards zero with stiffness k and damping c; solved in every
// biased pass only, as the spring is a force of the model, not an error correction. With `unilateral` the
// spring only pushes (impulse >= 0), as a bump stop does.
void solve_spring_row(const jacobian &j, scalar C, scalar k, scalar c, scalar &impulse, solver_body &a,
                      solver_body &b, const constraint_solve_context &ctx, bool unilateral = false) noexcept;

// Position projection, after the sub-step's positions are integrated: moves the bodies so that
// the pivots meet again. Velocity-level rows cannot see the second order drift of fast-turning
// links (L (w h)^2 / 2 per sub-step), which this removes. `fraction` of the error is removed.
// The bodies' velocities change by the correction over the sub-step (inv_h = 1 / h), as if they
// had moved there: the velocity that pulled the pivots apart is taken back with it. Moving the
// bodies alone would leave that velocity in them, unseen by the rigid pivot rows (their error
// is gone), to pull the pivots apart again every sub-step: joints the solver cannot hold (a
// taut bridge deck under a heavy box) then keep a hidden motion that nothing damps, and the
// corrections push it into what rests on them (the box kept the deck bouncing for minutes).
void project_point(const joint_anchor &anchor, solver_body &a, solver_body &b, scalar fraction,
                   scalar inv_h) noexcept;
// The same along the pivots' direction only, to bring them `distance` apart.
void project_distance(const joint_anchor &anchor, scalar distance, solver_body &a, solver_body &b,
                      scalar fraction, scalar inv_h) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_ROW_HPP
