#ifndef EDYN_DYNAMICS_SOLVER_BODY_HPP
#define EDYN_DYNAMICS_SOLVER_BODY_HPP

#include "edyn/math/matrix3x3.hpp"
#include <cstdint>

namespace edyn {

/// A body's state while the solver runs.
/// Gathered from the registry once per step into a contiguous array (gather_bodies), solved,
/// then written back (write_back). Constraints refer to bodies by index. Index 0 is reserved
/// for a body that never moves, shared by every static body. Engine-internal: programs read the
/// registry's components instead.
/// Aligned to a cache line, so that threads solving different bodies never write to one line
/// (unaligned, two threads' bodies of one colour shared lines, and the body array's traffic
/// between the cores took the 4,096-body pile's two-thread speed-up from about 1.6 to 1.1).
struct alignas(64) solver_body {
    vector3 linvel{vector3_zero}; ///< Linear velocity of the centre of mass, world space, m/s.
    vector3 angvel{vector3_zero}; ///< Angular velocity, world space, rad/s.
    /// Translation accumulated since the start of the step, world space, in metres, so that
    /// constraints can measure their current error without touching the registry.
    vector3 delta_position{vector3_zero};
    /// World-space rotation accumulated since the start of the step, a unit quaternion
    /// (x y z w): the body's orientation is now `delta_rotation * orientation`.
    quaternion delta_rotation{quaternion_identity};
    /// Inverse mass, 1/kg; 0 for the static body and kinematic bodies.
    scalar inv_mass{0};
    matrix3x3 inv_inertia{matrix3x3_zero}; ///< Inverse inertia, world space, fixed for the step, 1/(kg·m²).
    /// Acceleration applied in each sub-step (gravity), m/s²; zero for static and kinematic
    /// bodies.
    vector3 acceleration{vector3_zero};
};

/// Index of a body in the solver's body array (world_state::bodies).
using solver_body_index = std::uint32_t;
/// The index of the shared body that stands for every static body (and any body that is not
/// being solved); it never moves.
inline constexpr solver_body_index static_solver_body = 0;

/// Soft constraint coefficients for a spring of frequency `hertz` and damping ratio `zeta`
/// solved with time step `h`.
/// The constraint behaves like a damped spring instead of a rigid correction, which keeps
/// stacks quiet at low iteration counts. A solver computes each impulse as
/// `-effective_mass * mass_scale * (velocity + bias_rate * error) - impulse_scale * accumulated`.
/// Made by make_softness.
struct softness {
    /// Bias velocity per unit of position error, in 1/s; 0 for no position correction.
    scalar bias_rate{0};
    /// Fraction of the rigid effective mass applied, in [0, 1]; 1 for a rigid row.
    scalar mass_scale{1};
    /// Fraction of the accumulated impulse taken off each iteration, in [0, 1]; 0 for a rigid
    /// row.
    scalar impulse_scale{0};
};

/// Computes the soft constraint coefficients of a damped spring.
/// Implicit integration of the spring over one sub-step, expressed as a bias velocity and a
/// mix of the rigid and the accumulated impulse.
/// @param hertz Spring frequency, in Hz; 0 or less gives a rigid row with no position bias
/// (`{0, 1, 0}`).
/// @param zeta Damping ratio (1 is critical damping).
/// @param h Time step the constraint is solved with (the sub-step), in seconds.
/// @return The coefficients.
softness make_softness(scalar hertz, scalar zeta, scalar h) noexcept;

/// Whether impulses move the body.
/// True for dynamic bodies; false for the static body and kinematic bodies (zero inverse mass
/// and inertia), which the solver never writes, so that constraints solved at once on several
/// threads may share them.
/// @param body The solver body.
/// @return Whether it has a non-zero inverse mass or inverse inertia.
inline bool moves(const solver_body &body) noexcept {
    return body.inv_mass > 0 || body.inv_inertia != matrix3x3_zero;
}

/// Applies the impulse `p` at the offsets `rA`, `rB` (from each centre of mass): +p to A, -p to B.
/// Bodies that do not move (see moves) are not written.
/// @param a First body.
/// @param b Second body.
/// @param p The impulse, world space, in N·s.
/// @param rA Point of application on A, from A's centre of mass, world space, in metres.
/// @param rB Point of application on B, from B's centre of mass, world space, in metres.
inline void apply_impulse(solver_body &a, solver_body &b, const vector3 &p, const vector3 &rA,
                          const vector3 &rB) noexcept {
    if (moves(a)) {
        a.linvel += p * a.inv_mass;
        a.angvel += a.inv_inertia * cross(rA, p);
    }
    if (moves(b)) {
        b.linvel -= p * b.inv_mass;
        b.angvel -= b.inv_inertia * cross(rB, p);
    }
}

/// Applies the angular impulse `l`: +l to A, -l to B.
/// Bodies that do not move (see moves) are not written.
/// @param a First body.
/// @param b Second body.
/// @param l The angular impulse, world space, in N·m·s.
inline void apply_angular_impulse(solver_body &a, solver_body &b, const vector3 &l) noexcept {
    if (moves(a)) a.angvel += a.inv_inertia * l;
    if (moves(b)) b.angvel -= b.inv_inertia * l;
}

/// Velocity of A's point at `rA` relative to B's point at `rB`.
/// @param a First body.
/// @param b Second body.
/// @param rA The point on A, from A's centre of mass, world space, in metres.
/// @param rB The point on B, from B's centre of mass, world space, in metres.
/// @return The relative velocity, world space, in m/s.
inline vector3 relative_velocity(const solver_body &a, const solver_body &b, const vector3 &rA,
                                 const vector3 &rB) noexcept {
    return a.linvel + cross(a.angvel, rA) - b.linvel - cross(b.angvel, rB);
}

/// Effective mass of an angular row about the unit axis `d`.
/// @param a First body.
/// @param b Second body.
/// @param d Unit axis of the row, world space.
/// @return The effective moment of inertia, in kg·m²; 0 when neither body can turn about `d`.
inline scalar effective_angular_mass(const solver_body &a, const solver_body &b, const vector3 &d) noexcept {
    auto k = dot(d, a.inv_inertia * d) + dot(d, b.inv_inertia * d);
    return k > 0 ? scalar(1) / k : scalar(0);
}

} // namespace edyn

#endif // EDYN_DYNAMICS_SOLVER_BODY_HPP
