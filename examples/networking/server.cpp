// edyn-example-server: an edyn server over ENet. It simulates a ground and a few boxes, gives
// every client that connects a box of its own to drive, and keeps the clients' views in step
// with its world. Run edyn-example-client against it.
#include "shared.hpp"
#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <enet/enet.h>
#include <thread>
#include <vector>

namespace {

volatile std::sig_atomic_t stop_requested = 0;
void request_stop(int) { stop_requested = 1; }

// Kept on each client's entity in the server's registry.
struct client_peer {
    ENetPeer *peer{nullptr};
    edyn::entity box{edyn::null};
};

struct server {
    edyn::registry registry;
    ENetHost *host{nullptr};
    int boxes_given{0};
};

// ENet gives each peer one pointer for the program: the client's entity fits in it.
void *to_peer_data(edyn::entity client) {
    return reinterpret_cast<void *>(static_cast<std::uintptr_t>(client));
}
edyn::entity from_peer_data(const ENetPeer *peer) {
    return static_cast<edyn::entity>(reinterpret_cast<std::uintptr_t>(peer->data));
}

void send_to_client(server &s, edyn::entity client, const edyn::packet::edyn_packet &packet) {
    auto *cp = s.registry.try_get<client_peer>(client);
    if (!cp) return;
    auto *peer = cp->peer;

    auto data = std::vector<std::uint8_t>{};
    auto archive = edyn::memory_output_archive(data);
    archive(packet);

    auto reliable = edyn::should_send_reliably(packet);
    auto *enet_packet = enet_packet_create(
        data.data(), data.size(), reliable ? ENET_PACKET_FLAG_RELIABLE : ENET_PACKET_FLAG_UNSEQUENCED);
    auto channel = reliable ? example::reliable_channel : example::unreliable_channel;
    // On success ENet owns the packet; on failure it is still ours.
    if (enet_peer_send(peer, channel, enet_packet) != 0) enet_packet_destroy(enet_packet);
}

edyn::entity make_box(edyn::registry &registry, const edyn::vector3 &position) {
    auto def = edyn::rigidbody_def();
    def.mass = example::box_mass;
    def.shape = edyn::box_shape{0.5, 0.5, 0.5};
    def.position = position;
    auto box = edyn::make_rigidbody(registry, def);
    registry.emplace<edyn::networked_tag>(box);
    return box;
}

void make_scene(edyn::registry &registry) {
    auto ground = edyn::rigidbody_def();
    ground.kind = edyn::rigidbody_kind::rb_static;
    ground.shape = edyn::plane_shape{{0, 1, 0}, 0};
    registry.emplace<edyn::networked_tag>(edyn::make_rigidbody(registry, ground));

    // A stack of three and three boxes dropped around it, away from where clients' boxes drive.
    const edyn::vector3 positions[example::scene_box_count] = {{0, 0.5, -4}, {0, 1.5, -4}, {0, 2.5, -4},
                                                               {-3, 2, -6},  {3, 4, -6},   {0, 6, -8}};
    for (auto &p : positions)
        make_box(registry, p);
}

void on_connect(server &s, ENetPeer *peer) {
    auto client = edyn::server_make_client(s.registry);

    // Side by side in a row in front of the scene, one per client.
    auto slot = s.boxes_given++ % 5;
    auto box = make_box(s.registry, {edyn::scalar(slot * 3 - 6), 0.5, 4});
    s.registry.emplace<example::owner>(box, client);
    s.registry.get<edyn::remote_client>(client).owned_entities.push_back(box);
    s.registry.emplace<client_peer>(client, peer, box);
    peer->data = to_peer_data(client);

    char address[64] = "?";
    enet_address_get_host_ip(&peer->address, address, sizeof(address));
    std::printf("client %u connected from %s:%u\n", unsigned(edyn::to_index(client)), address,
                unsigned(peer->address.port));
}

void on_disconnect(server &s, ENetPeer *peer) {
    auto client = from_peer_data(peer);
    peer->data = nullptr;
    if (!s.registry.valid(client) || !s.registry.all_of<client_peer>(client)) return;
    s.registry.destroy(s.registry.get<client_peer>(client).box);
    s.registry.destroy(client);
    std::printf("client %u disconnected\n", unsigned(edyn::to_index(client)));
}

void on_receive(server &s, ENetPeer *peer, const ENetPacket &enet_packet) {
    auto client = from_peer_data(peer);
    if (!s.registry.valid(client) || !s.registry.all_of<client_peer>(client)) return;

    auto archive = edyn::memory_input_archive(enet_packet.data, enet_packet.dataLength);
    edyn::packet::edyn_packet packet;
    archive(packet);
    if (!archive.failed()) edyn::server_receive_packet(s.registry, client, packet);
}

void poll_network(server &s) {
    ENetEvent event;
    while (enet_host_service(s.host, &event, 0) > 0) {
        switch (event.type) {
        case ENET_EVENT_TYPE_CONNECT:
            on_connect(s, event.peer);
            break;
        case ENET_EVENT_TYPE_RECEIVE:
            on_receive(s, event.peer, *event.packet);
            enet_packet_destroy(event.packet);
            break;
        case ENET_EVENT_TYPE_DISCONNECT:
            on_disconnect(s, event.peer);
            break;
        case ENET_EVENT_TYPE_NONE:
            break;
        }
    }
}

int run(std::uint16_t port, double duration) {
    server s;
    edyn::attach(s.registry);
    example::register_components(s.registry);
    make_scene(s.registry);
    edyn::init_network_server(s.registry);
    edyn::network_server_packet_sink(s.registry).connect<&send_to_client>(s);

    auto address = ENetAddress{};
    address.host = ENET_HOST_ANY;
    address.port = port;
    s.host = enet_host_create(&address, 32, example::channel_count, 0, 0);
    if (!s.host) {
        std::fprintf(stderr, "edyn-example-server: cannot listen on UDP port %u\n", unsigned(port));
        return 1;
    }
    std::printf("listening on UDP port %u\n", unsigned(port));
    std::fflush(stdout);

    using clock = std::chrono::steady_clock;
    constexpr auto frame = std::chrono::microseconds(1'000'000 / 60);
    auto start = clock::now();
    auto next_frame = start;
    auto next_report = 1;

    while (!stop_requested) {
        auto now = example::seconds_since(start);
        if (duration > 0 && now >= duration) break;

        poll_network(s);
        for (auto [client, cp] : s.registry.view<client_peer>().each())
            edyn::server_set_client_round_trip_time(s.registry, client, cp.peer->roundTripTime / 1000.0);
        edyn::update_network_server(s.registry);
        edyn::update(s.registry, now);
        enet_host_flush(s.host);

        if (now >= next_report) {
            std::printf("t = %d s: %zu client(s), %zu bodies\n", next_report,
                        s.registry.storage<client_peer>().size(),
                        s.registry.storage<edyn::rigidbody_tag>().size());
            for (auto [client, cp] : s.registry.view<client_peer>().each()) {
                auto &p = s.registry.get<edyn::present_position>(cp.box);
                std::printf("  client %u's box at (%.2f, %.2f, %.2f), round trip %u ms\n",
                            unsigned(edyn::to_index(client)), p.x, p.y, p.z,
                            unsigned(cp.peer->roundTripTime));
            }
            std::fflush(stdout);
            ++next_report;
        }

        next_frame += frame;
        std::this_thread::sleep_until(next_frame);
    }

    // The disconnects go out with this flush; a client that misses one times out instead.
    for (auto [client, cp] : s.registry.view<client_peer>().each())
        enet_peer_disconnect(cp.peer, 0);
    enet_host_flush(s.host);
    enet_host_destroy(s.host);
    edyn::deinit_network_server(s.registry);
    edyn::detach(s.registry);
    std::printf("server stopped\n");
    return 0;
}

} // namespace

int main(int argc, char **argv) {
    std::uint16_t port = 7788;
    double duration = 0;
    CLI::App app{"edyn-example-server: an edyn server over ENet; clients each get a box to drive"};
    app.add_option("--port", port, "UDP port to listen on");
    app.add_option("--duration", duration, "seconds to run, 0 for ever (until Ctrl-C)")
        ->check(CLI::NonNegativeNumber);
    CLI11_PARSE(app, argc, argv);

    if (enet_initialize() != 0) {
        std::fprintf(stderr, "edyn-example-server: enet_initialize failed\n");
        return 1;
    }
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    auto result = run(port, duration);
    enet_deinitialize();
    return result;
}
