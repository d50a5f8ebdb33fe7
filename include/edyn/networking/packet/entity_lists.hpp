#ifndef EDYN_NETWORKING_PACKET_ENTITY_LISTS_HPP
#define EDYN_NETWORKING_PACKET_ENTITY_LISTS_HPP

// Packets that name entities and nothing else.

#include "edyn/ecs/entity.hpp"
#include "edyn/serialization/std_types.hpp"
#include <vector>

namespace edyn::packet {

// Entities destroyed in the server.
struct destroy_entity {
    double timestamp{};
    std::vector<entity> entities;
};

// Entities that left the client's AABB of interest: the client destroys its copies.
struct entity_exited {
    std::vector<entity> entities;
};

// A client asks for the full state of entities a snapshot named before their create_entity
// arrived (it can be lost or late); the server answers with a create_entity.
struct entity_request {
    std::vector<entity> entities;
};

template<typename Archive>
void serialize(Archive &archive, destroy_entity &packet) {
    archive(packet.timestamp, packet.entities);
}

template<typename Archive>
void serialize(Archive &archive, entity_exited &packet) {
    archive(packet.entities);
}

template<typename Archive>
void serialize(Archive &archive, entity_request &packet) {
    archive(packet.entities);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_ENTITY_LISTS_HPP
