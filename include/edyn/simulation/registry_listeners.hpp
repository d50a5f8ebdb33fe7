#ifndef EDYN_SIMULATION_REGISTRY_LISTENERS_HPP
#define EDYN_SIMULATION_REGISTRY_LISTENERS_HPP

#include "edyn/ecs/registry.hpp"

namespace edyn {

/// Connects the listeners that keep the simulation in step with changes the program makes.
/// Bodies are added to and removed from the broadphase and the islands, islands are woken when
/// a body is changed through replace/patch, AABBs are refreshed when a body is moved by the
/// program, pairs are re-filtered when collision filters change, and manifolds and constraints
/// leave their islands when destroyed. attach calls it in the sequential modes (in asynchronous
/// mode the simulation worker's registry has them instead).
/// @param registry A registry whose world_state and settings are in its context.
void connect_registry_listeners(registry &registry);
/// Disconnects what connect_registry_listeners connected (detach).
/// @param registry The registry.
void disconnect_registry_listeners(registry &registry);

/// Checks the motion the program wrote (replace or patch of position, orientation, linvel or
/// angvel) into bodies since the last step, before the step uses it.
/// A NaN or infinite value would spread through contacts to every body it touches.
/// @param registry A registry whose listeners are connected.
/// @throws std::invalid_argument Naming the first body whose written position, velocity or
/// orientation is not finite, or whose orientation is zero; the bodies stay to be checked again.
void check_written_motion(registry &registry);

/// Makes the bodies and constraints created before attach() join the simulation, oldest first.
/// @param registry A registry whose listeners were just connected.
void adopt_existing_bodies(registry &registry);

/// Removes every edyn component from every entity and destroys edyn's own entities (manifolds,
/// islands).
/// The program's own entities and components stay. Called by detach.
/// @param registry The registry.
void remove_edyn_components(registry &registry);

} // namespace edyn

#endif // EDYN_SIMULATION_REGISTRY_LISTENERS_HPP
