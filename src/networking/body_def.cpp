#include "body_def.hpp"
#include "edyn/collision/collision_filter.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/serialization/dynamics_types.hpp"
#include "edyn/serialization/quantize.hpp"
#include "edyn/serialization/shape_types.hpp"
#include "edyn/serialization/std_types.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "value_bytes.hpp"
#include <cmath>

namespace edyn {

rigidbody_def get_rigidbody_def(const registry &registry, entity e) {
    rigidbody_def def;
    if (registry.all_of<static_tag>(e)) {
        def.kind = rigidbody_kind::rb_static;
    } else if (registry.all_of<kinematic_tag>(e)) {
        def.kind = rigidbody_kind::rb_kinematic;
    } else {
        def.kind = rigidbody_kind::rb_dynamic;
        def.mass = registry.get<mass>(e);
        def.inertia = static_cast<const matrix3x3 &>(registry.get<inertia>(e));
    }
    if (auto *m = registry.try_get<material>(e)) {
        def.material = *m;
    } else {
        def.material.reset();
    }
    def.position = get_rigidbody_origin(registry, e);
    def.orientation = registry.get<orientation>(e);
    def.linvel = registry.get<linvel>(e);
    def.angvel = registry.get<angvel>(e);
    if (auto *g = registry.try_get<gravity>(e)) def.gravity = *g;
    if (auto *com = registry.try_get<center_of_mass>(e)) def.center_of_mass = *com;
    if (registry.all_of<shape_index>(e)) {
        def.shape = visit_shape(registry, e, [](const auto &shape) { return shapes_variant_t{shape}; });
        if (auto *filter = registry.try_get<collision_filter>(e)) {
            def.collision_group = filter->group;
            def.collision_mask = filter->mask;
        }
    }
    def.sleeping_disabled = registry.all_of<sleeping_disabled_tag>(e);
    return def;
}

namespace {

// Puts `value` on `e` as a Component, or removes the component when there is no value.
template<typename Component, typename T>
void set_optional(registry &registry, entity e, const std::optional<T> &value) {
    if (value) {
        registry.emplace_or_replace<Component>(e, *value);
    } else {
        registry.remove<Component>(e);
    }
}

} // namespace

void update_rigidbody(registry &registry, entity e, const rigidbody_def &def) {
    auto current = get_rigidbody_def(registry, e);
    auto dynamic = def.kind == rigidbody_kind::rb_dynamic;
    // A shape a dynamic body may not have (a plane, a mesh) is left before the body becomes
    // dynamic, and taken after it stops being dynamic.
    auto shape_changed = value_bytes(current.shape) != value_bytes(def.shape);
    if (shape_changed && dynamic) rigidbody_set_shape(registry, e, def.shape);
    if (current.kind != def.kind) rigidbody_set_kind(registry, e, def.kind);
    if (shape_changed && !dynamic) rigidbody_set_shape(registry, e, def.shape);
    if (current.center_of_mass != def.center_of_mass)
        set_center_of_mass(registry, e, def.center_of_mass.value_or(vector3_zero));
    if (dynamic && def.inertia) {
        auto &m = registry.get<mass>(e);
        auto &I = static_cast<const matrix3x3 &>(registry.get<inertia>(e));
        if (m.s != def.mass || I != *def.inertia) {
            registry.replace<mass>(e, def.mass);
            registry.replace<mass_inv>(e, scalar(1) / def.mass);
            registry.replace<inertia>(e, *def.inertia);
            registry.replace<inertia_inv>(e, inverse(*def.inertia));
            update_inertia_world(registry, e);
        }
    }
    // A body without a material is a sensor (the simulation's listeners keep sensor_tag).
    if (current.material != def.material) set_optional<material>(registry, e, def.material);
    if (dynamic && current.gravity != def.gravity) set_optional<gravity>(registry, e, def.gravity);
    if (auto *filter = registry.try_get<collision_filter>(e);
        filter && (filter->group != def.collision_group || filter->mask != def.collision_mask))
        registry.replace<collision_filter>(e, def.collision_group, def.collision_mask);
    if (current.sleeping_disabled != def.sleeping_disabled) {
        if (def.sleeping_disabled) {
            registry.emplace<sleeping_disabled_tag>(e);
        } else {
            registry.remove<sleeping_disabled_tag>(e);
        }
    }
    if (def.kind == rigidbody_kind::rb_static &&
        (current.position != def.position || current.orientation != def.orientation)) {
        auto com = def.center_of_mass.value_or(vector3_zero);
        registry.replace<orientation>(e, def.orientation);
        registry.replace<position>(e, def.position + rotate(def.orientation, com));
    }
}

namespace {
bool within(const vector3 &v, scalar bound) {
    return std::abs(v.x) <= bound && std::abs(v.y) <= bound && std::abs(v.z) <= bound;
}
} // namespace

bool within_network_range(const rigidbody_def &def) {
    auto bound = max_quantized_coordinate;
    if (!within(def.position, bound) || !within(def.linvel, bound) || !within(def.angvel, bound))
        return false;
    if (def.center_of_mass && !within(*def.center_of_mass, bound)) return false;
    // Planes are infinite and never move.
    if (def.shape && !std::holds_alternative<plane_shape>(*def.shape)) {
        auto aabb = shape_aabb(*def.shape, def.position, def.orientation);
        if (!within(aabb.min, 2 * bound) || !within(aabb.max, 2 * bound)) return false;
    }
    return true;
}

} // namespace edyn
