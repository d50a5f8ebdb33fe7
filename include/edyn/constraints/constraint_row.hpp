#ifndef EDYN_CONSTRAINTS_CONSTRAINT_ROW_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_ROW_HPP

#include "edyn/dynamics/solver_body.hpp"
#include "edyn/math/quaternion.hpp"
#include <type_traits>

namespace edyn {

/// How rows of joints are solved in one pass of the soft-step solver. Rigid rows are soft
/// springs in the biased pass (a stiff, well damped correction of their position error) and
/// purely rigid velocity constraints in the relax pass.
/// Made by make_constraint_solve_context() from the world's constraint_solver_settings, once per
/// pass kind, and passed to every joint's solve function.
struct constraint_solve_context {
    scalar h{0};     ///< Duration of the sub-step (s).
    scalar inv_h{0}; ///< 1 / h (1/s).
    /// Soft coefficients of the joints' rigid rows in the biased pass, from the joint frequency
    /// and damping ratio of the settings; ignored when `use_bias` is false.
    softness joint{};
    /// True in the biased pass (position errors are corrected softly), false in the relax pass
    /// (velocity constraints only).
    bool use_bias{false};
    /// Pivots are kept together by position projection after each sub-step, so their velocity
    /// rows are rigid and carry no bias: a soft pivot would sag under the load of a chain.
    bool rigid_pivots{false};
    /// The fastest the soft correction closes a joint's pivot gap, where it has one, or draws a
    /// cone's point back across its wall (m/s): constraint_solver_settings::max_correction_speed.
    scalar max_correction_speed{0};
    /// A limit reached slower than this does not bounce, so that resting limits stay quiet
    /// (m/s or rad/s, as the limit's coordinate).
    scalar restitution_threshold{0};
};

/// Current pivots: lever arms from the centres of mass and d = pivot A - pivot B.
/// Computed by current_pose() from a joint_anchor and the bodies' motion so far in the step.
struct joint_pose {
    /// @var rA
    /// Current pivot A relative to body A's centre of mass, world space (m).
    /// @var rB
    /// Current pivot B relative to body B's centre of mass, world space (m).
    /// @var d
    /// Current pivot A minus pivot B, world space (m): zero when a ball joint is satisfied.
    vector3 rA, rB, d;
};

/// A joint's pivots as seen when the step begins. Every sub-step recovers the current pivots
/// from the bodies' accumulated motion, so errors are measured exactly without the registry.
/// Made by make_joint_anchor() when the solver gathers the joints.
struct joint_anchor {
    /// Indices of the two bodies in the step's solver bodies (0: the static body).
    solver_body_index body[2]{0, 0};
    /// @var rA
    /// Pivot A relative to body A's centre of mass, world space (m), at the start of the step.
    /// @var rB
    /// Pivot B relative to body B's centre of mass, world space (m), at the start of the step.
    vector3 rA{vector3_zero}, rB{vector3_zero};
    vector3 separation{vector3_zero}; ///< Pivot A minus pivot B, world space (m).
    /// Inverse of the pivots' 3x3 effective mass K (kg) at the pose it was last measured at.
    /// K depends only on the bodies' poses and masses, so the velocity passes reuse it until the
    /// bodies move far. A joint of a path of two or more (see joint_path_set) has it measured by
    /// its path's factors after each sub-step's integration, for the relax pass and the next
    /// sub-step's warm start and biased pass; any other joint has it measured at the step's first
    /// warm start and again at a later one only once its lever arms have turned
    /// (warm_point_mass()), and its position and relax passes reuse it.
    matrix3x3 point_mass{matrix3x3_zero};
    /// Whether `point_mass` holds an inverse: false when K is singular (neither body moves).
    bool point_mass_valid{false};
    /// Whether the position projection measured `point_mass` after the last integration (see
    /// joint_path_set): the next warm start keeps it instead of measuring K again (see
    /// warm_point_mass()).
    bool point_mass_current{false};
    /// Whether the joint was left out of this step's position projection because its pivots lay
    /// farther apart than constraint_solver_settings::max_projected_gap (see
    /// gather_constraints()): its pivot rows then carry the soft position bias.
    bool unprojected{false};
    /// The pivots at the bodies' present poses, kept by refresh_pose(). Only integration and
    /// position projection move bodies, so the solver refreshes it after them and the velocity
    /// passes between (relax, the next sub-step's warm start and biased pass) all read it.
    joint_pose pose{vector3_zero, vector3_zero, vector3_zero};
};

/// The pivots of a joint now: its anchor moved and turned by each body's motion accumulated
/// since the start of the step (`delta_position`, `delta_rotation`).
/// @param j The joint's pivots at the start of the step.
/// @param a The solver body of the joint's first body.
/// @param b The solver body of the joint's second body.
/// @return The current lever arms and pivot separation.
inline joint_pose current_pose(const joint_anchor &j, const solver_body &a, const solver_body &b) noexcept {
    auto rA = rotate(a.delta_rotation, j.rA);
    auto rB = rotate(b.delta_rotation, j.rB);
    auto d = j.separation + (a.delta_position - b.delta_position) + (rA - j.rA) - (rB - j.rB);
    return {rA, rB, d};
}

/// Sets `j.pose` to current_pose(): to be called whenever the bodies have moved.
/// @param j The joint's pivots.
/// @param a The solver body of the joint's first body.
/// @param b The solver body of the joint's second body.
inline void refresh_pose(joint_anchor &j, const solver_body &a, const solver_body &b) noexcept {
    j.pose = current_pose(j, a, b);
}

/// One row of a constraint: its velocity is dot(linA, vA) + dot(angA, wA) + dot(linB, vB) +
/// dot(angB, wB), and an impulse `lambda` along the row changes the bodies' velocities by
/// M^-1 J^T lambda.
struct jacobian {
    /// @var linA
    /// Linear part for body A (dimensionless direction, world space).
    /// @var angA
    /// Angular part for body A (m for a linear row, dimensionless for an angular one).
    /// @var linB
    /// Linear part for body B (dimensionless direction, world space).
    /// @var angB
    /// Angular part for body B (m for a linear row, dimensionless for an angular one).
    vector3 linA, angA, linB, angB;
};

/// Row along the world direction n at the pivots: its velocity is the velocity of pivot A
/// relative to pivot B along n.
/// @param n Unit direction, world space.
/// @param rA Pivot A relative to body A's centre of mass, world space (m).
/// @param rB Pivot B relative to body B's centre of mass, world space (m).
/// @return The row's jacobian.
inline jacobian linear_jacobian(const vector3 &n, const vector3 &rA, const vector3 &rB) noexcept {
    return {n, cross(rA, n), -n, -cross(rB, n)};
}

/// Row about the world axis: its velocity is the angular velocity of A relative to B about it.
/// @param axis Unit axis, world space.
/// @return The row's jacobian.
inline jacobian angular_jacobian(const vector3 &axis) noexcept {
    return {vector3_zero, axis, vector3_zero, -axis};
}

/// Velocity of a row: how fast its coordinate changes with the bodies' current velocities.
/// @param j The row.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @return dot(linA, vA) + dot(angA, wA) + dot(linB, vB) + dot(angB, wB) (m/s or rad/s).
inline scalar row_velocity(const jacobian &j, const solver_body &a, const solver_body &b) noexcept {
    return dot(j.linA, a.linvel) + dot(j.angA, a.angvel) + dot(j.linB, b.linvel) + dot(j.angB, b.angvel);
}

/// Inverse of J M^-1 J^T, or zero when neither body can move along the row.
/// @param j The row.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @return The row's effective mass (kg for a linear row, kg m^2 for an angular one), or 0.
inline scalar row_effective_mass(const jacobian &j, const solver_body &a, const solver_body &b) noexcept {
    auto k = a.inv_mass * length_sqr(j.linA) + dot(j.angA, a.inv_inertia * j.angA) +
             b.inv_mass * length_sqr(j.linB) + dot(j.angB, b.inv_inertia * j.angB);
    return k > 0 ? scalar(1) / k : scalar(0);
}

/// Applies an impulse along a row: changes the bodies' velocities by M^-1 J^T lambda.
/// Bodies that do not move (the static body, kinematic bodies) are left untouched, so that
/// rows solved at once on several threads may share them.
/// @param j The row.
/// @param a Body A's solver state, changed when it moves.
/// @param b Body B's solver state, changed when it moves.
/// @param lambda The impulse along the row (N s, or N m s for an angular row).
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

/// A row that only turns the bodies: angular_jacobian(axis) without its zero linear parts, which
/// the row functions then skip, and with its effective mass measured when the row is made (the
/// bodies' inertia is the step's, so a joint measures its axes' rows once a sub-step, when it
/// refreshes its geometry). Every row function gives the same bits for it as for that jacobian
/// (the zero terms it leaves out add nothing): the hinge's and the CV joint's rows about an axis
/// are such.
struct angular_row {
    /// Axis, world space, unit or not (as angular_jacobian()'s): the row's velocity is
    /// dot(axis, wA - wB).
    vector3 axis;
    /// The row's effective mass, 1 / axis . (IA^-1 + IB^-1) axis, or 0 when neither body can
    /// turn about the axis (kg m^2 for a unit axis).
    scalar mass;
};

/// The row about -axis: its rate is the opposite, its effective mass the same (the lower and
/// upper limits of an angle push along opposite rows).
/// @param j The row.
/// @return The row about -j.axis, with j's mass.
inline angular_row operator-(const angular_row &j) noexcept { return {-j.axis, j.mass}; }

/// Makes the angular row about `axis` for bodies a and b, its effective mass measured.
/// @param axis Axis, world space, unit or not.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @return The row.
inline angular_row make_angular_row(const vector3 &axis, const solver_body &a,
                                    const solver_body &b) noexcept {
    auto k = dot(axis, a.inv_inertia * axis) + dot(axis, b.inv_inertia * axis);
    return {axis, k > 0 ? scalar(1) / k : scalar(0)};
}

/// Velocity of an angular row: dot(axis, wA) - dot(axis, wB) (rad/s for a unit axis).
/// @param j The row.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @return The rate of the row's angle.
inline scalar row_velocity(const angular_row &j, const solver_body &a, const solver_body &b) noexcept {
    return dot(j.axis, a.angvel) - dot(j.axis, b.angvel);
}

/// The effective mass an angular row was made with (see make_angular_row()).
/// @param j The row.
/// @return `j.mass`.
inline scalar row_effective_mass(const angular_row &j, const solver_body &, const solver_body &) noexcept {
    return j.mass;
}

/// Applies an angular impulse `lambda` about the row's axis: +lambda to A, -lambda to B.
/// Bodies that do not move are left untouched, as apply_row_impulse() for a jacobian leaves them.
/// @param j The row.
/// @param a Body A's solver state, changed when it moves.
/// @param b Body B's solver state, changed when it moves.
/// @param lambda The impulse about the axis (N m s).
inline void apply_row_impulse(const angular_row &j, solver_body &a, solver_body &b, scalar lambda) noexcept {
    apply_angular_impulse(a, b, j.axis * lambda);
}

/// The rows that the row solvers below take: a full jacobian or an angular row.
template<typename Row>
concept constraint_row = std::is_same_v<Row, jacobian> || std::is_same_v<Row, angular_row>;

/// Soft coefficients of an implicit spring of stiffness k and damping c acting on a row of
/// effective mass `mass` over the sub-step h (the rigid softness formula expressed in physical
/// units, so that the spring's frequency is sqrt(k / mass) whatever the sub-step).
/// @param k Stiffness (N/m, or N m/rad for an angular row).
/// @param c Damping (N s/m, or N m s/rad for an angular row).
/// @param mass The row's effective mass (kg, or kg m^2).
/// @param h The sub-step (s).
/// @return The coefficients; when c + h k or `mass` is not positive, zero bias rate and mass
/// scale with an impulse scale of 1, so that the row only takes back its accumulated impulse.
softness make_spring_softness(scalar k, scalar c, scalar mass, scalar h) noexcept;

/// Bilateral row keeping C at zero: soft in the biased pass, rigid in the relax pass.
/// Does nothing when the row's effective mass is zero.
/// @param j The row.
/// @param C The row's position error now (m or rad).
/// @param impulse The row's impulse accumulated over the sub-step (N s or N m s), updated.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param ctx The pass: sub-step, softness and whether to correct position errors.
template<constraint_row Row>
void solve_equality_row(const Row &j, scalar C, scalar &impulse, solver_body &a, solver_body &b,
                        const constraint_solve_context &ctx) noexcept;

/// Unilateral row keeping C >= 0 (impulse >= 0). A gap (C > 0) may close within the sub-step
/// but no further.
/// Does nothing when the row's effective mass is zero.
/// @param j The row.
/// @param C The row's gap now (m or rad): positive apart, negative past the limit.
/// @param impulse The row's impulse accumulated over the sub-step, kept non-negative, updated.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param ctx The pass: sub-step, softness and whether to correct position errors.
/// @param max_correction The fastest the soft correction of a negative C may drive the row (in
/// the row's units, m/s or rad/s); unbounded by default.
template<constraint_row Row>
void solve_limit_row(const Row &j, scalar C, scalar &impulse, solver_body &a, solver_body &b,
                     const constraint_solve_context &ctx, scalar max_correction = large_scalar) noexcept;

/// Row driving its velocity to zero with an impulse bounded by max_impulse per sub-step.
/// Does nothing when the row's effective mass is zero.
/// @param j The row.
/// @param max_impulse Bound on the accumulated impulse's magnitude, usually a friction force or
/// torque times the sub-step (N s or N m s).
/// @param impulse The row's impulse accumulated over the sub-step, kept in
/// [-max_impulse, max_impulse], updated.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
template<constraint_row Row>
void solve_friction_row(const Row &j, scalar max_impulse, scalar &impulse, solver_body &a,
                        solver_body &b) noexcept;

/// Spring and damper pulling C towards zero with stiffness k and damping c; solved in every
/// biased pass only, as the spring is a force of the model, not an error correction. With `unilateral` the
/// spring only pushes (impulse >= 0), as a bump stop does.
/// Does nothing in the relax pass or when the row's effective mass is zero.
/// @param j The row.
/// @param C The spring's extension now (m or rad).
/// @param k Stiffness (N/m or N m/rad).
/// @param c Damping (N s/m or N m s/rad).
/// @param impulse The row's impulse accumulated over the sub-step (N s or N m s), updated.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param ctx The pass: its sub-step sets the spring's softness; `use_bias` must be true.
/// @param unilateral Whether the spring may only push.
template<constraint_row Row>
void solve_spring_row(const Row &j, scalar C, scalar k, scalar c, scalar &impulse, solver_body &a,
                      solver_body &b, const constraint_solve_context &ctx, bool unilateral = false) noexcept;

/// Position projection, after the sub-step's positions are integrated: moves the bodies so that
/// the pivots meet again. Velocity-level rows cannot see the second order drift of fast-turning
/// links (L (w h)^2 / 2 per sub-step), which this removes. `fraction` of the error is removed.
/// The bodies' velocities change by the correction over the sub-step (inv_h = 1 / h), as if they
/// had moved there: the velocity that pulled the pivots apart is taken back with it. Moving the
/// bodies alone would leave that velocity in them, unseen by the rigid pivot rows (their error
/// is gone), to pull the pivots apart again every sub-step: joints the solver cannot hold (a
/// taut bridge deck under a heavy box) then keep a hidden motion that nothing damps, and the
/// corrections push it into what rests on them (the box kept the deck bouncing for minutes).
/// Does nothing when the pivots' 3x3 effective mass cannot be inverted (neither body moves).
/// @param anchor The joint's pivots at the start of the step.
/// @param a Body A's solver state: its `delta_position`, `delta_rotation` and velocities change.
/// @param b Body B's solver state: its `delta_position`, `delta_rotation` and velocities change.
/// @param fraction Share of the separation removed, in [0, 1].
/// @param inv_h 1 / h of the sub-step just integrated (1/s).
/// Uses `anchor.point_mass` from the warm start (warm_point_mass()), out of date by the motion since,
/// unless the pivots are more than 1 cm apart (large corrections turn the bodies too much):
/// recomputing it after the integration made the worst error of a swinging 100-link chain no
/// smaller (9.1 mm against 8.7 mm) and cost a tenth of the chain's step.
void project_point(joint_anchor &anchor, solver_body &a, solver_body &b, scalar fraction,
                   scalar inv_h) noexcept;

/// Moves a body by `dv` and turns it by `dw` in its `delta_position` and `delta_rotation`, and
/// changes its velocities by that motion over the sub-step; a body that does not move is left.
/// @param body The body's solver state.
/// @param dv Its displacement (m, world space).
/// @param dw Its turn, as a rotation vector (rad, world space).
/// @param inv_h 1 / h of the sub-step just integrated (1/s).
void move_body(solver_body &body, const vector3 &dv, const vector3 &dw, scalar inv_h) noexcept;

/// Moves the bodies by a position-level impulse: +p on A at the lever arm rA, -p on B at rB, as
/// an impulse p would change their velocities, applied to their `delta_position` and
/// `delta_rotation` instead; their velocities change by that motion over the sub-step (see
/// project_point()). Bodies that do not move are not written.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param p The position-level impulse on A (kg m, world space).
/// @param rA Lever arm on A, from its centre of mass, world space (m).
/// @param rB Lever arm on B, from its centre of mass, world space (m).
/// @param inv_h 1 / h of the sub-step just integrated (1/s).
void apply_position_impulse(solver_body &a, solver_body &b, const vector3 &p, const vector3 &rA,
                            const vector3 &rB, scalar inv_h) noexcept;

/// The pivots' effective mass matrix K = (1/mA + 1/mB) I - [rA] IA^-1 [rA] - [rB] IB^-1 [rB]:
/// how the pivot separation changes under a position-level impulse at the pivots.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param pose The current pose, from current_pose().
/// @return K, symmetric.
matrix3x3 point_mass_matrix(const solver_body &a, const solver_body &b, const joint_pose &pose) noexcept;

/// Squared pivot separation (m²) beyond which a joint's reused effective mass is recomputed:
/// past a centimetre, corrections turn the bodies enough to make it diverge.
inline constexpr scalar large_point_separation_sqr = scalar(1e-4);

/// How far either lever arm of a joint may move, as a fraction of its length, from where it was
/// when the step began, before the warm start measures the pivots' effective mass again: about
/// half a degree of turning (see warm_point_mass()). With 5 %, a 1 m pendulum swinging down from
/// horizontal opened by up to 0.41 mm over 2 s instead of less than 0.01 mm.
inline constexpr scalar max_point_mass_turn = scalar(0.01);

/// The inverse of the pivots' effective mass matrix
/// K = (1/mA + 1/mB) I - [rA] IA^-1 [rA] - [rB] IB^-1 [rB] at the pose `pose`.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param pose The current pose, from current_pose().
/// @param inverse_k Receives the inverse of K, or zero when K is singular.
/// @return False when K is singular (neither body moves).
bool inverse_point_mass(const solver_body &a, const solver_body &b, const joint_pose &pose,
                        matrix3x3 &inverse_k) noexcept;

/// Computes `anchor.point_mass`, the inverse of the pivots' effective mass matrix
/// K = (1/mA + 1/mB) I - [rA] IA^-1 [rA] - [rB] IB^-1 [rB], for the pose `pose` of the bodies.
/// @param anchor The joint's pivots; its `point_mass` and `point_mass_valid` are written.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param pose The current pose, from current_pose().
void update_point_mass(joint_anchor &anchor, const solver_body &a, const solver_body &b,
                       const joint_pose &pose) noexcept;

/// The warm start's update_point_mass(), done only where K is out of date: K depends on the
/// bodies' masses, their inertia (fixed for the step) and the lever arms, so a K measured earlier
/// in the step is kept while neither arm has moved by more than max_point_mass_turn of its length
/// since the step began. Skipped too when the position projection measured K after the
/// integration just before (`anchor.point_mass_current`), at poses that the projection's
/// corrections have moved by micrometres since. (Measured at every sub-step's warm start
/// instead, 300 steps of edyn-bench's 64 rag dolls ran 13.96 G instructions against 13.58 G, for
/// the same worst joint error.)
/// @param anchor The joint's pivots; its `point_mass`, `point_mass_valid` and
/// `point_mass_current` are written.
/// @param a Body A's solver state.
/// @param b Body B's solver state.
/// @param pose The current pose, from current_pose().
void warm_point_mass(joint_anchor &anchor, const solver_body &a, const solver_body &b,
                     const joint_pose &pose) noexcept;
/// The same along the pivots' direction only, to bring them `distance` apart.
/// Position projection of the distance joint; does nothing when the pivots coincide.
/// @param anchor The joint's pivots at the start of the step.
/// @param distance The length to restore between the pivots (m).
/// @param a Body A's solver state: its `delta_position`, `delta_rotation` and velocities change.
/// @param b Body B's solver state: its `delta_position`, `delta_rotation` and velocities change.
/// @param fraction Share of the length error removed, in [0, 1].
/// @param inv_h 1 / h of the sub-step just integrated (1/s).
void project_distance(const joint_anchor &anchor, scalar distance, solver_body &a, solver_body &b,
                      scalar fraction, scalar inv_h) noexcept;

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_ROW_HPP
