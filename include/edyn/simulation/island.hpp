#ifndef EDYN_SIMULATION_ISLAND_HPP
#define EDYN_SIMULATION_ISLAND_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/math/scalar.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

// A connected component of the entity graph: dynamic bodies (nodes) joined by manifolds in
// contact and constraints (edges). Static and kinematic bodies are not nodes, so they never join
// two islands. Each island is an entity with this component; when it sleeps, it and every
// entity in it carry sleeping_tag.
struct island {
    std::vector<entity> nodes;
    std::vector<entity> edges;
    // An edge left since the island was last split: it may have come apart.
    bool may_split{false};
};

// On every node and linked edge: the island it belongs to, and its position in that island's
// `nodes` or `edges` (for removal in constant time).
struct island_resident {
    entity island_entity;
    std::uint32_t index;
};

// On every linked edge: the two bodies it joins.
struct island_edge {
    entity body[2];
};

// A constraint and the two entities it joins.
struct constraint_ref {
    entity constraint;
    entity body[2];
};

// On every entity that constraints join (a rigid body or an external entity, dynamic or not):
// those constraints, linked into an island or not, so that what happens to the entity reaches
// its own constraints without a look through everyone else's.
struct body_constraints {
    std::vector<constraint_ref> refs;
};

// How long a dynamic body has been slow enough to sleep, in simulated seconds.
struct sleep_timer {
    scalar time{0};
};

} // namespace edyn

#endif // EDYN_SIMULATION_ISLAND_HPP
