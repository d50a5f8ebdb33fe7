// Assets: a client instantiates a group of entities from its own copy of the asset and links
// it to the server's, at once or after loading it.
#include "network_harness.hpp"
#include <edyn/networking/asset_ref.hpp>
#include <edyn/networking/remote_client.hpp>
#include <gtest/gtest.h>

namespace {

using namespace edyn;
using edyn::test::net_harness;

constexpr asset_id_type crate_pair_id = 77;

// The asset: two boxes side by side, drifting without gravity.
std::map<asset_index_type, entity> instantiate_crates(registry &registry, const vector3 &origin,
                                                      const vector3 &v) {
    auto result = std::map<asset_index_type, entity>{};
    for (asset_index_type i = 0; i < 2; ++i) {
        auto def = rigidbody_def{};
        def.shape = box_shape{{0.5, 0.5, 0.5}};
        def.position = origin + vector3{scalar(i) * 2, 0, 0};
        def.linvel = v;
        def.gravity = vector3_zero;
        def.sleeping_disabled = true;
        result[i + 10] = make_rigidbody(registry, def);
    }
    return result;
}

entity make_server_asset(registry &server) {
    auto asset = server.create();
    server.emplace<asset_ref>(asset, asset_ref{crate_pair_id, {}});
    for (auto [index, e] : instantiate_crates(server, {1, 2, 3}, {0.5, 0, 0})) {
        server.emplace<networked_tag>(e);
        assign_to_asset<position, orientation, linvel, angvel>(server, asset, index, e);
    }
    return asset;
}

struct client_program {
    registry *reg;
    std::vector<entity> entered;
    int instantiated{0};
    bool link_at_once{true};
};

void link(client_program &p, entity asset_entity) {
    // Instantiated anywhere: the link (or the state received) puts it where the server has it.
    for (auto [index, e] : instantiate_crates(*p.reg, {-50, 0, 0}, vector3_zero))
        assign_to_asset(*p.reg, asset_entity, index, e);
    client_link_asset(*p.reg, asset_entity);
}

void on_entered(client_program &p, entity asset_entity) {
    p.entered.push_back(asset_entity);
    if (p.link_at_once) link(p, asset_entity);
}

void on_instantiate(client_program &p, entity asset_entity) {
    ++p.instantiated;
    link(p, asset_entity);
}

TEST(network_assets, an_asset_linked_at_once_follows_the_server) {
    net_harness h;
    auto asset = make_server_asset(h.server);
    auto &c = h.add_client({.latency = 0.03});
    auto program = client_program{&c.reg, {}, 0, true};
    network_client_entity_entered_sink(c.reg).connect<&on_entered>(program);
    h.run(1.5);
    ASSERT_EQ(program.entered.size(), 1u);
    auto local_asset = program.entered[0];
    EXPECT_EQ(c.reg.get<asset_ref>(local_asset).id, crate_pair_id);
    EXPECT_EQ(client_local_entity(c.reg, asset), local_asset);
    for (auto [index, server_e] : h.server.get<asset_ref>(asset).entities) {
        auto local = client_local_entity(c.reg, server_e);
        ASSERT_NE(local, entity{null}) << "asset entity " << index << " was not linked";
        EXPECT_EQ(c.reg.get<asset_ref>(local_asset).entities.at(index), local);
        // The client is ahead of the server by its lead; the crates drift at 0.5 m/s.
        auto ahead = scalar(get_network_client_time(c.reg) - get_simulation_time(h.server));
        auto expected = h.server.get<position>(server_e) + vector3{scalar(0.5) * ahead, 0, 0};
        EXPECT_LT(length(c.reg.get<position>(local) - expected), scalar(0.02))
            << "crate " << index << " at x=" << c.reg.get<position>(local).x << ", server's " << expected.x;
    }
    // The asset's entities were never sent whole: the client has only its own two crates.
    auto bodies = 0;
    for (auto e : c.reg.view<rigidbody_tag>())
        bodies += e != null;
    EXPECT_EQ(bodies, 2);
}

TEST(network_assets, an_asset_loaded_later_is_instantiated_with_the_servers_state) {
    net_harness h;
    auto asset = make_server_asset(h.server);
    auto &c = h.add_client({.latency = 0.03});
    auto program = client_program{&c.reg, {}, 0, true};
    program.link_at_once = false;
    network_client_entity_entered_sink(c.reg).connect<&on_entered>(program);
    network_client_instantiate_asset_sink(c.reg).connect<&on_instantiate>(program);
    h.run(0.5);
    ASSERT_EQ(program.entered.size(), 1u);
    EXPECT_EQ(program.instantiated, 0);
    client_asset_ready(c.reg, program.entered[0]);
    // Snapshots name the asset's entities meanwhile; the client must not ask for them whole.
    h.run(0.2);
    EXPECT_EQ(program.instantiated, 1);
    for (auto [index, server_e] : h.server.get<asset_ref>(asset).entities) {
        auto local = client_local_entity(c.reg, server_e);
        ASSERT_NE(local, entity{null});
        EXPECT_LT(std::abs(c.reg.get<position>(local).x - h.server.get<position>(server_e).x), scalar(0.2));
        EXPECT_FLOAT_EQ(c.reg.get<linvel>(local).x, 0.5f) << "the asset's state did not arrive with it";
    }
    auto bodies = 0;
    for (auto e : c.reg.view<rigidbody_tag>())
        bodies += e != null;
    EXPECT_EQ(bodies, 2);
}

TEST(network_assets, linking_what_is_not_an_asset_is_refused) {
    net_harness h;
    auto &c = h.add_client();
    auto e = c.reg.create();
    EXPECT_THROW(client_link_asset(c.reg, e), std::invalid_argument);
    EXPECT_THROW(client_asset_ready(c.reg, e), std::invalid_argument);
    EXPECT_THROW(assign_to_asset(c.reg, e, 0, e), std::invalid_argument);
}

} // namespace
