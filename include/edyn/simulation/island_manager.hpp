#ifndef EDYN_SIMULATION_ISLAND_MANAGER_HPP
#define EDYN_SIMULATION_ISLAND_MANAGER_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/island.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

struct settings;

/// Keeps islands up to date as the graph changes.
/// Merging is immediate (an edge joining two islands merges the smaller into the larger);
/// splitting is deferred until a body of an island that lost edges is ready to sleep, since a
/// split island would only matter then and splits cost a traversal. One lives in world_state; the registry
/// listeners and the step call it. Programs do not call it directly (wake_up_entity wakes a
/// body).
class island_manager {
public:
    /// A new dynamic body: a node in an island of its own, with a sleep_timer.
    /// @param registry The registry the body lives in.
    /// @param node The body; it must not be in an island yet.
    void add_node(registry &registry, entity node);
    /// The body stops being a dynamic node (destroyed, cleared, made static or kinematic).
    /// Its island is woken, since its bodies may have lost their support, and marked as one that
    /// may split; an island left with no node is destroyed and its edges unlinked. Does nothing
    /// for an entity that is not in an island.
    /// @param registry The registry the body lives in.
    /// @param node The body.
    void remove_node(registry &registry, entity node);

    /// Joins `edge` (a manifold in contact or a constraint) to the island of its dynamic
    /// bodies, merging their islands and waking them.
    /// Bodies that are not nodes are ignored; an edge with no node is not linked, and an edge
    /// already linked is left as it is.
    /// @param registry The registry the entities live in.
    /// @param edge The manifold or constraint entity.
    /// @param body0 One body it joins.
    /// @param body1 The other body it joins.
    void link_edge(registry &registry, entity edge, entity body0, entity body1);
    /// Removes `edge` from its island, if it is linked, and marks the island as one that may
    /// split.
    /// @param registry The registry the edge lives in.
    /// @param edge The manifold or constraint entity.
    void unlink_edge(registry &registry, entity edge);

    /// Listener of `on_destroy<island_resident>`.
    /// When an entity is destroyed, the registry may remove its island_resident before the
    /// component whose listener would unlink it (the order follows pool creation), so the entity
    /// is taken out of its island here in that case. Removals made by the manager itself are
    /// recognised and ignored.
    /// @param registry The registry the entity lives in.
    /// @param e The entity losing its island_resident.
    void on_resident_destroyed(registry &registry, entity e);

    /// Wakes an island if it sleeps: removes sleeping_tag from it and its entities and resets its
    /// bodies' sleep timers.
    /// @param registry The registry the island lives in.
    /// @param island_entity The island entity.
    void wake_island(registry &registry, entity island_entity);
    /// Wakes the island of `entity` (a node or a linked edge), if it sleeps.
    /// An awake body's sleep timer is reset too, so that a change made just before its island
    /// would have slept gets the steps to act. Invalid entities are ignored.
    /// @param registry The registry the entity lives in.
    /// @param entity A body, manifold or constraint.
    void wake_entity(registry &registry, entity entity);
    /// Wakes, as wake_entity does, every body joined to `entity` by a constraint.
    /// A static or kinematic body is in no island: when it moves, what hangs from it must wake.
    /// @param registry The registry the entity lives in.
    /// @param entity A body or external entity; one without constraints wakes nothing.
    void wake_joined_to(registry &registry, entity entity);

    /// Advances the sleep timers of awake bodies by dt, then puts to sleep every island whose
    /// bodies have all been slow for settings.time_to_sleep.
    /// An island that may have come apart is split first instead, and its pieces are checked
    /// on the next call. So is, one a call, an island that may have come apart where only some
    /// bodies are ready to sleep: the one whose ready body has waited longest (a body that left
    /// and never slows down would otherwise keep the rest awake). Islands with a
    /// sleeping_disabled_tag body never sleep, and such a body is never ready. A sleeping
    /// body's velocities are set to zero. Islands are visited in the island pool's order, which
    /// depends only on the sequence of operations, so the result is reproducible.
    /// @param registry The registry the islands live in.
    /// @param settings Sleep thresholds: sleep_linear_velocity (m/s), sleep_angular_velocity
    /// (rad/s) and time_to_sleep (s).
    /// @param dt Time to add to the timers, in seconds (the fixed step).
    void update_sleeping(registry &registry, const settings &settings, scalar dt);

    /// Splits `island_entity` into its connected components.
    /// The component of the island's first node keeps the entity; the others get new island
    /// entities. Edges that no longer join a node are unlinked, and an island with no node is
    /// destroyed.
    /// @param registry The registry the island lives in.
    /// @param island_entity The island to split.
    void split(registry &registry, entity island_entity);

    /// Destroys every island entity and removes every island_resident, island_edge and
    /// sleep_timer (detach).
    /// @param registry The registry the islands live in.
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
