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

/// Checks the bodies the program changed since the last step (replace or patch of position,
/// orientation, linvel, angvel, a shape, material or gravity; emplace of a material or gravity),
/// before the step uses them. A NaN or infinite value would spread through contacts to every
/// body it touches; a shape or material out of range gives wrong physics.
/// @param registry A registry whose listeners are connected.
/// @throws std::invalid_argument Naming the first such body whose position, velocity or
/// orientation is not finite, whose orientation is zero, whose gravity is not finite or longer
/// than max_gravity, or whose shape or material fails validate_shape or validate_material; the
/// bodies stay to be checked again.
void check_written_bodies(registry &registry);

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
