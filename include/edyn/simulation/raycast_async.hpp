#ifndef EDYN_SIMULATION_RAYCAST_ASYNC_HPP
#define EDYN_SIMULATION_RAYCAST_ASYNC_HPP

#include "edyn/ecs/delegate.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/simulation/raycast.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

/// Id of an asynchronous raycast, returned by raycast_async and passed to its delegate.
/// Ids of raycasts and AABB queries come from one counter per registry.
using raycast_id_type = std::uint32_t;
/// Receiver of a raycast_async result:
/// `void fn(raycast_id_type id, const raycast_result &result, vector3 p0, vector3 p1)`.
using raycast_delegate_type = delegate<void(raycast_id_type, const raycast_result &, vector3, vector3)>;

/// Casts a ray where the simulation lives and hands the result to `delegate` later.
/// In asynchronous mode the ray is cast in the simulation worker, with the bodies as the
/// worker has them. The result (with the main registry's entity) is handed to `delegate` on the
/// calling thread during a later update() (or wait_for_simulation()); in the other modes the
/// ray is cast at once and the result is handed over during the next update() or
/// wait_for_simulation(). The ray is cast as raycast describes.
/// @param registry An attached registry (the main one, in asynchronous mode).
/// @param p0 Start of the ray, world space, in metres.
/// @param p1 End of the ray, world space, in metres.
/// @param delegate Receives the id, the result, p0 and p1; it must stay callable until then.
/// @param ignore_entities Bodies the ray passes through (main-registry entities).
/// @return The id the delegate will receive.
/// @throws std::invalid_argument When the registry is not attached, when the delegate is empty,
/// or when p0 or p1 is not finite.
raycast_id_type raycast_async(registry &registry, const vector3 &p0, const vector3 &p1,
                              const raycast_delegate_type &delegate,
                              const std::vector<entity> &ignore_entities = {});

/// Id of an asynchronous AABB query, returned by query_aabb_async and passed to its delegate.
using query_aabb_id_type = std::uint32_t;

/// The answer to query_aabb_async.
/// Every rigid body whose AABB (as of the last step) intersects the query box, lowest entity
/// value first.
struct query_aabb_result {
    std::vector<entity> entities; ///< The bodies found (main-registry entities), sorted.
};

/// Receiver of a query_aabb_async result:
/// `void fn(query_aabb_id_type id, const query_aabb_result &result)`.
using query_aabb_delegate_type = delegate<void(query_aabb_id_type, const query_aabb_result &)>;

/// As raycast_async, for the bodies whose AABB intersects `aabb`.
/// Sleeping bodies and sensors are included; the AABBs are those of the last step, which for
/// moving bodies are swept over their next step's motion.
/// @param registry An attached registry (the main one, in asynchronous mode).
/// @param aabb The query box, world space, in metres.
/// @param delegate Receives the id and the result, during a later update() (or
/// wait_for_simulation(), in asynchronous mode); it must stay callable until then.
/// @return The id the delegate will receive.
/// @throws std::invalid_argument When the registry is not attached, when the delegate is empty,
/// or when the box is not finite or has a min above its max on some axis.
query_aabb_id_type query_aabb_async(registry &registry, const AABB &aabb,
                                    const query_aabb_delegate_type &delegate);

} // namespace edyn

#endif // EDYN_SIMULATION_RAYCAST_ASYNC_HPP
