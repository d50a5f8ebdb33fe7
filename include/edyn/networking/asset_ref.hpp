#ifndef EDYN_NETWORKING_ASSET_REF_HPP
#define EDYN_NETWORKING_ASSET_REF_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/ecs/type_info.hpp"
#include "edyn/networking/packet/asset_packets.hpp"
#include <cstddef>
#include <map>
#include <vector>

namespace edyn {

// An asset: a group of entities (bodies, constraints, external entities) that a client
// instantiates from its own copy of the asset (a file, a cache) instead of receiving them one
// by one. On the entity that stands for the asset; `entities` holds its entities by their
// index in the asset, which is the same in every copy (the server's entities in the server,
// the client's in the client).
struct asset_ref {
    asset_id_type id{};
    std::map<asset_index_type, entity> entities;
};

// On every entity assigned to an asset: which, its index, and the components (type_index) sent
// with the asset's state when a client asks for it (client_asset_ready).
struct asset_member {
    entity asset_entity{null};
    asset_index_type index{};
    std::vector<std::size_t> components;
};

namespace detail {
void assign_to_asset(registry &registry, entity asset_entity, asset_index_type index, entity e,
                     std::vector<std::size_t> components);
}

// Puts `entity` in the asset of `asset_entity` (which has an asset_ref) at `index`; the
// Components, which must be networked, are the state a client receives to instantiate it
// (client_asset_ready). Used the same way on the client, to link its copy (client_link_asset).
// Throws std::invalid_argument when `asset_entity` has no asset_ref or `entity` is not valid.
template<typename... Components>
void assign_to_asset(registry &registry, entity asset_entity, asset_index_type index, entity entity) {
    detail::assign_to_asset(registry, asset_entity, index, entity, {type_index<Components>()...});
}

} // namespace edyn

#endif // EDYN_NETWORKING_ASSET_REF_HPP
