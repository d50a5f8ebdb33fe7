#include "client_context.hpp"
#include "edyn/networking/asset_ref.hpp"
#include "edyn/networking/networked_tag.hpp"

// Assets on the client's side: the server says an asset entered, the program instantiates its
// copy and links it, at once or once the state it asked for has arrived.

namespace edyn {

namespace client_detail {

void receive_entered(registry &registry, client_context &ctx, const packet::entity_entered &entered) {
    for (auto &asset : entered.assets) {
        if (asset.asset_entity == null || ctx.remote_to_local.find(asset.asset_entity) != null) continue;
        if (!make_room_for(registry, ctx, asset.asset_entity)) continue;
        auto local = registry.create();
        registry.emplace<asset_ref>(local, asset_ref{asset.id, {}});
        registry.emplace<client_asset>(local,
                                       client_asset{asset.asset_entity, asset.members, false, false, {}});
        ctx.remote_to_local.insert(asset.asset_entity, local);
        ctx.local_to_remote.insert(local, asset.asset_entity);
        for (auto &[index, remote] : asset.members)
            ctx.unlinked_members.insert(remote);
        ctx.entity_entered_signal.publish(local);
    }
}

void receive_asset_state(registry &registry, client_context &ctx,
                         const packet::asset_sync_response &response) {
    auto local = ctx.remote_to_local.find(response.asset_entity);
    if (local == null || !registry.valid(local) || !registry.all_of<client_asset>(local)) return;
    auto &types = registry.ctx().get<network_registry>();
    auto pools = decode_pools(types, response.pools, response.entities.size());
    if (!pools) return;
    auto &asset = registry.get<client_asset>(local);
    asset.state = decoded_packet{response.timestamp, response.entities, std::move(*pools)};
    asset.has_state = true;
    ctx.instantiate_asset_signal.publish(local);
}

} // namespace client_detail

using namespace client_detail;

namespace {
client_asset &get_client_asset(registry &registry, entity asset_entity, const char *function) {
    if (!registry.valid(asset_entity) || !registry.all_of<client_asset, asset_ref>(asset_entity))
        throw std::invalid_argument(std::string(function) + ": entity " +
                                    std::to_string(to_index(asset_entity)) +
                                    " is not an asset the server sent");
    return registry.get<client_asset>(asset_entity);
}
} // namespace

sink<network_client_entity_signal> network_client_entity_entered_sink(registry &registry) {
    return sink{get_client(registry, "network_client_entity_entered_sink").entity_entered_signal};
}

sink<network_client_entity_signal> network_client_instantiate_asset_sink(registry &registry) {
    return sink{get_client(registry, "network_client_instantiate_asset_sink").instantiate_asset_signal};
}

void client_link_asset(registry &registry, entity asset_entity) {
    auto &ctx = get_client(registry, "client_link_asset");
    auto &asset = get_client_asset(registry, asset_entity, "client_link_asset");
    auto &ref = registry.get<asset_ref>(asset_entity);
    for (auto &[index, remote] : asset.members) {
        auto it = ref.entities.find(index);
        ctx.unlinked_members.erase(remote);
        // A null member (from the server's bytes) maps nothing.
        if (remote == null || it == ref.entities.end() || !registry.valid(it->second)) continue;
        auto local = it->second;
        // A member under the index of the asset's own entity (from the server's bytes) is not
        // mapped: making room for it would destroy the asset while it is being linked.
        if (ctx.remote_to_local.source_at(remote) == asset.remote) continue;
        if (!make_room_for(registry, ctx, remote) || !registry.valid(local)) continue;
        if (auto previous = ctx.local_to_remote.find(local); previous != null)
            ctx.remote_to_local.erase(previous);
        ctx.remote_to_local.insert(remote, local);
        ctx.local_to_remote.insert(local, remote);
        registry.emplace_or_replace<networked_tag>(local);
    }
    asset.linked = true;
    if (asset.has_state) {
        auto &types = registry.ctx().get<network_registry>();
        auto muted = muted_scope(types);
        apply_pools(registry, types, asset.state.pools, to_local(ctx, asset.state.entities),
                    remote_to_local_map(ctx));
        asset.has_state = false;
        asset.state = {};
    }
}

void client_asset_ready(registry &registry, entity asset_entity) {
    auto &ctx = get_client(registry, "client_asset_ready");
    auto &asset = get_client_asset(registry, asset_entity, "client_asset_ready");
    ctx.packet_signal.publish({packet::asset_sync{asset.remote}});
}

} // namespace edyn
