#ifndef EDYN_SERIALIZATION_DYNAMICS_TYPES_HPP
#define EDYN_SERIALIZATION_DYNAMICS_TYPES_HPP

// Serialization of materials and rigidbody_def: what a peer needs to make the same body with
// make_rigidbody. Values are not checked beyond the enumerations and the shapes' own rebuilding
// (shape_types.hpp); make_rigidbody validates the rest and throws, so a receiver calls it inside
// try/catch.

#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/serialization/enum_range.hpp"
#include "edyn/serialization/math_types.hpp"
#include "edyn/serialization/memory_archive.hpp"
#include "edyn/serialization/shape_types.hpp"
#include "edyn/serialization/std_types.hpp"

namespace edyn {

/// Writes or reads a material's coefficients: friction, restitution, roll and spin friction,
/// stiffness and damping. Values are not checked.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param m The material to write from or read into.
template<typename Archive>
void serialize(Archive &archive, material_base &m) {
    archive(m.friction, m.restitution, m.roll_friction, m.spin_friction, m.stiffness, m.damping);
}

/// Writes or reads a material: its coefficients (material_base) and its id.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param m The material to write from or read into.
template<typename Archive>
void serialize(Archive &archive, material &m) {
    archive(static_cast<material_base &>(m), m.id);
}

/// Writes or reads a body kind, failing the input archive on a value that names no kind.
/// Called directly by rigidbody_def's serializer: `archive(kind)` would bypass the range check.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param kind The kind to write from or read into.
template<typename Archive>
void serialize(Archive &archive, rigidbody_kind &kind) {
    serialize_enum(archive, kind, rigidbody_kind::rb_kinematic);
}

/// Writes or reads a rigidbody_def: kind, mass, inertia, material, restitution, transform,
/// velocities, gravity, shape, collision filter, centre of mass and whether sleeping is disabled.
/// Values are not checked beyond the enumerations and the shapes' own rebuilding: a receiver
/// passes the result to make_rigidbody, which validates it and throws, inside try/catch.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param def The definition to write from or read into.
template<typename Archive>
void serialize(Archive &archive, rigidbody_def &def) {
    serialize(archive, def.kind);
    archive(def.mass, def.inertia, def.material, def.restitution, def.position, def.orientation, def.linvel,
            def.angvel, def.gravity, def.shape, def.collision_group, def.collision_mask, def.center_of_mass,
            def.sleeping_disabled);
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_DYNAMICS_TYPES_HPP
