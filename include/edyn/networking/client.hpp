#ifndef EDYN_NETWORKING_CLIENT_HPP
#define EDYN_NETWORKING_CLIENT_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/networking/packet/edyn_packet.hpp"
#include <cstdint>

namespace edyn {

// What the client refused of its server's packets, by reason: values that would make its
// simulation hang or fail. The client trusts its server no more than the server its clients
// (remote_client_rejections): a refused packet is dropped whole, a refused body or constraint
// leaves its entity without it; nothing throws.
struct network_client_rejections {
    // Settings (server_settings), a playout delay or a time outside the ranges the client
    // accepts (settings.hpp, body_limits.hpp; times within a few seconds of its clock).
    std::uint32_t out_of_range{0};
    // A body or constraint make_rigidbody or make_constraint would refuse, or a body beyond the
    // range snapshots can carry (max_quantized_coordinate).
    std::uint32_t invalid_value{0};
    // A body or constraint for an entity that already has another role: a constraint for a
    // body, a body for a constraint, either for an asset, a manifold or an island.
    std::uint32_t conflicting_role{0};

    std::uint32_t total() const noexcept { return out_of_range + invalid_value + conflicting_role; }
};

using network_client_packet_signal = sigh<void(const packet::edyn_packet &)>;
using network_client_entity_signal = sigh<void(entity)>;

// Makes `registry` (attached) a client: it instantiates what the server sends, sends its own
// inputs and actions, and extrapolates the server's state, which arrives in the past, to the
// present.
void init_network_client(registry &registry);
void deinit_network_client(registry &registry);

// Packets for the server are handed to this signal:
//   edyn::network_client_packet_sink(registry).connect<&send_to_server>();
//   void send_to_server(const edyn::packet::edyn_packet &);
sink<network_client_packet_signal> network_client_packet_sink(registry &registry);

// Feeds a packet received from the server.
void client_receive_packet(registry &registry, const packet::edyn_packet &packet);

// Call before every update(): instantiates and destroys what the server said, merges finished
// extrapolations (their corrections go into each body's discontinuity) and starts the next,
// and sends a snapshot of the client's inputs and actions at its snapshot rate.
void update_network_client(registry &registry);

// The round-trip time to the server in seconds, from the transport.
void set_network_client_round_trip_time(registry &registry, double rtt);
// Snapshots sent to the server per second (default 30).
void set_network_client_snapshot_rate(registry &registry, double rate);
// In [0, 1): what fraction of a correction is still shown after one step (default 0.9).
void set_network_client_discontinuity_decay_rate(registry &registry, scalar rate);

// Assets (networking/asset_ref.hpp). When an asset's entities enter the client's AABB of
// interest, the client makes an entity for the asset, with an asset_ref holding its id, and
// this signal gives it:
//   edyn::network_client_entity_entered_sink(registry).connect<&on_entered>(registry);
//   void on_entered(edyn::registry &, edyn::entity asset_entity);
// The program instantiates the asset, assigns its entities to the asset entity with
// assign_to_asset, and calls client_link_asset; snapshots keep them in step from then on. An
// asset that takes time to load: call client_asset_ready once loaded; the server sends the
// state of its entities, and network_client_instantiate_asset_sink's signal fires when it has
// arrived: instantiate there, assign, and call client_link_asset, which applies that state.
sink<network_client_entity_signal> network_client_entity_entered_sink(registry &registry);
sink<network_client_entity_signal> network_client_instantiate_asset_sink(registry &registry);
// Links the client's entities of the asset (assigned with assign_to_asset) to the server's.
// Throws std::invalid_argument when `asset_entity` is not an asset the server sent.
void client_link_asset(registry &registry, entity asset_entity);
// Asks the server for the state of the asset's entities (see above).
void client_asset_ready(registry &registry, entity asset_entity);

// Waits until the extrapolation in progress, if any, has finished (the next
// update_network_client merges it). For tools and tests that run frames faster than real time,
// where a background job would otherwise always finish frames late.
void wait_for_network_client(registry &registry);

// What the client refused of its server's packets so far.
const network_client_rejections &get_network_client_rejections(const registry &registry);

// The client's entity in the server, once the server said it (null before).
entity get_network_client_entity(const registry &registry);
// The local entity made for the server's entity `remote`, or null.
entity client_local_entity(const registry &registry, entity remote);
// The server's entity of the local entity `local`, or null.
entity client_remote_entity(const registry &registry, entity local);
// The server time the client is at: its inputs made now apply at this time in the server.
double get_network_client_time(const registry &registry);

} // namespace edyn

#endif // EDYN_NETWORKING_CLIENT_HPP
