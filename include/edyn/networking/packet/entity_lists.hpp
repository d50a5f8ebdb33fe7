#ifndef EDYN_NETWORKING_PACKET_ENTITY_LISTS_HPP
#define EDYN_NETWORKING_PACKET_ENTITY_LISTS_HPP

// Packets that name entities and nothing else.

#include "edyn/ecs/entity.hpp"
#include "edyn/serialization/std_types.hpp"
#include <vector>

namespace edyn::packet {

/// Server to client: entities destroyed in the server that the client has; it destroys its
/// copies.
struct destroy_entity {
    double timestamp{};           ///< Server simulation time of the destruction, in seconds.
    std::vector<entity> entities; ///< The server's entities.
};

/// Server to client: entities that left the client's AABB of interest; the client destroys its
/// copies.
struct entity_exited {
    std::vector<entity> entities; ///< The server's entities.
};

/// Client to server: a client asks for the full state of entities a snapshot named before their
/// create_entity arrived (it can be lost or late); the server answers with a create_entity.
struct entity_request {
    std::vector<entity> entities; ///< The server's entities the client does not know.
};

/// Writes or reads a destroy_entity packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, destroy_entity &packet) {
    archive(packet.timestamp, packet.entities);
}

/// Writes or reads an entity_exited packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, entity_exited &packet) {
    archive(packet.entities);
}

/// Writes or reads an entity_request packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, entity_request &packet) {
    archive(packet.entities);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_ENTITY_LISTS_HPP
