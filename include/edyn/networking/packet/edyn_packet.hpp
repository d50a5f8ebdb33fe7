#ifndef EDYN_NETWORKING_PACKET_EDYN_PACKET_HPP
#define EDYN_NETWORKING_PACKET_EDYN_PACKET_HPP

#include "edyn/networking/packet/asset_packets.hpp"
#include "edyn/networking/packet/create_entity.hpp"
#include "edyn/networking/packet/entity_lists.hpp"
#include "edyn/networking/packet/registry_snapshot.hpp"
#include "edyn/networking/packet/session_packets.hpp"
#include <variant>

namespace edyn::packet {

/// Every kind of packet edyn's server and clients exchange. Serialized as the alternative's index
/// (one byte) and its contents. New kinds are appended, so that the indices of the existing ones
/// stay.
using edyn_packet_variant =
    std::variant<registry_snapshot, create_entity, destroy_entity, entity_entered, entity_exited,
                 entity_request, asset_sync, asset_sync_response, time_request, time_response,
                 server_settings, set_playout_delay, client_created>;

/// A packet of edyn's networking, as the packet sinks hand it over and the receive functions take
/// it.
///
/// The program transports it as bytes:
/// @code
/// std::vector<uint8_t> data;
/// auto archive = edyn::memory_output_archive(data);
/// archive(packet);
/// @endcode
/// and decodes them on the other end with a memory_input_archive, passing the packet on only when
/// the archive has not failed().
struct edyn_packet {
    edyn_packet_variant var; ///< The packet itself, one of the kinds of edyn_packet_variant.
};

/// Writes or reads an edyn_packet: its kind (one byte) and its contents; reading an unknown kind fails
/// the archive.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, edyn_packet &packet) {
    archive(packet.var);
}

} // namespace edyn::packet

namespace edyn {

/// The manual's name for a packet: `edyn::edyn_packet` is packet::edyn_packet.
using packet::edyn_packet;

/// Whether a packet must be sent through a reliable channel.
///
/// Every packet must arrive but registry snapshots, which are sent many times per second and
/// repeat recent changes, and the clock's requests and replies, which are repeated too. Passing
/// this to the transport lets it skip acknowledgements and resends for the most frequent packets.
/// @param packet The packet about to be sent.
/// @return False for packet::registry_snapshot, packet::time_request and packet::time_response;
/// true for every other kind.
bool should_send_reliably(const packet::edyn_packet &packet) noexcept;

} // namespace edyn

#endif // EDYN_NETWORKING_PACKET_EDYN_PACKET_HPP
