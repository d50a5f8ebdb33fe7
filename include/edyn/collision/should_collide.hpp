#ifndef EDYN_COLLISION_SHOULD_COLLIDE_HPP
#define EDYN_COLLISION_SHOULD_COLLIDE_HPP

#include "edyn/collision/collision_filter.hpp"
#include "edyn/ecs/fwd.hpp"

namespace edyn {

/// Signature of the function that decides whether two bodies may collide: it receives the
/// registry and the two bodies and returns false to keep them from colliding.
using should_collide_func_t = bool (*)(const registry &, entity, entity);

/// The default collision filter.
///
/// Returns false when the groups and masks exclude each other
/// ((groupA & maskB) == 0 or (groupB & maskA) == 0, collision_filter defaults for entities
/// without one) or when either body lists the other in its collision_exclusion. A custom filter
/// set with set_should_collide() may call it to keep the default behaviour as part of its logic.
/// @param registry The registry holding the bodies.
/// @param first One body.
/// @param second The other body.
/// @return Whether the two bodies may collide.
bool should_collide_default(const registry &registry, entity first, entity second);

/// Keeps two bodies from colliding with each other, whatever their collision filters.
///
/// Adds each entity to the other's collision_exclusion (created when missing, replaced
/// otherwise, so that the change reaches the simulation worker); adding an existing pair again
/// changes nothing. Entities in either list that have been destroyed are dropped from it here,
/// so that they do not count against max_exclusions. A contact the two bodies already have is destroyed, as
/// for any change of their collision_exclusion.
/// @param registry The registry holding the bodies.
/// @param first One body.
/// @param second The other body.
/// @throws std::invalid_argument When an entity is not valid in `registry`, both are the same,
///         or a list would exceed collision_exclusion::max_exclusions; nothing is changed then.
void exclude_collision(registry &registry, entity first, entity second);

/// Replaces the function the broadphase asks whether two bodies may collide.
///
/// The function is stored in the registry's context and asked once per pair, when the pair's AABBs
/// start overlapping, and about every overlapping pair at the next step after the function
/// changes (here or through reset_should_collide): pairs it refuses then lose their manifolds,
/// overlapping pairs it accepts get one. In asynchronous mode it is copied to the simulation
/// worker and called there, on the worker's thread, with the worker's registry (from the next
/// update()).
/// @param registry The registry whose filter is replaced.
/// @param func The new filter; see should_collide_func_t.
/// @throws std::invalid_argument When `func` is null.
void set_should_collide(registry &registry, should_collide_func_t func);

/// Forgets the function set by set_should_collide() (back to should_collide_default()),
/// removing its context variable.
/// @param registry The registry whose filter is reset.
void reset_should_collide(registry &registry) noexcept;

/// The function set by set_should_collide(), or should_collide_default() when none is set.
/// @param registry The registry to look in.
/// @return The filter in use; never null.
should_collide_func_t get_should_collide(const registry &registry) noexcept;

} // namespace edyn

#endif // EDYN_COLLISION_SHOULD_COLLIDE_HPP
