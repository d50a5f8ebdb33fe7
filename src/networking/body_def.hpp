#ifndef EDYN_SRC_NETWORKING_BODY_DEF_HPP
#define EDYN_SRC_NETWORKING_BODY_DEF_HPP

#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/ecs/registry.hpp"

namespace edyn {

// The definition that makes a copy of the rigid body `e` as it is now.
rigidbody_def get_rigidbody_def(const registry &registry, entity e);

// Whether a definition validate_rigidbody_def accepts lies within the range snapshots carry
// (max_quantized_coordinate on each axis, for its position, centre of mass, velocities and
// shape): a body beyond it could not be kept in step, and its arithmetic (a constraint's lever
// arm, the broadphase's areas) would leave the range of a float.
bool within_network_range(const rigidbody_def &def);

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_BODY_DEF_HPP
