#include "edyn/dynamics/integration.hpp"
#include "edyn/math/math.hpp"

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
