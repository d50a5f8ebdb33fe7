#ifndef EDYN_NETWORKING_PACKET_CREATE_ENTITY_HPP
#define EDYN_NETWORKING_PACKET_CREATE_ENTITY_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/networking/packet/pool_snapshot.hpp"
#include <vector>

namespace edyn::packet {

// Entities to instantiate with all their networked components: whole islands that entered a
// client's AABB of interest, or the reply to an entity_request.
struct create_entity {
    double timestamp{};
    std::vector<entity> entities;
    std::vector<pool_snapshot> pools;
};

template<typename Archive>
void serialize(Archive &archive, create_entity &packet) {
    archive(packet.timestamp, packet.entities, packet.pools);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_CREATE_ENTITY_HPP
