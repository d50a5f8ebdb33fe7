#ifndef EDYN_NETWORKING_REMOTE_CLIENT_HPP
#define EDYN_NETWORKING_REMOTE_CLIENT_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/shapes/aabb.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

/// Packets from a client the server refused, by reason. A refused packet is dropped whole.
/// Counted by the engine in remote_client::rejected; all counts start at 0.
struct remote_client_rejections {
    /// The bytes did not decode, a pool's values were malformed, or a snapshot was stamped more
    /// than the longest playout delay (10 s) from the server's time.
    std::uint32_t malformed{0};
    /// Named an entity the client does not own.
    std::uint32_t not_owned{0};
    /// Carried a component that is not an input of the client's, or a packet kind a client may
    /// not send.
    std::uint32_t not_input{0};
    /// Named an entity the server never sent the client (in a snapshot or an asset request), or
    /// an id the server never issued (in an entity request: one it sent before the entity left
    /// the client's interest or was destroyed is no refusal, and gets no answer).
    std::uint32_t unknown_entity{0};
    /// Snapshots that arrived too late to be applied at their time (they are applied at once
    /// instead, not refused).
    std::uint32_t late{0};

    /// The number of refused packets.
    /// @return `malformed + not_owned + not_input + unknown_entity`; `late` is not a refusal and
    /// is left out.
    std::uint32_t total() const noexcept { return malformed + not_owned + not_input + unknown_entity; }
};

/// A client of the server, on the entity server_make_client made.
///
/// Fields the program may set: snapshot_rate, aabb_of_interest, aabb_follows_owned and
/// owned_entities; the others are written by the engine. Other application data about the client
/// goes on the same entity, as the program's own components.
struct remote_client {
    /// Registry snapshots sent to the client per second (default 30); finite and > 0. Set it
    /// with server_set_client_snapshot_rate, which checks it; update_network_server refuses a
    /// bad value written here directly.
    double snapshot_rate{30};
    /// The region of the world the client is sent, in world space (m; default a 100 m cube
    /// centred at the origin): islands with a body whose bounding box overlaps it are created in
    /// the client, those leaving it destroyed; static bodies are sent where their boxes overlap
    /// it (a plane everywhere), and networked entities without a shape where their position is
    /// inside it. Finite, with min <= max on every axis: update_network_server
    /// refuses another box.
    AABB aabb_of_interest{{-50, -50, -50}, {50, 50, 50}};
    /// When set (the default) and the client owns bodies, aabb_of_interest is recentred on them
    /// every update, keeping its size.
    bool aabb_follows_owned{true};
    /// Round-trip time in seconds (0 by default); set it with server_set_client_round_trip_time.
    double round_trip_time{0};
    /// Entities whose inputs and actions this client may send (empty by default).
    std::vector<entity> owned_entities;
    /// How long (seconds) its snapshots wait in the jitter buffer; set by the server from the
    /// client's round-trip time and how late its snapshots arrive, and sent to the client when it
    /// changes.
    double playout_delay{0};

    /// What the server refused of this client's packets so far.
    remote_client_rejections rejected;
    /// Packets the server handed to the packet sink for this client.
    std::uint64_t packets_sent{0};
    /// Entities the server could not send the client: one of their values takes more bytes than
    /// a packet's pool may hold (max_archive_count), as a triangle mesh of more than about 58,000
    /// triangles does. Make such an entity an asset, which the client loads from its own files.
    std::uint64_t entities_too_large{0};
};

} // namespace edyn

#endif // EDYN_NETWORKING_REMOTE_CLIENT_HPP
