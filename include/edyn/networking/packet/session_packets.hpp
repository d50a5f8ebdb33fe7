#ifndef EDYN_NETWORKING_PACKET_SESSION_PACKETS_HPP
#define EDYN_NETWORKING_PACKET_SESSION_PACKETS_HPP

// Packets that set up and keep a client's session with the server: its identity, the
// simulation settings, the clock and the playout delay.

#include "edyn/ecs/entity.hpp"
#include "edyn/math/scalar.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/serialization/math_types.hpp"
#include "edyn/serialization/solver_settings.hpp"
#include <cstdint>

namespace edyn::packet {

/// Server to client: the server made the client (get_network_client_entity).
struct client_created {
    entity client_entity{}; ///< The client's entity in the server.
};

/// Server to client: settings the client's simulation must share with the server's for its
/// extrapolation to agree: what the setters of world.hpp change in the step, and the contact and
/// joint solvers' settings. Sent when the client is made and whenever they change; the client
/// applies them, or refuses the packet whole when a value is out of range (validate_settings).
/// Pausing, the step callbacks, max_steps_per_update and the sleep thresholds stay the client's
/// own.
struct server_settings {
    scalar fixed_dt{};                    ///< Fixed time step in seconds (`settings::fixed_dt`).
    vector3 gravity{};                    ///< Default gravity in m/s² (`settings::gravity`).
    std::uint32_t num_substeps{};         ///< Sub-steps per step (`settings::num_substeps`).
    std::uint32_t num_relax_iterations{}; ///< Relax iterations per sub-step.
    /// Iterations of the restitution solver (`settings::num_restitution_iterations`).
    std::uint32_t num_restitution_iterations{};
    /// Individual iterations of the restitution solver
    /// (`settings::num_individual_restitution_iterations`).
    std::uint32_t num_individual_restitution_iterations{};
    /// The fastest a body moves, in m/s (`settings::max_linear_speed`).
    scalar max_linear_speed{};
    /// The contact solver's settings (`settings::contact`).
    contact_solver_settings contact{};
    /// The joint solver's settings, the position passes among them (`settings::joint`).
    constraint_solver_settings joint{};

    /// Whether every field is the same (the server sends the settings again when not).
    bool operator==(const server_settings &) const = default;
};

/// Client to server, for clock synchronisation: the client asks for the server's time; the
/// server answers with a time_response.
struct time_request {
    std::uint32_t id{}; ///< The client's number for the request, repeated in the reply.
};

/// Server to client: the server's simulation time, in reply to a time_request.
struct time_response {
    std::uint32_t id{}; ///< The id of the request answered.
    double timestamp{}; ///< Server simulation time in seconds when the request was handled.
};

/// Server to client: how long the server holds a client's snapshots before applying them; the
/// client stamps its inputs this far ahead of the server's clock.
struct set_playout_delay {
    double value{}; ///< The playout delay in seconds (remote_client::playout_delay).
};

/// Writes or reads a client_created packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, client_created &packet) {
    archive(packet.client_entity);
}

/// Writes or reads a server_settings packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, server_settings &packet) {
    archive(packet.fixed_dt, packet.gravity, packet.num_substeps, packet.num_relax_iterations,
            packet.num_restitution_iterations, packet.num_individual_restitution_iterations,
            packet.max_linear_speed, packet.contact, packet.joint);
}

/// Writes or reads a time_request packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, time_request &packet) {
    archive(packet.id);
}

/// Writes or reads a time_response packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, time_response &packet) {
    archive(packet.id, packet.timestamp);
}

/// Writes or reads a set_playout_delay packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, set_playout_delay &packet) {
    archive(packet.value);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_SESSION_PACKETS_HPP
