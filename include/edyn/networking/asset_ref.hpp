#ifndef EDYN_NETWORKING_ASSET_REF_HPP
#define EDYN_NETWORKING_ASSET_REF_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/ecs/type_info.hpp"
#include "edyn/networking/packet/asset_packets.hpp"
#include <cstddef>
#include <map>
#include <vector>

namespace edyn {

/// An asset: a group of entities (bodies, constraints, external entities) that a client
/// instantiates from its own copy of the asset (a file, a cache) instead of receiving them one
/// by one.
///
/// The component is on the entity that stands for the asset. In the server the program emplaces
/// it with the asset's id and fills `entities` with assign_to_asset; in the client the engine
/// makes the asset entity, with the id, when the asset's entities enter the client's AABB of
/// interest (network_client_entity_entered_sink), and the program fills `entities` with its own
/// copies, again with assign_to_asset.
struct asset_ref {
    /// The program's id of the asset (which file or record to load it from); 0 by default.
    asset_id_type id{};
    /// The asset's entities by their index in the asset, which is the same in every copy (the
    /// server's entities in the server, the client's in the client). Filled by assign_to_asset.
    std::map<asset_index_type, entity> entities;
};

/// Which asset an entity belongs to; on every entity assigned to an asset. Written by
/// assign_to_asset, not by the program.
struct asset_member {
    entity asset_entity{null}; ///< The entity with the asset_ref (null by default).
    asset_index_type index{};  ///< The entity's index in the asset.
    /// The components (their `type_index`) sent with the asset's state when a client asks for it
    /// (client_asset_ready).
    std::vector<std::size_t> components;
};

namespace detail {
void assign_to_asset(registry &registry, entity asset_entity, asset_index_type index, entity e,
                     std::vector<std::size_t> components);
}

/// Puts an entity in an asset at the given index, and names the components that make up its
/// initial state.
///
/// On the server, call it for every networked entity of the asset after creating them. On the
/// client, call it the same way for the local copies once the asset is instantiated, then call
/// client_link_asset to link them to the server's entities. Assigning another entity to an index
/// already used replaces it in asset_ref::entities; the entity's asset_member is replaced too.
///
/// @tparam Components Networked components (registered with register_networked_components or
/// edyn's own) whose values a client receives to instantiate the entity (client_asset_ready).
/// @param registry The registry of the server or client.
/// @param asset_entity The entity that has the asset's asset_ref.
/// @param index The entity's index in the asset, the same in every copy of the asset.
/// @param entity The entity to assign; it receives an asset_member.
/// @throws std::invalid_argument When `asset_entity` is not valid or has no asset_ref, or when
/// `entity` is not valid.
template<typename... Components>
void assign_to_asset(registry &registry, entity asset_entity, asset_index_type index, entity entity) {
    detail::assign_to_asset(registry, asset_entity, index, entity, {type_index<Components>()...});
}

} // namespace edyn

#endif // EDYN_NETWORKING_ASSET_REF_HPP
