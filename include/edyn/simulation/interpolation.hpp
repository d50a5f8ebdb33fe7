#ifndef EDYN_SIMULATION_INTERPOLATION_HPP
#define EDYN_SIMULATION_INTERPOLATION_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/math/quaternion.hpp"

namespace edyn {

// Transform of a moving body before the last step, for interpolating present transforms.
struct previous_transform {
    vector3 position;
    quaternion orientation;
};

// Copies position and orientation of every awake moving body into its previous_transform.
void save_previous_transforms(registry &registry);

// present_* = the transform a fraction `alpha` (in [0, 1]) of the way from the previous step's
// to the last step's. Sleeping and static bodies are presented where they are.
void interpolate_present_transforms(registry &registry, scalar alpha);

} // namespace edyn

#endif // EDYN_SIMULATION_INTERPOLATION_HPP
