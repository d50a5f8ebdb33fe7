#include "edyn/simulation/registry_listeners.hpp"
#include "../shapes/invalid_argument.hpp"
#include "../shapes/validate_compound_child.hpp"
#include "component_list.hpp"
#include "edyn/collision/collision_filter.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/collision/shape_epoch.hpp"
#include "edyn/constraints/constraint_links.hpp"
#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/constraints/external_entity.hpp"
#include "edyn/dynamics/body_limits.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/compound_shape.hpp"
#include "edyn/shapes/validate_shape.hpp"
#include "edyn/simulation/contact_events.hpp"
#include "edyn/simulation/interpolation.hpp"
#include "edyn/simulation/island.hpp"
#include "edyn/simulation/world_state.hpp"
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace edyn {

namespace {

world_state &world(registry &registry) { return registry.ctx().get<world_state>(); }

void on_construct_rigidbody(registry &registry, entity e) {
    if (!registry.all_of<static_tag>(e))
        registry.emplace_or_replace<previous_transform>(e, registry.get<position>(e),
                                                        registry.get<orientation>(e));
    if (registry.all_of<dynamic_tag>(e)) world(registry).islands.add_node(registry, e);
}

void on_destroy_rigidbody(registry &registry, entity e) {
    destroy_constraints_of(registry, e);
    world(registry).islands.remove_node(registry, e);
    registry.remove<previous_transform>(e);
}

template<typename T>
void on_construct_constraint(registry &registry, entity e) {
    auto &con = registry.get<T>(e);
    auto body0 = con.body[0], body1 = con.body[1];
    link_constraint(registry, e, body0, body1);
    world(registry).islands.link_edge(registry, e, body0, body1);
}

void on_destroy_constraint(registry &registry, entity e) {
    // The bodies it held lose a force: if they sleep (a bob hanging from a rope that is cut),
    // they wake to respond.
    world(registry).islands.wake_entity(registry, e);
    world(registry).islands.unlink_edge(registry, e);
    release_constraint(registry, e);
}

void on_destroy_constraint_links(registry &registry, entity e) { unlink_constraint(registry, e); }

// The entity is being destroyed (its list goes with it, maybe before the component whose
// listener would destroy its constraints): its constraints go too.
void on_destroy_constraint_list(registry &registry, entity e) { destroy_constraints_of(registry, e); }

// Links the constraints of a body that just became a node: while none of their bodies was
// dynamic they had no island to join.
void link_constraints_of(registry &registry, entity e) {
    std::vector<constraint_ref> refs;
    constraints_of(registry, e, refs);
    for (auto &ref : refs) {
        if (registry.all_of<island_resident>(ref.constraint)) continue;
        world(registry).islands.link_edge(registry, ref.constraint, ref.body[0], ref.body[1]);
    }
}

void on_construct_dynamic(registry &registry, entity e) {
    if (registry.all_of<rigidbody_tag>(e) && !registry.all_of<island_resident>(e)) {
        world(registry).islands.add_node(registry, e);
        link_constraints_of(registry, e);
    }
}

void on_destroy_dynamic(registry &registry, entity e) { world(registry).islands.remove_node(registry, e); }

void on_destroy_resident(registry &registry, entity e) {
    world(registry).islands.on_resident_destroyed(registry, e);
}

void on_construct_static(registry &registry, entity e) { registry.remove<previous_transform>(e); }

void on_destroy_static(registry &registry, entity e) {
    if (registry.all_of<rigidbody_tag, position, orientation>(e)) {
        registry.emplace_or_replace<previous_transform>(e, registry.get<position>(e),
                                                        registry.get<orientation>(e));
    }
}

void on_construct_aabb(registry &registry, entity e) {
    world(registry).broadphase.insert(e, registry.get<AABB>(e), registry.all_of<static_tag>(e));
}

void on_destroy_aabb(registry &registry, entity e) {
    auto &bp = world(registry).broadphase;
    if (bp.contains(e)) bp.remove(registry, e);
}

void on_destroy_manifold(registry &registry, entity e) {
    auto &w = world(registry);
    w.islands.unlink_edge(registry, e);
    auto &manifold = registry.get<contact_manifold>(e);
    if (manifold.num_points == 0) return;
    // A body asleep against the other one (a static floor destroyed or cleared from under it)
    // has lost its support: it wakes to fall. An awake body needs nothing: it is stepped anyway.
    for (auto body : manifold.body) {
        if (registry.valid(body) && registry.all_of<sleeping_tag>(body))
            w.islands.wake_entity(registry, body);
    }
    // Contact is lost with the manifold: say so while the entity still exists, of what the
    // listeners were told began.
    auto &events = registry.ctx().get<contact_events>();
    using kind = contact_events::kind;
    auto untold = events.withdraw(e);
    if (untold.started) return;
    for (std::uint32_t i = 0; i < manifold.num_points; ++i) {
        if (!(untold.ids & (std::uint32_t{1} << manifold.ids[i])))
            events.publish({kind::point_destroyed, e, manifold.ids[i]});
    }
    events.publish({kind::ended, e, 0});
}

// The program moved a body: refresh what depends on its transform and wake it.
void wake_sleepers_near(registry &registry, world_state &w, entity e, const AABB &aabb) {
    auto margin = vector3_one * contact_breaking_threshold;
    std::vector<entity> sleepers;
    w.broadphase.query(inset(aabb, margin), [&](entity other) {
        if (other != e && registry.all_of<sleeping_tag>(other)) sleepers.push_back(other);
    });
    for (auto other : sleepers)
        w.islands.wake_entity(registry, other);
}

// The program moved a body or changed its shape: its AABB is computed again, and a static
// body's proxy is put back where it now is (the broadphase never moves static proxies). A static
// or kinematic body is in no island, so waking it wakes nothing: what lay against it where it
// was, or is in its way where it is now, and what it holds by a constraint, wake instead.
void refresh_placement(registry &registry, entity e) {
    auto &w = world(registry);
    bool dynamic = registry.all_of<dynamic_tag>(e);
    if (!dynamic) w.islands.wake_joined_to(registry, e);
    if (registry.all_of<AABB>(e)) {
        auto old_aabb = registry.get<AABB>(e);
        update_rigidbody_aabb(registry, e);
        if (!dynamic && w.broadphase.contains(e)) {
            wake_sleepers_near(registry, w, e, old_aabb);
            wake_sleepers_near(registry, w, e, registry.get<AABB>(e));
        }
        if (registry.all_of<static_tag>(e) && w.broadphase.contains(e)) {
            w.broadphase.remove(registry, e);
            w.broadphase.insert(e, registry.get<AABB>(e), true);
        }
    }
    w.islands.wake_entity(registry, e);
}

// A body the program changed: checked before the next step (check_written_bodies).
void note_written(registry &registry, entity e) {
    if (registry.all_of<rigidbody_tag>(e)) world(registry).written_bodies.push_back(e);
}

void on_update_velocity(registry &registry, entity e) { note_written(registry, e); }

void on_update_transform(registry &registry, entity e) {
    if (!registry.all_of<rigidbody_tag>(e)) return;
    note_written(registry, e);
    if (registry.all_of<dynamic_tag>(e)) update_inertia_world(registry, e);
    if (auto *prev = registry.try_get<previous_transform>(e)) {
        // A teleport is not interpolated.
        *prev = {registry.get<position>(e), registry.get<orientation>(e)};
    }
    refresh_placement(registry, e);
}

void on_destroy_external(registry &registry, entity e) { destroy_constraints_of(registry, e); }

// A change the simulation must respond to: a body's velocity, mass, material or shape, or a
// constraint's settings (its island wakes, asleep or not).
void on_update_wake(registry &registry, entity e) { world(registry).islands.wake_entity(registry, e); }

// A component that wakes a body by coming or going (waking_presence_components); a body being
// made gets it before it is a body, one being destroyed needs nothing.
void on_presence_wake(registry &registry, entity e) {
    if (registry.all_of<rigidbody_tag>(e) && !registry.destroying(e)) on_update_wake(registry, e);
}

// A static or kinematic body's new friction or restitution acts on what rests on it: that wakes.
// (Its new velocity needs nothing here: each step wakes what a moving kinematic body touches.)
void on_update_material(registry &registry, entity e) {
    note_written(registry, e);
    if (!registry.all_of<rigidbody_tag>(e) || registry.all_of<dynamic_tag>(e)) return;
    auto &w = world(registry);
    if (w.broadphase.contains(e)) wake_sleepers_near(registry, w, e, registry.get<AABB>(e));
}

// A body that gains or loses its material stops or starts being a sensor: its contacts are
// solved, or no longer, from the next step. It wakes, and so does what rests on it, or against
// it when a sensor becomes solid. (A body being made gets its material before it is a body; one
// being cleared or destroyed loses it after.)
void on_change_has_material(registry &registry, entity e, bool has_material) {
    if (!registry.all_of<rigidbody_tag>(e) || registry.destroying(e)) return;
    if (has_material)
        registry.remove<sensor_tag>(e);
    else
        registry.emplace_or_replace<sensor_tag>(e);
    world(registry).islands.wake_entity(registry, e);
    on_update_material(registry, e);
}

void on_construct_material(registry &registry, entity e) { on_change_has_material(registry, e, true); }

void on_destroy_material(registry &registry, entity e) { on_change_has_material(registry, e, false); }

// What validate_shape finds wrong with the shape of `e`, if it has one; the step refuses it.
std::optional<std::string> shape_problem(const registry &registry, entity e) {
    if (!registry.all_of<shape_index>(e)) return std::nullopt;
    try {
        visit_shape(registry, e, [](const auto &shape) { validate_shape(shape); });
    } catch (const std::invalid_argument &error) {
        return error.what();
    }
    return std::nullopt;
}

// A compound changed in place takes its children's bounds and its tree again (finish()), so that
// its change applies from the next step as any shape's does. One with an invalid child is left
// as it is, for the step to refuse with that child's problem.
void refresh_compound(compound_shape &compound) {
    if (compound.children.empty()) return;
    try {
        for (const auto &child : compound.children)
            detail::validate_compound_child(child.shape, child.position, child.orientation);
    } catch (const std::invalid_argument &) {
        return;
    }
    compound.finish();
}

void on_update_shape(registry &registry, entity e) {
    if (auto *compound = registry.try_get<compound_shape>(e)) refresh_compound(*compound);
    ++registry.get_or_emplace<shape_epoch>(e).value;
    note_written(registry, e);
    // A dynamic body's box follows its shape every step; a static or kinematic one's is computed
    // when it moves, so now, once the shape is one the step will take.
    if (registry.all_of<rigidbody_tag>(e) && !registry.all_of<dynamic_tag>(e) && !shape_problem(registry, e))
        refresh_placement(registry, e);
}

// A body's own gravity, given or changed.
void on_write_gravity(registry &registry, entity e) { note_written(registry, e); }

void on_change_filter(registry &registry, entity e) {
    auto &w = world(registry);
    if (!w.broadphase.contains(e)) return;
    // Pairs the new filter refuses lose their manifolds, which wakes what slept on them
    // (on_destroy_manifold); pairs it now allows are searched at the next step. The body wakes so
    // that those are collided (a pair of sleeping bodies is not), and so do the bodies asleep
    // against it when it is static or kinematic.
    w.broadphase.refilter(registry, e);
    w.islands.wake_entity(registry, e);
    if (!registry.all_of<dynamic_tag>(e)) wake_sleepers_near(registry, w, e, registry.get<AABB>(e));
}

// A removed exclusion list lets its pairs collide again (the search runs at the next step, once
// it is gone), unless the entity itself is going.
void on_destroy_exclusion(registry &registry, entity e) {
    if (!registry.destroying(e)) on_change_filter(registry, e);
}

// Every component edyn puts on the program's entities.
using edyn_components =
    component_list<rigidbody_tag, dynamic_tag, static_tag, kinematic_tag, sleeping_tag, sleeping_disabled_tag,
                   sensor_tag, position, orientation, present_position, present_orientation, linvel, angvel,
                   gravity, mass, mass_inv, inertia, inertia_inv, inertia_world_inv, center_of_mass,
                   rigidbody_dynamic_mass, material, shape_index, AABB, collision_filter, collision_exclusion,
                   previous_transform, island_resident, island_edge, sleep_timer, constraint_links,
                   constraint_list, plane_shape, sphere_shape, cylinder_shape, capsule_shape, box_shape,
                   polyhedron_shape, compound_shape, mesh_shape, paged_mesh_shape>;

template<typename... Components>
void clear_all(registry &registry, component_list<Components...>) {
    (registry.clear<Components>(), ...);
}

template<typename... Constraints>
void connect_constraints(registry &registry, constraint_type_list<Constraints...>) {
    (registry.on_construct<Constraints>().template connect<&on_construct_constraint<Constraints>>(), ...);
    (registry.on_destroy<Constraints>().template connect<&on_destroy_constraint>(), ...);
    (registry.on_update<Constraints>().template connect<&on_update_wake>(), ...);
}

template<typename... Constraints>
void disconnect_constraints(registry &registry, constraint_type_list<Constraints...>) {
    (registry.on_construct<Constraints>().template disconnect<&on_construct_constraint<Constraints>>(), ...);
    (registry.on_destroy<Constraints>().template disconnect<&on_destroy_constraint>(), ...);
    (registry.on_update<Constraints>().template disconnect<&on_update_wake>(), ...);
}

// Constraints stay on the program's entities as plain components when edyn lets go.
template<typename... Constraints>
void clear_constraints(registry &registry, constraint_type_list<Constraints...>) {
    (registry.clear<Constraints>(), ...);
}

template<typename... Constraints>
void adopt_constraints(registry &registry, constraint_type_list<Constraints...>) {
    auto adopt = [&](auto *tag) {
        using component = std::remove_pointer_t<decltype(tag)>;
        std::vector<entity> entities;
        for (auto e : registry.view<component>())
            entities.push_back(e);
        std::reverse(entities.begin(), entities.end());
        for (auto e : entities)
            on_construct_constraint<component>(registry, e);
    };
    (adopt(static_cast<Constraints *>(nullptr)), ...);
}

template<auto Fn, typename... Components>
void connect_update(registry &registry, component_list<Components...>) {
    (registry.on_update<Components>().template connect<Fn>(), ...);
}

template<auto Fn, typename... Components>
void disconnect_update(registry &registry, component_list<Components...>) {
    (registry.on_update<Components>().template disconnect<Fn>(), ...);
}

template<auto Fn, typename... Components>
void connect_presence(registry &registry, component_list<Components...>, bool connect) {
    if (connect) {
        (registry.on_construct<Components>().template connect<Fn>(), ...);
        (registry.on_destroy<Components>().template connect<Fn>(), ...);
    } else {
        (registry.on_construct<Components>().template disconnect<Fn>(), ...);
        (registry.on_destroy<Components>().template disconnect<Fn>(), ...);
    }
}

// Changes after which contact points computed with the old geometry must not be reused.
using shape_components =
    component_list<shape_index, plane_shape, sphere_shape, cylinder_shape, capsule_shape, box_shape,
                   polyhedron_shape, compound_shape, mesh_shape, paged_mesh_shape>;

} // namespace

void connect_registry_listeners(registry &registry) {
    registry.on_construct<rigidbody_tag>().connect<&on_construct_rigidbody>();
    registry.on_destroy<rigidbody_tag>().connect<&on_destroy_rigidbody>();
    registry.on_construct<dynamic_tag>().connect<&on_construct_dynamic>();
    registry.on_destroy<dynamic_tag>().connect<&on_destroy_dynamic>();
    registry.on_construct<static_tag>().connect<&on_construct_static>();
    registry.on_destroy<static_tag>().connect<&on_destroy_static>();
    registry.on_construct<AABB>().connect<&on_construct_aabb>();
    registry.on_destroy<AABB>().connect<&on_destroy_aabb>();
    registry.on_destroy<contact_manifold>().connect<&on_destroy_manifold>();
    registry.on_destroy<island_resident>().connect<&on_destroy_resident>();
    registry.on_update<position>().connect<&on_update_transform>();
    registry.on_update<orientation>().connect<&on_update_transform>();
    registry.on_update<linvel>().connect<&on_update_velocity>();
    registry.on_update<angvel>().connect<&on_update_velocity>();
    connect_update<&on_update_wake>(registry, waking_components{});
    connect_presence<&on_presence_wake>(registry, waking_presence_components{}, true);
    connect_update<&on_update_shape>(registry, shape_components{});
    registry.on_update<material>().connect<&on_update_material>();
    registry.on_construct<gravity>().connect<&on_write_gravity>();
    registry.on_update<gravity>().connect<&on_write_gravity>();
    registry.on_construct<material>().connect<&on_construct_material>();
    registry.on_destroy<material>().connect<&on_destroy_material>();
    registry.on_update<collision_filter>().connect<&on_change_filter>();
    registry.on_construct<collision_exclusion>().connect<&on_change_filter>();
    registry.on_update<collision_exclusion>().connect<&on_change_filter>();
    registry.on_destroy<collision_exclusion>().connect<&on_destroy_exclusion>();
    connect_constraints(registry, constraint_types{});
    registry.on_destroy<constraint_links>().connect<&on_destroy_constraint_links>();
    registry.on_destroy<constraint_list>().connect<&on_destroy_constraint_list>();
    registry.on_destroy<external_tag>().connect<&on_destroy_external>();
}

void disconnect_registry_listeners(registry &registry) {
    registry.on_construct<rigidbody_tag>().disconnect<&on_construct_rigidbody>();
    registry.on_destroy<rigidbody_tag>().disconnect<&on_destroy_rigidbody>();
    registry.on_construct<dynamic_tag>().disconnect<&on_construct_dynamic>();
    registry.on_destroy<dynamic_tag>().disconnect<&on_destroy_dynamic>();
    registry.on_construct<static_tag>().disconnect<&on_construct_static>();
    registry.on_destroy<static_tag>().disconnect<&on_destroy_static>();
    registry.on_construct<AABB>().disconnect<&on_construct_aabb>();
    registry.on_destroy<AABB>().disconnect<&on_destroy_aabb>();
    registry.on_destroy<contact_manifold>().disconnect<&on_destroy_manifold>();
    registry.on_destroy<island_resident>().disconnect<&on_destroy_resident>();
    registry.on_update<position>().disconnect<&on_update_transform>();
    registry.on_update<orientation>().disconnect<&on_update_transform>();
    registry.on_update<linvel>().disconnect<&on_update_velocity>();
    registry.on_update<angvel>().disconnect<&on_update_velocity>();
    disconnect_update<&on_update_wake>(registry, waking_components{});
    connect_presence<&on_presence_wake>(registry, waking_presence_components{}, false);
    disconnect_update<&on_update_shape>(registry, shape_components{});
    registry.on_update<material>().disconnect<&on_update_material>();
    registry.on_construct<gravity>().disconnect<&on_write_gravity>();
    registry.on_update<gravity>().disconnect<&on_write_gravity>();
    registry.on_construct<material>().disconnect<&on_construct_material>();
    registry.on_destroy<material>().disconnect<&on_destroy_material>();
    registry.on_update<collision_filter>().disconnect<&on_change_filter>();
    registry.on_construct<collision_exclusion>().disconnect<&on_change_filter>();
    registry.on_update<collision_exclusion>().disconnect<&on_change_filter>();
    registry.on_destroy<collision_exclusion>().disconnect<&on_destroy_exclusion>();
    disconnect_constraints(registry, constraint_types{});
    registry.on_destroy<constraint_links>().disconnect<&on_destroy_constraint_links>();
    registry.on_destroy<constraint_list>().disconnect<&on_destroy_constraint_list>();
    registry.on_destroy<external_tag>().disconnect<&on_destroy_external>();
}

void check_written_bodies(registry &registry) {
    auto &written = world(registry).written_bodies;
    for (auto e : written) {
        if (!registry.valid(e) || !registry.all_of<rigidbody_tag>(e)) continue;
        auto refuse = [&](const std::string &problem) {
            throw detail::entity_refusal(e, "step: body entity ", ", changed after it was made: " + problem);
        };
        auto refuse_value = [&](const char *component, const std::string &value, const char *what) {
            refuse(std::string(component) + " must be " + what + ", got " + value);
        };
        auto &pos = registry.get<position>(e);
        if (!isfinite(pos))
            refuse_value("position", detail::concat(static_cast<const vector3 &>(pos)), "finite");
        auto &orn = registry.get<orientation>(e);
        if (!isfinite(orn) || !(length_sqr(orn) > scalar(1e-12)))
            refuse_value("orientation", detail::concat(static_cast<const quaternion &>(orn)),
                         "finite and not zero");
        if (auto *v = registry.try_get<linvel>(e); v && !isfinite(*v))
            refuse_value("linvel", detail::concat(static_cast<const vector3 &>(*v)), "finite");
        if (auto *w = registry.try_get<angvel>(e); w && !isfinite(*w))
            refuse_value("angvel", detail::concat(static_cast<const vector3 &>(*w)), "finite");
        if (auto *g = registry.try_get<gravity>(e); g && !(isfinite(*g) && length(*g) <= max_gravity))
            refuse_value("gravity", detail::concat(static_cast<const vector3 &>(*g)),
                         ("finite and at most " + detail::concat(max_gravity) + " m/s^2 long").c_str());
        // The shape's and material's own checks, as make_rigidbody makes them.
        if (auto problem = shape_problem(registry, e)) refuse(*problem);
        try {
            if (auto *m = registry.try_get<material>(e)) validate_material("step", "material", *m);
        } catch (const std::invalid_argument &error) {
            std::string problem = error.what();
            // validate_material's messages begin with the function's name.
            if (problem.rfind("step: ", 0) == 0) problem.erase(0, 6);
            refuse(problem);
        }
    }
    written.clear();
}

void adopt_existing_bodies(registry &registry) {
    std::vector<entity> bodies;
    for (auto e : registry.view<rigidbody_tag>())
        bodies.push_back(e);
    // Oldest first, as if they had been made after attach().
    std::reverse(bodies.begin(), bodies.end());
    for (auto e : bodies) {
        on_construct_rigidbody(registry, e);
        if (registry.all_of<AABB>(e)) on_construct_aabb(registry, e);
    }
    adopt_constraints(registry, constraint_types{});
}

void remove_edyn_components(registry &registry) {
    std::vector<entity> internal;
    for (auto e : registry.view<contact_manifold>())
        internal.push_back(e);
    for (auto e : registry.view<island>())
        internal.push_back(e);
    for (auto e : internal)
        registry.destroy(e);
    clear_all(registry, edyn_components{});
    clear_constraints(registry, constraint_types{});
    registry.clear<external_tag>();
}

} // namespace edyn
