#ifndef EDYN_NETWORKING_PACKET_EDYN_PACKET_HPP
#define EDYN_NETWORKING_PACKET_EDYN_PACKET_HPP

#include "edyn/networking/packet/asset_packets.hpp"
#include "edyn/networking/packet/create_entity.hpp"
#include "edyn/networking/packet/entity_lists.hpp"
#include "edyn/networking/packet/registry_snapshot.hpp"
#include "edyn/networking/packet/session_packets.hpp"
#include <variant>

namespace edyn::packet {

// Every packet edyn's server and clients exchange. Serialized as the alternative's index (one
// byte) and its contents:
//
//   std::vector<uint8_t> data;
//   auto archive = edyn::memory_output_archive(data);
//   archive(packet);
//
// New kinds are appended, so that the indices of the existing ones stay.
using edyn_packet_variant =
    std::variant<registry_snapshot, create_entity, destroy_entity, entity_entered, entity_exited,
                 entity_request, asset_sync, asset_sync_response, time_request, time_response,
                 server_settings, set_playout_delay, client_created>;

struct edyn_packet {
    edyn_packet_variant var;
};

template<typename Archive>
void serialize(Archive &archive, edyn_packet &packet) {
    archive(packet.var);
}

} // namespace edyn::packet

namespace edyn {

// Whether the packet must arrive: everything but registry snapshots, which are sent many times
// per second and repeat recent changes, and the clock's requests and replies, which are
// repeated too.
bool should_send_reliably(const packet::edyn_packet &packet) noexcept;

} // namespace edyn

#endif // EDYN_NETWORKING_PACKET_EDYN_PACKET_HPP
