#include "async_execution.hpp"
#include "clock.hpp"
#include "component_list.hpp"
#include "edyn/collision/collision_filter.hpp"
#include "edyn/collision/should_collide.hpp"
#include "edyn/constraints/constraint_links.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/constraints/external_entity.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/worker_calls.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/shapes.hpp"
#include "edyn/simulation/interpolation.hpp"
#include "edyn/simulation/world.hpp"
#include "edyn/simulation/world_state.hpp"
#include "simulation_worker.hpp"
#include <optional>
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

// On every main entity the worker has a counterpart of. Only destroy() removes it (detach
// clears it with the listeners gone, and an entity the worker destroyed loses it unsent), so
// its removal means the entity is going away.
struct replicated_tag {};

// edyn's components that travel to the worker, in an order in which a body's parts arrive
// before the tag that makes it a body and before its AABB, and bodies before constraints (so
// that bodies made before attach() are sent in an order the worker's listeners accept).
using replicated_components =
    component_list<plane_shape, sphere_shape, cylinder_shape, capsule_shape, box_shape, polyhedron_shape,
                   compound_shape, mesh_shape, paged_mesh_shape, shape_index, position, orientation, linvel,
                   angvel, gravity, mass, mass_inv, inertia, inertia_inv, inertia_world_inv, center_of_mass,
                   rigidbody_dynamic_mass, material, collision_filter, collision_exclusion, sensor_tag,
                   sleeping_disabled_tag, dynamic_tag, static_tag, kinematic_tag, rigidbody_tag, AABB,
                   external_tag>;

template<typename... Components, typename... Constraints>
std::vector<detail::replicated_type> edyn_types(component_list<Components...>,
                                                constraint_type_list<Constraints...>) {
    return {detail::make_replicated_type<Components, true>()...,
            detail::make_replicated_type<Constraints, true>()...};
}

worker_calls &calls(registry &registry) { return registry.ctx().get<worker_calls>(); }

struct scoped_mute {
    worker_calls &c;
    explicit scoped_mute(registry &registry)
        : c(calls(registry)) {
        ++c.muted;
    }
    ~scoped_mute() { --c.muted; }
    scoped_mute(const scoped_mute &) = delete;
    scoped_mute &operator=(const scoped_mute &) = delete;
};

// The program's code run while the worker's results are applied (contact listeners, query
// replies) is heard: a body it destroys or a velocity it sets reaches the worker.
struct scoped_unmute {
    worker_calls &c;
    int saved;
    explicit scoped_unmute(registry &registry)
        : c(calls(registry))
        , saved(c.muted) {
        c.muted = 0;
    }
    ~scoped_unmute() { c.muted = saved; }
    scoped_unmute(const scoped_unmute &) = delete;
    scoped_unmute &operator=(const scoped_unmute &) = delete;
};

// Main-side bookkeeping the sequential listeners do as well: the previous transform for
// interpolation, and constraint lists, so that a body's constraints go with it on this side.
void on_construct_body(registry &registry, entity e) {
    if (!registry.all_of<static_tag>(e) && registry.all_of<position, orientation>(e))
        registry.emplace_or_replace<previous_transform>(e, registry.get<position>(e),
                                                        registry.get<orientation>(e));
}

void on_destroy_body(registry &registry, entity e) {
    destroy_constraints_of(registry, e);
    registry.remove<previous_transform>(e);
}

void main_on_construct_static(registry &registry, entity e) { registry.remove<previous_transform>(e); }
void main_on_destroy_static(registry &registry, entity e) {
    // An entity being destroyed may have lost its transform already (pools go newest first).
    if (!registry.destroying(e) && registry.all_of<rigidbody_tag, position, orientation>(e)) {
        registry.emplace_or_replace<previous_transform>(e, registry.get<position>(e),
                                                        registry.get<orientation>(e));
    }
}

// A body the program changes wakes (with its island, in the worker): it is shown awake here
// at once.
void main_on_update_wake(registry &registry, entity e) { registry.remove<sleeping_tag>(e); }

// A teleport is not interpolated.
void main_on_update_transform(registry &registry, entity e) {
    if (auto *prev = registry.try_get<previous_transform>(e))
        *prev = {registry.get<position>(e), registry.get<orientation>(e)};
    main_on_update_wake(registry, e);
}

// A body that gains or loses its material stops or starts being a sensor (the worker does the
// same, and wakes it).
void main_on_construct_material(registry &registry, entity e) {
    if (!registry.all_of<rigidbody_tag>(e)) return;
    registry.remove<sensor_tag>(e);
    main_on_update_wake(registry, e);
}
void main_on_destroy_material(registry &registry, entity e) {
    if (!registry.all_of<rigidbody_tag>(e) || registry.destroying(e)) return;
    registry.emplace_or_replace<sensor_tag>(e);
    main_on_update_wake(registry, e);
}

void main_on_presence_wake(registry &registry, entity e) {
    if (registry.all_of<rigidbody_tag>(e) && !registry.destroying(e)) main_on_update_wake(registry, e);
}

template<typename... Components>
void connect_wake(registry &registry, component_list<Components...>, bool connect) {
    if (connect)
        (registry.on_update<Components>().template connect<&main_on_update_wake>(), ...);
    else
        (registry.on_update<Components>().template disconnect<&main_on_update_wake>(), ...);
}

template<typename... Components>
void connect_presence_wake(registry &registry, component_list<Components...>, bool connect) {
    if (connect) {
        (registry.on_construct<Components>().template connect<&main_on_presence_wake>(), ...);
        (registry.on_destroy<Components>().template connect<&main_on_presence_wake>(), ...);
    } else {
        (registry.on_construct<Components>().template disconnect<&main_on_presence_wake>(), ...);
        (registry.on_destroy<Components>().template disconnect<&main_on_presence_wake>(), ...);
    }
}

template<typename T>
void main_on_construct_constraint(registry &registry, entity e) {
    auto &con = registry.get<T>(e);
    link_constraint(registry, e, con.body[0], con.body[1]);
}

void main_on_destroy_constraint(registry &registry, entity e) { release_constraint(registry, e); }
void on_destroy_links(registry &registry, entity e) { unlink_constraint(registry, e); }

void on_destroy_replicated(registry &registry, entity e) {
    auto *link = registry.ctx().find<async_execution>();
    if (!link || calls(registry).muted) return;
    link->push_call(
        e, [](edyn::registry &worker, entity local) { worker.destroy(local); }, motion_parts::all);
}

template<typename... Constraints>
void connect_main_listeners(registry &registry, constraint_type_list<Constraints...>, bool connect) {
    if (connect) {
        registry.on_construct<rigidbody_tag>().connect<&on_construct_body>();
        registry.on_destroy<rigidbody_tag>().connect<&on_destroy_body>();
        registry.on_construct<static_tag>().connect<&main_on_construct_static>();
        registry.on_destroy<static_tag>().connect<&main_on_destroy_static>();
        registry.on_update<position>().connect<&main_on_update_transform>();
        registry.on_update<orientation>().connect<&main_on_update_transform>();
        registry.on_construct<material>().connect<&main_on_construct_material>();
        registry.on_destroy<material>().connect<&main_on_destroy_material>();
        (registry.on_construct<Constraints>().template connect<&main_on_construct_constraint<Constraints>>(),
         ...);
        (registry.on_destroy<Constraints>().template connect<&main_on_destroy_constraint>(), ...);
        registry.on_destroy<constraint_links>().connect<&on_destroy_links>();
        registry.on_destroy<constraint_list>().connect<&destroy_constraints_of>();
        registry.on_destroy<external_tag>().connect<&destroy_constraints_of>();
        registry.on_destroy<replicated_tag>().connect<&on_destroy_replicated>();
        connect_wake(registry, waking_components{}, true);
        connect_presence_wake(registry, waking_presence_components{}, true);
    } else {
        connect_wake(registry, waking_components{}, false);
        connect_presence_wake(registry, waking_presence_components{}, false);
        registry.on_construct<rigidbody_tag>().disconnect<&on_construct_body>();
        registry.on_destroy<rigidbody_tag>().disconnect<&on_destroy_body>();
        registry.on_construct<static_tag>().disconnect<&main_on_construct_static>();
        registry.on_destroy<static_tag>().disconnect<&main_on_destroy_static>();
        registry.on_update<position>().disconnect<&main_on_update_transform>();
        registry.on_update<orientation>().disconnect<&main_on_update_transform>();
        registry.on_construct<material>().disconnect<&main_on_construct_material>();
        registry.on_destroy<material>().disconnect<&main_on_destroy_material>();
        (registry.on_construct<Constraints>()
             .template disconnect<&main_on_construct_constraint<Constraints>>(),
         ...);
        (registry.on_destroy<Constraints>().template disconnect<&main_on_destroy_constraint>(), ...);
        registry.on_destroy<constraint_links>().disconnect<&on_destroy_links>();
        registry.on_destroy<constraint_list>().disconnect<&destroy_constraints_of>();
        registry.on_destroy<external_tag>().disconnect<&destroy_constraints_of>();
        registry.on_destroy<replicated_tag>().disconnect<&on_destroy_replicated>();
    }
}

// Bodies and constraints made before attach() get the main side's bookkeeping too.
template<typename... Constraints>
void adopt_main_side(registry &registry, constraint_type_list<Constraints...>) {
    std::vector<entity> entities;
    for (auto e : registry.view<rigidbody_tag>())
        entities.push_back(e);
    for (auto e : entities)
        on_construct_body(registry, e);
    auto link_all = [&](auto *type) {
        using constraint = std::remove_pointer_t<decltype(type)>;
        entities.clear();
        for (auto e : registry.view<constraint>())
            entities.push_back(e);
        for (auto e : entities)
            main_on_construct_constraint<constraint>(registry, e);
    };
    (link_all(static_cast<Constraints *>(nullptr)), ...);
}

// The filter as it is now on the main side; the settings and pause when they differ from
// `sent`, the ones the worker has; and the material table when it differs from `sent_table`.
// Settings and table are copied only when the program changed them, so that what a step
// callback changed on the worker stays there.
worker_op settings_op(registry &registry, std::optional<world_controls> &sent,
                      std::optional<material_mix_table> &sent_table) {
    auto now = world_controls{get_settings(registry), is_paused(registry)};
    std::optional<world_controls> controls;
    if (now != sent) controls = sent = now;
    auto filter = get_should_collide(registry);
    auto events = registry.ctx().get<contact_events>().has_listeners();
    auto *table_now = registry.ctx().find<material_mix_table>();
    auto table_changed =
        table_now ? !sent_table || sent_table->pairs != table_now->pairs : sent_table.has_value();
    std::optional<material_mix_table> table;
    if (table_changed) {
        if (table_now) table = *table_now;
        sent_table = table;
    }
    return [controls, filter, events, table_changed, table = std::move(table)](worker_context &w) mutable {
        w.send_events(events);
        auto &reg = w.reg;
        if (controls) {
            auto &current = reg.ctx().get<settings>();
            auto mode = current.execution_mode;
            auto gravity_changed = current.gravity != controls->settings.gravity;
            current = controls->settings;
            current.execution_mode = mode;
            // set_gravity wakes resting bodies, which must fall the new way.
            if (gravity_changed) set_gravity(reg, current.gravity);
            set_paused(reg, controls->paused);
        }
        if (filter == &should_collide_default)
            reset_should_collide(reg);
        else
            set_should_collide(reg, filter);
        if (!table_changed) return;
        if (table)
            reg.ctx().emplace_or_replace<material_mix_table>(std::move(*table));
        else
            reg.ctx().erase<material_mix_table>();
    };
}

} // namespace

async_execution::async_execution(registry &registry)
    : worker(std::make_unique<simulation_worker>())
    , types(edyn_types(replicated_components{}, constraint_types{})) {
    registry.ctx().emplace<worker_calls>().forward = [this](entity e, worker_calls::call_type call,
                                                            motion_parts sets) {
        push_call(e, std::move(call), sets);
    };
    connect_main_listeners(registry, constraint_types{}, true);
    for (auto &type : types)
        type.connect(registry);
}

void async_execution::adopt_existing(registry &registry) {
    adopt_main_side(registry, constraint_types{});
    // Entities made before attach(), type by type in the order above.
    for (auto &type : types) {
        std::vector<entity> entities;
        registry.each([&](entity e) { entities.push_back(e); });
        for (auto e : entities)
            type.send_existing(registry, e);
    }
}

async_execution::~async_execution() = default;

void async_execution::disconnect(registry &registry) {
    for (auto &type : types)
        type.disconnect(registry);
    for (auto &type : external_types)
        type.disconnect(registry);
    connect_main_listeners(registry, constraint_types{}, false);
    registry.clear<replicated_tag>();
    registry.ctx().erase<worker_calls>();
}

void async_execution::add_type(registry &registry, const detail::replicated_type &type) {
    for (auto &known : external_types) {
        if (known.id == type.id) return;
    }
    for (auto &known : types) {
        if (known.id == type.id) return;
    }
    external_types.push_back(type);
    type.connect(registry);
    for (auto e : registry.view<replicated_tag>())
        type.send_existing(registry, e);
}

bool async_execution::accepts(registry &registry, entity e, bool edyn_component) {
    if (calls(registry).muted) return false;
    if (registry.all_of<replicated_tag>(e)) return true;
    if (!edyn_component) return false;
    // The first of edyn's components on this entity: the worker will have it from now on,
    // with the program's registered components it already holds.
    registry.emplace<replicated_tag>(e);
    for (auto &type : external_types)
        type.send_existing(registry, e);
    return true;
}

void async_execution::send(
    entity e, std::function<void(registry &, entity, const std::function<entity(entity)> &)> apply,
    motion_parts sets) {
    mark_pending(e, sets);
    ops.push_back([e, apply = std::move(apply)](worker_context &w) {
        auto local = w.local(e);
        apply(w.reg, local, [&w](entity main) { return w.local(main); });
    });
    ++ops_made;
}

void async_execution::push(worker_op op) {
    ops.push_back(std::move(op));
    ++ops_made;
}

void async_execution::push_gravity(const vector3 &gravity) {
    push([gravity](worker_context &w) { set_gravity(w.reg, gravity); });
}

void async_execution::push_call(entity e, std::function<void(registry &, entity)> call, motion_parts sets) {
    mark_pending(e, sets);
    push([e, call = std::move(call)](worker_context &w) {
        auto local = w.find(e);
        if (local != null) call(w.reg, local);
    });
}

void async_execution::mark_pending(entity e, motion_parts sets) {
    auto i = to_index(e);
    if (i >= pending.size()) pending.resize(std::size_t(i) + 1);
    auto &slot = pending[i];
    if (slot.e != e) slot = {e};
    // The operation about to be queued is number ops_made + 1.
    slot.seq = ops_made + 1;
    auto parts = unsigned(sets);
    if (parts & unsigned(motion_parts::transform)) slot.transform_seq = slot.seq;
    if (parts & unsigned(motion_parts::velocity)) slot.velocity_seq = slot.seq;
}

bool async_execution::pending_after(entity e, std::uint64_t ops_applied) const noexcept {
    auto i = to_index(e);
    return i < pending.size() && pending[i].e == e && pending[i].seq > ops_applied;
}

bool async_execution::pending_after(entity e, std::uint64_t ops_applied, motion_parts part) const noexcept {
    auto i = to_index(e);
    if (i >= pending.size() || pending[i].e != e) return false;
    auto seq = part == motion_parts::transform ? pending[i].transform_seq : pending[i].velocity_seq;
    return seq > ops_applied;
}

void async_execution::send_batch(registry &registry, worker_op last, std::optional<double> time) {
    // The actions made since the last batch go with it, to the worker's next step.
    detail::consume_actions(registry);
    auto controls_before = sent_controls;
    push(settings_op(registry, sent_controls, sent_table));
    if (sent_controls != controls_before) controls_seq = ops_made;
    if (last) push(std::move(last));
    last_batch = worker->send(ops, time);
}

void async_execution::update(registry &registry, double time) {
    apply_messages(registry);
    auto &world = registry.ctx().get<world_state>();
    if (!world.started) {
        // The first time only sets the start: it is never merged with a later one.
        world.started = true;
        send_batch(registry, [time](worker_context &w) { w.advance(time); });
    } else {
        send_batch(registry, {}, time);
    }
    interpolate_present_transforms(registry, alpha);
    if (!errors.empty()) {
        auto error = errors.front();
        errors.clear();
        std::rethrow_exception(error);
    }
}

void async_execution::step_simulation(registry &registry) {
    send_batch(registry, [](worker_context &w) { w.step_once(); });
}

void async_execution::wait(registry &registry) {
    send_batch(registry, {});
    worker->wait(last_batch);
    apply_messages(registry);
    interpolate_present_transforms(registry, alpha);
    if (!errors.empty()) {
        auto error = errors.front();
        errors.clear();
        std::rethrow_exception(error);
    }
}

void async_execution::apply_messages(registry &registry) {
    auto messages = worker->receive();
    // When several steps came back at once, only the last two steps' motion matters (the
    // present lies between them) and only the last contacts: the others' records still apply.
    std::size_t motion_from = messages.size(), contacts_from = messages.size();
    for (std::size_t i = messages.size(), found = 0; i-- > 0 && found < 2;) {
        if (messages[i].has_motion) {
            motion_from = i;
            ++found;
        }
    }
    for (std::size_t i = messages.size(); i-- > 0;) {
        if (messages[i].has_contacts) {
            contacts_from = i;
            break;
        }
    }
    for (std::size_t i = 0; i < messages.size(); ++i)
        apply(registry, messages[i], i >= motion_from, i >= contacts_from);
}

void async_execution::apply(registry &registry, worker_message &message, bool motion, bool contacts) {
    scoped_mute mute(registry);
    if (message.stepped) {
        auto &world = registry.ctx().get<world_state>();
        world.simulation_time = message.simulation_time;
        world.step_count = message.step_count;
    }
    // Motion first: events were delivered at the end of the worker's step, when the bodies
    // already stood where the step left them.
    if (motion && message.has_motion) {
        save_previous_transforms(registry);
        apply_motion(registry, message.bodies, message.ops_applied);
    }
    apply_motion(registry, message.rested, message.ops_applied);
    auto apply_constraints = [&](const constraint_states &states) {
        std::apply(
            [&](auto &...lists) { (apply_constraint_states(registry, lists, message.ops_applied), ...); },
            states);
    };
    if (contacts && message.has_contacts) apply_constraints(message.constraints);
    apply_constraints(message.rested_constraints);
    apply_records(registry, message.records);
    if (contacts && message.has_contacts) apply_manifolds(registry, message.manifolds);
    apply_manifolds(registry, message.rested_manifolds);
    for (auto e : message.slept) {
        if (registry.valid(e) && !registry.all_of<sleeping_tag>(e)) registry.emplace<sleeping_tag>(e);
    }
    for (auto e : message.woke) {
        if (registry.valid(e)) registry.remove<sleeping_tag>(e);
    }
    for (auto &reply : message.replies) {
        try {
            scoped_unmute heard(registry);
            reply(registry);
        } catch (...) {
            errors.push_back(std::current_exception());
        }
    }
    for (auto &error : message.errors)
        errors.push_back(error);
    if (message.has_alpha) alpha = message.alpha;
    adopt_controls(registry, message);
}

void async_execution::adopt_controls(registry &registry, const worker_message &message) {
    // A step callback changed the worker's settings or paused it. The program's registry takes
    // them unless the program changed its own since they were last sent, or the worker had not
    // yet received those: then the program's stand, and go to the worker at the next batch.
    if (!message.controls || message.ops_applied < controls_seq) return;
    auto &current = registry.ctx().get<settings>();
    auto &world = registry.ctx().get<world_state>();
    if (sent_controls != world_controls{current, world.paused}) return;
    auto mode = current.execution_mode;
    current = message.controls->settings;
    current.execution_mode = mode;
    world.paused = message.controls->paused;
    sent_controls = world_controls{current, world.paused};
}

void async_execution::apply_motion(registry &registry, const std::vector<body_state> &states,
                                   std::uint64_t ops_applied) {
    // Straight into the pools: the hottest loop of update().
    auto &positions = registry.storage<position>();
    auto &orientations = registry.storage<orientation>();
    auto &linvels = registry.storage<linvel>();
    auto &angvels = registry.storage<angvel>();
    for (auto &state : states) {
        auto *pos = positions.try_get(state.main);
        if (!pos) continue;
        auto *orn = orientations.try_get(state.main);
        auto *v = linvels.try_get(state.main);
        auto *w = angvels.try_get(state.main);
        if (!orn || !v || !w) continue;
        if (!pending_after(state.main, ops_applied, motion_parts::transform)) {
            *pos = state.pos;
            *orn = state.orn;
        }
        if (!pending_after(state.main, ops_applied, motion_parts::velocity)) {
            *v = state.v;
            *w = state.w;
        }
    }
}

void async_execution::apply_manifolds(registry &registry,
                                      const std::vector<std::pair<entity, contact_manifold>> &states) {
    auto &pool = registry.storage<contact_manifold>();
    for (auto &[worker_entity, manifold] : states) {
        auto *current = pool.try_get(manifolds.find(worker_entity));
        if (!current) continue;
        auto bodies = current->body;
        *current = manifold;
        current->body = bodies;
    }
}

template<typename Constraint>
void async_execution::apply_constraint_states(registry &registry,
                                              const std::vector<std::pair<entity, Constraint>> &states,
                                              std::uint64_t ops_applied) {
    for (auto &[e, con] : states) {
        if (!registry.valid(e) || pending_after(e, ops_applied)) continue;
        auto *current = registry.try_get<Constraint>(e);
        if (!current) continue;
        entity body0 = current->body[0], body1 = current->body[1];
        *current = con;
        current->body[0] = body0;
        current->body[1] = body1;
    }
}

void async_execution::apply_records(registry &registry, const std::vector<worker_record> &records) {
    auto &events = registry.ctx().get<contact_events>();
    using kind = worker_record::kind;
    for (auto &record : records) {
        switch (record.type) {
        case kind::manifold_created: {
            // The worker, a step or more ahead, found a contact of a body the program has
            // destroyed since: the destruction is on its way there, the contact is not shown.
            if (!registry.valid(record.manifold.body[0]) || !registry.valid(record.manifold.body[1])) break;
            auto m = registry.create();
            registry.emplace<contact_manifold>(m, record.manifold);
            manifolds.insert(record.worker_entity, m);
            break;
        }
        case kind::manifold_destroyed: {
            auto m = manifolds.find(record.worker_entity);
            manifolds.erase(record.worker_entity);
            if (m != null && registry.valid(m)) registry.destroy(m);
            break;
        }
        case kind::contact_event: {
            auto m = manifolds.find(record.worker_entity);
            if (m == null || !registry.valid(m)) break;
            auto &manifold = registry.get<contact_manifold>(m);
            manifold = record.manifold;
            // What begins with a body the program has destroyed is not told, and neither is its
            // end; what ends of what was told is told whatever became of the bodies (a listener
            // keeps its count).
            auto gone = !registry.valid(manifold.body[0]) || !registry.valid(manifold.body[1]);
            auto bit = std::uint32_t{1} << record.event.id;
            auto *untold = registry.try_get<contact_events::untold>(m);
            auto told = true;
            switch (record.event.type) {
            case contact_events::kind::started:
                if (gone) registry.get_or_emplace<contact_events::untold>(m).started = true;
                told = !gone;
                break;
            case contact_events::kind::point_created:
                if (gone) registry.get_or_emplace<contact_events::untold>(m).ids |= bit;
                told = !gone && !(untold && untold->started);
                break;
            case contact_events::kind::point_destroyed:
                told = !(untold && (untold->started || (untold->ids & bit)));
                if (untold) untold->ids &= ~bit;
                break;
            case contact_events::kind::ended:
                told = !(untold && untold->started);
                break;
            }
            if (!told) break;
            try {
                scoped_unmute heard(registry);
                events.publish({record.event.type, m, record.event.id});
            } catch (...) {
                errors.push_back(std::current_exception());
            }
            break;
        }
        case kind::entity_destroyed:
            // Destroyed in the worker (by a step callback, or by an operation from here): the
            // tag goes first, unsent, so that its destruction is not sent back, while what the
            // program's own listeners do as it goes (a body made in its place) is.
            if (registry.valid(record.main_entity)) {
                registry.remove<replicated_tag>(record.main_entity);
                scoped_unmute heard(registry);
                registry.destroy(record.main_entity);
            }
            break;
        }
    }
}

void tag_external_entity(registry &registry, entity e) {
    const char *function = "tag_external_entity";
    if (!is_attached(registry))
        throw std::invalid_argument(std::string(function) +
                                    ": the registry is not attached (call edyn::attach first)");
    if (!registry.valid(e))
        throw std::invalid_argument(std::string(function) + ": entity must be valid, got " +
                                    detail::describe(e));
    if (registry.all_of<rigidbody_tag>(e)) {
        throw std::invalid_argument(std::string(function) + ": " + detail::describe(e) +
                                    " is a rigid body, which is part of the simulation already");
    }
    if (!registry.all_of<external_tag>(e)) registry.emplace<external_tag>(e);
}

namespace detail {

void register_replicated(registry &registry, const char *function, const replicated_type &type) {
    if (!is_attached(registry))
        throw std::invalid_argument(std::string(function) +
                                    ": the registry is not attached (call edyn::attach first)");
    if (auto *link = registry.ctx().find<async_execution>()) link->add_type(registry, type);
}

replication_sink *find_replication_sink(registry &registry) noexcept {
    return registry.ctx().find<async_execution>();
}

} // namespace detail

} // namespace edyn
