#ifndef EDYN_DYNAMICS_SOLVER_BODY_HPP
#define EDYN_DYNAMICS_SOLVER_BODY_HPP

#include "edyn/math/matrix3x3.hpp"
#include <cstdint>

namespace edyn {

// A body's state while the solver runs: gathered from the registry once per step into a
// contiguous array, solved, then written back. Constraints refer to bodies by index. Index 0
// is reserved for a body that never moves, shared by every static body.
struct solver_body {
    vector3 linvel{vector3_zero};
    vector3 angvel{vector3_zero};
    // Motion accumulated since the start of the step, so constraints can measure their
    // current error without touching the registry.
    vector3 delta_position{vector3_zero};
    quaternion delta_rotation{quaternion_identity};
    scalar inv_mass{0};
    matrix3x3 inv_inertia{matrix3x3_zero}; // world space, fixed for the step
    // Acceleration applied in each sub-step (gravity), zero for static and kinematic bodies.
    vector3 acceleration{vector3_zero};
};

using solver_body_index = std::uint32_t;
inline constexpr solver_body_index static_solver_body = 0;

// Soft constraint coefficients for a spring of frequency `hertz` and damping ratio `zeta`
// solved with time step h: the constraint behaves like a damped spring instead of a rigid
// correction, which keeps stacks quiet at low iteration counts.
struct softness {
    scalar bias_rate{0};
    scalar mass_scale{1};
    scalar impulse_scale{0};
};

softness make_softness(scalar hertz, scalar zeta, scalar h) noexcept;

// Whether impulses move the body: dynamic bodies; not the static body nor kinematic bodies
// (zero inverse mass and inertia), which the solver never writes, so that constraints solved at
// once on several threads may share them.
inline bool moves(const solver_body &body) noexcept {
    return body.inv_mass > 0 || body.inv_inertia != matrix3x3_zero;
}

// Applies the impulse `p` at the offsets rA, rB (from each centre of mass): +p to A, -p to B.
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

inline void apply_angular_impulse(solver_body &a, solver_body &b, const vector3 &l) noexcept {
    if (moves(a)) a.angvel += a.inv_inertia * l;
    if (moves(b)) b.angvel -= b.inv_inertia * l;
}

// Velocity of A's point at rA relative to B's point at rB.
inline vector3 relative_velocity(const solver_body &a, const solver_body &b, const vector3 &rA,
                                 const vector3 &rB) noexcept {
    return a.linvel + cross(a.angvel, rA) - b.linvel - cross(b.angvel, rB);
}

// Effective mass of the constraint row with linear direction d at offsets rA and rB.
inline scalar effective_mass(const solver_body &a, const solver_body &b, const vector3 &d, const vector3 &rA,
                             const vector3 &rB) noexcept {
    auto rnA = cross(rA, d);
    auto rnB = cross(rB, d);
    auto k = a.inv_mass + b.inv_mass + dot(rnA, a.inv_inertia * rnA) + dot(rnB, b.inv_inertia * rnB);
    return k > 0 ? scalar(1) / k : scalar(0);
}

// Effective mass of an angular row about the unit axis d.
inline scalar effective_angular_mass(const solver_body &a, const solver_body &b, const vector3 &d) noexcept {
    auto k = dot(d, a.inv_inertia * d) + dot(d, b.inv_inertia * d);
    return k > 0 ? scalar(1) / k : scalar(0);
}

} // namespace edyn

#endif // EDYN_DYNAMICS_SOLVER_BODY_HPP
