#ifndef EDYN_SIMULATION_PAGED_MESH_LOADING_HPP
#define EDYN_SIMULATION_PAGED_MESH_LOADING_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/world_state.hpp"

namespace edyn {

/// Loads and unloads the pages of every paged mesh, before the narrowphase.
/// Each moving (awake, dynamic) body within its reach ahead of a paged mesh has the pages it
/// can touch during this step loaded now (waiting for a late background load) and those it can
/// reach within the mesh's lookahead_time requested in the background; pages no body neared for
/// the mesh's unload_delay steps are unloaded. Called by run_step, after the broadphase.
/// @param registry An attached registry.
/// @param world The registry's world_state (its step count dates the pages' use).
void update_paged_meshes(registry &registry, world_state &world);

} // namespace edyn

#endif // EDYN_SIMULATION_PAGED_MESH_LOADING_HPP
