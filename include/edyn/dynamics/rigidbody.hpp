#ifndef EDYN_DYNAMICS_RIGIDBODY_HPP
#define EDYN_DYNAMICS_RIGIDBODY_HPP

#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/ecs/registry.hpp"
#include <optional>

namespace edyn {

// Throws std::invalid_argument naming the field and value when `def` cannot make a body: NaN
// or non-positive mass of a dynamic body, a dynamic body with neither shape nor inertia,
// non-finite or non-unit orientation, non-finite vectors, friction or restitution out of range,
// an invalid shape, a plane on a non-static body; a mass, an explicit inertia (which must also
// be symmetric and positive definite) or a gravity outside the ranges of body_limits.hpp.
void validate_rigidbody_def(const rigidbody_def &def);

// Creates a rigid body from `def` on a new entity, or on `entity` (which must be valid and not
// already a rigid body). The definition is validated first; nothing is created when it throws.
entity make_rigidbody(registry &registry, const rigidbody_def &def);
void make_rigidbody(entity entity, registry &registry, const rigidbody_def &def);

// Changes a body between dynamic, static and kinematic. A body becoming dynamic needs a mass
// and inertia: the ones it had when created, or computed from its shape with mass 1.
void rigidbody_set_kind(registry &registry, entity entity, rigidbody_kind kind);

// Replaces the body's shape (or removes it, making the body amorphous), recomputing inertia
// from the current mass for dynamic bodies.
void rigidbody_set_shape(registry &registry, entity entity, std::optional<shapes_variant_t> shape);

// Removes every rigid-body component from `entity`, keeping the entity and its other
// components.
void clear_rigidbody(registry &registry, entity entity);

// Moves the centre of mass to `com` (object space, offset from the origin). position and
// linvel are updated to describe the new centre of mass; the origin stays where it is.
void set_center_of_mass(registry &registry, entity entity, const vector3 &com);

// World-space position of the body's origin (where its shape and constraint pivots are
// anchored), which differs from `position` when the centre of mass is shifted.
vector3 get_rigidbody_origin(const registry &registry, entity entity);

// Sets the mass of a dynamic body and scales its inertia to match.
void rigidbody_set_mass(registry &registry, entity entity, scalar mass);

// Applies an impulse at a point given relative to the centre of mass, in world space.
void rigidbody_apply_impulse(registry &registry, entity entity, const vector3 &impulse,
                             const vector3 &rel_location);

// Recomputes the body's AABB component from its shape and current transform.
void update_rigidbody_aabb(registry &registry, entity entity);

// Refreshes inertia_world_inv from orientation and inertia_inv.
void update_inertia_world(registry &registry, entity entity);

} // namespace edyn

#endif // EDYN_DYNAMICS_RIGIDBODY_HPP
