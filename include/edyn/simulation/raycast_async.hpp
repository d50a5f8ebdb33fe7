#ifndef EDYN_SIMULATION_RAYCAST_ASYNC_HPP
#define EDYN_SIMULATION_RAYCAST_ASYNC_HPP

#include "edyn/ecs/delegate.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/simulation/raycast.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

using raycast_id_type = std::uint32_t;
// void fn(raycast_id_type id, const raycast_result &result, vector3 p0, vector3 p1)
using raycast_delegate_type = delegate<void(raycast_id_type, const raycast_result &, vector3, vector3)>;

// Casts a ray where the simulation lives: in asynchronous mode in the simulation worker, with
// the bodies as the worker has them. The result (with the main registry's entity) is handed to
// `delegate` on the calling thread during a later update() (or wait_for_simulation()); in the
// other modes the ray is cast at once and the result is handed over during the next update().
// Returns the id the delegate will receive. Throws std::invalid_argument naming the function
// when the registry is not attached or p0 or p1 is not finite.
raycast_id_type raycast_async(registry &registry, const vector3 &p0, const vector3 &p1,
                              const raycast_delegate_type &delegate,
                              const std::vector<entity> &ignore_entities = {});

using query_aabb_id_type = std::uint32_t;

// Every rigid body whose AABB (as of the last step) intersects the query box, lowest entity
// value first.
struct query_aabb_result {
    std::vector<entity> entities;
};

// void fn(query_aabb_id_type id, const query_aabb_result &result)
using query_aabb_delegate_type = delegate<void(query_aabb_id_type, const query_aabb_result &)>;

// As raycast_async, for the bodies whose AABB intersects `aabb`. Throws std::invalid_argument
// naming the function when the registry is not attached or the box is not finite or inverted.
query_aabb_id_type query_aabb_async(registry &registry, const AABB &aabb,
                                    const query_aabb_delegate_type &delegate);

} // namespace edyn

#endif // EDYN_SIMULATION_RAYCAST_ASYNC_HPP
