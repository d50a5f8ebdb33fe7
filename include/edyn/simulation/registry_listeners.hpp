#ifndef EDYN_SIMULATION_REGISTRY_LISTENERS_HPP
#define EDYN_SIMULATION_REGISTRY_LISTENERS_HPP

#include "edyn/ecs/registry.hpp"

namespace edyn {

// The listeners that keep the simulation in step with changes the program makes: bodies added
// to and removed from the broadphase and the islands, islands woken when a body is changed
// through replace/patch, AABBs refreshed when a body is moved by the program, pairs re-filtered
// when collision filters change, manifolds leaving their islands when destroyed.
void connect_registry_listeners(registry &registry);
void disconnect_registry_listeners(registry &registry);

// Bodies made before attach() join the simulation.
void adopt_existing_bodies(registry &registry);

// Removes every edyn component from every entity and destroys edyn's own entities (manifolds,
// islands).
void remove_edyn_components(registry &registry);

} // namespace edyn

#endif // EDYN_SIMULATION_REGISTRY_LISTENERS_HPP
