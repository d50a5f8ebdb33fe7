#include "edyn/dynamics/integration.hpp"
#include "edyn/math/math.hpp"

namespace edyn {

void integrate_velocities(std::span<solver_body> bodies, scalar h) noexcept {
    for (std::size_t i = 1; i < bodies.size(); ++i) {
        bodies[i].linvel += bodies[i].acceleration * h;
    }
}

void integrate_positions(std::span<solver_body> bodies, scalar h) noexcept {
    const auto max_rotation = half_pi * scalar(0.5);
    for (std::size_t i = 1; i < bodies.size(); ++i) {
        auto &body = bodies[i];
        auto speed_sqr = length_sqr(body.angvel);
        if (speed_sqr * h * h > max_rotation * max_rotation) {
            body.angvel *= max_rotation / (std::sqrt(speed_sqr) * h);
        }
        body.delta_position += body.linvel * h;
        body.delta_rotation = integrate(body.delta_rotation, body.angvel, h);
    }
}

} // namespace edyn
