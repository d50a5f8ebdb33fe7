#include "edyn/dynamics/integration.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/quaternion.hpp"
#include <cmath>
#include <limits>

namespace edyn {

namespace {

// Bodies per parallel range: integrating one is a handful of operations.
constexpr std::uint32_t integrated_bodies_per_task = 1024;

// Lowers the body's angular speed to `max_angular`, keeping its axis.
void limit_turn(solver_body &body, scalar max_angular) noexcept {
    auto angular_sqr = length_sqr(body.angvel);
    if (angular_sqr > max_angular * max_angular) body.angvel *= max_angular / std::sqrt(angular_sqr);
}

} // namespace

scalar max_angular_speed(scalar h) noexcept { return half_pi * scalar(0.5) / h; }

vector3 gyroscopic_step(const vector3 &angvel, const matrix3x3 &inertia, const quaternion &orn,
                        scalar h) noexcept {
    auto diagonal = inertia[0][1] == 0 && inertia[0][2] == 0 && inertia[1][2] == 0;
    if (diagonal && inertia[0][0] == inertia[1][1] && inertia[1][1] == inertia[2][2])
        return angvel; // the same about every axis: no gyroscopic torque
    auto trace = inertia[0][0] + inertia[1][1] + inertia[2][2];
    if (!(trace > 0) || !std::isfinite(trace)) return angvel;

    // In the body's frame, where the inertia is constant. The implicit midpoint rule,
    // I (ω' - ω) + h m × I m = 0 with m = (ω + ω') / 2, keeps both the energy and the angular
    // momentum's length; one step of Newton's method from ω solves J (ω' - ω) = -h ω × I ω with
    // J = I + h/2 (ω× I - (I ω)×). The inertia is divided by its trace, so that any mass from a
    // grain's to an asteroid's stays in range.
    auto I = inertia * (scalar(1) / trace);
    auto w = rotate(conjugate(orn), angvel);
    auto k = h * scalar(0.5);
    vector3 rhs;
    matrix3x3 J;
    if (diagonal) {
        // Most shapes' inertia is diagonal in their own frame: the same, term by term.
        auto ix = I[0][0], iy = I[1][1], iz = I[2][2];
        rhs = vector3{w.y * w.z * (iy - iz), w.z * w.x * (iz - ix), w.x * w.y * (ix - iy)} * h;
        J = matrix3x3_rows({ix, k * w.z * (iz - iy), k * w.y * (iz - iy)},
                           {k * w.z * (ix - iz), iy, k * w.x * (ix - iz)},
                           {k * w.y * (iy - ix), k * w.x * (iy - ix), iz});
    } else {
        auto L = I * w;
        rhs = cross(L, w) * h;
        J = I + (skew_matrix(w) * I - skew_matrix(L)) * k;
    }
    if (rhs == vector3_zero) return angvel; // about a principal axis
    // Cramer's rule: J is close to the inertia, whose determinant is positive.
    auto c0 = cross(J[1], J[2]), c1 = cross(J[2], J[0]), c2 = cross(J[0], J[1]);
    auto det = dot(J[0], c0);
    if (!(det > 0)) return angvel;
    auto next = w + (c0 * rhs.x + c1 * rhs.y + c2 * rhs.z) * (scalar(1) / det);
    if (!isfinite(next)) return angvel;
    // One Newton step keeps the energy to second order in h |ω|; it is never let grow.
    auto energy = dot(w, I * w), next_energy = dot(next, I * next);
    if (next_energy > energy) next *= std::sqrt(energy / next_energy);
    return rotate(orn, next);
}

void limit_speed(solver_body &body, scalar max_linear_speed, scalar max_angular) noexcept {
    auto linear_sqr = length_sqr(body.linvel);
    if (linear_sqr > max_linear_speed * max_linear_speed) {
        body.linvel *= max_linear_speed / std::sqrt(linear_sqr);
    }
    limit_turn(body, max_angular);
}

void integrate_velocities(std::span<solver_body> bodies, scalar h, scalar max_linear_speed,
                          stage_queue &queue) {
    auto max_angular = max_angular_speed(h);
    queue.add_for(1u, std::uint32_t(bodies.size()), integrated_bodies_per_task,
                  [bodies, h, max_linear_speed, max_angular](std::uint32_t i) {
                      auto &body = bodies[i];
                      body.linvel += body.acceleration * h;
                      limit_speed(body, max_linear_speed, max_angular);
                  });
}

void integrate_positions(std::span<solver_body> bodies, scalar h, stage_queue &queue) {
    auto max_angular = max_angular_speed(h);
    queue.add_for(1u, std::uint32_t(bodies.size()), integrated_bodies_per_task,
                  [bodies, h, max_angular](std::uint32_t i) {
                      auto &body = bodies[i];
                      limit_turn(body, max_angular);
                      body.delta_position += body.linvel * h;
                      body.delta_rotation = integrate(body.delta_rotation, body.angvel, h);
                  });
}

void limit_speeds(std::span<solver_body> bodies, scalar h, scalar max_linear_speed, stage_queue &queue) {
    auto max_angular = max_angular_speed(h);
    queue.add_for(1u, std::uint32_t(bodies.size()), integrated_bodies_per_task,
                  [bodies, max_linear_speed, max_angular](std::uint32_t i) {
                      limit_speed(bodies[i], max_linear_speed, max_angular);
                  });
}

} // namespace edyn
