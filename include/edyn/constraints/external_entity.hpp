#ifndef EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP
#define EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP

#include "edyn/ecs/registry.hpp"

namespace edyn {

/// An entity that is not a rigid body but belongs to the simulation, joined to a rigid body's
/// island with a null_constraint (so that it travels with it, e.g. to a simulation worker).
/// Put on an entity by tag_external_entity (simulation/replication.hpp), not by hand. Destroying
/// the tag destroys the constraints that join the entity.
struct external_tag {};

} // namespace edyn

#endif // EDYN_CONSTRAINTS_EXTERNAL_ENTITY_HPP
