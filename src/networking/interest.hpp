#ifndef EDYN_SRC_NETWORKING_INTEREST_HPP
#define EDYN_SRC_NETWORKING_INTEREST_HPP

// Which networked entities a client should have: those in its AABB of interest, each moving body
// with its island, and whole assets. The server sends the entities that enter it and removes
// those that leave.

#include "edyn/ecs/registry.hpp"
#include "edyn/networking/remote_client.hpp"
#include "edyn/shapes/aabb.hpp"
#include "entity_set.hpp"
#include <utility>
#include <vector>

namespace edyn::detail {

/// Moves the client's AABB of interest, keeping its size, to the mean position of the entities
/// it owns, when it follows them (remote_client::aabb_follows_owned).
void recentre_on_owned(registry &registry, remote_client &rc);

/// Adds `e` and, for a body in an island, the whole island: its bodies and the networked
/// constraints among them, and the bodies those constraints hold. The networked constraints
/// joined to `e` through moving bodies come with it too (where islands are not kept).
void add_with_island(const registry &registry, entity e, entity_set &out);

/// Each networked entity with a position and the box the AABBs of interest are tested against
/// (written over `out`).
void gather_interest_boxes(const registry &registry, std::vector<std::pair<entity, AABB>> &out);

/// Adds the networked entities whose box overlaps `aabb` (a plane's box is unbounded), each
/// moving body with its island.
void collect_interest(const registry &registry, const std::vector<std::pair<entity, AABB>> &boxes,
                      const AABB &aabb, entity_set &out);

/// Adds the asset of each asset member in `interest`, and all the asset's entities: an asset
/// travels whole.
void add_assets(const registry &registry, entity_set &interest);

} // namespace edyn::detail

#endif // EDYN_SRC_NETWORKING_INTEREST_HPP
