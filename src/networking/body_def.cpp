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
#include "edyn/serialization/quantize.hpp"
#include "edyn/shapes/shape_aabb.hpp"
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
