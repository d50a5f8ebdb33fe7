#ifndef EDYN_NETWORKING_SERVER_HPP
#define EDYN_NETWORKING_SERVER_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/networking/packet/edyn_packet.hpp"
#include "edyn/networking/remote_client.hpp"

namespace edyn {

using network_server_packet_signal = sigh<void(entity client, const packet::edyn_packet &)>;

// Makes `registry` (attached) a server: it sends each client the networked entities inside the
// client's AABB of interest and snapshots of their changes, and applies the clients' inputs and
// actions at the time they were made, after a playout delay that absorbs the network's jitter.
void init_network_server(registry &registry);
void deinit_network_server(registry &registry);

// Packets for clients are handed to this signal, with the client's entity:
//   edyn::network_server_packet_sink(registry).connect<&send_to_client>(registry);
//   void send_to_client(edyn::registry &, edyn::entity client, const edyn::packet::edyn_packet &);
sink<network_server_packet_signal> network_server_packet_sink(registry &registry);

// A client connected: returns its entity, with a remote_client component. Its first packets
// (its identity, the settings) go at the next update_network_server. Destroy the entity when
// the client disconnects.
entity server_make_client(registry &registry);

// Feeds a packet received from `client`. Packets a client may not send (it does not own the
// entities they name, they carry more than inputs and actions, they name entities the server
// never sent it) are dropped and counted in its remote_client::rejected.
void server_receive_packet(registry &registry, entity client, const packet::edyn_packet &packet);

// Call before every update(): applies the clients' snapshots that are due, updates the AABBs of
// interest (creating and destroying entities in the clients) and sends snapshots at each
// client's rate.
void update_network_server(registry &registry);

// The client's round-trip time in seconds, from the transport; it sets the client's playout
// delay.
void server_set_client_round_trip_time(registry &registry, entity client, double rtt);

} // namespace edyn

#endif // EDYN_NETWORKING_SERVER_HPP
