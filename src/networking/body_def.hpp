#ifndef EDYN_SRC_NETWORKING_BODY_DEF_HPP
#define EDYN_SRC_NETWORKING_BODY_DEF_HPP

#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/ecs/registry.hpp"

namespace edyn {

// The definition that makes a copy of the rigid body `e` as it is now.
rigidbody_def get_rigidbody_def(const registry &registry, entity e);

// Makes the rigid body `e` what `def` (a definition validate_rigidbody_def accepts) describes,
// changing only what differs, through the calls a program would make (rigidbody_set_kind,
// rigidbody_set_shape, set_center_of_mass, ...): kind, shape, centre of mass, mass and inertia,
// material (not whether it has one), gravity, collision filter, sleeping_disabled, and a static
// body's pose. A moving body's pose and velocities are left alone (snapshots carry them). Throws
// std::invalid_argument as those calls do, for a change they refuse.
void update_rigidbody(registry &registry, entity e, const rigidbody_def &def);

// Whether a definition validate_rigidbody_def accepts lies within the range snapshots carry
// (max_quantized_coordinate on each axis, for its position, centre of mass, velocities and
// shape): a body beyond it could not be kept in step, and its arithmetic (a constraint's lever
// arm, the broadphase's areas) would leave the range of a float.
bool within_network_range(const rigidbody_def &def);

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_BODY_DEF_HPP
