#ifndef EDYN_NETWORKING_PACKET_SESSION_PACKETS_HPP
#define EDYN_NETWORKING_PACKET_SESSION_PACKETS_HPP

// Packets that set up and keep a client's session with the server: its identity, the
// simulation settings, the clock and the playout delay.

#include "edyn/ecs/entity.hpp"
#include "edyn/math/scalar.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/serialization/math_types.hpp"
#include <cstdint>

namespace edyn::packet {

// The server made the client: `client_entity` is its entity in the server.
struct client_created {
    entity client_entity{};
};

// Settings the client's simulation must share with the server's for its extrapolation to agree.
struct server_settings {
    scalar fixed_dt{};
    vector3 gravity{};
    std::uint32_t num_substeps{};
    std::uint32_t num_relax_iterations{};
    std::uint32_t num_restitution_iterations{};
    std::uint32_t num_individual_restitution_iterations{};
};

// Clock synchronisation: the client asks, the server answers with its simulation time.
struct time_request {
    std::uint32_t id{};
};

struct time_response {
    std::uint32_t id{};
    double timestamp{};
};

// How long (seconds) the server holds a client's snapshots before applying them; the client
// stamps its inputs this far ahead of the server's clock.
struct set_playout_delay {
    double value{};
};

template<typename Archive>
void serialize(Archive &archive, client_created &packet) {
    archive(packet.client_entity);
}

template<typename Archive>
void serialize(Archive &archive, server_settings &packet) {
    archive(packet.fixed_dt, packet.gravity, packet.num_substeps, packet.num_relax_iterations,
            packet.num_restitution_iterations, packet.num_individual_restitution_iterations);
}

template<typename Archive>
void serialize(Archive &archive, time_request &packet) {
    archive(packet.id);
}

template<typename Archive>
void serialize(Archive &archive, time_response &packet) {
    archive(packet.id, packet.timestamp);
}

template<typename Archive>
void serialize(Archive &archive, set_playout_delay &packet) {
    archive(packet.value);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_SESSION_PACKETS_HPP
