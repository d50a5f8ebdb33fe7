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
/// The program's id of an asset (asset_ref::id): which asset to load, from file, cache or server.
using asset_id_type = std::uint64_t;
/// An entity's id inside its asset, the same in every copy of the asset.
using asset_index_type = std::uint32_t;
} // namespace edyn

namespace edyn::packet {

/// One asset whose entities entered a client's AABB of interest (part of entity_entered).
struct entered_asset {
    entity asset_entity{}; ///< The server's asset entity (the one with the asset_ref).
    asset_id_type id{};    ///< The asset's id (asset_ref::id).
    /// The server's entity of each of the asset's entities, by index in the asset.
    std::vector<std::pair<asset_index_type, entity>> members;
};

/// Server to client: assets whose entities entered the client's AABB of interest. The client
/// makes an asset entity for each (network_client_entity_entered_sink).
struct entity_entered {
    std::vector<entered_asset> assets; ///< The assets that entered.
};

/// Client to server: the client has loaded an asset and asks for the current state of its
/// entities (client_asset_ready); the server answers with an asset_sync_response.
struct asset_sync {
    entity asset_entity{}; ///< The server's asset entity.
};

/// Server to client: the state of an asset's entities, the components assign_to_asset named for
/// each, in reply to an asset_sync.
struct asset_sync_response {
    double timestamp{};               ///< Server simulation time of the state, in seconds.
    entity asset_entity{};            ///< The server's asset entity.
    std::vector<entity> entities;     ///< The server's entities the pools refer to, by position.
    std::vector<pool_snapshot> pools; ///< The components' values, one pool per component type.
};

/// Writes or reads an entered_asset.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param asset The value to write from or read into.
template<typename Archive>
void serialize(Archive &archive, entered_asset &asset) {
    archive(asset.asset_entity, asset.id, asset.members);
}

/// Writes or reads an entity_entered packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, entity_entered &packet) {
    archive(packet.assets);
}

/// Writes or reads an asset_sync packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, asset_sync &packet) {
    archive(packet.asset_entity);
}

/// Writes or reads an asset_sync_response packet.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param packet The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, asset_sync_response &packet) {
    archive(packet.timestamp, packet.asset_entity, packet.entities, packet.pools);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_ASSET_PACKETS_HPP
