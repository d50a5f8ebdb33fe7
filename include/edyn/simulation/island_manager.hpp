#ifndef EDYN_SIMULATION_ISLAND_MANAGER_HPP
#define EDYN_SIMULATION_ISLAND_MANAGER_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/island.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

struct settings;

// Keeps islands up to date as the graph changes. Merging is immediate (an edge joining two
// islands merges the smaller into the larger); splitting is deferred until an island that lost
// edges is about to sleep, since a split island would only matter then and splits cost a
// traversal.
class island_manager {
public:
    // A new dynamic body: a node in an island of its own.
    void add_node(registry &registry, entity node);
    // The body stops being a dynamic node (destroyed, cleared, made static or kinematic). Its
    // island is woken: its bodies may have lost their support.
    void remove_node(registry &registry, entity node);

    // Joins `edge` (a manifold in contact or a constraint) to the island of its dynamic
    // bodies, merging their islands and waking them. Bodies that are not nodes are ignored;
    // an edge with no node is not linked.
    void link_edge(registry &registry, entity edge, entity body0, entity body1);
    // Removes `edge` from its island, if it is linked.
    void unlink_edge(registry &registry, entity edge);

    // Listener of on_destroy<island_resident>: when an entity is destroyed, the registry may
    // remove its island_resident before the component whose listener would unlink it (the order
    // follows pool creation), so the entity is taken out of its island here in that case.
    // Removals made by the manager itself are recognised and ignored.
    void on_resident_destroyed(registry &registry, entity e);

    void wake_island(registry &registry, entity island_entity);
    // Wakes the island of `entity` (a node or a linked edge), if it sleeps.
    void wake_entity(registry &registry, entity entity);

    // Advances the sleep timers of awake bodies by dt, then puts to sleep every island whose
    // bodies have all been slow for settings.time_to_sleep (splitting it first if it lost
    // edges). Islands are visited in the island pool's order, which depends only on the sequence
    // of operations, so the result is reproducible.
    void update_sleeping(registry &registry, const settings &settings, scalar dt);

    // Splits `island_entity` into its connected components; returns the islands it became.
    void split(registry &registry, entity island_entity);

    // Destroys every island entity (detach).
    void clear(registry &registry);

private:
    entity create_island(registry &registry);
    void destroy_island(registry &registry, entity island_entity);
    void merge(registry &registry, entity into, entity from);
    void put_to_sleep(registry &registry, entity island_entity);
    // Unlinks the edges of an island left with no node, and destroys it.
    void dissolve_empty(registry &registry, entity island_entity);

    // Scratch: islands to visit while the island pool changes.
    std::vector<entity> candidates;
    // Scratch for split(): union-find parents and local indices by entity index.
    std::vector<std::uint32_t> parent;
    std::vector<std::uint32_t> local_index;
};

} // namespace edyn

#endif // EDYN_SIMULATION_ISLAND_MANAGER_HPP
