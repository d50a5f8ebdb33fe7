#ifndef EDYN_SIMULATION_INTERPOLATION_HPP
#define EDYN_SIMULATION_INTERPOLATION_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/math/quaternion.hpp"

namespace edyn {

/// Component: transform of a moving body before the last step, for interpolating present
/// transforms.
/// Written by the engine on dynamic and kinematic bodies (not static ones); a transform the
/// program assigns with `replace` or `patch` resets it, so that a teleport is not interpolated.
struct previous_transform {
    vector3 position;       ///< World-space position of the centre of mass, in metres.
    quaternion orientation; ///< World-space orientation, a unit quaternion (x y z w).
};

/// Copies position and orientation of every awake moving body into its previous_transform.
/// Called before each step that update() and step_simulation() run.
/// @param registry An attached registry.
void save_previous_transforms(registry &registry);

/// Sets present_position and present_orientation to the transform a fraction `alpha` of the
/// way from the previous step's to the last step's.
/// Positions are blended linearly, orientations along the shorter arc. Sleeping and static
/// bodies, and bodies without a previous_transform, are presented where they are. A
/// discontinuity, where a body has one, is added on top.
/// @param registry An attached registry.
/// @param alpha Fraction of the way from the previous transform to the current one, in [0, 1].
void interpolate_present_transforms(registry &registry, scalar alpha);

} // namespace edyn

#endif // EDYN_SIMULATION_INTERPOLATION_HPP
