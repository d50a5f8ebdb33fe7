#ifndef EDYN_NETWORKING_REMOTE_CLIENT_HPP
#define EDYN_NETWORKING_REMOTE_CLIENT_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/shapes/aabb.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

// Packets from a client the server refused, by reason. A refused packet is dropped whole.
struct remote_client_rejections {
    // The bytes did not decode, or a pool's values were malformed.
    std::uint32_t malformed{0};
    // Named an entity the client does not own.
    std::uint32_t not_owned{0};
    // Carried a component that is not an input of the client's, or a packet kind a client may
    // not send.
    std::uint32_t not_input{0};
    // Named an entity the server never sent the client.
    std::uint32_t unknown_entity{0};
    // Arrived too late to be applied at its time (it is applied at once instead, not refused).
    std::uint32_t late{0};

    std::uint32_t total() const noexcept { return malformed + not_owned + not_input + unknown_entity; }
};

// A client of the server, on the entity server_make_client made. Fields the program may set:
// snapshot_rate, aabb_of_interest, owned_entities (through server_set_entity_owner or directly).
struct remote_client {
    // Registry snapshots sent to the client per second.
    double snapshot_rate{30};
    // The region of the world the client is sent: islands with a body inside it are created in
    // the client, those leaving it destroyed. When the client owns bodies and
    // aabb_follows_owned is set, it is recentred on them every update, keeping its size.
    AABB aabb_of_interest{{-50, -50, -50}, {50, 50, 50}};
    bool aabb_follows_owned{true};
    // Round-trip time in seconds (server_set_client_round_trip_time).
    double round_trip_time{0};
    // Entities whose inputs and actions this client may send.
    std::vector<entity> owned_entities;
    // How long its snapshots wait in the jitter buffer; set by the server from its clients'
    // latencies, and sent to the client when it changes.
    double playout_delay{0};

    remote_client_rejections rejected;
    // Packets the server handed to the packet sink for this client.
    std::uint64_t packets_sent{0};
};

} // namespace edyn

#endif // EDYN_NETWORKING_REMOTE_CLIENT_HPP
