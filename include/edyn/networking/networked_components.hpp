#ifndef EDYN_NETWORKING_NETWORKED_COMPONENTS_HPP
#define EDYN_NETWORKING_NETWORKED_COMPONENTS_HPP

#include "edyn/ecs/entity_members.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/ecs/type_info.hpp"
#include "edyn/networking/action_list.hpp"
#include "edyn/networking/networked_tag.hpp"
#include "edyn/serialization/memory_archive.hpp"
#include "edyn/serialization/std_types.hpp"
#include "edyn/simulation/replication.hpp"
#include "edyn/simulation/world.hpp"
#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <tuple>
#include <vector>

namespace edyn {

namespace detail {

// Translates entities between the two ends' registries (identity when null).
using entity_mapper = std::function<entity(entity)>;

// A pool of a packet, decoded and checked: the values by position in the packet's entity list,
// ready to be set on the receiving registry's entities.
struct decoded_pool {
    virtual ~decoded_pool() = default;
    std::uint16_t component_index{};
    std::vector<std::uint32_t> positions;
    // Sets each value on `entities[position]`, skipping null entities, with the entities the
    // values hold translated by `map`.
    virtual void apply(registry &registry, const std::vector<entity> &entities, const entity_mapper &map) = 0;
};

// Type-erased handlers of one networked component type.
struct networked_type {
    std::size_t type{}; // type_index of the component
    bool input{false};  // derives from network_input
    bool action{false}; // an action_list<A>
    // Connects the listeners that record its changes (snapshots carry recent changes).
    void (*connect)(registry &){};
    bool (*has)(const registry &, entity){};
    // Removes the component from `e` (which may lack it): a removal the other end sent.
    void (*remove)(registry &, entity){};
    // Writes the value of `e` (which has it), with the entities it holds translated by `map`.
    void (*write)(const registry &, entity, const entity_mapper &map, memory_output_archive &){};
    // Reads values until the end of the pool's bytes; null when they are malformed or name a
    // position past `entity_count`.
    std::unique_ptr<decoded_pool> (*read)(const std::vector<std::uint8_t> &data, std::size_t entity_count){};
    // Actions only: copies every entity's action_list into its action_history, stamped `time`
    // (or `spacing` after the entity's last entry, if that is later), and drops entries older
    // than `time - keep` (the client's side, just before the lists are emptied:
    // simulation/action_list.hpp).
    void (*record_actions)(registry &, double time, double keep, double spacing){};
};

template<typename Component>
struct typed_decoded_pool : decoded_pool {
    std::vector<Component> values;

    void apply(registry &registry, const std::vector<entity> &entities, const entity_mapper &map) override {
        for (std::size_t i = 0; i < positions.size(); ++i) {
            auto e = entities[positions[i]];
            if (e == null || !registry.valid(e)) continue;
            auto value = values[i];
            if (map) map_entity_members(value, map);
            if (auto *current = registry.try_get<Component>(e)) {
                if constexpr (!std::is_empty_v<Component>) *current = std::move(value);
                registry.patch<Component>(e);
            } else {
                registry.emplace<Component>(e, std::move(value));
            }
        }
    }
};

// The action histories a client sends: each entry not seen before is added to the entity's
// action_list, once.
template<typename Action>
struct typed_decoded_pool<action_history<Action>> : decoded_pool {
    std::vector<action_history<Action>> values;

    void apply(registry &registry, const std::vector<entity> &entities, const entity_mapper &map) override {
        for (std::size_t i = 0; i < positions.size(); ++i) {
            auto e = entities[positions[i]];
            if (e == null || !registry.valid(e)) continue;
            auto &seen = registry.get_or_emplace<action_history<Action>>(e);
            auto &list = registry.get_or_emplace<action_list<Action>>(e);
            auto newest = seen.last_applied;
            for (auto &entry : values[i].entries) {
                if (!(entry.timestamp > seen.last_applied)) continue;
                for (auto action : entry.actions) {
                    if (map) map_entity_members(action, map);
                    list.actions.push_back(std::move(action));
                }
                newest = std::max(newest, entry.timestamp);
            }
            seen.last_applied = newest;
            registry.patch<action_list<Action>>(e);
        }
    }
};

// Records that `e`'s component changed, in the registry's list of networked types.
void mark_network_change(registry &registry, std::size_t type, entity e);
// Records that `e`'s component was removed.
void mark_network_removal(registry &registry, std::size_t type, entity e);

template<typename Component>
void on_networked_change(registry &registry, entity e) {
    mark_network_change(registry, type_index<Component>(), e);
}

template<typename Component>
void on_networked_removal(registry &registry, entity e) {
    mark_network_removal(registry, type_index<Component>(), e);
}

// Each entry goes `spacing` after the entity's last at least: the server adds only entries later
// than those it applied, and the client's time can repeat (its lead moved down, or two updates
// ran no step between them).
template<typename Action>
void record_actions(registry &registry, double time, double keep, double spacing) {
    for (auto [e, list] : registry.view<action_list<Action>>().each()) {
        if (list.actions.empty()) continue;
        auto &entries = registry.get_or_emplace<action_history<Action>>(e).entries;
        auto stamp = entries.empty() ? time : std::max(time, entries.back().timestamp + spacing);
        entries.push_back({stamp, list.actions});
    }
    for (auto [e, history] : registry.view<action_history<Action>>().each()) {
        auto &entries = history.entries;
        auto old = std::find_if(entries.begin(), entries.end(),
                                [&](auto &entry) { return entry.timestamp >= time - keep; });
        entries.erase(entries.begin(), old);
    }
}

template<typename Component>
networked_type make_networked_type() {
    networked_type t;
    t.type = type_index<Component>();
    t.input = is_network_input_v<Component>;
    t.connect = [](registry &r) {
        r.on_construct<Component>().template connect<&on_networked_change<Component>>();
        r.on_update<Component>().template connect<&on_networked_change<Component>>();
        r.on_destroy<Component>().template connect<&on_networked_removal<Component>>();
    };
    t.has = [](const registry &r, entity e) { return r.all_of<Component>(e); };
    t.remove = [](registry &r, entity e) { r.remove<Component>(e); };
    t.write = [](const registry &r, entity e, const entity_mapper &map, memory_output_archive &archive) {
        if constexpr (!std::is_empty_v<Component>) {
            auto value = r.get<Component>(e);
            if (map) map_entity_members(value, map);
            archive(value);
        }
    };
    t.read = [](const std::vector<std::uint8_t> &data,
                std::size_t entity_count) -> std::unique_ptr<decoded_pool> {
        auto pool = std::make_unique<typed_decoded_pool<Component>>();
        auto archive = memory_input_archive(data.data(), data.size());
        while (archive.remaining() > 0 && !archive.failed()) {
            if (entity_count == 0) return nullptr;
            auto position = archive.read_size(entity_count - 1);
            Component value{};
            archive(value);
            if (archive.failed()) return nullptr;
            pool->positions.push_back(std::uint32_t(position));
            pool->values.push_back(std::move(value));
            // Empty components take no bytes: a pool of them cannot be longer than its entities.
            if (pool->positions.size() > entity_count) return nullptr;
        }
        if (archive.failed()) return nullptr;
        return pool;
    };
    return t;
}

// Adds the types to the registry's list (created with edyn's own types first); a type already
// listed keeps its place.
void register_networked_types(registry &registry, std::vector<networked_type> types);

} // namespace detail

/// Makes the program's components part of registry snapshots.
///
/// Their values travel between server and clients, on networked entities, whenever they change
/// (and with the entity when it is created on a client). Components derived from network_input
/// are the clients' inputs. Actions (simulation/action_list.hpp) are listed in the tuple, as they
/// are in register_external_components. Server and clients
/// must register the same types in the same order, after register_external_components; a
/// component that is not empty needs a free `serialize(Archive &, T &)`, found by
/// argument-dependent lookup. A type registered already keeps its place; nothing throws.
/// @code
/// edyn::register_networked_components<steering, health>(registry, std::tuple<jump>{});
/// @endcode
/// @tparam Components The program's networked components.
/// @tparam Actions The program's action types (each travels as an action_history).
/// @param registry The registry of the server or client.
template<typename... Components, typename... Actions>
void register_networked_components(registry &registry, std::tuple<Actions...> = {}) {
    auto types = std::vector<detail::networked_type>{detail::make_networked_type<Components>()...};
    (
        [&] {
            auto t = detail::make_networked_type<action_history<Actions>>();
            t.action = true;
            t.connect = [](edyn::registry &) {};
            t.record_actions = &detail::record_actions<Actions>;
            types.push_back(t);
            // Emptied after each step even where the program left them out of
            // register_external_components.
            if (is_attached(registry))
                detail::register_action_type(registry, "register_networked_components",
                                             detail::make_action_type<Actions>());
        }(),
        ...);
    detail::register_networked_types(registry, std::move(types));
}

} // namespace edyn

#endif // EDYN_NETWORKING_NETWORKED_COMPONENTS_HPP
