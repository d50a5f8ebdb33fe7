// edyn-example-client: an edyn client over ENet. It connects to edyn-example-server, receives
// the server's world, and drives the box the server gave it in circles by sending a force as its
// input. With --check it exits non-zero unless the world arrived and its box moved.
#include "shared.hpp"
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <enet/enet.h>
#include <numbers>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace {

// The force turns full circle in this many seconds; the box follows it round.
constexpr double drive_period = 4;
constexpr edyn::scalar drive_force = 80; // newtons, below the 98 N that would tip the box over
constexpr edyn::scalar required_travel = 0.5;

struct client {
    edyn::registry registry;
    ENetHost *host{nullptr};
    ENetPeer *peer{nullptr};
    bool connected{false};

    edyn::entity box{edyn::null};
    double box_found_at{0};
    std::optional<edyn::vector3> first_seen;
    edyn::scalar farthest{0};
    std::size_t most_bodies{0};
};

void send_to_server(client &c, const edyn::packet::edyn_packet &packet) {
    if (!c.connected) return;
    auto data = std::vector<std::uint8_t>{};
    auto archive = edyn::memory_output_archive(data);
    archive(packet);

    auto reliable = edyn::should_send_reliably(packet);
    auto *enet_packet = enet_packet_create(
        data.data(), data.size(), reliable ? ENET_PACKET_FLAG_RELIABLE : ENET_PACKET_FLAG_UNSEQUENCED);
    auto channel = reliable ? example::reliable_channel : example::unreliable_channel;
    // On success ENet owns the packet; on failure it is still ours.
    if (enet_peer_send(c.peer, channel, enet_packet) != 0) enet_packet_destroy(enet_packet);
}

void on_receive(client &c, const ENetPacket &enet_packet) {
    auto archive = edyn::memory_input_archive(enet_packet.data, enet_packet.dataLength);
    edyn::packet::edyn_packet packet;
    archive(packet);
    if (!archive.failed()) edyn::client_receive_packet(c.registry, packet);
}

// Handles what arrived; false once the server has gone.
bool poll_network(client &c) {
    ENetEvent event;
    while (enet_host_service(c.host, &event, 0) > 0) {
        switch (event.type) {
        case ENET_EVENT_TYPE_RECEIVE:
            on_receive(c, *event.packet);
            enet_packet_destroy(event.packet);
            break;
        case ENET_EVENT_TYPE_DISCONNECT:
            c.connected = false;
            return false;
        case ENET_EVENT_TYPE_CONNECT:
        case ENET_EVENT_TYPE_NONE:
            break;
        }
    }
    return true;
}

bool connect(client &c, const std::string &host_name, std::uint16_t port) {
    auto address = ENetAddress{};
    if (enet_address_set_host(&address, host_name.c_str()) != 0) {
        std::fprintf(stderr, "edyn-example-client: unknown host %s\n", host_name.c_str());
        return false;
    }
    address.port = port;
    c.host = enet_host_create(nullptr, 1, example::channel_count, 0, 0);
    if (!c.host) {
        std::fprintf(stderr, "edyn-example-client: cannot create an ENet host\n");
        return false;
    }
    c.peer = enet_host_connect(c.host, &address, example::channel_count, 0);
    ENetEvent event;
    // ENet retries the handshake meanwhile, so a server started a moment later is still found.
    if (c.peer && enet_host_service(c.host, &event, 5000) > 0 && event.type == ENET_EVENT_TYPE_CONNECT) {
        c.connected = true;
        return true;
    }
    std::fprintf(stderr, "edyn-example-client: no server answered at %s:%u\n", host_name.c_str(),
                 unsigned(port));
    return false;
}

// The server marks the box it made for this client with the client's entity in the server.
edyn::entity find_own_box(const edyn::registry &registry) {
    auto me = edyn::get_network_client_entity(registry);
    if (me == edyn::null) return edyn::null;
    for (auto [e, o] : registry.view<example::owner>().each())
        if (o.client == me) return e;
    return edyn::null;
}

void drive(client &c, double now) {
    if (c.box != edyn::null && !c.registry.valid(c.box)) c.box = edyn::null;
    if (c.box == edyn::null) {
        c.box = find_own_box(c.registry);
        if (c.box == edyn::null) return;
        c.box_found_at = now;
    }

    auto angle = 2 * std::numbers::pi * (now - c.box_found_at) / drive_period;
    auto input = example::drive_input{};
    input.force =
        edyn::vector3{edyn::scalar(std::cos(angle)), 0, edyn::scalar(std::sin(angle))} * drive_force;
    c.registry.emplace_or_replace<example::drive_input>(c.box, input);
    // A box at rest may have fallen asleep in the client's simulation; the server wakes its own
    // when the input arrives.
    if (c.registry.all_of<edyn::sleeping_tag>(c.box)) edyn::wake_up_entity(c.registry, c.box);
}

void observe(client &c) {
    c.most_bodies = std::max(c.most_bodies, c.registry.storage<edyn::rigidbody_tag>().size());
    if (c.box == edyn::null) return;
    auto *pos = c.registry.try_get<edyn::present_position>(c.box);
    if (!pos) return;
    if (!c.first_seen) c.first_seen = *pos;
    c.farthest = std::max(c.farthest, edyn::length(*pos - *c.first_seen));
}

void report(const client &c, int second) {
    std::printf("t = %d s: %zu bodies", second, c.registry.storage<edyn::rigidbody_tag>().size());
    if (auto *p = c.box != edyn::null ? c.registry.try_get<edyn::present_position>(c.box) : nullptr) {
        std::printf(", own box at (%.2f, %.2f, %.2f)", p->x, p->y, p->z);
    } else {
        std::printf(", own box not received yet");
    }
    std::printf("\n");
    std::fflush(stdout);
}

void disconnect(client &c) {
    if (!c.connected) return;
    enet_peer_disconnect(c.peer, 0);
    ENetEvent event;
    // Waits for the server's acknowledgement, so it frees the client at once instead of after a
    // timeout; whatever else arrives meanwhile is dropped.
    while (enet_host_service(c.host, &event, 1000) > 0) {
        if (event.type == ENET_EVENT_TYPE_RECEIVE) enet_packet_destroy(event.packet);
        if (event.type == ENET_EVENT_TYPE_DISCONNECT) break;
    }
    c.connected = false;
}

// The world's bodies (ground, the scene's boxes, this client's box) arrived, and the box moved:
// its input reached the server and the server's motion came back.
int check(const client &c) {
    auto expected_bodies = std::size_t(example::scene_box_count + 2);
    auto ok = true;
    if (c.most_bodies < expected_bodies) {
        std::printf("check failed: received %zu bodies, expected at least %zu\n", c.most_bodies,
                    expected_bodies);
        ok = false;
    }
    if (!c.first_seen) {
        std::printf("check failed: the client's own box never arrived\n");
        ok = false;
    } else if (c.farthest <= required_travel) {
        std::printf(
            "check failed: the box moved at most %.3f m from where it was first seen, expected more than "
            "%.1f m\n",
            c.farthest, required_travel);
        ok = false;
    }
    if (ok)
        std::printf("check passed: %zu bodies received, own box moved up to %.2f m\n", c.most_bodies,
                    c.farthest);
    return ok ? 0 : 1;
}

int run(const std::string &host_name, std::uint16_t port, double duration, bool checked) {
    client c;
    edyn::attach(c.registry);
    example::register_components(c.registry);
    edyn::init_network_client(c.registry);

    if (!connect(c, host_name, port)) {
        enet_host_destroy(c.host);
        return 1;
    }
    std::printf("connected to %s:%u\n", host_name.c_str(), unsigned(port));
    edyn::network_client_packet_sink(c.registry).connect<&send_to_server>(c);

    using clock = std::chrono::steady_clock;
    constexpr auto frame = std::chrono::microseconds(1'000'000 / 60);
    auto start = clock::now();
    auto next_frame = start;
    auto next_report = 1;

    while (duration <= 0 || example::seconds_since(start) < duration) {
        auto now = example::seconds_since(start);
        if (!poll_network(c)) {
            std::printf("the server closed the connection\n");
            break;
        }
        edyn::set_network_client_round_trip_time(c.registry, c.peer->roundTripTime / 1000.0);
        drive(c, now);
        edyn::update_network_client(c.registry);
        edyn::update(c.registry, now);
        enet_host_flush(c.host);
        observe(c);

        if (now >= next_report) report(c, next_report++);

        next_frame += frame;
        std::this_thread::sleep_until(next_frame);
    }

    disconnect(c);
    edyn::deinit_network_client(c.registry);
    edyn::detach(c.registry);
    enet_host_destroy(c.host);
    return checked ? check(c) : 0;
}

} // namespace

int main(int argc, char **argv) {
    std::string host = "127.0.0.1";
    std::uint16_t port = 7788;
    double duration = 10;
    bool checked = false;
    CLI::App app{"edyn-example-client: joins edyn-example-server over ENet and drives its own box"};
    app.add_option("--host", host, "server address or name");
    app.add_option("--port", port, "server's UDP port");
    app.add_option("--duration", duration, "seconds to run, 0 for ever")->check(CLI::NonNegativeNumber);
    app.add_flag("--check", checked, "at exit, fail unless the world arrived and the own box moved");
    CLI11_PARSE(app, argc, argv);

    if (enet_initialize() != 0) {
        std::fprintf(stderr, "edyn-example-client: enet_initialize failed\n");
        return 1;
    }
    auto result = run(host, port, duration, checked);
    enet_deinitialize();
    return result;
}
