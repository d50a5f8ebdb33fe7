#ifndef EDYN_SRC_NETWORKING_BODY_DEF_HPP
#define EDYN_SRC_NETWORKING_BODY_DEF_HPP

#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/ecs/registry.hpp"

namespace edyn {

// The definition that makes a copy of the rigid body `e` as it is now.
rigidbody_def get_rigidbody_def(const registry &registry, entity e);

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_BODY_DEF_HPP
