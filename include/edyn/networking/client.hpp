#ifndef EDYN_NETWORKING_CLIENT_HPP
#define EDYN_NETWORKING_CLIENT_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/networking/packet/edyn_packet.hpp"
#include <cstdint>

namespace edyn {

/// What the client refused of its server's packets, by reason: values that would make its
/// simulation hang or fail.
///
/// The client trusts its server no more than the server its clients (remote_client_rejections):
/// a refused packet is dropped whole, a refused body or constraint leaves its entity without it;
/// nothing throws. Counted by the engine; read it with get_network_client_rejections. All counts
/// start at 0.
struct network_client_rejections {
    /// Settings (packet::server_settings), a playout delay or a time outside the ranges the
    /// client accepts (settings.hpp, body_limits.hpp; times within a few seconds of its clock).
    std::uint32_t out_of_range{0};
    /// A body or constraint make_rigidbody or make_constraint would refuse, or a body beyond the
    /// range snapshots can carry (max_quantized_coordinate).
    std::uint32_t invalid_value{0};
    /// A body or constraint for an entity that already has another role: a constraint for a
    /// body, a body for a constraint, either for an asset, a manifold or an island.
    std::uint32_t conflicting_role{0};

    /// The sum of all counts.
    /// @return `out_of_range + invalid_value + conflicting_role`.
    std::uint32_t total() const noexcept { return out_of_range + invalid_value + conflicting_role; }
};

/// The signal that hands the client's outgoing packets to the program (network_client_packet_sink).
using network_client_packet_signal = sigh<void(const packet::edyn_packet &)>;
/// A signal that names one entity of the client's registry (the client's asset signals).
using network_client_entity_signal = sigh<void(entity)>;

/// Makes a registry a network client.
///
/// From then on it instantiates what the server sends, sends its own inputs and actions, and
/// extrapolates the server's state, which arrives in the past, to the present (in a background
/// job). Call it once, after `attach`; a second call does nothing. Then connect to
/// network_client_packet_sink and call update_network_client before every `update`.
/// @param registry An attached registry.
/// @throws std::invalid_argument When `registry` is not attached (call `attach` first).
void init_network_client(registry &registry);
/// Stops being a network client: waits for the extrapolation in progress, if any, and drops the
/// client's state (entity links, signals, counts). Does nothing on a registry that is not a
/// client. The entities the client made stay.
/// @param registry The client's registry.
void deinit_network_client(registry &registry);

/// The sink of the signal that hands over the packets the client makes for the server.
///
/// Connect a function that serializes the packet and sends it to the server (reliably when
/// should_send_reliably says so):
/// @code
/// edyn::network_client_packet_sink(registry).connect<&send_to_server>();
/// void send_to_server(const edyn::packet::edyn_packet &);
/// @endcode
/// Packets are published from update_network_client, client_receive_packet (requests for
/// entities it does not know yet) and client_asset_ready, on the calling thread.
/// @param registry The client's registry.
/// @return A sink to connect the listener to.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
sink<network_client_packet_signal> network_client_packet_sink(registry &registry);

/// Feeds a packet received from the server into the client.
///
/// Decode the bytes with a memory_input_archive first and pass the packet only when the archive
/// has not failed(). Values the client refuses are dropped and counted in
/// network_client_rejections; bad packets never throw.
/// @param registry The client's registry.
/// @param packet The decoded packet.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
void client_receive_packet(registry &registry, const packet::edyn_packet &packet);

/// Performs the client's duties; call it before every `update`.
///
/// Instantiates and destroys what the server said, merges finished extrapolations (their
/// corrections go into each body's discontinuity, which then decays) and starts the next, keeps
/// the clock in step with the server's, and sends a snapshot of the client's inputs and actions
/// at its snapshot rate.
/// @param registry The client's registry.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
void update_network_client(registry &registry);

/// Sets the round-trip time to the server, as measured by the transport. Update it regularly:
/// the client's timing depends on it.
/// @param registry The client's registry.
/// @param rtt Round-trip time in seconds, finite and >= 0 (0 by default).
/// @throws std::invalid_argument When `rtt` is negative or not finite, or when `registry` is not a
/// network client.
void set_network_client_round_trip_time(registry &registry, double rtt);
/// Sets how often the client sends a registry snapshot (its inputs and actions) to the server.
/// @param registry The client's registry.
/// @param rate Snapshots per second, finite and > 0 (default 30).
/// @throws std::invalid_argument When `rate` is not positive or not finite, or when `registry` is
/// not a network client.
void set_network_client_snapshot_rate(registry &registry, double rate);
/// Sets how fast corrections from extrapolation fade out of the presented transforms.
///
/// Each step, the discontinuity added to `present_position` and `present_orientation` is
/// multiplied by `rate`. Since it applies per step, changing the fixed time step changes how fast
/// it decays in seconds.
/// @param registry The client's registry.
/// @param rate In [0, 1): what fraction of a correction is still shown after one step (default
/// 0.9); 0 shows corrections at once.
/// @throws std::invalid_argument When `rate` is outside [0, 1), or when `registry` is not a
/// network client.
void set_network_client_discontinuity_decay_rate(registry &registry, scalar rate);

/// The sink of the signal fired when an asset's entities enter the client's AABB of interest.
///
/// The client makes an entity for the asset, with an asset_ref holding its id, and this signal
/// gives it:
/// @code
/// edyn::network_client_entity_entered_sink(registry).connect<&on_entered>(registry);
/// void on_entered(edyn::registry &, edyn::entity asset_entity);
/// @endcode
/// The program instantiates the asset, assigns its entities to the asset entity with
/// assign_to_asset, and calls client_link_asset; snapshots keep them in step from then on. An
/// asset that takes time to load: call client_asset_ready once loaded; the server sends the state
/// of its entities, and network_client_instantiate_asset_sink's signal fires when it has arrived:
/// instantiate there, assign, and call client_link_asset, which applies that state. The signal
/// fires from client_receive_packet.
/// @param registry The client's registry.
/// @return A sink to connect the listener to.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
sink<network_client_entity_signal> network_client_entity_entered_sink(registry &registry);
/// The sink of the signal fired when the state asked for with client_asset_ready has arrived: the
/// asset can be instantiated in the listener, its entities assigned with assign_to_asset, and
/// client_link_asset called, which applies that state. The listener receives the asset entity;
/// the signal fires from client_receive_packet.
/// @param registry The client's registry.
/// @return A sink to connect the listener to.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
sink<network_client_entity_signal> network_client_instantiate_asset_sink(registry &registry);
/// Links the client's entities of an asset (assigned with assign_to_asset) to the server's.
///
/// Each local entity gets a networked_tag and from then on receives the server's snapshots for
/// its counterpart. When the state asked for with client_asset_ready has arrived, it is applied
/// now. Indices the program did not assign are skipped.
/// @param registry The client's registry.
/// @param asset_entity The asset entity the client made (network_client_entity_entered_sink).
/// @throws std::invalid_argument When `asset_entity` is not an asset the server sent, or when
/// `registry` is not a network client.
void client_link_asset(registry &registry, entity asset_entity);
/// Asks the server for the current state of an asset's entities, for an asset that took time to
/// load; network_client_instantiate_asset_sink's signal fires when it arrives.
/// @param registry The client's registry.
/// @param asset_entity The asset entity the client made (network_client_entity_entered_sink).
/// @throws std::invalid_argument When `asset_entity` is not an asset the server sent, or when
/// `registry` is not a network client.
void client_asset_ready(registry &registry, entity asset_entity);

/// Waits until the extrapolation in progress, if any, has finished (the next
/// update_network_client merges it). For tools and tests that run frames faster than real time,
/// where a background job would otherwise always finish frames late.
/// @param registry The client's registry.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
void wait_for_network_client(registry &registry);

/// What the client refused of its server's packets so far.
/// @param registry The client's registry.
/// @return The counts, kept in the registry's context until deinit_network_client.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
const network_client_rejections &get_network_client_rejections(const registry &registry);

/// The client's entity in the server, as the server said it (packet::client_created).
/// @param registry The client's registry.
/// @return The entity in the server's registry, or null before the server said it.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
entity get_network_client_entity(const registry &registry);
/// The local entity made for (or linked to) a server's entity.
/// @param registry The client's registry.
/// @param remote An entity of the server's registry.
/// @return The client's entity, or null when there is none.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
entity client_local_entity(const registry &registry, entity remote);
/// The server's entity of a local entity.
/// @param registry The client's registry.
/// @param local An entity of the client's registry.
/// @return The server's entity, or null when `local` is not linked to one.
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
entity client_remote_entity(const registry &registry, entity local);
/// The server time the client is at: its inputs made now apply at this time in the server.
/// @param registry The client's registry.
/// @return Server simulation time in seconds (the client's simulation time plus its lead).
/// @throws std::invalid_argument When `registry` is not a network client (init_network_client was
/// not called).
double get_network_client_time(const registry &registry);

} // namespace edyn

#endif // EDYN_NETWORKING_CLIENT_HPP
