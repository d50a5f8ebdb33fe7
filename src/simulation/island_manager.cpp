#include "edyn/simulation/island_manager.hpp"
#include "edyn/constraints/constraint_links.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/simulation/settings.hpp"
#include <algorithm>

namespace edyn {

namespace {

bool is_node(const registry &registry, entity e) {
    return registry.valid(e) && registry.all_of<island_resident, dynamic_tag>(e);
}

// Appends `e` to `list` and records where, on its island_resident.
void push_resident(registry &registry, std::vector<entity> &list, entity e, entity island_entity) {
    registry.emplace_or_replace<island_resident>(e, island_entity, std::uint32_t(list.size()));
    list.push_back(e);
}

// Removes `e` from `list` by moving the last element into its place.
void erase_resident(registry &registry, std::vector<entity> &list, entity e) {
    auto index = registry.get<island_resident>(e).index;
    EDYN_ASSERT(index < list.size() && list[index] == e);
    auto last = list.back();
    list[index] = last;
    registry.get<island_resident>(last).index = index;
    list.pop_back();
}

} // namespace

entity island_manager::create_island(registry &registry) {
    auto e = registry.create();
    registry.emplace<island>(e);
    return e;
}

void island_manager::destroy_island(registry &registry, entity island_entity) {
    registry.destroy(island_entity);
}

void island_manager::add_node(registry &registry, entity node) {
    EDYN_ASSERT(!registry.all_of<island_resident>(node));
    auto island_entity = create_island(registry);
    push_resident(registry, registry.get<island>(island_entity).nodes, node, island_entity);
    registry.emplace_or_replace<sleep_timer>(node);
}

void island_manager::remove_node(registry &registry, entity node) {
    auto *resident = registry.try_get<island_resident>(node);
    if (!resident) return;
    auto island_entity = resident->island_entity;
    wake_island(registry, island_entity);
    auto &isle = registry.get<island>(island_entity);
    erase_resident(registry, isle.nodes, node);
    registry.remove<island_resident, sleep_timer>(node);

    // Edges of this node now join at most one island node; the split decides where they go.
    isle.may_split = true;
    if (isle.nodes.empty()) dissolve_empty(registry, island_entity);
}

void island_manager::dissolve_empty(registry &registry, entity island_entity) {
    // Out of the list first, so that on_resident_destroyed sees these removals as internal.
    auto edges = std::move(registry.get<island>(island_entity).edges);
    for (auto edge : edges)
        registry.remove<island_resident, island_edge>(edge);
    destroy_island(registry, island_entity);
}

void island_manager::on_resident_destroyed(registry &registry, entity e) {
    auto &resident = registry.get<island_resident>(e);
    auto island_entity = resident.island_entity;
    if (!registry.valid(island_entity)) return;
    auto &isle = registry.get<island>(island_entity);
    auto index = resident.index;
    // Every removal made by the manager takes the entity out of its list first.
    if (index < isle.edges.size() && isle.edges[index] == e) {
        erase_resident(registry, isle.edges, e);
        isle.may_split = true;
    } else if (index < isle.nodes.size() && isle.nodes[index] == e) {
        // Out of the list before waking: the registry may already have removed its sleep_timer.
        erase_resident(registry, isle.nodes, e);
        wake_island(registry, island_entity);
        isle.may_split = true;
        if (isle.nodes.empty()) dissolve_empty(registry, island_entity);
    }
}

void island_manager::link_edge(registry &registry, entity edge, entity body0, entity body1) {
    if (registry.all_of<island_resident>(edge)) return;
    bool node0 = is_node(registry, body0);
    bool node1 = is_node(registry, body1);
    if (!node0 && !node1) return;

    auto island0 = node0 ? registry.get<island_resident>(body0).island_entity : null;
    auto island1 = node1 ? registry.get<island_resident>(body1).island_entity : null;
    auto target = node0 ? island0 : island1;
    if (node0) wake_island(registry, island0);
    if (node1) wake_island(registry, island1);

    if (node0 && node1 && island0 != island1) {
        // Merge the smaller island into the larger: the fewest residents change.
        auto size0 = registry.get<island>(island0).nodes.size() + registry.get<island>(island0).edges.size();
        auto size1 = registry.get<island>(island1).nodes.size() + registry.get<island>(island1).edges.size();
        if (size0 >= size1) {
            merge(registry, island0, island1);
            target = island0;
        } else {
            merge(registry, island1, island0);
            target = island1;
        }
    }

    registry.emplace_or_replace<island_edge>(edge, island_edge{{body0, body1}});
    push_resident(registry, registry.get<island>(target).edges, edge, target);
}

void island_manager::unlink_edge(registry &registry, entity edge) {
    auto *resident = registry.try_get<island_resident>(edge);
    if (!resident) return;
    auto island_entity = resident->island_entity;
    auto &isle = registry.get<island>(island_entity);
    erase_resident(registry, isle.edges, edge);
    registry.remove<island_resident, island_edge>(edge);
    isle.may_split = true;
}

void island_manager::merge(registry &registry, entity into, entity from) {
    auto &target = registry.get<island>(into);
    auto &source = registry.get<island>(from);
    for (auto node : source.nodes)
        push_resident(registry, target.nodes, node, into);
    for (auto edge : source.edges)
        push_resident(registry, target.edges, edge, into);
    target.may_split |= source.may_split;
    source.nodes.clear();
    source.edges.clear();
    destroy_island(registry, from);
}

void island_manager::wake_island(registry &registry, entity island_entity) {
    if (!registry.all_of<sleeping_tag>(island_entity)) return;
    auto &isle = registry.get<island>(island_entity);
    registry.remove<sleeping_tag>(island_entity);
    for (auto node : isle.nodes) {
        registry.remove<sleeping_tag>(node);
        // A node being destroyed may have lost its timer already (pools go newest first): its
        // constraints, destroyed with it, wake the island while it is still listed.
        if (auto *timer = registry.try_get<sleep_timer>(node)) timer->time = 0;
    }
    for (auto edge : isle.edges)
        registry.remove<sleeping_tag>(edge);
}

void island_manager::wake_entity(registry &registry, entity e) {
    if (!registry.valid(e)) return;
    if (auto *resident = registry.try_get<island_resident>(e)) wake_island(registry, resident->island_entity);
    // Awake already, the body still starts its wait for sleep again: a change made just before
    // its island would have slept (a new centre of mass, a push) must get the steps to act.
    if (auto *timer = registry.try_get<sleep_timer>(e)) timer->time = 0;
}

void island_manager::wake_joined_to(registry &registry, entity e) {
    auto *list = registry.try_get<constraint_list>(e);
    for (auto constraint = list ? list->first : null; constraint != null;) {
        auto &links = registry.get<constraint_links>(constraint);
        auto side = links.body[0] == e ? 0 : 1;
        wake_entity(registry, links.body[1 - side]);
        constraint = links.next[side];
    }
}

void island_manager::put_to_sleep(registry &registry, entity island_entity) {
    auto &isle = registry.get<island>(island_entity);
    registry.emplace_or_replace<sleeping_tag>(island_entity);
    for (auto node : isle.nodes) {
        registry.emplace_or_replace<sleeping_tag>(node);
        // A sleeping body is at rest: what is left of its motion would make it pop on waking.
        registry.get<linvel>(node) = vector3_zero;
        registry.get<angvel>(node) = vector3_zero;
    }
    for (auto edge : isle.edges)
        registry.emplace_or_replace<sleeping_tag>(edge);
}

void island_manager::split(registry &registry, entity island_entity) {
    auto &isle = registry.get<island>(island_entity);
    isle.may_split = false;
    isle.since_split = 0;
    auto nodes = std::move(isle.nodes);
    auto edges = std::move(isle.edges);
    isle.nodes.clear();
    isle.edges.clear();

    // Union-find over the island's nodes, indexed through their entity index.
    std::size_t max_index = 0;
    for (auto node : nodes)
        max_index = std::max<std::size_t>(max_index, to_index(node));
    if (local_index.size() <= max_index) local_index.resize(max_index + 1);
    parent.resize(nodes.size());
    for (std::uint32_t i = 0; i < nodes.size(); ++i) {
        local_index[to_index(nodes[i])] = i;
        parent[i] = i;
    }
    auto find = [&](std::uint32_t i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    // Membership is read from `nodes`, not from island_resident: the nodes move to their new
    // islands before the edges are placed, and an edge must still find its node then.
    auto node_of = [&](entity body) -> std::int64_t {
        auto index = to_index(body);
        if (body == null || index >= local_index.size()) return -1;
        auto local = local_index[index];
        return local < nodes.size() && nodes[local] == body ? std::int64_t(local) : -1;
    };
    for (auto edge : edges) {
        auto &ends = registry.get<island_edge>(edge);
        auto a = node_of(ends.body[0]), b = node_of(ends.body[1]);
        if (a >= 0 && b >= 0) parent[find(std::uint32_t(a))] = find(std::uint32_t(b));
    }

    // The component of the first node keeps the island entity; others get new islands, in the
    // order their first node appears, so that the result does not depend on entity values.
    std::vector<entity> island_of(nodes.size(), null);
    for (std::uint32_t i = 0; i < nodes.size(); ++i) {
        auto root = find(i);
        if (island_of[root] == null) island_of[root] = i == 0 ? island_entity : create_island(registry);
        auto target = island_of[root];
        push_resident(registry, registry.get<island>(target).nodes, nodes[i], target);
    }
    for (auto edge : edges) {
        auto &ends = registry.get<island_edge>(edge);
        auto a = node_of(ends.body[0]);
        auto b = a >= 0 ? a : node_of(ends.body[1]);
        if (b < 0) {
            registry.remove<island_resident, island_edge>(edge);
            continue;
        }
        auto target = island_of[find(std::uint32_t(b))];
        push_resident(registry, registry.get<island>(target).edges, edge, target);
    }
    if (nodes.empty()) destroy_island(registry, island_entity);
}

void island_manager::update_sleeping(registry &registry, const settings &settings, scalar dt) {
    auto lin_sqr = settings.sleep_linear_velocity * settings.sleep_linear_velocity;
    auto ang_sqr = settings.sleep_angular_velocity * settings.sleep_angular_velocity;
    registry.view<sleep_timer, linvel, angvel>(exclude<sleeping_tag>)
        .each([&](sleep_timer &timer, const linvel &v, const angvel &w) {
            if (length_sqr(v) > lin_sqr || length_sqr(w) > ang_sqr) {
                timer.time = 0;
            } else {
                timer.time += dt;
            }
        });

    // A copy, since splitting creates islands.
    candidates.clear();
    for (auto island_entity : registry.view<island>(exclude<sleeping_tag>))
        candidates.push_back(island_entity);
    // Of the islands that may have come apart, were not split for time_to_sleep, and hold a body
    // ready to sleep but also one that is not: the one whose ready body has waited longest (the
    // first of equals).
    entity sleepiest_island = null;
    scalar sleepiest_time = 0;
    for (auto island_entity : candidates) {
        if (!registry.valid(island_entity) || registry.all_of<sleeping_tag>(island_entity)) continue;
        auto &isle = registry.get<island>(island_entity);
        isle.since_split += dt;
        bool splittable = isle.may_split && isle.since_split >= settings.time_to_sleep;
        bool can_sleep = !isle.nodes.empty();
        bool any_ready = false;
        scalar longest_ready = 0;
        for (auto node : isle.nodes) {
            auto time = registry.get<sleep_timer>(node).time;
            if (time < settings.time_to_sleep || registry.all_of<sleeping_disabled_tag>(node)) {
                can_sleep = false;
                // Only an island that may split now needs to know whether any body is ready.
                if (!splittable) break;
            } else if (!any_ready || time > longest_ready) {
                any_ready = true;
                longest_ready = time;
            }
        }
        if (can_sleep) {
            if (isle.may_split) {
                // The pieces are checked again next step, each on its own.
                split(registry, island_entity);
                continue;
            }
            put_to_sleep(registry, island_entity);
        } else if (splittable && any_ready && (sleepiest_island == null || longest_ready > sleepiest_time)) {
            sleepiest_island = island_entity;
            sleepiest_time = longest_ready;
        }
    }
    // A body that left an island and never slows down (a ball rolling away) would keep every body
    // it once touched awake if an island split only once all its bodies were ready. So an island
    // that lost links and holds a body ready to sleep is split too: one a step, and each at most
    // once per time_to_sleep, since a split walks the whole island and a heap that keeps moving
    // loses links every step while it stays whole.
    if (sleepiest_island != null) split(registry, sleepiest_island);
}

void island_manager::clear(registry &registry) {
    candidates.clear();
    for (auto island_entity : registry.view<island>())
        candidates.push_back(island_entity);
    for (auto island_entity : candidates)
        registry.destroy(island_entity);
    registry.clear<island_resident, island_edge, sleep_timer>();
}

} // namespace edyn
