#ifndef EDYN_SERIALIZATION_CONSTRAINT_TYPES_HPP
#define EDYN_SERIALIZATION_CONSTRAINT_TYPES_HPP

// Serialization of every constraint of constraint_types: its bodies, its definition and the
// state it carries from step to step (unwrapped angles and warm-starting impulses), so that a
// copy continues exactly as the original would. The solver structs (the *_solver types, with
// their start-of-step rates and bounced flags) are rebuilt from these at every step and are
// not serialized.
//
// Bodies are written as the sender's entities; the receiver translates them (entity_members).
// Values are not checked beyond the enumerations: validate_constraint is the receiver's.

#include "edyn/constraints/constraints.hpp"
#include "edyn/serialization/enum_range.hpp"
#include "edyn/serialization/math_types.hpp"
#include "edyn/serialization/memory_archive.hpp"
#include <cstddef>
#include <type_traits>

namespace edyn {

namespace detail {

// Built-in arrays, nested ones included. Not a `serialize` overload: argument-dependent lookup
// finds nothing for an array of scalars.
template<typename Archive, typename T, std::size_t N>
void serialize_array(Archive &archive, T (&values)[N]) {
    for (auto &v : values) {
        if constexpr (std::is_array_v<T>) {
            serialize_array(archive, v);
        } else {
            archive(v);
        }
    }
}

} // namespace detail

/// Writes or reads a point constraint: bodies, pivots, friction torque and its impulses.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, point_constraint &c) {
    detail::serialize_array(archive, c.body);
    detail::serialize_array(archive, c.pivot);
    archive(c.friction_torque, c.impulse, c.friction_impulse);
}

/// Writes or reads a distance constraint: bodies, pivots, distance and its impulse.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, distance_constraint &c) {
    detail::serialize_array(archive, c.body);
    detail::serialize_array(archive, c.pivot);
    archive(c.distance, c.impulse);
}

/// Writes or reads a soft distance constraint: bodies, pivots, distance, stiffness, damping and
/// its impulse.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, soft_distance_constraint &c) {
    detail::serialize_array(archive, c.body);
    detail::serialize_array(archive, c.pivot);
    archive(c.distance, c.stiffness, c.damping, c.impulse);
}

/// Writes or reads a hinge constraint: bodies, pivots, frames, limits, friction, damping, bump
/// stops, spring, its current angle and its impulses.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, hinge_constraint &c) {
    detail::serialize_array(archive, c.body);
    detail::serialize_array(archive, c.pivot);
    detail::serialize_array(archive, c.frame);
    archive(c.angle_min, c.angle_max, c.limit_restitution, c.friction_torque, c.damping, c.bump_stop_angle,
            c.bump_stop_stiffness, c.rest_angle, c.stiffness, c.angle, c.impulse);
    detail::serialize_array(archive, c.align_impulse);
    detail::serialize_array(archive, c.limit_impulse);
    detail::serialize_array(archive, c.bump_stop_impulse);
    archive(c.friction_impulse, c.spring_impulse);
}

/// Writes or reads a constant-velocity joint: bodies, pivots, frames, twist limits, friction,
/// damping, spring and bump stops, its current twist angle and its impulses.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, cvjoint_constraint &c) {
    detail::serialize_array(archive, c.body);
    detail::serialize_array(archive, c.pivot);
    detail::serialize_array(archive, c.frame);
    archive(c.twist_min, c.twist_max, c.twist_restitution, c.twist_friction_torque, c.twist_damping,
            c.bend_friction_torque, c.twist_rest_angle, c.twist_stiffness, c.twist_bump_stop_angle,
            c.twist_bump_stop_stiffness, c.twist_angle, c.impulse, c.twist_impulse);
    detail::serialize_array(archive, c.limit_impulse);
    detail::serialize_array(archive, c.bump_stop_impulse);
    archive(c.friction_impulse, c.spring_impulse, c.bend_friction_impulse);
}

/// Writes or reads a cone constraint: bodies, pivots, frame, span angles, restitution, bump stop
/// and its impulses.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, cone_constraint &c) {
    detail::serialize_array(archive, c.body);
    detail::serialize_array(archive, c.pivot);
    archive(c.frame);
    detail::serialize_array(archive, c.span_angle);
    archive(c.restitution, c.bump_stop_angle, c.bump_stop_stiffness, c.impulse, c.bump_stop_impulse);
}

/// Writes or reads a degree of freedom's mode, failing the input archive on a value that names no
/// mode. Called directly by generic_dof's serializer: `archive(mode)` would bypass the range check.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param mode The mode to write from or read into.
template<typename Archive>
void serialize(Archive &archive, dof_mode &mode) {
    serialize_enum(archive, mode, dof_mode::limited);
}

/// Writes or reads one degree of freedom of a generic constraint: mode, limits, stiffness, rest
/// value, damping and friction.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param dof The degree of freedom to write from or read into.
template<typename Archive>
void serialize(Archive &archive, generic_dof &dof) {
    serialize(archive, dof.mode);
    archive(dof.min, dof.max, dof.stiffness, dof.rest, dof.damping, dof.friction);
}

/// Writes or reads a generic constraint: bodies, pivots, frames, each degree of freedom and the
/// impulses.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, generic_constraint &c) {
    detail::serialize_array(archive, c.body);
    detail::serialize_array(archive, c.pivot);
    detail::serialize_array(archive, c.frame);
    detail::serialize_array(archive, c.linear);
    detail::serialize_array(archive, c.angular);
    archive(c.linear_block_impulse, c.angular_block_impulse);
    detail::serialize_array(archive, c.impulse);
    detail::serialize_array(archive, c.limit_impulse);
    detail::serialize_array(archive, c.spring_impulse);
    detail::serialize_array(archive, c.friction_impulse);
}

/// Writes or reads a gravity constraint: its bodies.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, gravity_constraint &c) {
    detail::serialize_array(archive, c.body);
}

/// Writes or reads a null constraint: its bodies.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param c The constraint to write from or read into.
template<typename Archive>
void serialize(Archive &archive, null_constraint &c) {
    detail::serialize_array(archive, c.body);
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_CONSTRAINT_TYPES_HPP
