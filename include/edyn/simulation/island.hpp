#ifndef EDYN_SIMULATION_ISLAND_HPP
#define EDYN_SIMULATION_ISLAND_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/math/scalar.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

/// Component: a connected component of the entity graph, on an island entity of its own.
/// Dynamic bodies are its nodes, joined by manifolds in contact and constraints (its edges).
/// Static and kinematic bodies are not nodes, so they never join two islands. When the island
/// sleeps, it and every entity in it carry sleeping_tag. Written only by the island_manager;
/// programs may read it.
struct island {
    std::vector<entity> nodes; ///< The dynamic bodies in the island, in no particular order.
    std::vector<entity> edges; ///< The manifolds in contact and constraints linking them.
    /// Whether an edge or node left since the island was last split: it may have come apart.
    /// The island is split once one of its bodies is ready to sleep.
    bool may_split{false};
    /// Simulated seconds since the island was made or last split (s). An island where only some
    /// bodies are ready to sleep is split at most once per settings::time_to_sleep: a heap that
    /// keeps moving loses links every step and is found whole by most splits.
    scalar since_split{0};
};

/// Component: on every node and linked edge, the island it belongs to and its place there.
/// Its position in that island's `nodes` or `edges` allows removal in constant time. Written
/// by the island_manager.
struct island_resident {
    entity island_entity; ///< The entity with the island component.
    std::uint32_t index;  ///< Index in the island's `nodes` (for a body) or `edges` (for an edge).
};

/// Component: on every linked edge, the two bodies it joins.
/// Either may be a static or kinematic body, which is not a node of the island.
struct island_edge {
    entity body[2]; ///< The two bodies, in the edge's own order.
};

/// Component: how long a dynamic body has been slow enough to sleep, in simulated seconds.
/// Written by the island_manager each step: reset to 0 when the body moves faster than
/// settings::sleep_linear_velocity or settings::sleep_angular_velocity, or is woken.
struct sleep_timer {
    scalar time{0}; ///< Seconds spent below the sleep speeds; starts at 0.
};

} // namespace edyn

#endif // EDYN_SIMULATION_ISLAND_HPP
