// The manual's networking snippets, as it writes them: packet sinks that serialize with
// memory_output_archive, receivers that deserialize with memory_input_archive and feed the
// packet in, and the client's settings.
#include <deque>
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace {

using namespace edyn;

// A transport: bytes in flight, one queue each way.
std::deque<std::vector<std::uint8_t>> to_server, to_client;
entity the_client{null};

void send_edyn_packet_to_client(registry &, entity client_entity, const packet::edyn_packet &packet) {
    auto data = std::vector<uint8_t>{};
    auto archive = memory_output_archive(data);
    archive(packet);
    ASSERT_EQ(client_entity, the_client);
    to_client.push_back(std::move(data));
}

// The manual names the packet both edyn::edyn_packet and edyn::packet::edyn_packet: one type.
static_assert(std::is_same_v<edyn::edyn_packet, edyn::packet::edyn_packet>);

void send_edyn_packet_to_server(const edyn::edyn_packet &packet) {
    auto data = std::vector<uint8_t>{};
    auto archive = memory_output_archive(data);
    archive(packet);
    to_server.push_back(std::move(data));
}

void server_receive(registry &registry, const std::uint8_t *data, std::size_t data_length) {
    auto archive = memory_input_archive(data, data_length);
    packet::edyn_packet packet;
    archive(packet);

    if (!archive.failed()) {
        server_receive_packet(registry, the_client, packet);
    }
}

void client_receive(registry &registry, const std::uint8_t *data, std::size_t data_length) {
    auto archive = memory_input_archive(data, data_length);
    packet::edyn_packet packet;
    archive(packet);

    if (!archive.failed()) {
        client_receive_packet(registry, packet);
    }
}

// An external networked component, as the manual's serialization example.
struct my_component {
    int member_one{0};
    float member_two{0};
};

template<typename Archive>
void serialize(Archive &archive, my_component &comp) {
    archive(comp.member_one);
    archive(comp.member_two);
}

TEST(network_manual, server_and_client_set_up_as_the_manual_does) {
    to_server.clear();
    to_client.clear();
    registry server;
    attach(server, init_config{execution_mode::sequential});
    register_external_components<my_component>(server);
    register_networked_components<my_component>(server);
    init_network_server(server);
    network_server_packet_sink(server).connect<&send_edyn_packet_to_client>(server);

    auto def = rigidbody_def{};
    def.shape = sphere_shape{0.5};
    def.position = {0, 5, 0};
    auto body = make_rigidbody(server, def);
    server.emplace<networked_tag>(body);
    server.emplace<my_component>(body, my_component{7, 2.5f});

    registry client;
    attach(client, init_config{execution_mode::sequential});
    register_external_components<my_component>(client);
    register_networked_components<my_component>(client);
    init_network_client(client);
    network_client_packet_sink(client).connect<&send_edyn_packet_to_server>();
    set_network_client_round_trip_time(client, 0);
    set_network_client_snapshot_rate(client, 20);
    set_network_client_discontinuity_decay_rate(client, 0.8f);

    the_client = server_make_client(server);
    server_set_client_round_trip_time(server, the_client, 0);
    EXPECT_EQ(server.get<remote_client>(the_client).owned_entities.size(), 0u);

    auto time = 0.0;
    for (int i = 0; i < 150; ++i) {
        time += 1.0 / 60;
        while (!to_server.empty()) {
            server_receive(server, to_server.front().data(), to_server.front().size());
            to_server.pop_front();
        }
        update_network_server(server);
        update(server, time);
        while (!to_client.empty()) {
            client_receive(client, to_client.front().data(), to_client.front().size());
            to_client.pop_front();
        }
        update_network_client(client);
        wait_for_network_client(client);
        update(client, time);
    }
    auto local = client_local_entity(client, body);
    ASSERT_NE(local, entity{null});
    EXPECT_TRUE(client.all_of<networked_tag>(local));
    EXPECT_EQ(client.get<my_component>(local).member_one, 7);
    EXPECT_FLOAT_EQ(client.get<my_component>(local).member_two, 2.5f);
    // The sphere has landed on neither's ground (there is none): both see it fall as one.
    EXPECT_NEAR(client.get<position>(local).y,
                server.get<position>(body).y + server.get<linvel>(body).y * (get_network_client_time(client) -
                                                                             get_simulation_time(server)),
                0.05);

    deinit_network_client(client);
    deinit_network_server(server);
}

TEST(network_manual, should_send_reliably_spares_only_what_is_repeated) {
    EXPECT_FALSE(should_send_reliably({packet::registry_snapshot{}}));
    EXPECT_FALSE(should_send_reliably({packet::time_request{}}));
    EXPECT_TRUE(should_send_reliably({packet::create_entity{}}));
    EXPECT_TRUE(should_send_reliably({packet::destroy_entity{}}));
    EXPECT_TRUE(should_send_reliably({packet::entity_entered{}}));
}

TEST(network_manual, settings_and_calls_are_validated) {
    registry client;
    EXPECT_THROW(init_network_client(client), std::invalid_argument) << "a registry that is not attached";
    attach(client, init_config{execution_mode::sequential});
    EXPECT_THROW(update_network_client(client), std::invalid_argument);
    init_network_client(client);
    EXPECT_THROW(set_network_client_round_trip_time(client, -1), std::invalid_argument);
    EXPECT_THROW(set_network_client_snapshot_rate(client, 0), std::invalid_argument);
    EXPECT_THROW(set_network_client_discontinuity_decay_rate(client, 1), std::invalid_argument);
    EXPECT_THROW(set_network_client_discontinuity_decay_rate(client, -0.5f), std::invalid_argument);
    deinit_network_client(client);

    registry server;
    attach(server, init_config{execution_mode::sequential});
    EXPECT_THROW(server_make_client(server), std::invalid_argument);
    init_network_server(server);
    EXPECT_THROW(server_set_client_round_trip_time(server, server.create(), 0.1), std::invalid_argument);
    auto c = server_make_client(server);
    EXPECT_THROW(server_set_client_round_trip_time(server, c, std::nan("")), std::invalid_argument);
    deinit_network_server(server);
}

// Runs `fn`, expecting std::invalid_argument whose message contains every fragment.
template<typename Fn>
void expect_invalid(Fn fn, std::initializer_list<const char *> fragments) {
    try {
        fn();
        ADD_FAILURE() << "expected std::invalid_argument";
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        for (auto *fragment : fragments)
            EXPECT_NE(what.find(fragment), std::string::npos)
                << "message: " << what << "\nmissing: " << fragment;
    }
}

TEST(network_manual, server_client_settings_need_a_server) {
    registry plain;
    attach(plain, init_config{execution_mode::sequential});
    auto e = plain.create();
    expect_invalid([&] { server_set_client_round_trip_time(plain, e, 0.1); },
                   {"server_set_client_round_trip_time", "not a network server"});
    expect_invalid([&] { server_set_client_snapshot_rate(plain, e, 10); },
                   {"server_set_client_snapshot_rate", "not a network server"});
}

TEST(network_manual, server_refuses_a_bad_client_snapshot_rate) {
    registry server;
    attach(server, init_config{execution_mode::sequential});
    init_network_server(server);
    auto c = server_make_client(server);
    for (double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        expect_invalid([&] { server_set_client_snapshot_rate(server, c, bad); },
                       {"server_set_client_snapshot_rate", "rate", std::to_string(bad).c_str()});
    }
    EXPECT_EQ(server.get<remote_client>(c).snapshot_rate, 30) << "a refused rate is not stored";
    server_set_client_snapshot_rate(server, c, 10);
    EXPECT_EQ(server.get<remote_client>(c).snapshot_rate, 10);
    EXPECT_THROW(server_set_client_snapshot_rate(server, server.create(), 10), std::invalid_argument);

    // Written directly, a bad rate is refused by the next update, before anything is sent.
    server.get<remote_client>(c).snapshot_rate = std::nan("");
    auto client_name = "entity " + std::to_string(to_index(c));
    expect_invalid([&] { update_network_server(server); },
                   {"update_network_server", "snapshot_rate", client_name.c_str(), "nan"});
    server.get<remote_client>(c).snapshot_rate = 0;
    EXPECT_THROW(update_network_server(server), std::invalid_argument);
    EXPECT_EQ(server.get<remote_client>(c).packets_sent, 0u) << "nothing was sent to the client";
    server.get<remote_client>(c).snapshot_rate = 20;

    // So is a box of interest that holds nothing: NaN, or inverted.
    auto &box = server.get<remote_client>(c).aabb_of_interest;
    auto good = box;
    box.min.x = std::nanf("");
    expect_invalid([&] { update_network_server(server); },
                   {"update_network_server", "aabb_of_interest", client_name.c_str()});
    box = good;
    std::swap(box.min.y, box.max.y);
    EXPECT_THROW(update_network_server(server), std::invalid_argument);
    EXPECT_EQ(server.get<remote_client>(c).packets_sent, 0u) << "nothing was sent to the client";
    box = good;
    update_network_server(server);
    EXPECT_GT(server.get<remote_client>(c).packets_sent, 0u);
    deinit_network_server(server);
}

} // namespace
