#ifndef EDYN_SERIALIZATION_SOLVER_SETTINGS_HPP
#define EDYN_SERIALIZATION_SOLVER_SETTINGS_HPP

// Serialization of the contact and joint solver settings (settings::contact, settings::joint),
// which a server sends its clients in packet::server_settings.

#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/contact_solver.hpp"
#include "edyn/serialization/memory_archive.hpp"

namespace edyn {

/// Writes or reads the contact solver settings, every field.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param s The settings to write from or read into.
template<typename Archive>
void serialize(Archive &archive, contact_solver_settings &s) {
    archive(s.contact_hertz, s.friction_anchor_hertz, s.contact_damping_ratio, s.max_hertz_ratio,
            s.max_push_out_velocity, s.restitution_threshold);
}

/// Writes or reads the joint solver settings, every field.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param s The settings to write from or read into.
template<typename Archive>
void serialize(Archive &archive, constraint_solver_settings &s) {
    archive(s.joint_hertz, s.joint_damping_ratio, s.max_hertz_ratio, s.restitution_threshold,
            s.position_projection, s.position_projection_iterations, s.max_projected_gap,
            s.max_correction_speed);
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_SOLVER_SETTINGS_HPP
