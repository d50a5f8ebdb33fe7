#ifndef EDYN_SIMULATION_REPLICATION_HPP
#define EDYN_SIMULATION_REPLICATION_HPP

#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/worker_calls.hpp"
#include "edyn/ecs/entity_members.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/action_list.hpp"
#include <functional>
#include <memory>
#include <tuple>
#include <type_traits>

namespace edyn {

/// How a value arriving from the main registry is merged into the simulation worker's copy of a
/// component the entity already has: by default it replaces it.
/// Specialise it to merge otherwise (before calling register_external_components for that
/// type). It runs in the worker thread, at the start of a step, after the value's entities
/// have been translated into the worker's:
/// @code
/// template<>
/// void edyn::merge_component<my_component>(my_component &current, const my_component &incoming) {
///     current.items.insert(current.items.end(), incoming.items.begin(), incoming.items.end());
/// }
/// @endcode
/// @tparam Component A component type registered with register_external_components (or one of
/// edyn's own).
/// @param current The worker's component, to update in place.
/// @param new_value The value that arrived from the main registry.
template<typename Component>
void merge_component(Component &current, const Component &new_value) {
    current = new_value;
}

namespace detail {

// Type-erased handlers of one replicated component type, built where its type is known.
struct replicated_type {
    const void *id; // unique per type
    void (*connect)(registry &);
    void (*disconnect)(registry &);
    // Sends the component's current value of entity e, if it has one.
    void (*send_existing)(registry &, entity);
};

// Registers the type with the main registry's asynchronous link (a no-op in the other modes).
// Throws std::invalid_argument naming `function` when the registry is not attached.
void register_replicated(registry &registry, const char *function, const replicated_type &type);

// Called by the listeners below: queue a copy, a removal, for the worker.
struct replication_sink {
    virtual ~replication_sink() = default;
    virtual bool accepts(registry &registry, entity e, bool edyn_component) = 0;
    // `sets`: the parts of the entity's motion the value sets (a position, a velocity).
    virtual void send(entity e,
                      std::function<void(registry &worker, entity worker_entity,
                                         const std::function<entity(entity)> &to_worker)>
                          apply,
                      motion_parts sets) = 0;
};

// The parts of a body's motion a component's value is.
template<typename Component>
constexpr motion_parts motion_parts_of() {
    if constexpr (std::is_same_v<Component, position> || std::is_same_v<Component, orientation>)
        return motion_parts::transform;
    else if constexpr (std::is_same_v<Component, linvel> || std::is_same_v<Component, angvel>)
        return motion_parts::velocity;
    else
        return motion_parts::none;
}
replication_sink *find_replication_sink(registry &registry) noexcept;

// An entity member naming an entity the program has destroyed (an exclusion list keeps the
// bodies it names) is sent as null: the worker would map it to a new entity of its own, in the
// place of the live entity that now has its index.
template<typename Component>
void forget_destroyed_members(const registry &registry, Component &value) {
    map_entity_members(value, [&](entity m) { return registry.valid(m) ? m : entity{null}; });
}

template<typename Component, bool EdynComponent>
void send_value(registry &registry, entity e) {
    auto *sink = find_replication_sink(registry);
    if (!sink || !sink->accepts(registry, e, EdynComponent)) return;
    if constexpr (std::is_empty_v<Component>) {
        sink->send(
            e,
            [](edyn::registry &worker, entity local, const std::function<entity(entity)> &) {
                if (!worker.all_of<Component>(local)) worker.emplace<Component>(local);
            },
            motion_parts::none);
    } else {
        auto value = registry.get<Component>(e);
        forget_destroyed_members(registry, value);
        sink->send(
            e,
            [value = std::move(value)](edyn::registry &worker, entity local,
                                       const std::function<entity(entity)> &to_worker) {
                auto copy = value;
                map_entity_members(copy, to_worker);
                if (auto *current = worker.try_get<Component>(local)) {
                    merge_component(*current, copy);
                    worker.patch<Component>(local);
                } else {
                    worker.emplace<Component>(local, std::move(copy));
                }
            },
            motion_parts_of<Component>());
    }
}

template<typename Component, bool EdynComponent>
void send_removal(registry &registry, entity e) {
    // An entity being destroyed is sent as a whole; its components are not sent one by one.
    if (registry.destroying(e)) return;
    auto *sink = find_replication_sink(registry);
    if (!sink || !sink->accepts(registry, e, EdynComponent)) return;
    sink->send(
        e,
        [](edyn::registry &worker, entity local, const std::function<entity(entity)> &) {
            worker.remove<Component>(local);
        },
        motion_parts_of<Component>());
}

template<typename Component, bool EdynComponent>
replicated_type make_replicated_type() {
    static_assert(!is_action_list_v<Component>,
                  "an action type is registered in the tuple: register_external_components<...>(registry, "
                  "std::tuple<Action>{})");
    static const char id = 0;
    return {&id,
            [](registry &r) {
                r.on_construct<Component>().template connect<&send_value<Component, EdynComponent>>();
                r.on_update<Component>().template connect<&send_value<Component, EdynComponent>>();
                r.on_destroy<Component>().template connect<&send_removal<Component, EdynComponent>>();
            },
            [](registry &r) {
                r.on_construct<Component>().template disconnect<&send_value<Component, EdynComponent>>();
                r.on_update<Component>().template disconnect<&send_value<Component, EdynComponent>>();
                r.on_destroy<Component>().template disconnect<&send_removal<Component, EdynComponent>>();
            },
            [](registry &r, entity e) {
                if (r.all_of<Component>(e)) send_value<Component, EdynComponent>(r, e);
            }};
}

template<typename Action>
action_type make_action_type() {
    static const char id = 0;
    return {&id,
            [](registry &r) {
                for (auto [e, list] : r.view<action_list<Action>>().each())
                    list.actions.clear();
            },
            [](registry &r, replication_sink &sink) {
                for (auto [e, list] : r.view<action_list<Action>>().each()) {
                    if (list.actions.empty() || !sink.accepts(r, e, false)) continue;
                    auto actions = list.actions;
                    for (auto &action : actions)
                        forget_destroyed_members(r, action);
                    sink.send(
                        e,
                        [actions = std::move(actions)](registry &worker, entity local,
                                                       const std::function<entity(entity)> &to_worker) {
                            auto &target = worker.get_or_emplace<action_list<Action>>(local).actions;
                            for (auto action : actions) {
                                map_entity_members(action, to_worker);
                                target.push_back(std::move(action));
                            }
                        },
                        motion_parts::none);
                }
            }};
}

} // namespace detail

/// Makes the program's own components, and its actions, travel to the simulation worker in
/// asynchronous mode.
/// On the entities the worker has (rigid bodies, constraints, external entities), the
/// components' emplace, replace, patch and removal are applied in the worker's registry at the
/// start of its next step, in the order they were made, and step callbacks see them there.
/// Values the entities have already are sent too. Entities the components hold are translated
/// into the worker's: declare them with edyn::entity_members (ecs/entity_members.hpp).
/// Changes only travel from the main registry to the worker, not back.
///
/// Action types (simulation/action_list.hpp) are listed in the tuple, in every mode: each
/// entity's action_list<A> is then seen by exactly one step and emptied after it. In
/// asynchronous mode each update sends the lists' actions to the worker (appended to the
/// worker's lists) and empties them in the main registry.
///
/// Registering a type twice does nothing more.
/// @code
/// edyn::register_external_components<steering, health>(registry, std::tuple<jump>{});
/// @endcode
/// @tparam Components The component types to replicate; each must be copyable, and none an
/// action_list.
/// @tparam Actions The action types; each must be copyable.
/// @param registry The main registry, attached.
/// @throws std::invalid_argument Naming the function, when the registry is not attached.
template<typename... Components, typename... Actions>
void register_external_components(registry &registry, std::tuple<Actions...> = {}) {
    (detail::register_replicated(registry, "register_external_components",
                                 detail::make_replicated_type<Components, false>()),
     ...);
    (detail::register_action_type(registry, "register_external_components",
                                  detail::make_action_type<Actions>()),
     ...);
}

/// Marks `entity` as external, so that it can take part in the simulation without being a
/// rigid body.
/// An external entity (constraints/external_entity.hpp) joined to a rigid body with a
/// null_constraint travels, with its registered components, to the simulation worker, where
/// step callbacks can use it. Tagging an entity twice does nothing more.
/// @param registry An attached registry (the main one, in asynchronous mode).
/// @param entity The entity to tag; not a rigid body.
/// @throws std::invalid_argument Naming the function, when the registry is not attached, when
/// `entity` is not valid, or when it is a rigid body (which is part of the simulation already).
void tag_external_entity(registry &registry, entity entity);

} // namespace edyn

#endif // EDYN_SIMULATION_REPLICATION_HPP
