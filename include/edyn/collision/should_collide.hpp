#ifndef EDYN_COLLISION_SHOULD_COLLIDE_HPP
#define EDYN_COLLISION_SHOULD_COLLIDE_HPP

#include "edyn/collision/collision_filter.hpp"
#include "edyn/ecs/fwd.hpp"

namespace edyn {

using should_collide_func_t = bool (*)(const registry &, entity, entity);

// The default filter: false when the groups and masks exclude each other
// ((groupA & maskB) == 0 or (groupB & maskA) == 0, collision_filter defaults for entities
// without one) or when either body lists the other in its collision_exclusion.
bool should_collide_default(const registry &registry, entity first, entity second);

// Adds each entity to the other's collision_exclusion (created when missing); adding an
// existing pair again changes nothing. Throws std::invalid_argument, changing nothing, when an
// entity is not valid, both are the same, or a list would exceed
// collision_exclusion::max_exclusions.
void exclude_collision(registry &registry, entity first, entity second);

// Replaces the function the broadphase asks whether two bodies may collide, stored in the
// registry's context. Throws std::invalid_argument for a null function.
void set_should_collide(registry &registry, should_collide_func_t func);

// Forgets the function set by set_should_collide (back to should_collide_default), removing
// its context variable.
void reset_should_collide(registry &registry) noexcept;

// The function set by set_should_collide, or should_collide_default.
should_collide_func_t get_should_collide(const registry &registry) noexcept;

} // namespace edyn

#endif // EDYN_COLLISION_SHOULD_COLLIDE_HPP
