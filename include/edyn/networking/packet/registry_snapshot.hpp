#ifndef EDYN_NETWORKING_PACKET_REGISTRY_SNAPSHOT_HPP
#define EDYN_NETWORKING_PACKET_REGISTRY_SNAPSHOT_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/networking/packet/pool_snapshot.hpp"
#include <vector>

namespace edyn::packet {

// Entities and the networked components of theirs that changed recently, as they were at
// `timestamp` (server simulation time; a client stamps its own with the server time at which
// its inputs should apply). Sent many times per second through an unreliable channel.
struct registry_snapshot {
    double timestamp{};
    std::vector<entity> entities;
    std::vector<pool_snapshot> pools;
};

template<typename Archive>
void serialize(Archive &archive, registry_snapshot &snapshot) {
    archive(snapshot.timestamp, snapshot.entities, snapshot.pools);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_REGISTRY_SNAPSHOT_HPP
