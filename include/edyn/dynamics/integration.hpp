#ifndef EDYN_DYNAMICS_INTEGRATION_HPP
#define EDYN_DYNAMICS_INTEGRATION_HPP

#include "edyn/dynamics/solver_body.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <span>

namespace edyn {

// Adds each body's acceleration (gravity) over the sub-step h. Index 0, the shared static body,
// is left alone. Both integrations spread the bodies over the scheduler's threads when one is
// given; each body's result is the same either way.
void integrate_velocities(std::span<solver_body> bodies, scalar h, task_scheduler *scheduler = nullptr);

// Advances each body's accumulated motion over the sub-step h (semi-implicit Euler: the new
// velocities move the bodies). Angular speed is capped so that no body turns more than a
// quarter turn per sub-step, which would alias its orientation.
void integrate_positions(std::span<solver_body> bodies, scalar h, task_scheduler *scheduler = nullptr);

} // namespace edyn

#endif // EDYN_DYNAMICS_INTEGRATION_HPP
