#include "edyn/dynamics/integration.hpp"
#include "edyn/math/math.hpp"

namespace edyn {

namespace {

// Bodies per parallel range: integrating one is a handful of operations.
constexpr std::uint32_t integrated_bodies_per_task = 1024;

} // namespace

void integrate_velocities(std::span<solver_body> bodies, scalar h, stage_queue &queue) {
    queue.add_for(1u, std::uint32_t(bodies.size()), integrated_bodies_per_task,
                  [bodies, h](std::uint32_t i) { bodies[i].linvel += bodies[i].acceleration * h; });
}

void integrate_positions(std::span<solver_body> bodies, scalar h, stage_queue &queue) {
    const auto max_rotation = half_pi * scalar(0.5);
    queue.add_for(1u, std::uint32_t(bodies.size()), integrated_bodies_per_task,
                  [bodies, h, max_rotation](std::uint32_t i) {
                      auto &body = bodies[i];
                      auto speed_sqr = length_sqr(body.angvel);
                      if (speed_sqr * h * h > max_rotation * max_rotation) {
                          body.angvel *= max_rotation / (std::sqrt(speed_sqr) * h);
                      }
                      body.delta_position += body.linvel * h;
                      body.delta_rotation = integrate(body.delta_rotation, body.angvel, h);
                  });
}

} // namespace edyn
