#ifndef EDYN_DYNAMICS_INTEGRATION_HPP
#define EDYN_DYNAMICS_INTEGRATION_HPP

#include "edyn/dynamics/solver_body.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <span>

namespace edyn {

/// Adds each body's acceleration (gravity) over the sub-step `h` to its linear velocity.
/// Index 0, the shared static body, is left alone. Both integrations spread the bodies over the
/// scheduler's threads when one is given; each body's result is the same either way. The step
/// calls it at the start of every sub-step, before the constraints are solved.
/// @param bodies The solver's body array, as gathered for this step (index 0 is the static body).
/// @param h Length of the sub-step, in seconds.
/// @param scheduler Threads to spread the work over, or null to run it on the calling thread.
void integrate_velocities(std::span<solver_body> bodies, scalar h, task_scheduler *scheduler = nullptr);

/// Advances each body's accumulated motion over the sub-step `h`.
/// Semi-implicit Euler: the velocities just solved move the bodies, adding to
/// `solver_body::delta_position` and `solver_body::delta_rotation` (the registry is written
/// later, by write_back). Index 0, the shared static body, is left alone. Angular speed is
/// capped so that no body turns more than π/4 radians in one sub-step, which would alias its
/// orientation; the cap lowers the body's `angvel` itself.
/// @param bodies The solver's body array, as gathered for this step (index 0 is the static body).
/// @param h Length of the sub-step, in seconds.
/// @param scheduler Threads to spread the work over, or null to run it on the calling thread.
void integrate_positions(std::span<solver_body> bodies, scalar h, task_scheduler *scheduler = nullptr);

} // namespace edyn

#endif // EDYN_DYNAMICS_INTEGRATION_HPP
