#ifndef EDYN_NETWORKING_PACKET_CREATE_ENTITY_HPP
#define EDYN_NETWORKING_PACKET_CREATE_ENTITY_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/networking/packet/pool_snapshot.hpp"
#include <vector>

namespace edyn::packet {

/// Server to client: entities to instantiate with all their networked components: whole islands
/// that entered a client's AABB of interest, or the reply to an entity_request. Also the new
/// values of bodies and constraints the server's program changed: the client updates the
/// entities it has already.
struct create_entity {
    double timestamp{};               ///< Server simulation time of the state, in seconds.
    std::vector<entity> entities;     ///< The server's entities to create, by position.
    std::vector<pool_snapshot> pools; ///< Their components' values, one pool per component type.
};

/// Writes or reads a create_entity packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, create_entity &packet) {
    archive(packet.timestamp, packet.entities, packet.pools);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_CREATE_ENTITY_HPP
