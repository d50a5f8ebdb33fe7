#ifndef EDYN_ECS_REGISTRY_HPP
#define EDYN_ECS_REGISTRY_HPP

#include "edyn/config/assert.hpp"
#include "edyn/ecs/construct.hpp"
#include "edyn/ecs/context.hpp"
#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/entity_allocator.hpp"
#include "edyn/ecs/sigh.hpp"
#include "edyn/ecs/sink.hpp"
#include "edyn/ecs/sparse_set.hpp"
#include "edyn/ecs/storage.hpp"
#include "edyn/ecs/type_info.hpp"
#include "edyn/ecs/view.hpp"
#include <algorithm>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace edyn {

namespace detail {

[[nodiscard]] inline std::string describe(entity e) {
    auto text = "entity " + std::to_string(to_index(e));
    if (to_version(e) != 0) {
        text += " (version " + std::to_string(to_version(e)) + ")";
    }
    return text;
}

[[noreturn]] inline void throw_invalid_entity(std::string_view function, entity e, std::string_view type) {
    auto message = std::string(function) + ": " + describe(e) + " is not valid";
    if (!type.empty()) {
        message += " (component " + std::string(type) + ")";
    }
    throw std::invalid_argument(message);
}

[[noreturn]] inline void throw_has_component(std::string_view function, entity e, std::string_view type) {
    throw std::invalid_argument(std::string(function) + ": " + describe(e) + " already has component " +
                                std::string(type));
}

// Throws std::invalid_argument when the range holds an entity twice: range functions check
// the whole range before changing anything.
template<typename It>
void check_no_repeats(std::string_view function, It first, It last, std::string_view type) {
    std::vector<entity> sorted(first, last);
    std::sort(sorted.begin(), sorted.end());
    if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end()) {
        auto message = std::string(function) + ": " + describe(*it) + " appears more than once in the range";
        if (!type.empty()) {
            message += " (component " + std::string(type) + ")";
        }
        throw std::invalid_argument(message);
    }
}

} // namespace detail

/// Entities and their components, EnTT style: the container of a world's whole state.
///
/// See `sparse_set` and `storage` for what invalidates references, `basic_view` for what is safe
/// while iterating. A registry is not thread-safe: use it from one thread at a time. In
/// asynchronous mode the simulation worker owns a registry of its own; the application's
/// registry stays with the thread that calls `edyn::update`.
///
/// Misuse:
/// - `get`, `replace`, `patch`, `erase` and `orphan` on an invalid entity, or `get`, `replace`,
///   `patch`, `erase` of a component the entity does not have: `EDYN_ASSERT` (debug builds).
/// - `emplace` (and `emplace_or_replace`, `get_or_emplace`, `insert`) on an invalid entity, or
///   of a component the entity already has, and `destroy` of an invalid entity:
///   `std::invalid_argument` naming the function, the entity and the component type; the
///   registry is left unchanged.
/// - `remove`, `try_get`, `all_of` and `any_of` accept stale entities (they have no components).
///
/// Signals (`on_construct<T>()`, `on_update<T>()`, `on_destroy<T>()`; listeners take
/// `(registry &, entity)`):
/// - on_construct fires after the component is in place (the listener can `get` it): on
///   `emplace`, `get_or_emplace`, `insert` and the emplacing branch of `emplace_or_replace`.
/// - on_update fires after the component was changed: on `replace`, `patch` (with or without
///   functions) and the replacing branch of `emplace_or_replace`.
/// - on_destroy fires before the component is removed (the listener can still `get` it): on
///   `remove`, `erase`, `clear<T>()` and `destroy`. `destroy(e)` fires it for each component of
///   `e`, pools visited in reverse order of their creation in this registry, then frees the id:
///   `valid(e)` is still true inside those listeners.
///
/// Listeners may add and remove components and create and destroy entities, within the rules of
/// `basic_view` when the registry is being iterated. Components that on_destroy listeners add to
/// an entity being destroyed are removed too (with their own on_destroy), and `destroy(e)` called
/// from a listener that `destroy(e)` fired does nothing. Listeners connected to a signal while
/// it fires are first called by its next firing (see `sigh`). Nothing fires when the registry
/// is destroyed or moved.
///
/// Empty component types (tags) store nothing; `emplace`, `get` and `try_get` give a reference
/// or pointer to one shared instance of the type.
class registry {
    using signal_type = sigh<void(registry &, entity)>;

    struct pool_signals {
        signal_type construct;
        signal_type update;
        signal_type destroy;
    };

    // Pools and their signals are allocated one by one, so that sinks, views and running
    // publishes keep valid pointers while new pools are added.
    struct pool_record {
        std::unique_ptr<sparse_set> set;
        std::unique_ptr<pool_signals> signals;
    };

    struct pool_slot {
        sparse_set *set{nullptr};
        pool_signals *signals{nullptr};
    };

    template<typename Type>
    struct typed_pool {
        edyn::storage<Type> &pool;
        pool_signals &signals;
    };

    struct destroy_guard {
        std::vector<entity> &destroying;
        explicit destroy_guard(std::vector<entity> &destroying) noexcept
            : destroying(destroying) {}
        destroy_guard(const destroy_guard &) = delete;
        destroy_guard &operator=(const destroy_guard &) = delete;
        ~destroy_guard() { destroying.pop_back(); }
    };

public:
    /// Unsigned integer type for counts of entities and components.
    using size_type = std::size_t;

    registry() = default;
    registry(const registry &) = delete;
    registry &operator=(const registry &) = delete;
    /// Takes over the entities, pools, signals and context of `other`, which is left empty;
    /// references to components stay valid. No signal fires.
    registry(registry &&) noexcept = default;

    /// Destroys this registry's context variables and pools (no signal fires), then takes over
    /// those of `other`.
    /// @param other The registry to move from; left empty.
    /// @return This registry.
    registry &operator=(registry &&other) noexcept {
        if (this != &other) {
            release_storage();
            ids = std::move(other.ids);
            records = std::move(other.records);
            slots = std::move(other.slots);
            in_destroy = std::move(other.in_destroy);
            vars = std::move(other.vars);
        }
        return *this;
    }

    /// Destroys the context variables first (they may hold sinks of the pools), then the pools,
    /// newest first. No signal fires.
    ~registry() { release_storage(); }

    /// Creates an entity with no component, reusing the most recently freed index (with its
    /// bumped version) when there is one.
    /// @return The new entity.
    /// @throws std::length_error When all 2^20 - 1 indices are in use.
    entity create() { return ids.create(); }

    /// Creates exactly `hint` if its index is free (any version), otherwise behaves as
    /// `create()`. Indices skipped over become free. Used to give entities the same ids as in
    /// another registry, for example when loading a snapshot.
    /// @param hint The entity wanted; null means no preference.
    /// @return `hint`, or a new entity when its index was taken.
    /// @throws std::length_error When a new index is needed and all indices are in use.
    entity create(entity hint) { return ids.create(hint); }

    /// Removes every component of `e` (firing on_destroy for each), then frees its id, so that
    /// `valid(e)` becomes false. Called again for `e` from one of the listeners this fires, it
    /// does nothing: the outer call finishes the job.
    /// @param e The entity to destroy.
    /// @throws std::invalid_argument When `e` is not valid (null, stale or never created);
    /// nothing is changed then.
    void destroy(entity e) {
        if (!valid(e)) {
            detail::throw_invalid_entity("registry::destroy", e, {});
        }
        if (std::find(in_destroy.begin(), in_destroy.end(), e) != in_destroy.end()) {
            return;
        }
        ids.reserve_release();
        in_destroy.push_back(e);
        const destroy_guard guard{in_destroy};
        remove_all(e);
        ids.release(e);
    }

    /// Whether `destroy(e)` is under way: true inside the on_destroy listeners it fires, which
    /// can so tell an entity going away from one component being removed.
    /// @param e Any entity.
    /// @return True while `destroy(e)` runs.
    [[nodiscard]] bool destroying(entity e) const noexcept {
        return std::find(in_destroy.begin(), in_destroy.end(), e) != in_destroy.end();
    }

    /// Destroys each entity of the range, in order.
    /// @param first Iterator to the first entity.
    /// @param last Iterator past the last entity.
    /// @throws std::invalid_argument When one of the entities is invalid, or the range holds the
    /// same entity twice; none is destroyed then.
    template<typename It>
    void destroy(It first, It last) {
        for (auto it = first; it != last; ++it) {
            if (!valid(*it)) {
                detail::throw_invalid_entity("registry::destroy", *it, {});
            }
        }
        detail::check_no_repeats("registry::destroy", first, last, {});
        for (; first != last; ++first) {
            destroy(*first);
        }
    }

    /// Whether `e` is alive in this registry.
    /// @param e Any entity.
    /// @return False for null, destroyed (stale) and never-created entities.
    [[nodiscard]] bool valid(entity e) const noexcept { return ids.valid(e); }

    /// The version the slot of `e` has now (the version a new entity there would get if free).
    /// @param e Any entity; only its index is used.
    /// @return The slot's version, or 0 for an index never handed out.
    [[nodiscard]] entity_traits::value_type current(entity e) const noexcept { return ids.current(e); }

    /// Number of entities alive.
    /// @return How many entities are valid.
    [[nodiscard]] size_type alive() const noexcept { return ids.alive(); }

    /// Calls `func(entity)` for each entity alive, highest index first. Destroying the visited
    /// entity, or creating entities (which are not visited unless they reuse a lower index), is
    /// safe.
    /// @param func Callable taking an `entity`.
    template<typename Func>
    void each(Func func) const {
        for (auto idx = ids.size(); idx-- > 0;) {
            if (const auto e = ids.at(idx); e != null) {
                func(e);
            }
        }
    }

    /// Whether `e` has no component at all.
    /// @param e A valid entity (precondition, checked by `EDYN_ASSERT`).
    /// @return True when no pool holds `e`.
    [[nodiscard]] bool orphan(entity e) const noexcept {
        EDYN_ASSERT(valid(e), "registry::orphan: invalid entity");
        return std::none_of(records.begin(), records.end(),
                            [e](const pool_record &record) { return record.set->contains(e); });
    }

    /// Adds a component of type `Type` to `e`, built from `args` (parentheses, or braces for
    /// aggregates), then fires on_construct.
    /// @tparam Type The component type.
    /// @param e The entity that receives the component.
    /// @param args Constructor arguments of the component.
    /// @return The new component (it may have moved if an on_construct listener changed the pool:
    /// the reference returned is looked up after the listeners ran).
    /// @throws std::invalid_argument When `e` is not valid or already has a `Type`; nothing is
    /// changed then.
    template<typename Type, typename... Args>
    Type &emplace(entity e, Args &&...args) {
        if (!valid(e)) {
            detail::throw_invalid_entity("registry::emplace", e, type_name<Type>());
        }
        auto [pool, signals] = assure<Type>();
        if (pool.contains(e)) {
            detail::throw_has_component("registry::emplace", e, type_name<Type>());
        }
        return construct(pool, signals, e, std::forward<Args>(args)...);
    }

    /// Adds a copy of `value` to each entity of the range, firing on_construct for each.
    /// @tparam Type The component type.
    /// @param first Iterator to the first entity.
    /// @param last Iterator past the last entity.
    /// @param value The component to copy; value-initialised by default.
    /// @throws std::invalid_argument When an entity is invalid or already has the component, or
    /// the range holds the same entity twice; nothing is added then.
    template<typename Type, typename It>
    void insert(It first, It last, const Type &value = {}) {
        auto [pool, signals] = assure<Type>();
        for (auto it = first; it != last; ++it) {
            if (!valid(*it)) {
                detail::throw_invalid_entity("registry::insert", *it, type_name<Type>());
            }
            if (pool.contains(*it)) {
                detail::throw_has_component("registry::insert", *it, type_name<Type>());
            }
        }
        detail::check_no_repeats("registry::insert", first, last, type_name<Type>());
        for (; first != last; ++first) {
            construct(pool, signals, *first, value);
        }
    }

    /// Adds a component of type `Type` to `e` (firing on_construct) or, if `e` already has
    /// one, assigns a new value built from `args` (firing on_update).
    /// @tparam Type The component type.
    /// @param e The entity.
    /// @param args Constructor arguments of the component.
    /// @return The component.
    /// @throws std::invalid_argument When `e` is not valid; nothing is changed then.
    template<typename Type, typename... Args>
    Type &emplace_or_replace(entity e, Args &&...args) {
        if (!valid(e)) {
            detail::throw_invalid_entity("registry::emplace_or_replace", e, type_name<Type>());
        }
        auto [pool, signals] = assure<Type>();
        if (!pool.contains(e)) {
            return construct(pool, signals, e, std::forward<Args>(args)...);
        }
        assign(pool.get(e), std::forward<Args>(args)...);
        return notify(pool, signals.update, e);
    }

    /// The component of type `Type` of `e`, added from `args` (firing on_construct) if `e` has
    /// none; `args` are ignored otherwise and no signal fires.
    /// @tparam Type The component type.
    /// @param e The entity.
    /// @param args Constructor arguments used when the component is added.
    /// @return The component.
    /// @throws std::invalid_argument When `e` is not valid; nothing is changed then.
    template<typename Type, typename... Args>
    Type &get_or_emplace(entity e, Args &&...args) {
        if (!valid(e)) {
            detail::throw_invalid_entity("registry::get_or_emplace", e, type_name<Type>());
        }
        auto [pool, signals] = assure<Type>();
        if (pool.contains(e)) {
            return pool.get(e);
        }
        return construct(pool, signals, e, std::forward<Args>(args)...);
    }

    /// Assigns a component built from `args` (the new value is built before the old one is
    /// touched), then fires on_update. In asynchronous mode and with networking, this is how a
    /// change to a registered component reaches the simulation worker or the peers.
    /// @tparam Type The component type.
    /// @param e A valid entity that has a `Type` (preconditions, checked by `EDYN_ASSERT` only).
    /// @param args Constructor arguments of the new value.
    /// @return The component.
    template<typename Type, typename... Args>
    Type &replace(entity e, Args &&...args) {
        auto [pool, signals] = checked_pool<Type>(e);
        assign(pool.get(e), std::forward<Args>(args)...);
        return notify(pool, signals.update, e);
    }

    /// Calls each `func(component)` in turn, then fires on_update. With no function it only
    /// fires on_update, to publish a change made through a reference. In asynchronous mode and
    /// with networking, this is how a change to a registered component reaches the simulation
    /// worker or the peers.
    /// @tparam Type The component type.
    /// @param e A valid entity that has a `Type` (preconditions, checked by `EDYN_ASSERT` only).
    /// @param func Callables taking `Type &`, called in order.
    /// @return The component.
    template<typename Type, typename... Func>
    Type &patch(entity e, Func &&...func) {
        auto [pool, signals] = checked_pool<Type>(e);
        auto &component = pool.get(e);
        (std::forward<Func>(func)(component), ...);
        return notify(pool, signals.update, e);
    }

    /// Removes the components `e` has among `Type...`, firing on_destroy before each removal.
    /// @tparam Type The component types.
    /// @param e Any entity; stale and null ones have no component.
    /// @return How many of the components `e` had.
    template<typename... Type>
    size_type remove(entity e) {
        size_type count = 0;
        ((count += remove_one<Type>(e)), ...);
        return count;
    }

    /// Removes the components among `Type...` from every entity of the range, firing
    /// on_destroy before each removal.
    /// @tparam Type The component types.
    /// @param first Iterator to the first entity.
    /// @param last Iterator past the last entity.
    /// @return How many components were removed in all.
    template<typename... Type, typename It>
    size_type remove(It first, It last) {
        size_type count = 0;
        for (; first != last; ++first) {
            count += remove<Type...>(*first);
        }
        return count;
    }

    /// Removes components `e` must have, firing on_destroy before each removal; `remove` for
    /// components that may be missing.
    /// @tparam Type The component types.
    /// @param e A valid entity that has every `Type` (preconditions, checked by `EDYN_ASSERT`).
    template<typename... Type>
    void erase(entity e) {
        EDYN_ASSERT(valid(e), "registry::erase: invalid entity");
        EDYN_ASSERT(all_of<Type...>(e), "registry::erase: entity does not have the component");
        (remove_one<Type>(e), ...);
    }

    /// Components of `e`: `get<T>(e)` gives `T &`, `get<T, U>(e)` a `std::tuple<T &, U &>`.
    /// @tparam Type The component types.
    /// @param e A valid entity that has every `Type` (preconditions, checked by `EDYN_ASSERT`).
    /// @return A reference, or a tuple of references; see `storage` for how long they stay
    /// valid.
    template<typename... Type>
    [[nodiscard]] decltype(auto) get(entity e) {
        if constexpr (sizeof...(Type) == 1) {
            return (get_one<Type>(e), ...);
        } else {
            return std::forward_as_tuple(get_one<Type>(e)...);
        }
    }

    /// Read-only `get`: `const` references.
    /// @tparam Type The component types.
    /// @param e A valid entity that has every `Type` (preconditions, checked by `EDYN_ASSERT`).
    /// @return A const reference, or a tuple of const references.
    template<typename... Type>
    [[nodiscard]] decltype(auto) get(entity e) const {
        if constexpr (sizeof...(Type) == 1) {
            return (get_one<const Type>(e), ...);
        } else {
            return std::forward_as_tuple(get_one<const Type>(e)...);
        }
    }

    /// Pointer to the component, or null when `e` has none; several types give a tuple of
    /// pointers.
    /// @tparam Type The component types.
    /// @param e Any entity, stale and null ones included.
    /// @return A pointer, or a tuple of pointers.
    template<typename... Type>
    [[nodiscard]] auto try_get(entity e) {
        if constexpr (sizeof...(Type) == 1) {
            return (try_get_one<Type>(e), ...);
        } else {
            return std::make_tuple(try_get_one<Type>(e)...);
        }
    }

    /// Read-only `try_get`: pointers to `const`.
    /// @tparam Type The component types.
    /// @param e Any entity, stale and null ones included.
    /// @return A pointer, or a tuple of pointers.
    template<typename... Type>
    [[nodiscard]] auto try_get(entity e) const {
        if constexpr (sizeof...(Type) == 1) {
            return (try_get_one<const Type>(e), ...);
        } else {
            return std::make_tuple(try_get_one<const Type>(e)...);
        }
    }

    /// Whether `e` has every component among `Type...`.
    /// @param e Any entity, stale and null ones included.
    /// @return True when it has all of them (true for an empty list).
    template<typename... Type>
    [[nodiscard]] bool all_of([[maybe_unused]] entity e) const noexcept {
        return (has<Type>(e) && ...);
    }

    /// Whether `e` has at least one component among `Type...`.
    /// @param e Any entity, stale and null ones included.
    /// @return True when it has one of them (false for an empty list).
    template<typename... Type>
    [[nodiscard]] bool any_of([[maybe_unused]] entity e) const noexcept {
        return (has<Type>(e) || ...);
    }

    /// `clear<T...>()` removes those components from every entity (firing on_destroy for each,
    /// newest first); `clear()` destroys every entity, as `destroy` does.
    /// @tparam Type The component types, or none to destroy every entity.
    template<typename... Type>
    void clear() {
        if constexpr (sizeof...(Type) == 0) {
            for (auto idx = ids.size(); idx-- > 0;) {
                if (const auto e = ids.at(idx); e != null) {
                    destroy(e);
                }
            }
        } else {
            (clear_pool<Type>(), ...);
        }
    }

    /// The pool of `Type`, created if needed. Changes made through it fire no signals.
    /// @tparam Type The component type.
    /// @return The pool, valid as long as the registry.
    template<typename Type>
    edyn::storage<Type> &storage() {
        return assure<Type>().pool;
    }

    /// The pool of `Type`, or a shared empty pool if this registry has none.
    /// @tparam Type The component type.
    /// @return A read-only pool.
    template<typename Type>
    [[nodiscard]] const edyn::storage<Type> &storage() const {
        return const_pool<Type>();
    }

    /// A view of the entities that have every component among `Type...` and none among
    /// `Exclude...`: `registry.view<A, B>(edyn::exclude<C>)`. Creates the pools it needs.
    /// @tparam Type The component types iterated (`const` for read-only access).
    /// @return A view; see `basic_view` for what is safe while iterating.
    template<typename... Type, typename... Exclude>
    [[nodiscard]] basic_view<get_t<Type...>, exclude_t<Exclude...>>
    view(exclude_t<Exclude...> = exclude_t<Exclude...>{}) {
        using filter_type = std::array<const sparse_set *, sizeof...(Exclude)>;
        return {assure<std::remove_const_t<Type>>().pool..., filter_type{&assure<Exclude>().pool...}};
    }

    /// A read-only view of the entities that have every component among `Type...` and none
    /// among `Exclude...`; missing pools are taken as empty.
    /// @tparam Type The component types iterated.
    /// @return A view whose components are `const`.
    template<typename... Type, typename... Exclude>
    [[nodiscard]] basic_view<get_t<const Type...>, exclude_t<Exclude...>>
    view(exclude_t<Exclude...> = exclude_t<Exclude...>{}) const {
        using filter_type = std::array<const sparse_set *, sizeof...(Exclude)>;
        return {const_pool<std::remove_const_t<Type>>()..., filter_type{&const_pool<Exclude>()...}};
    }

    /// The signal fired after a component of type `Type` is added to an entity.
    /// @tparam Type The component type.
    /// @return A sink for listeners taking `(registry &, entity)`.
    template<typename Type>
    [[nodiscard]] sink<signal_type> on_construct() {
        return sink{assure<Type>().signals.construct};
    }

    /// The signal fired after a component of type `Type` is changed through `replace`, `patch`
    /// or `emplace_or_replace`.
    /// @tparam Type The component type.
    /// @return A sink for listeners taking `(registry &, entity)`.
    template<typename Type>
    [[nodiscard]] sink<signal_type> on_update() {
        return sink{assure<Type>().signals.update};
    }

    /// The signal fired before a component of type `Type` is removed from an entity, whether
    /// by `remove`, `erase`, `clear` or `destroy`.
    /// @tparam Type The component type.
    /// @return A sink for listeners taking `(registry &, entity)`.
    template<typename Type>
    [[nodiscard]] sink<signal_type> on_destroy() {
        return sink{assure<Type>().signals.destroy};
    }

    /// The registry's context variables: per-registry values, one per type.
    /// @return The context, valid as long as the registry.
    [[nodiscard]] context &ctx() noexcept { return vars; }
    /// Read-only `ctx`.
    /// @return The context.
    [[nodiscard]] const context &ctx() const noexcept { return vars; }

private:
    template<typename Type>
    typed_pool<Type> assure() {
        static_assert(std::is_same_v<Type, std::remove_cvref_t<Type>>,
                      "registry: component types must not be references or cv-qualified");
        const auto id = type_index<Type>();
        if (id >= slots.size() || slots[id].set == nullptr) {
            create_pool<Type>(id);
        }
        const auto slot = slots[id];
        return {static_cast<edyn::storage<Type> &>(*slot.set), *slot.signals};
    }

    template<typename Type>
    void create_pool(std::size_t id) {
        pool_record record{std::make_unique<edyn::storage<Type>>(), std::make_unique<pool_signals>()};
        if (id >= slots.size()) {
            slots.resize(id + 1);
        }
        records.push_back(std::move(record));
        slots[id] = {records.back().set.get(), records.back().signals.get()};
    }

    // The slot of `Type` (a copy: `slots` may grow while a listener runs), empty if none.
    template<typename Type>
    [[nodiscard]] pool_slot find_slot() const noexcept {
        const auto id = type_index<Type>();
        return id < slots.size() ? slots[id] : pool_slot{};
    }

    template<typename Type>
    [[nodiscard]] edyn::storage<Type> *find_pool() const noexcept {
        return static_cast<edyn::storage<Type> *>(find_slot<Type>().set);
    }

    template<typename Type>
    [[nodiscard]] const edyn::storage<Type> &const_pool() const {
        if (const auto *pool = find_pool<Type>()) {
            return *pool;
        }
        static const edyn::storage<Type> placeholder{};
        return placeholder;
    }

    template<typename Type>
    typed_pool<Type> checked_pool([[maybe_unused]] entity e) {
        EDYN_ASSERT(valid(e), "registry: invalid entity");
        const auto slot = find_slot<Type>();
        EDYN_ASSERT(slot.set != nullptr && slot.set->contains(e),
                    "registry: entity does not have the component");
        return {static_cast<edyn::storage<Type> &>(*slot.set), *slot.signals};
    }

    template<typename Type, typename... Args>
    Type &construct(edyn::storage<Type> &pool, pool_signals &signals, entity e, Args &&...args) {
        auto &component = pool.emplace(e, std::forward<Args>(args)...);
        if (signals.construct.empty()) {
            return component;
        }
        return notify(pool, signals.construct, e);
    }

    template<typename Type, typename... Args>
    static void assign(Type &component, Args &&...args) {
        if constexpr (!std::is_empty_v<Type>) {
            component = detail::make_component<Type>(std::forward<Args>(args)...);
        } else {
            ((void)args, ...);
        }
    }

    // Publishes, then looks the component up again: a listener may have moved it.
    template<typename Type>
    Type &notify(edyn::storage<Type> &pool, signal_type &signal, entity e) {
        if (!signal.empty()) {
            signal.publish(*this, e);
        }
        return pool.get(e);
    }

    template<typename Type>
    size_type remove_one(entity e) {
        static_assert(std::is_same_v<Type, std::remove_cvref_t<Type>>,
                      "registry: component types must not be references or cv-qualified");
        const auto slot = find_slot<Type>();
        if (slot.set == nullptr || !slot.set->contains(e)) {
            return 0;
        }
        auto &pool = static_cast<edyn::storage<Type> &>(*slot.set);
        if (!slot.signals->destroy.empty()) {
            slot.signals->destroy.publish(*this, e);
        }
        if (pool.contains(e)) {
            pool.erase(e);
        }
        return 1;
    }

    // Fires on_destroy for and removes every component of `e`. Listeners may add components to
    // pools already visited, hence the repeated passes while any listener ran.
    void remove_all(entity e) {
        for (bool listeners_ran = true; listeners_ran;) {
            listeners_ran = false;
            for (auto i = records.size(); i-- > 0;) {
                // Copies of the pointers: `records` may grow while a listener runs.
                auto *set = records[i].set.get();
                auto *signals = records[i].signals.get();
                if (!set->contains(e)) {
                    continue;
                }
                if (!signals->destroy.empty()) {
                    signals->destroy.publish(*this, e);
                    listeners_ran = true;
                }
                set->remove(e);
            }
        }
    }

    template<typename Type>
    void clear_pool() {
        const auto slot = find_slot<Type>();
        if (slot.set == nullptr) {
            return;
        }
        auto &pool = static_cast<edyn::storage<Type> &>(*slot.set);
        auto &signal = slot.signals->destroy;
        // Newest first, so that each removal is a pop from the back.
        while (!pool.empty()) {
            if (signal.empty()) {
                pool.clear();
                return;
            }
            const auto e = pool.data()[pool.size() - 1];
            signal.publish(*this, e);
            if (pool.contains(e)) {
                pool.erase(e);
            }
        }
    }

    template<typename Type>
    Type &get_one(entity e) const noexcept {
        EDYN_ASSERT(valid(e), "registry::get: invalid entity");
        auto *pool = find_pool<std::remove_const_t<Type>>();
        EDYN_ASSERT(pool != nullptr && pool->contains(e),
                    "registry::get: entity does not have the component");
        return pool->get(e);
    }

    template<typename Type>
    Type *try_get_one(entity e) const noexcept {
        auto *pool = find_pool<std::remove_const_t<Type>>();
        return pool != nullptr ? pool->try_get(e) : nullptr;
    }

    template<typename Type>
    [[nodiscard]] bool has(entity e) const noexcept {
        const auto *set = find_slot<std::remove_const_t<Type>>().set;
        return set != nullptr && set->contains(e);
    }

    // Context variables first (they may hold sinks of the pools), then pools, newest first.
    void release_storage() noexcept {
        vars.clear();
        while (!records.empty()) {
            records.pop_back();
        }
        slots.clear();
    }

    entity_allocator ids;
    std::vector<pool_record> records; // in order of creation
    std::vector<pool_slot> slots;     // by type_index
    std::vector<entity> in_destroy;   // entities inside `destroy`, innermost last
    context vars;
};

} // namespace edyn

#endif // EDYN_ECS_REGISTRY_HPP
