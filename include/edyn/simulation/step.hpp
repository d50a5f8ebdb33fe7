#ifndef EDYN_SIMULATION_STEP_HPP
#define EDYN_SIMULATION_STEP_HPP

#include "edyn/ecs/registry.hpp"

namespace edyn {

/// Runs one fixed step of the simulation, phase by phase.
/// Pre-step callback, broadphase, paged meshes, narrowphase, gathering, solving, write back,
/// sleeping, then collision events and the post-step callback; the simulation time and step
/// count advance by one step. Called by update() and step_simulation(), which also save and
/// interpolate the transforms for rendering; requires attach(), and in asynchronous mode runs
/// in the worker.
/// @param registry An attached registry (the worker's, in asynchronous mode).
void run_step(registry &registry);

} // namespace edyn

#endif // EDYN_SIMULATION_STEP_HPP
