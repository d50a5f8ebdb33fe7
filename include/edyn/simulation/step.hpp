#ifndef EDYN_SIMULATION_STEP_HPP
#define EDYN_SIMULATION_STEP_HPP

#include "edyn/ecs/registry.hpp"

namespace edyn {

// One fixed step of the simulation, phase by phase (see step.cpp). Called by update() and
// step_simulation(); requires attach().
void run_step(registry &registry);

} // namespace edyn

#endif // EDYN_SIMULATION_STEP_HPP
