#ifndef EDYN_SIMULATION_NARROWPHASE_HPP
#define EDYN_SIMULATION_NARROWPHASE_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/world_state.hpp"

namespace edyn {

// Step phase 2: closest points for every awake manifold whose pair has a dynamic body, merged
// into the manifold (points matched across steps for warm starting); contact events recorded;
// manifolds that start touching join (and wake) their bodies' islands, those that stop leave.
void run_narrowphase(registry &registry, world_state &world);

} // namespace edyn

#endif // EDYN_SIMULATION_NARROWPHASE_HPP
