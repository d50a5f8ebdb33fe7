#include "edyn/dynamics/integration.hpp"
#include "edyn/math/math.hpp"
#include "edyn/parallel/parallel_for.hpp"

namespace edyn {

namespace {

// Bodies per parallel range: integrating one is a handful of operations.
constexpr std::size_t bodies_per_task = 1024;

} // namespace

void integrate_velocities(std::span<solver_body> bodies, scalar h, task_scheduler *scheduler) {
    if (bodies.empty()) return;
    parallel_for(scheduler, std::size_t(1), bodies.size(), bodies_per_task,
                 [&](std::size_t i) { bodies[i].linvel += bodies[i].acceleration * h; });
}

void integrate_positions(std::span<solver_body> bodies, scalar h, task_scheduler *scheduler) {
    if (bodies.empty()) return;
    const auto max_rotation = half_pi * scalar(0.5);
    parallel_for(scheduler, std::size_t(1), bodies.size(), bodies_per_task, [&](std::size_t i) {
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
