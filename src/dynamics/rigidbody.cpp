#include "edyn/dynamics/rigidbody.hpp"
#include "../shapes/invalid_argument.hpp"
#include "edyn/collision/collision_filter.hpp"
#include "edyn/dynamics/body_limits.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/worker_calls.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/shapes/validate_shape.hpp"
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace edyn {

namespace {

using detail::concat;

[[noreturn]] void fail(const char *function, const char *field, const std::string &problem) {
    throw std::invalid_argument(std::string(function) + ": " + field + " " + problem);
}

void check_finite(const char *function, const char *field, const vector3 &v) {
    if (!isfinite(v)) fail(function, field, "must be finite, got " + concat(v));
}

void check_orientation(const char *function, const quaternion &q) {
    if (!isfinite(q) || !is_unit(q)) {
        std::ostringstream out;
        out << "must be a finite unit quaternion, got (" << q.x << ", " << q.y << ", " << q.z << ", " << q.w
            << ") of length " << length(q);
        fail(function, "orientation", out.str());
    }
}

void check_mass(const char *function, scalar mass) {
    if (!(mass > 0) || !std::isfinite(mass))
        fail(function, "mass", "must be positive and finite for a dynamic body, got " + concat(mass));
    if (!(mass >= min_body_mass && mass <= max_body_mass))
        fail(function, "mass",
             "must be in [" + concat(min_body_mass) + ", " + concat(max_body_mass) + "] kg, got " +
                 concat(mass));
}

// Symmetric to float rounding: a tensor rotated into object space by the program is rarely
// exactly symmetric.
bool is_symmetric(const matrix3x3 &m) {
    auto scale = std::max({std::abs(m[0][0]), std::abs(m[1][1]), std::abs(m[2][2])});
    auto tolerance = scale * scalar(1e-4);
    return std::abs(m[0][1] - m[1][0]) <= tolerance && std::abs(m[0][2] - m[2][0]) <= tolerance &&
           std::abs(m[1][2] - m[2][1]) <= tolerance;
}

// Sylvester's criterion: every leading principal minor positive. Positive diagonal entries and
// a positive determinant are not enough (two negative eigenvalues have a positive product).
// Tested on the tensor scaled to a unit diagonal (entry ij over the square root of ii times jj),
// which is positive definite when the tensor is, and whose minors neither overflow nor underflow
// however far apart the moments are (1e-12 and 1e30 in one tensor).
bool is_positive_definite(const matrix3x3 &m) {
    if (!(m[0][0] > 0 && m[1][1] > 0 && m[2][2] > 0)) return false;
    const vector3 s{1 / std::sqrt(m[0][0]), 1 / std::sqrt(m[1][1]), 1 / std::sqrt(m[2][2])};
    auto n = matrix3x3_zero;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            n[i][j] = m[i][j] * s[i] * s[j];
    return n[0][0] * n[1][1] - n[0][1] * n[1][0] > 0 && determinant(n) > 0;
}

void check_inertia(const char *function, const matrix3x3 &inertia) {
    auto d = get_diagonal(inertia);
    if (!isfinite(inertia) || !is_symmetric(inertia) || !is_positive_definite(inertia)) {
        fail(function, "inertia", "must be finite, symmetric and positive definite, got " + concat(inertia));
    }
    auto low = std::min({d.x, d.y, d.z});
    auto high = std::max({d.x, d.y, d.z});
    // A principal moment is at most the largest diagonal entry; the smallest is at least
    // 1 / (largest diagonal entry of the inverse) / 3, so a nearly singular tensor with a large
    // diagonal is caught by its inverse.
    auto inv = inverse(inertia);
    auto inv_high = std::max({inv[0][0], inv[1][1], inv[2][2]});
    if (!(low >= min_body_inertia && high <= max_body_inertia) || !isfinite(inv) ||
        !(inv_high <= scalar(1.0001) / min_body_inertia)) {
        fail(function, "inertia",
             "must have principal moments in [" + concat(min_body_inertia) + ", " + concat(max_body_inertia) +
                 "] kg*m^2, got " + concat(inertia));
    }
}

void check_gravity(const char *function, const vector3 &gravity) {
    check_finite(function, "gravity", gravity);
    if (!(length(gravity) <= max_gravity))
        fail(function, "gravity",
             "must be at most " + concat(max_gravity) + " m/s^2 long, got " + concat(gravity));
}

struct mass_properties {
    scalar mass;
    matrix3x3 inertia;
    vector3 com;
};

// Mass, inertia about the centre of mass and the centre of mass offset for a dynamic body.
mass_properties compute_mass_properties(scalar mass, const std::optional<matrix3x3> &inertia,
                                        const std::optional<shapes_variant_t> &shape,
                                        const std::optional<vector3> &center_of_mass) {
    auto centroid = shape ? shape_centroid(*shape) : vector3_zero;
    auto com = center_of_mass.value_or(centroid);
    if (inertia) return {mass, *inertia, com};
    auto I = moment_of_inertia(*shape, mass);
    if (com != centroid) I = shift_moment_of_inertia(I, mass, com - centroid);
    return {mass, I, com};
}

// The inertia `shape` gives the body about `com`, for the mass it has when dynamic: its own
// when it is, or the one a static or kinematic body takes back when it becomes dynamic again
// (rigidbody_dynamic_mass), so that a shape or centre of mass changed meanwhile is not forgotten.
// Shapes that only static and kinematic bodies may have leave the kept inertia as it was.
void take_inertia_of_shape(registry &registry, entity e, const shapes_variant_t &shape, const vector3 &com) {
    if (registry.all_of<dynamic_tag>(e)) {
        auto I = compute_mass_properties(registry.get<mass>(e).s, std::nullopt, shape, com).inertia;
        registry.replace<inertia>(e, I);
        registry.replace<inertia_inv>(e, inverse(I));
        update_inertia_world(registry, e);
        return;
    }
    auto *kept = registry.try_get<rigidbody_dynamic_mass>(e);
    auto may_be_dynamic = !std::holds_alternative<plane_shape>(shape) &&
                          !std::holds_alternative<mesh_shape>(shape) &&
                          !std::holds_alternative<paged_mesh_shape>(shape);
    if (!kept || !may_be_dynamic) return;
    auto I = compute_mass_properties(kept->mass, std::nullopt, shape, com).inertia;
    registry.patch<rigidbody_dynamic_mass>(e, [&](rigidbody_dynamic_mass &m) { m.inertia = I; });
}

void emplace_shape(registry &registry, entity e, const shapes_variant_t &shape) {
    std::visit([&](const auto &s) { registry.emplace<std::decay_t<decltype(s)>>(e, s); }, shape);
    registry.emplace<shape_index>(e, shape.index());
}

template<typename... Shapes>
void remove_shapes(registry &registry, entity e, std::tuple<Shapes...> *) {
    registry.remove<Shapes...>(e);
}

void remove_shape(registry &registry, entity e) {
    registry.remove<AABB, collision_filter, shape_index>(e);
    remove_shapes(registry, e, static_cast<shapes_tuple_t *>(nullptr));
}

void set_mass_components(registry &registry, entity e, rigidbody_kind kind, const mass_properties &props) {
    if (kind == rigidbody_kind::rb_dynamic) {
        registry.emplace_or_replace<mass>(e, props.mass);
        registry.emplace_or_replace<mass_inv>(e, scalar(1) / props.mass);
        registry.emplace_or_replace<inertia>(e, props.inertia);
        registry.emplace_or_replace<inertia_inv>(e, inverse(props.inertia));
    } else {
        registry.emplace_or_replace<mass>(e, large_scalar);
        registry.emplace_or_replace<mass_inv>(e, scalar(0));
        registry.emplace_or_replace<inertia>(e, diagonal_matrix(vector3_max));
        registry.emplace_or_replace<inertia_inv>(e, matrix3x3_zero);
    }
    registry.emplace_or_replace<inertia_world_inv>(e, matrix3x3_zero);
}

void emplace_kind_tag(registry &registry, entity e, rigidbody_kind kind) {
    switch (kind) {
    case rigidbody_kind::rb_dynamic:
        registry.emplace<dynamic_tag>(e);
        break;
    case rigidbody_kind::rb_static:
        registry.emplace<static_tag>(e);
        break;
    case rigidbody_kind::rb_kinematic:
        registry.emplace<kinematic_tag>(e);
        break;
    }
}

rigidbody_kind get_kind(const registry &registry, entity e) {
    if (registry.all_of<dynamic_tag>(e)) return rigidbody_kind::rb_dynamic;
    if (registry.all_of<kinematic_tag>(e)) return rigidbody_kind::rb_kinematic;
    return rigidbody_kind::rb_static;
}

void check_body(const char *function, const registry &registry, entity e) {
    if (!registry.valid(e)) throw std::invalid_argument(std::string(function) + ": entity is not valid");
    if (!registry.all_of<rigidbody_tag>(e))
        throw std::invalid_argument(std::string(function) + ": entity is not a rigid body");
}

// The shape currently stored on a body, rebuilt as a variant.
std::optional<shapes_variant_t> get_shape(const registry &registry, entity e) {
    auto *index = registry.try_get<shape_index>(e);
    if (!index) return std::nullopt;
    std::optional<shapes_variant_t> result;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((index->value == I ? void(result = registry.get<std::variant_alternative_t<I, shapes_variant_t>>(e))
                            : void()),
         ...);
    }
    (std::make_index_sequence<num_shapes>{});
    return result;
}

void refresh_aabb(registry &registry, entity e) {
    auto shape = get_shape(registry, e);
    if (!shape) return;
    auto aabb = shape_aabb(*shape, get_rigidbody_origin(registry, e), registry.get<orientation>(e));
    registry.emplace_or_replace<AABB>(e, aabb);
}

void check_kind(const char *function, rigidbody_kind kind) {
    if (kind != rigidbody_kind::rb_dynamic && kind != rigidbody_kind::rb_static &&
        kind != rigidbody_kind::rb_kinematic)
        throw std::invalid_argument(std::string(function) + ": kind " + std::to_string(unsigned(kind)) +
                                    " is not a rigidbody_kind (rb_dynamic, rb_static or rb_kinematic)");
}

} // namespace

void validate_rigidbody_def(const rigidbody_def &def) {
    const char *fn = "make_rigidbody";
    check_kind(fn, def.kind);
    check_finite(fn, "position", def.position);
    check_orientation(fn, def.orientation);
    check_finite(fn, "linvel", def.linvel);
    check_finite(fn, "angvel", def.angvel);
    if (def.gravity) check_gravity(fn, *def.gravity);
    if (def.center_of_mass) check_finite(fn, "center_of_mass", *def.center_of_mass);
    if (def.material) validate_material(fn, "material", *def.material);
    if (def.restitution) {
        if (!def.material) fail(fn, "restitution", "is set on a sensor, which has no material");
        if (!(*def.restitution >= 0 && *def.restitution <= 1))
            fail(fn, "restitution", "must be in [0, 1], got " + concat(*def.restitution));
    }
    if (def.shape) {
        validate_shape(*def.shape);
        if (std::holds_alternative<plane_shape>(*def.shape) && def.kind != rigidbody_kind::rb_static) {
            fail(fn, "shape", "plane_shape is only allowed on static bodies");
        }
        if (std::holds_alternative<mesh_shape>(*def.shape) && def.kind == rigidbody_kind::rb_dynamic) {
            fail(fn, "shape", "mesh_shape is only allowed on static and kinematic bodies");
        }
        if (std::holds_alternative<paged_mesh_shape>(*def.shape) && def.kind == rigidbody_kind::rb_dynamic) {
            fail(fn, "shape", "paged_mesh_shape is only allowed on static and kinematic bodies");
        }
    }
    if (def.kind == rigidbody_kind::rb_dynamic) {
        check_mass(fn, def.mass);
        if (def.inertia) {
            check_inertia(fn, *def.inertia);
        } else if (!def.shape) {
            fail(fn, "inertia", "must be set for a dynamic body without a shape");
        }
    }
}

void make_rigidbody(entity e, registry &registry, const rigidbody_def &def) {
    validate_rigidbody_def(def);
    if (!registry.valid(e)) throw std::invalid_argument("make_rigidbody: entity is not valid");
    if (registry.all_of<rigidbody_tag>(e))
        throw std::invalid_argument("make_rigidbody: entity is already a rigid body");

    auto props =
        def.kind == rigidbody_kind::rb_dynamic
            ? compute_mass_properties(def.mass, def.inertia, def.shape, def.center_of_mass)
            : mass_properties{large_scalar, matrix3x3_zero, def.center_of_mass.value_or(vector3_zero)};

    auto com_world = rotate(def.orientation, props.com);
    auto pos = def.position + com_world;
    registry.emplace<position>(e, pos);
    registry.emplace<orientation>(e, def.orientation);
    registry.emplace<present_position>(e, pos);
    registry.emplace<present_orientation>(e, def.orientation);
    // Static bodies never move; kinematic and dynamic ones have velocities.
    auto moves = def.kind != rigidbody_kind::rb_static;
    registry.emplace<linvel>(e, moves ? def.linvel : vector3_zero);
    registry.emplace<angvel>(e, moves ? def.angvel : vector3_zero);
    if (props.com != vector3_zero) registry.emplace<center_of_mass>(e, props.com);
    set_mass_components(registry, e, def.kind, props);
    update_inertia_world(registry, e);
    if (def.kind == rigidbody_kind::rb_dynamic && def.gravity) registry.emplace<gravity>(e, *def.gravity);
    if (def.material) {
        auto &m = registry.emplace<material>(e, *def.material);
        if (def.restitution) m.restitution = *def.restitution;
    } else {
        registry.emplace<sensor_tag>(e);
    }
    if (def.sleeping_disabled) registry.emplace<sleeping_disabled_tag>(e);
    emplace_kind_tag(registry, e, def.kind);

    if (def.shape) {
        emplace_shape(registry, e, *def.shape);
        registry.emplace<collision_filter>(e, def.collision_group, def.collision_mask);
    }
    // Last, so that listeners of rigidbody_tag and AABB (the simulation) see a complete body.
    registry.emplace<rigidbody_tag>(e);
    if (def.shape) refresh_aabb(registry, e);
}

entity make_rigidbody(registry &registry, const rigidbody_def &def) {
    validate_rigidbody_def(def);
    auto e = registry.create();
    make_rigidbody(e, registry, def);
    return e;
}

void rigidbody_set_kind(registry &registry, entity e, rigidbody_kind kind) {
    check_body("rigidbody_set_kind", registry, e);
    check_kind("rigidbody_set_kind", kind);
    auto old_kind = get_kind(registry, e);
    if (old_kind == kind) return;

    auto shape = get_shape(registry, e);
    if (shape && std::holds_alternative<plane_shape>(*shape) && kind != rigidbody_kind::rb_static) {
        throw std::invalid_argument("rigidbody_set_kind: a body with a plane_shape must stay static");
    }
    if (shape && std::holds_alternative<mesh_shape>(*shape) && kind == rigidbody_kind::rb_dynamic) {
        throw std::invalid_argument("rigidbody_set_kind: a body with a mesh_shape cannot become dynamic");
    }
    if (shape && std::holds_alternative<paged_mesh_shape>(*shape) && kind == rigidbody_kind::rb_dynamic) {
        throw std::invalid_argument(
            "rigidbody_set_kind: a body with a paged_mesh_shape cannot become dynamic");
    }
    auto *com = registry.try_get<center_of_mass>(e);
    auto com_value = com ? std::optional<vector3>(*com) : std::nullopt;
    mass_properties props{large_scalar, matrix3x3_zero, com_value.value_or(vector3_zero)};
    if (kind == rigidbody_kind::rb_dynamic) {
        auto *original = registry.try_get<rigidbody_dynamic_mass>(e);
        if (original) {
            props = {original->mass, original->inertia, props.com};
        } else if (shape) {
            // About the centre of mass the body keeps (its origin without a center_of_mass
            // component), as rigidbody_set_shape does, not about the shape's centroid.
            props = compute_mass_properties(1, std::nullopt, shape, props.com);
        } else {
            throw std::invalid_argument(
                "rigidbody_set_kind: an amorphous body needs a mass and inertia to become dynamic");
        }
    } else if (old_kind == rigidbody_kind::rb_dynamic) {
        // Remembered so that the body can become dynamic again with the same mass.
        registry.emplace_or_replace<rigidbody_dynamic_mass>(
            e, registry.get<mass>(e).s, static_cast<const matrix3x3 &>(registry.get<inertia>(e)));
    }

    // Removing the AABB takes the body out of the broadphase; emplacing it again after the new
    // tag re-inserts it in the right tree.
    auto had_aabb = registry.remove<AABB>(e) > 0;
    registry.remove<dynamic_tag, static_tag, kinematic_tag>(e);
    set_mass_components(registry, e, kind, props);
    update_inertia_world(registry, e);
    if (kind == rigidbody_kind::rb_static) {
        registry.replace<linvel>(e, vector3_zero);
        registry.replace<angvel>(e, vector3_zero);
    }
    emplace_kind_tag(registry, e, kind);
    if (had_aabb) refresh_aabb(registry, e);
}

void rigidbody_set_shape(registry &registry, entity e, std::optional<shapes_variant_t> shape) {
    check_body("rigidbody_set_shape", registry, e);
    auto kind = get_kind(registry, e);
    if (shape) {
        validate_shape(*shape);
        if (std::holds_alternative<plane_shape>(*shape) && kind != rigidbody_kind::rb_static) {
            throw std::invalid_argument("rigidbody_set_shape: plane_shape is only allowed on static bodies");
        }
        if (std::holds_alternative<mesh_shape>(*shape) && kind == rigidbody_kind::rb_dynamic) {
            throw std::invalid_argument(
                "rigidbody_set_shape: mesh_shape is only allowed on static and kinematic bodies");
        }
        if (std::holds_alternative<paged_mesh_shape>(*shape) && kind == rigidbody_kind::rb_dynamic) {
            throw std::invalid_argument(
                "rigidbody_set_shape: paged_mesh_shape is only allowed on static and kinematic bodies");
        }
    } else if (kind == rigidbody_kind::rb_dynamic && !registry.all_of<inertia>(e)) {
        throw std::invalid_argument("rigidbody_set_shape: a dynamic body without a shape needs an inertia");
    }

    auto *filter = registry.try_get<collision_filter>(e);
    auto filter_value = filter ? *filter : collision_filter{};
    remove_shape(registry, e);
    // Signals the change through linvel, whose listeners wake the body: a sleeping body must
    // move again when it loses the shape it rested on, or gets a new one.
    registry.patch<linvel>(e);
    if (!shape) return;

    // About the centre of mass, which stays where it is: at the origin when the body has no
    // center_of_mass component, wherever the new shape's centroid lies.
    auto *com = registry.try_get<center_of_mass>(e);
    take_inertia_of_shape(registry, e, *shape, com ? vector3(*com) : vector3_zero);
    emplace_shape(registry, e, *shape);
    registry.emplace<collision_filter>(e, filter_value);
    refresh_aabb(registry, e);
}

void clear_rigidbody(registry &registry, entity e) {
    check_body("clear_rigidbody", registry, e);
    // The tag goes first so that listeners see the body leave before its parts do.
    registry.remove<rigidbody_tag>(e);
    remove_shape(registry, e);
    registry.remove<position, orientation, present_position, present_orientation, linvel, angvel, gravity,
                    mass, mass_inv, inertia, inertia_inv, inertia_world_inv, center_of_mass, material,
                    sensor_tag, sleeping_disabled_tag, sleeping_tag, dynamic_tag, static_tag, kinematic_tag,
                    rigidbody_dynamic_mass>(e);
}

namespace {

void shift_center_of_mass(registry &registry, entity e, const vector3 &com) {
    auto &orn = registry.get<orientation>(e);
    auto *current = registry.try_get<center_of_mass>(e);
    auto old_com = current ? static_cast<vector3>(*current) : vector3_zero;
    auto delta = com - old_com;

    // The inertia follows the shape's mass distribution about the new centre; amorphous bodies
    // keep theirs, which describes no particular distribution.
    if (auto shape = get_shape(registry, e)) take_inertia_of_shape(registry, e, *shape, com);
    auto delta_world = rotate(orn, delta);
    auto &w = registry.get<angvel>(e);
    registry.patch<position>(e, [&](position &p) { p += delta_world; });
    registry.patch<linvel>(e, [&](linvel &v) { v += cross(w, delta_world); });
    // An asynchronous worker's bodies have no present transform: the main side presents them.
    if (registry.all_of<present_position>(e))
        registry.patch<present_position>(e, [&](present_position &p) { p += delta_world; });
    if (com == vector3_zero) {
        registry.remove<center_of_mass>(e);
    } else {
        registry.emplace_or_replace<center_of_mass>(e, com);
    }
    update_inertia_world(registry, e);
}

} // namespace

void set_center_of_mass(registry &registry, entity e, const vector3 &com) {
    check_body("set_center_of_mass", registry, e);
    check_finite("set_center_of_mass", "com", com);
    // It moves the position by the shift: in asynchronous mode the worker shifts its own.
    call_here_and_in_worker(registry, e, [com](edyn::registry &r, entity body) {
        if (r.all_of<rigidbody_tag>(body)) shift_center_of_mass(r, body, com);
    });
}

vector3 get_rigidbody_origin(const registry &registry, entity e) {
    check_body("get_rigidbody_origin", registry, e);
    auto *com = registry.try_get<center_of_mass>(e);
    if (!com) return registry.get<position>(e);
    return rigidbody_origin(registry.get<position>(e), registry.get<orientation>(e), com);
}

void rigidbody_set_mass(registry &registry, entity e, scalar new_mass) {
    check_body("rigidbody_set_mass", registry, e);
    check_mass("rigidbody_set_mass", new_mass);
    if (!registry.all_of<dynamic_tag>(e))
        throw std::invalid_argument("rigidbody_set_mass: body is not dynamic");
    auto scale = new_mass / registry.get<mass>(e).s;
    auto I = static_cast<const matrix3x3 &>(registry.get<inertia>(e)) * scale;
    registry.replace<mass>(e, new_mass);
    registry.replace<mass_inv>(e, scalar(1) / new_mass);
    registry.replace<inertia>(e, I);
    registry.replace<inertia_inv>(e, inverse(I));
    update_inertia_world(registry, e);
}

void rigidbody_apply_impulse(registry &registry, entity e, const vector3 &impulse,
                             const vector3 &rel_location) {
    check_body("rigidbody_apply_impulse", registry, e);
    check_finite("rigidbody_apply_impulse", "impulse", impulse);
    check_finite("rigidbody_apply_impulse", "rel_location", rel_location);
    // It adds to the velocity: in asynchronous mode the worker adds to its own.
    call_here_and_in_worker(
        registry, e,
        [impulse, rel_location](edyn::registry &r, entity body) {
            if (!r.all_of<dynamic_tag>(body)) return;
            auto m_inv = r.get<mass_inv>(body).s;
            auto &i_inv = r.get<inertia_world_inv>(body);
            r.patch<linvel>(body, [&](linvel &v) { v += impulse * m_inv; });
            r.patch<angvel>(body, [&](angvel &w) { w += i_inv * cross(rel_location, impulse); });
        },
        motion_parts::velocity);
}

void update_rigidbody_aabb(registry &registry, entity e) { refresh_aabb(registry, e); }

void update_inertia_world(registry &registry, entity e) {
    auto &orn = registry.get<orientation>(e);
    auto &i_inv = registry.get<inertia_inv>(e);
    auto r = to_matrix3x3(orn);
    registry.replace<inertia_world_inv>(e, r * i_inv * transpose(r));
}

} // namespace edyn
