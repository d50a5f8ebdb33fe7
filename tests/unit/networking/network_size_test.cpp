// A world larger than one packet can carry: the server cuts what it creates in a client into
// packets a client decodes, and counts an entity too large for any packet instead of losing the
// rest with it.
#include "network_harness.hpp"
#include <edyn/networking/remote_client.hpp>
#include <edyn_scenes/scenes.hpp>
#include <gtest/gtest.h>

namespace {

using namespace edyn;
using edyn::test::net_harness;

// The create_entity packets the server sends and their sizes in bytes.
struct create_sizes {
    std::vector<std::size_t> bytes;
    static void on_packet(create_sizes &sizes, entity, const packet::edyn_packet &packet) {
        if (std::holds_alternative<packet::create_entity>(packet.var))
            sizes.bytes.push_back(edyn::test::encode(packet).size());
    }
};

void static_grid_of_boxes(registry &server, int count) {
    for (int k = 0; k < count; ++k) {
        auto def = rigidbody_def{};
        def.kind = rigidbody_kind::rb_static;
        def.shape = box_shape{0.2, 0.2, 0.2};
        def.position = {scalar(k % 150) * scalar(0.5) - 37, 0.2, scalar(k / 150) * scalar(0.5) - 37};
        server.emplace<networked_tag>(make_rigidbody(server, def));
    }
}

TEST(network_size, a_world_larger_than_a_packet_reaches_the_client_in_several) {
    net_harness h;
    // About 1.1 MB of definitions, all in the client's AABB of interest: more than one pool may hold.
    static_grid_of_boxes(h.server, 12000);
    auto sizes = create_sizes{};
    network_server_packet_sink(h.server).connect<&create_sizes::on_packet>(sizes);
    auto &c = h.add_client();
    h.run(0.5);
    EXPECT_EQ(c.reg.view<rigidbody_tag>().size(), 12000u);
    ASSERT_GE(sizes.bytes.size(), 4u);
    for (auto bytes : sizes.bytes)
        EXPECT_LT(bytes, std::size_t{300} * 1024);
}

TEST(network_size, an_entity_too_large_for_a_packet_is_counted_and_the_rest_arrive) {
    net_harness h;
    // 80,000 triangles: about 1.4 MB of vertices and indices, more than a pool may hold.
    auto def = rigidbody_def{};
    def.kind = rigidbody_kind::rb_static;
    def.shape = mesh_shape{scenes::make_grid_mesh(200, 1, [](scalar, scalar) { return scalar(0); })};
    auto terrain = make_rigidbody(h.server, def);
    h.server.emplace<networked_tag>(terrain);
    static_grid_of_boxes(h.server, 10);
    auto &c = h.add_client();
    h.run(0.5);
    EXPECT_EQ(h.server.get<remote_client>(c.server_entity).entities_too_large, 1u);
    EXPECT_EQ(client_local_entity(c.reg, terrain), entity{null});
    EXPECT_EQ(c.reg.view<rigidbody_tag>().size(), 10u);
}

} // namespace
