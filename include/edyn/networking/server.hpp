#ifndef EDYN_NETWORKING_SERVER_HPP
#define EDYN_NETWORKING_SERVER_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/networking/packet/edyn_packet.hpp"
#include "edyn/networking/remote_client.hpp"

namespace edyn {

/// The signal that hands the server's outgoing packets to the program, with the entity of the
/// client each is for (network_server_packet_sink).
using network_server_packet_signal = sigh<void(entity client, const packet::edyn_packet &)>;

/// Makes a registry a network server.
///
/// From then on it sends each client the networked entities inside the client's AABB of interest
/// and snapshots of their changes, and applies the clients' inputs and actions at the time they
/// were made, after a playout delay that absorbs the network's jitter. Call it once, after
/// `attach`; a second call does nothing. Then connect to network_server_packet_sink and call
/// update_network_server before every `update`.
/// @param registry An attached registry.
/// @throws std::invalid_argument When `registry` is not attached (call `attach` first).
void init_network_server(registry &registry);
/// Stops being a network server: drops the server's state (signals, the clients' buffers). Does
/// nothing on a registry that is not a server. The client entities and their remote_client stay.
/// @param registry The server's registry.
void deinit_network_server(registry &registry);

/// The sink of the signal that hands over the packets the server makes for its clients.
///
/// Connect a function that serializes the packet and sends it to the client (reliably when
/// should_send_reliably says so):
/// @code
/// edyn::network_server_packet_sink(registry).connect<&send_to_client>(registry);
/// void send_to_client(edyn::registry &, edyn::entity client, const edyn::packet::edyn_packet &);
/// @endcode
/// Packets are published from update_network_server and server_receive_packet, on the calling
/// thread.
/// @param registry The server's registry.
/// @return A sink to connect the listener to.
/// @throws std::invalid_argument When `registry` is not a network server (init_network_server was
/// not called).
sink<network_server_packet_signal> network_server_packet_sink(registry &registry);

/// Creates the entity of a client that connected.
///
/// The entity gets a remote_client component; the program may add its own components (the
/// client's connection, its player) and set the remote_client's fields. Its first packets (its
/// identity, the settings) go at the next update_network_server. Destroy the entity when the
/// client disconnects.
/// @param registry The server's registry.
/// @return The client's entity.
/// @throws std::invalid_argument When `registry` is not a network server (init_network_server was
/// not called).
entity server_make_client(registry &registry);

/// Feeds a packet received from a client into the server.
///
/// Decode the bytes with a memory_input_archive first and pass the packet only when the archive
/// has not failed(). Packets a client may not send (it does not own the entities they name, they
/// carry more than inputs and actions, they name entities the server never sent it) are dropped
/// and counted in its remote_client::rejected; bad packets never throw.
/// @param registry The server's registry.
/// @param client The entity of the client that sent it (server_make_client).
/// @param packet The decoded packet.
/// @throws std::invalid_argument When `registry` is not a network server, or `client` is not an
/// entity made by server_make_client.
void server_receive_packet(registry &registry, entity client, const packet::edyn_packet &packet);

/// Performs the server's duties; call it before every `update`.
///
/// Greets new clients, applies the clients' snapshots that are due, updates the AABBs of interest
/// (creating and destroying entities in the clients) and sends snapshots at each client's rate.
/// @param registry The server's registry.
/// @throws std::invalid_argument When `registry` is not a network server (init_network_server was
/// not called), or when a client's remote_client::snapshot_rate is not positive or not finite
/// (nothing is done then).
void update_network_server(registry &registry);

/// Sets a client's round-trip time, as measured by the transport; it sets the client's playout
/// delay. Update it regularly.
/// @param registry The server's registry.
/// @param client The client's entity (server_make_client).
/// @param rtt Round-trip time in seconds, finite and >= 0; stored in remote_client::round_trip_time.
/// @throws std::invalid_argument When `registry` is not a network server, when `client` is not an
/// entity made by server_make_client (since the last init_network_server), or when `rtt` is
/// negative or not finite.
void server_set_client_round_trip_time(registry &registry, entity client, double rtt);

/// Sets how many registry snapshots per second the server sends a client.
/// @param registry The server's registry.
/// @param client The client's entity (server_make_client).
/// @param rate Snapshots per second, finite and > 0; stored in remote_client::snapshot_rate.
/// @throws std::invalid_argument When `registry` is not a network server, when `client` is not an
/// entity made by server_make_client (since the last init_network_server), or when `rate` is not
/// positive or not finite.
void server_set_client_snapshot_rate(registry &registry, entity client, double rate);

} // namespace edyn

#endif // EDYN_NETWORKING_SERVER_HPP
