#ifndef EDYN_DYNAMICS_INTEGRATION_HPP
#define EDYN_DYNAMICS_INTEGRATION_HPP

#include "edyn/dynamics/solver_body.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include <span>

namespace edyn {

/// Queues adding each body's acceleration (gravity) over the sub-step `h` to its linear velocity.
/// Index 0, the shared static body, is left alone. Each integration is queued as one stage
/// (see stage_queue), whose blocks of bodies may run on different threads; each body's result
/// is the same either way. The step queues it at the start of every sub-step, before the
/// constraints are solved. The storage behind `bodies` must outlive the queue's run.
/// @param bodies The solver's body array, as gathered for this step (index 0 is the static body).
/// @param h Length of the sub-step, in seconds.
/// @param queue Where the work is queued.
void integrate_velocities(std::span<solver_body> bodies, scalar h, stage_queue &queue);

/// Queues advancing each body's accumulated motion over the sub-step `h`.
/// Semi-implicit Euler: the velocities just solved move the bodies, adding to
/// `solver_body::delta_position` and `solver_body::delta_rotation` (the registry is written
/// later, by write_back). Index 0, the shared static body, is left alone. Angular speed is
/// capped so that no body turns more than π/4 radians in one sub-step, which would alias its
/// orientation; the cap lowers the body's `angvel` itself.
/// @param bodies The solver's body array, as gathered for this step (index 0 is the static body).
/// @param h Length of the sub-step, in seconds.
/// @param queue Where the work is queued.
void integrate_positions(std::span<solver_body> bodies, scalar h, stage_queue &queue);

} // namespace edyn

#endif // EDYN_DYNAMICS_INTEGRATION_HPP
