#ifndef EDYN_DYNAMICS_RIGIDBODY_HPP
#define EDYN_DYNAMICS_RIGIDBODY_HPP

#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/ecs/registry.hpp"
#include <optional>

namespace edyn {

/// Checks that `def` can make a rigid body, without creating anything.
/// make_rigidbody calls it first; call it yourself to check a definition read from a file or
/// the network before using it. Messages name make_rigidbody, the field and the value.
/// @param def The definition to check.
/// @throws std::invalid_argument When a dynamic body has a NaN, non-positive or infinite mass
/// or one outside [`min_body_mass`, `max_body_mass`]; when a dynamic body has neither shape nor
/// inertia; when an explicit inertia of a dynamic body is not finite, symmetric and positive
/// definite or has principal moments outside [`min_body_inertia`, `max_body_inertia`]; when
/// the orientation is not a finite unit quaternion; when the position, linvel, angvel or
/// center_of_mass is not finite; when the gravity is not finite or longer than `max_gravity`;
/// when the material has a friction, rolling or spinning friction that is negative or not
/// finite, a restitution outside [0, 1], a non-positive stiffness or a negative damping; when
/// `restitution` is outside [0, 1] or set on a sensor (no material); when the shape is invalid
/// (see validate_shape); when a plane_shape is on a non-static body, or a mesh_shape or
/// paged_mesh_shape on a dynamic one.
void validate_rigidbody_def(const rigidbody_def &def);

/// Creates a rigid body from `def` on a new entity.
/// The definition is validated first; nothing is created when it throws. The body gets
/// position, orientation, their present_* copies, linvel, angvel, mass and inertia components,
/// its kind's tag, its material (or sensor_tag), its shape with a collision_filter and an AABB,
/// and rigidbody_tag last. In an attached registry it joins the simulation at once (in
/// asynchronous mode it reaches the worker with the next update()).
/// @param registry The registry to create the body in; it need not be attached yet.
/// @param def What the body is made of (units in rigidbody_def).
/// @return The new body's entity.
/// @throws std::invalid_argument When validate_rigidbody_def refuses `def`.
entity make_rigidbody(registry &registry, const rigidbody_def &def);
/// Creates a rigid body from `def` on an existing entity, keeping its other components.
/// Note the order of the arguments: the entity comes first. The definition is validated
/// first; nothing is added when it throws.
/// @param entity The entity to make a body of.
/// @param registry The registry the entity lives in.
/// @param def What the body is made of (units in rigidbody_def).
/// @throws std::invalid_argument When validate_rigidbody_def refuses `def`, when `entity` is not
/// valid, or when it is a rigid body already.
void make_rigidbody(entity entity, registry &registry, const rigidbody_def &def);

/// Changes a body between dynamic, static and kinematic.
/// A body becoming dynamic needs a mass and inertia: the ones it had when it was last dynamic
/// (kept in rigidbody_dynamic_mass), or computed from its shape with a mass of 1 kg about its
/// centre of mass, which does not move (its center_of_mass component, or its origin without
/// one, wherever the shape's centroid lies). A body
/// becoming static loses its velocities. Nothing happens when the kind does not change.
/// @param registry The registry the body lives in.
/// @param entity The rigid body.
/// @param kind Its new kind.
/// @throws std::invalid_argument When `entity` is not valid or not a rigid body; when a body
/// with a plane_shape would stop being static; when a body with a mesh_shape or
/// paged_mesh_shape would become dynamic; when an amorphous body that was never dynamic would
/// become dynamic (it has no mass or inertia to take).
void rigidbody_set_kind(registry &registry, entity entity, rigidbody_kind kind);

/// Replaces the body's shape, or removes it, making the body amorphous.
/// A dynamic body's inertia is recomputed from its current mass and the new shape, about its
/// centre of mass, which does not move: its center_of_mass component, or the origin without
/// one, whether or not the new shape's centroid lies there. A static or kinematic body that was
/// dynamic before gets the same for the mass it will take back (rigidbody_dynamic_mass), so
/// that it becomes dynamic again with its new shape's inertia. Removing the shape keeps the
/// inertia the body had. The body keeps its collision_filter (a body that had no shape gets the default one,
/// every group and mask bit set, not its rigidbody_def's) and its AABB is refreshed. The body is woken, since
/// it may have lost what it rested on.
/// @param registry The registry the body lives in.
/// @param entity The rigid body.
/// @param shape The new shape, or `std::nullopt` to remove it.
/// @throws std::invalid_argument When `entity` is not valid or not a rigid body; when the shape
/// is invalid (see validate_shape); when a plane_shape is given to a non-static body, or a
/// mesh_shape or paged_mesh_shape to a dynamic one.
void rigidbody_set_shape(registry &registry, entity entity, std::optional<shapes_variant_t> shape);

/// Removes every rigid-body component from `entity`, keeping the entity and its other
/// components.
/// The body leaves the simulation (rigidbody_tag goes first, so listeners see the body leave
/// before its parts do); the entity may then be used for other purposes, or made a body again.
/// To remove the body and the entity, destroy the entity instead.
/// @param registry The registry the body lives in.
/// @param entity The rigid body.
/// @throws std::invalid_argument When `entity` is not valid or not a rigid body.
void clear_rigidbody(registry &registry, entity entity);

/// Moves the centre of mass to `com`, an offset from the body's origin in object space.
/// position and linvel are updated to describe the new centre of mass (linvel gains the
/// rotation's velocity at the new centre); the origin stays where it is. A dynamic body with
/// a shape gets its inertia recomputed from the shape and its mass about the new centre (an
/// inertia given in rigidbody_def is replaced), and so does the mass a static or kinematic body
/// will take back when it becomes dynamic again; an amorphous body keeps its inertia. In
/// asynchronous mode the change is made on the main registry at once and again in the
/// simulation worker at the start of its next step.
/// @param registry The registry the body lives in.
/// @param entity The rigid body.
/// @param com The new centre of mass, object space, in metres from the origin.
/// @throws std::invalid_argument When `entity` is not valid or not a rigid body, or when `com`
/// is not finite.
void set_center_of_mass(registry &registry, entity entity, const vector3 &com);

/// World-space position of the body's origin.
/// The origin is where the body's shape and constraint pivots are anchored; it differs from
/// `position` (the centre of mass) when the centre of mass is shifted.
/// @param registry The registry the body lives in.
/// @param entity A rigid body.
/// @return The origin, in world space, in metres.
/// @throws std::invalid_argument Naming the function, when `entity` is not a valid rigid body.
vector3 get_rigidbody_origin(const registry &registry, entity entity);

/// The body's origin from components the caller already holds, as get_rigidbody_origin()
/// computes it: for loops that have looked them up already.
/// @param pos The body's position (its centre of mass).
/// @param orn The body's orientation.
/// @param com The body's center_of_mass component, or null when it has none.
/// @return The origin, in world space, in metres.
inline vector3 rigidbody_origin(const position &pos, const orientation &orn,
                                const center_of_mass *com) noexcept {
    return com ? pos - rotate(orn, *com) : static_cast<vector3>(pos);
}

/// Sets the mass of a dynamic body and scales its inertia to match.
/// mass_inv, the inertia and the world-space inverse inertia are updated with it.
/// @param registry The registry the body lives in.
/// @param entity A dynamic rigid body.
/// @param mass The new mass, in kg.
/// @throws std::invalid_argument When `entity` is not valid or not a rigid body, when `mass` is
/// NaN, not positive, infinite or outside [`min_body_mass`, `max_body_mass`], or when the body
/// is not dynamic.
void rigidbody_set_mass(registry &registry, entity entity, scalar mass);

/// Applies an impulse to a dynamic body at a point given relative to its centre of mass, in
/// world space.
/// The linear velocity changes by `impulse / mass` and the angular velocity by the inverse
/// world inertia times `rel_location × impulse`. Static and kinematic bodies are left as they
/// are, without error. In asynchronous mode the impulse is applied to the main registry at
/// once and again in the simulation worker at the start of its next step, so it is not lost to
/// the worker's newer velocities.
/// @param registry The registry the body lives in.
/// @param entity The rigid body.
/// @param impulse The impulse, world space, in N·s.
/// @param rel_location Where it is applied: offset from the centre of mass, world space, in
/// metres.
/// @throws std::invalid_argument When `entity` is not valid or not a rigid body, or when
/// `impulse` or `rel_location` is not finite.
void rigidbody_apply_impulse(registry &registry, entity entity, const vector3 &impulse,
                             const vector3 &rel_location);

/// Recomputes the body's AABB component from its shape and current transform.
/// Bodies without a shape are left alone. The step does this itself, and so does an attached
/// registry when position or orientation is changed with `replace` or `patch`; call it after
/// assigning them some other way, when the AABB must be right before the next step. The step
/// trusts it: the broadphase pairs bodies by it, and the narrowphase skips a pair without
/// contact points whose AABBs lie farther apart than the contact threshold.
/// @param registry The registry the body lives in.
/// @param entity A rigid body; not checked, other than by assertions in debug builds.
void update_rigidbody_aabb(registry &registry, entity entity);

/// Refreshes inertia_world_inv from orientation and inertia_inv.
/// The step does this itself, and so does an attached registry when a dynamic body's position
/// or orientation is changed with `replace` or `patch`; call it after changing a body's
/// orientation or inertia_inv some other way.
/// @param registry The registry the body lives in.
/// @param entity A rigid body; not checked, other than by assertions in debug builds.
void update_inertia_world(registry &registry, entity entity);

} // namespace edyn

#endif // EDYN_DYNAMICS_RIGIDBODY_HPP
