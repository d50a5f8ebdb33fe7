#ifndef EDYN_NETWORKING_PACKET_ASSET_PACKETS_HPP
#define EDYN_NETWORKING_PACKET_ASSET_PACKETS_HPP

// Packets of assets (networking/asset_ref.hpp): groups of entities a client instantiates from
// its own copy of the asset instead of receiving them whole.

#include "edyn/ecs/entity.hpp"
#include "edyn/networking/packet/pool_snapshot.hpp"
#include <cstdint>
#include <utility>
#include <vector>

namespace edyn {
using asset_id_type = std::uint64_t;
// An entity's id inside its asset, the same in every copy of the asset.
using asset_index_type = std::uint32_t;
} // namespace edyn

namespace edyn::packet {

struct entered_asset {
    entity asset_entity{};
    asset_id_type id{};
    // The server's entity of each of the asset's entities.
    std::vector<std::pair<asset_index_type, entity>> members;
};

// Assets whose entities entered the client's AABB of interest.
struct entity_entered {
    std::vector<entered_asset> assets;
};

// A client has loaded an asset and asks for the current state of its entities.
struct asset_sync {
    entity asset_entity{};
};

// The state of an asset's entities: the components assign_to_asset named for each.
struct asset_sync_response {
    double timestamp{};
    entity asset_entity{};
    std::vector<entity> entities;
    std::vector<pool_snapshot> pools;
};

template<typename Archive>
void serialize(Archive &archive, entered_asset &asset) {
    archive(asset.asset_entity, asset.id, asset.members);
}

template<typename Archive>
void serialize(Archive &archive, entity_entered &packet) {
    archive(packet.assets);
}

template<typename Archive>
void serialize(Archive &archive, asset_sync &packet) {
    archive(packet.asset_entity);
}

template<typename Archive>
void serialize(Archive &archive, asset_sync_response &packet) {
    archive(packet.timestamp, packet.asset_entity, packet.entities, packet.pools);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_ASSET_PACKETS_HPP
