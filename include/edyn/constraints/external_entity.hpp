#ifndef EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP
#define EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP

#include "edyn/ecs/registry.hpp"

namespace edyn {

// An entity that is not a rigid body but belongs to the simulation, joined to a rigid body's
// island with a null_constraint (so that it travels with it, e.g. to a simulation worker).
struct external_tag {};

// Marks `entity` as external. Throws std::invalid_argument for an invalid entity or a rigid
// body (which is part of the simulation already).
void tag_external_entity(registry &registry, entity entity);

} // namespace edyn

#endif // EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP
