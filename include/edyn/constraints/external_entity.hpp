#ifndef EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP
#define EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP

#include "edyn/ecs/registry.hpp"

namespace edyn {

// An entity that is not a rigid body but belongs to the simulation, joined to a rigid body's
// island with a null_constraint (so that it travels with it, e.g. to a simulation worker).
struct external_tag {};

// tag_external_entity (simulation/replication.hpp) puts it on an entity.

} // namespace edyn

#endif // EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP
