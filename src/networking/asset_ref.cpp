#include "edyn/networking/asset_ref.hpp"
#include <stdexcept>
#include <string>

namespace edyn {

void detail::assign_to_asset(registry &registry, entity asset_entity, asset_index_type index, entity e,
                             std::vector<std::size_t> components) {
    if (!registry.valid(asset_entity) || !registry.all_of<asset_ref>(asset_entity))
        throw std::invalid_argument("assign_to_asset: entity " + std::to_string(to_index(asset_entity)) +
                                    " has no asset_ref");
    if (!registry.valid(e))
        throw std::invalid_argument("assign_to_asset: entity " + std::to_string(to_index(e)) +
                                    " is not valid");
    registry.get<asset_ref>(asset_entity).entities[index] = e;
    registry.emplace_or_replace<asset_member>(e, asset_member{asset_entity, index, std::move(components)});
}

} // namespace edyn
