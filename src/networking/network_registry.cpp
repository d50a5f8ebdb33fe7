#include "network_registry.hpp"
#include "body_def.hpp"
#include "edyn/collision/collision_filter.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/constraints/make_constraint.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/networking/asset_ref.hpp"
#include "edyn/networking/client.hpp"
#include "edyn/serialization/constraint_types.hpp"
#include "edyn/serialization/dynamics_types.hpp"
#include "edyn/serialization/shape_types.hpp"
#include "edyn/simulation/island.hpp"
#include "edyn/simulation/world.hpp"
#include "network_motion.hpp"
#include "value_bytes.hpp"
#include <exception>

namespace edyn {

namespace {

// Counted in a network client (its extrapolation's registry, which applies the same pools,
// counts nothing).
void count_invalid(registry &registry) {
    if (auto *r = registry.ctx().find<network_client_rejections>()) r->invalid_value += 1;
}

void count_conflict(registry &registry) {
    if (auto *r = registry.ctx().find<network_client_rejections>()) r->conflicting_role += 1;
}

template<typename... Ts>
bool has_constraint(const registry &registry, entity e, constraint_type_list<Ts...>) {
    return registry.any_of<Ts...>(e);
}

// An entity the simulation or the networking already uses for something else than a body or a
// constraint. A packet must not add a body or a constraint to it: the island graph would hold
// one entity as two things, and destroying it would corrupt the islands.
bool has_other_edyn_role(const registry &registry, entity e) {
    return registry.any_of<contact_manifold, island, island_edge, asset_ref>(e);
}

// Bodies are made with make_rigidbody on the receiving side, from a definition of the sender's.
struct decoded_bodies : detail::typed_decoded_pool<rigidbody_def> {
    void apply(registry &registry, const std::vector<entity> &entities,
               const detail::entity_mapper &) override {
        for (std::size_t i = 0; i < positions.size(); ++i) {
            auto e = entities[positions[i]];
            if (e == null || !registry.valid(e)) continue;
            // A body the program changed, or sent again (a create_entity repeated), is updated
            // where it differs.
            if (registry.all_of<rigidbody_tag>(e)) {
                update(registry, e, values[i]);
                continue;
            }
            if (has_constraint(registry, e, constraint_types{}) || has_other_edyn_role(registry, e)) {
                count_conflict(registry);
                continue;
            }
            try {
                validate_rigidbody_def(values[i]);
                if (!within_network_range(values[i])) {
                    count_invalid(registry);
                    continue;
                }
                make_rigidbody(e, registry, values[i]);
            } catch (const std::exception &) {
                // A definition this end refuses makes no body; the entity stays empty.
                count_invalid(registry);
            }
        }
    }

    static void update(registry &registry, entity e, const rigidbody_def &def) {
        try {
            validate_rigidbody_def(def);
            if (!within_network_range(def)) {
                count_invalid(registry);
                return;
            }
            update_rigidbody(registry, e, def);
        } catch (const std::exception &) {
            // A change this end refuses leaves the body as it was, or as far as it got.
            count_invalid(registry);
        }
    }
};

struct decoded_motion : detail::typed_decoded_pool<network_motion> {
    void apply(registry &registry, const std::vector<entity> &entities,
               const detail::entity_mapper &) override {
        for (std::size_t i = 0; i < positions.size(); ++i) {
            auto e = entities[positions[i]];
            if (e == null || !registry.valid(e) || !registry.all_of<rigidbody_tag>(e)) continue;
            auto &m = values[i];
            registry.replace<position>(e, m.position);
            registry.replace<orientation>(e, m.orientation);
            if (!registry.all_of<static_tag>(e)) {
                registry.replace<linvel>(e, m.linvel);
                registry.replace<angvel>(e, m.angvel);
            }
        }
    }
};

// Constraints are validated as make_constraint would, then set on the entity they came for.
template<typename T>
struct decoded_constraint : detail::typed_decoded_pool<T> {
    void apply(registry &registry, const std::vector<entity> &entities,
               const detail::entity_mapper &map) override {
        for (std::size_t i = 0; i < this->positions.size(); ++i) {
            auto e = entities[this->positions[i]];
            if (e == null || !registry.valid(e)) continue;
            if (auto *current = registry.try_get<T>(e)) {
                update(registry, e, *current, this->values[i], map);
                continue;
            }
            if (registry.all_of<rigidbody_tag>(e) || has_constraint(registry, e, constraint_types{}) ||
                has_other_edyn_role(registry, e)) {
                count_conflict(registry);
                continue;
            }
            auto con = this->values[i];
            if (map) map_entity_members(con, map);
            try {
                validate_constraint_bodies(registry, constraint_type_name<T>, con.body[0], con.body[1],
                                           std::is_same_v<T, null_constraint>);
                validate_constraint(con);
            } catch (const std::exception &) {
                count_invalid(registry);
                continue;
            }
            registry.emplace<T>(e, con);
        }
    }

    // A constraint the program changed, or sent again (a create_entity repeated): replaced when
    // its value differs, on the same bodies.
    static void update(registry &registry, entity e, const T &current, T con,
                       const detail::entity_mapper &map) {
        if (map) map_entity_members(con, map);
        if (con.body[0] != current.body[0] || con.body[1] != current.body[1]) {
            count_conflict(registry);
            return;
        }
        try {
            validate_constraint(con);
        } catch (const std::exception &) {
            count_invalid(registry);
            return;
        }
        if (value_bytes(con) != value_bytes(current)) registry.replace<T>(e, con);
    }
};

template<typename Pool, typename Value>
std::unique_ptr<detail::decoded_pool> read_pool(const std::vector<std::uint8_t> &data,
                                                std::size_t entity_count) {
    auto pool = std::make_unique<Pool>();
    auto archive = memory_input_archive(data.data(), data.size());
    while (archive.remaining() > 0) {
        if (entity_count == 0) return nullptr;
        auto position = archive.read_size(entity_count - 1);
        Value value{};
        archive(value);
        if (archive.failed() || pool->positions.size() >= entity_count) return nullptr;
        pool->positions.push_back(std::uint32_t(position));
        pool->values.push_back(std::move(value));
    }
    return pool;
}

// A change the program made to what defines a body (the engine's own writes go through
// neither patch nor replace); made by make_rigidbody, before the body's tag, it is not one.
void on_body_change(registry &registry, entity e) {
    if (!registry.all_of<rigidbody_tag>(e)) return;
    if (auto *types = registry.ctx().find<network_registry>()) types->mark_redefined(e);
}

// A static body does not send motion: its move is a change of its definition.
void on_static_move(registry &registry, entity e) {
    if (registry.all_of<static_tag>(e)) on_body_change(registry, e);
}

template<typename... Shapes>
void connect_shape_changes(registry &registry, std::tuple<Shapes...> *) {
    (registry.on_update<Shapes>().template connect<&on_body_change>(), ...);
}

template<typename... Components>
void connect_body_changes(registry &registry) {
    (registry.on_construct<Components>().template connect<&on_body_change>(), ...);
    (registry.on_update<Components>().template connect<&on_body_change>(), ...);
    (registry.on_destroy<Components>().template connect<&on_body_change>(), ...);
}

detail::networked_type body_type() {
    detail::networked_type t;
    t.type = type_index<rigidbody_def>();
    // What get_rigidbody_def reads, but for motion, which snapshots carry.
    t.connect = [](registry &r) {
        connect_body_changes<shape_index, material, mass, inertia, center_of_mass, gravity, collision_filter,
                             static_tag, kinematic_tag, dynamic_tag, sleeping_disabled_tag>(r);
        connect_shape_changes(r, static_cast<shapes_tuple_t *>(nullptr));
        r.on_update<position>().connect<&on_static_move>();
        r.on_update<orientation>().connect<&on_static_move>();
    };
    t.has = [](const registry &r, entity e) { return r.all_of<rigidbody_tag>(e); };
    t.write = [](const registry &r, entity e, const detail::entity_mapper &, memory_output_archive &archive) {
        archive(get_rigidbody_def(r, e));
    };
    t.read = &read_pool<decoded_bodies, rigidbody_def>;
    return t;
}

void on_motion_change(registry &registry, entity e) {
    if (auto *types = registry.ctx().find<network_registry>()) types->mark(type_index<network_motion>(), e);
}

detail::networked_type motion_type() {
    detail::networked_type t;
    t.type = type_index<network_motion>();
    // The program moving a body, and a body falling asleep (its last pose must reach the
    // clients, which stop receiving it then).
    t.connect = [](registry &r) {
        r.on_update<position>().connect<&on_motion_change>();
        r.on_update<orientation>().connect<&on_motion_change>();
        r.on_construct<sleeping_tag>().connect<&on_motion_change>();
    };
    t.has = [](const registry &r, entity e) {
        return r.all_of<rigidbody_tag>(e) && !r.all_of<static_tag>(e);
    };
    t.write = [](const registry &r, entity e, const detail::entity_mapper &, memory_output_archive &archive) {
        auto m =
            network_motion{r.get<position>(e), r.get<orientation>(e), r.get<linvel>(e), r.get<angvel>(e)};
        // Speeds well under those of sleep are sent as zero: a body settling in an island that
        // is still awake then keeps the same encoding, and is not sent again (server.cpp).
        auto &s = get_settings(r);
        if (length_sqr(m.linvel) < (s.sleep_linear_velocity * s.sleep_linear_velocity / 16))
            m.linvel = vector3_zero;
        if (length_sqr(m.angvel) < (s.sleep_angular_velocity * s.sleep_angular_velocity / 16))
            m.angvel = vector3_zero;
        archive(m);
    };
    t.read = &read_pool<decoded_motion, network_motion>;
    return t;
}

void on_constraint_change(registry &registry, entity e) {
    if (auto *types = registry.ctx().find<network_registry>()) types->mark_redefined(e);
}

template<typename T>
detail::networked_type constraint_type() {
    auto t = detail::make_networked_type<T>();
    // Constraints are sent whole when created, and again when the program changes them; the
    // solver's changes to them are its own.
    t.connect = [](registry &r) { r.on_update<T>().template connect<&on_constraint_change>(); };
    t.read = &read_pool<decoded_constraint<T>, T>;
    return t;
}

template<typename... Ts>
void add_constraint_types(std::vector<detail::networked_type> &types, constraint_type_list<Ts...>) {
    (types.push_back(constraint_type<Ts>()), ...);
}

void forget_destroyed(registry &registry, entity e) {
    if (auto *types = registry.ctx().find<network_registry>()) types->forget(e);
}

} // namespace

std::unique_ptr<detail::typed_decoded_pool<rigidbody_def>> make_body_pool() {
    auto pool = std::make_unique<decoded_bodies>();
    pool->component_index = network_index::body;
    return pool;
}

std::unique_ptr<detail::typed_decoded_pool<network_motion>> make_motion_pool() {
    auto pool = std::make_unique<decoded_motion>();
    pool->component_index = network_index::motion;
    return pool;
}

namespace {
void record(std::vector<network_registry::change> &list, entity e, double now) {
    auto i = to_index(e);
    if (i >= list.size()) list.resize(std::size_t(i) + 1);
    list[i] = {e, now};
}

double recorded_at(const std::vector<network_registry::change> &list, entity e) noexcept {
    auto i = to_index(e);
    if (i >= list.size() || list[i].e != e) return -std::numeric_limits<double>::infinity();
    return list[i].time;
}
} // namespace

void network_registry::mark(std::size_t type, entity e) {
    if (muted) return;
    auto index = this->index_of(type);
    if (index >= 0) record(changes[std::size_t(index)], e, now);
}

void network_registry::mark_removed(std::size_t type, entity e) {
    if (muted) return;
    auto index = this->index_of(type);
    if (index >= 0) record(removals[std::size_t(index)], e, now);
}

double network_registry::removed_at(std::uint16_t index, entity e) const noexcept {
    return recorded_at(removals[index], e);
}

void network_registry::mark_redefined(entity e) {
    if (track_redefined && !muted) redefined.push_back(e);
}

double network_registry::changed_at(std::uint16_t index, entity e) const noexcept {
    return recorded_at(changes[index], e);
}

void network_registry::forget(entity e) {
    auto i = to_index(e);
    for (auto *lists : {&changes, &removals}) {
        for (auto &list : *lists) {
            if (i < list.size() && list[i].e == e) list[i] = {};
        }
    }
}

network_registry &ensure_network_registry(registry &registry) {
    if (auto *existing = registry.ctx().find<network_registry>()) return *existing;
    auto &types = registry.ctx().emplace<network_registry>();
    auto builtins = std::vector<detail::networked_type>{body_type(), motion_type()};
    add_constraint_types(builtins, constraint_types{});
    registry.on_destroy<networked_tag>().connect<&forget_destroyed>();
    detail::register_networked_types(registry, std::move(builtins));
    types.first_program_type = std::uint16_t(types.types.size());
    return types;
}

void detail::register_networked_types(registry &registry, std::vector<networked_type> new_types) {
    auto &types = ensure_network_registry(registry);
    for (auto &t : new_types) {
        if (types.index_of(t.type) >= 0) continue;
        if (t.type >= types.index_of_type.size()) types.index_of_type.resize(t.type + 1, -1);
        types.index_of_type[t.type] = int(types.types.size());
        types.types.push_back(t);
        types.changes.emplace_back();
        types.removals.emplace_back();
        t.connect(registry);
    }
}

void detail::mark_network_change(registry &registry, std::size_t type, entity e) {
    if (auto *types = registry.ctx().find<network_registry>()) types->mark(type, e);
}

void detail::mark_network_removal(registry &registry, std::size_t type, entity e) {
    if (auto *types = registry.ctx().find<network_registry>()) types->mark_removed(type, e);
}

std::optional<std::vector<std::unique_ptr<detail::decoded_pool>>>
decode_pools(const network_registry &types, const std::vector<packet::pool_snapshot> &pools,
             std::size_t entity_count) {
    std::vector<std::unique_ptr<detail::decoded_pool>> decoded;
    decoded.reserve(pools.size());
    for (auto &pool : pools) {
        if (pool.component_index >= types.types.size()) return std::nullopt;
        auto d = types.types[pool.component_index].read(pool.data, entity_count);
        if (!d) return std::nullopt;
        d->component_index = pool.component_index;
        decoded.push_back(std::move(d));
    }
    return decoded;
}

void apply_pools(registry &registry, const network_registry &types,
                 const std::vector<std::unique_ptr<detail::decoded_pool>> &pools,
                 const std::vector<entity> &entities, const detail::entity_mapper &map) {
    for (auto &pool : pools)
        pool->apply(registry, entities, map);
    for (auto &pool : pools) {
        auto &t = types.types[pool->component_index];
        if (!t.input && !t.action) continue;
        for (auto position : pool->positions) {
            auto e = entities[position];
            if (e != null && registry.valid(e) && registry.all_of<rigidbody_tag>(e))
                wake_up_entity(registry, e);
        }
    }
}

std::uint32_t pool_writer::position_of(entity e) {
    auto i = to_index(e);
    if (i >= positions.size()) positions.resize(std::size_t(i) + 1, {null, 0});
    if (positions[i].first != e) {
        positions[i] = {e, std::uint32_t(entities.size())};
        entities.push_back(map ? map(e) : e);
    }
    return positions[i].second;
}

void pool_writer::add(entity e, std::uint16_t index) {
    if (index >= pool_data.size()) pool_data.resize(std::size_t(index) + 1);
    auto position = position_of(e);
    auto archive = memory_output_archive(pool_data[index]);
    archive.write_size(position);
    types->types[index].write(*source, e, map, archive);
}

void pool_writer::add_encoded(entity e, std::uint16_t index, const std::vector<std::uint8_t> &bytes) {
    if (index >= pool_data.size()) pool_data.resize(std::size_t(index) + 1);
    auto position = position_of(e);
    auto archive = memory_output_archive(pool_data[index]);
    archive.write_size(position);
    archive.write_bytes(bytes.data(), bytes.size());
}

std::size_t pool_writer::bytes() const noexcept {
    auto total = std::size_t{0};
    for (auto &data : pool_data)
        total += data.size();
    return total;
}

std::size_t pool_writer::largest_pool() const noexcept {
    auto largest = std::size_t{0};
    for (auto &data : pool_data)
        largest = std::max(largest, data.size());
    return largest;
}

void pool_writer::clear() noexcept {
    for (auto &data : pool_data)
        data.clear();
    for (auto &data : removed_data)
        data.clear();
    // The list holds the entities as mapped; without a map, only their slots need emptying.
    if (map) {
        positions.clear();
    } else {
        for (auto e : entities)
            positions[to_index(e)] = {null, 0};
    }
    entities.clear();
}

void pool_writer::remove(entity e, std::uint16_t index) {
    if (index >= removed_data.size()) removed_data.resize(std::size_t(index) + 1);
    auto archive = memory_output_archive(removed_data[index]);
    archive.write_size(position_of(e));
}

void pool_writer::finish(std::vector<entity> &entities_out, std::vector<packet::pool_snapshot> &pools_out) {
    auto removed = std::vector<packet::pool_snapshot>{};
    finish(entities_out, pools_out, removed);
}

void pool_writer::finish(std::vector<entity> &entities_out, std::vector<packet::pool_snapshot> &pools_out,
                         std::vector<packet::pool_snapshot> &removed_out) {
    entities_out = std::move(entities);
    auto collect = [](std::vector<std::vector<std::uint8_t>> &data, std::vector<packet::pool_snapshot> &out) {
        for (std::size_t i = 0; i < data.size(); ++i) {
            if (data[i].empty()) continue;
            out.push_back({std::uint16_t(i), std::move(data[i])});
        }
        data.clear();
    };
    collect(pool_data, pools_out);
    collect(removed_data, removed_out);
    entities.clear();
    positions.clear();
}

} // namespace edyn
