#ifndef EDYN_TESTS_NETWORK_HARNESS_HPP
#define EDYN_TESTS_NETWORK_HARNESS_HPP

// An in-process server and clients joined by simulated links: every packet is encoded to bytes,
// carried with the link's latency, jitter and loss, decoded and fed to the other end, as a real
// transport would. Time advances in frames; each frame the ends run their network update and
// then update().

#include <edyn/edyn.hpp>
#include <edyn/networking/client.hpp>
#include <edyn/networking/server.hpp>
#include <edyn/networking/simulated_link.hpp>
#include <functional>
#include <memory>
#include <vector>

namespace edyn::test {

struct net_client {
    registry reg;
    entity server_entity{null}; // its remote_client in the server
    simulated_link up;          // client → server
    simulated_link down;        // server → client
    std::uint64_t bytes_received{0};
    double now{0}; // the harness's time, for packets the client sends

    net_client(const simulated_link_settings &up_settings, const simulated_link_settings &down_settings)
        : up(up_settings)
        , down(down_settings) {}
};

inline std::vector<std::uint8_t> encode(const packet::edyn_packet &packet) {
    auto data = std::vector<std::uint8_t>{};
    auto archive = memory_output_archive(data);
    archive(packet);
    return data;
}

struct net_harness {
    registry server;
    std::vector<std::unique_ptr<net_client>> clients;
    double time{0};
    double frame_dt{1.0 / 60};
    // Called on every registry (server and clients) right after attach, to register components
    // and step callbacks.
    std::function<void(registry &)> setup;

    // Called for each client between its network update and update(), as a program that adds
    // its inputs and actions there would.
    std::function<void(net_client &)> before_client_update;

    // The execution mode of every end. In asynchronous mode each update() is followed by
    // wait_for_simulation, so that frames faster than real time still see their steps.
    execution_mode mode;

    explicit net_harness(std::function<void(registry &)> setup_fn = {},
                         execution_mode mode_ = execution_mode::sequential)
        : setup(std::move(setup_fn))
        , mode(mode_) {
        attach(server, init_config{mode});
        if (setup) setup(server);
        init_network_server(server);
        network_server_packet_sink(server).connect<&net_harness::on_server_packet>(*this);
    }

    ~net_harness() {
        for (auto &c : clients)
            deinit_network_client(c->reg);
    }

    net_client &add_client(const simulated_link_settings &link = {}) {
        auto up = link;
        auto down = link;
        down.seed = link.seed * 7919 + 13;
        auto &c = *clients.emplace_back(std::make_unique<net_client>(up, down));
        attach(c.reg, init_config{mode});
        if (setup) setup(c.reg);
        init_network_client(c.reg);
        set_network_client_round_trip_time(c.reg, 2 * link.latency);
        network_client_packet_sink(c.reg).connect<&net_harness::on_client_packet>(c);
        joining = &c;
        c.server_entity = server_make_client(server);
        joining = nullptr;
        server_set_client_round_trip_time(server, c.server_entity, 2 * link.latency);
        return c;
    }

    net_client *find(entity server_entity) {
        for (auto &c : clients)
            if (c->server_entity == server_entity) return c.get();
        // server_make_client sends its first packets before returning the entity.
        return joining;
    }
    net_client *joining{nullptr};

    static void on_server_packet(net_harness &h, entity client, const packet::edyn_packet &packet) {
        if (auto *c = h.find(client)) c->down.send(h.time, encode(packet), should_send_reliably(packet));
    }

    static void on_client_packet(net_client &c, const packet::edyn_packet &packet) {
        c.up.send(c.now, encode(packet), should_send_reliably(packet));
    }

    static bool decode(const std::vector<std::uint8_t> &data, packet::edyn_packet &packet) {
        auto archive = memory_input_archive(data.data(), data.size());
        archive(packet);
        return !archive.failed();
    }

    // One frame: deliver due packets, run the network updates and update() on every end.
    void frame() {
        time += frame_dt;
        for (auto &c : clients) {
            c->now = time;
            for (auto &data : c->up.receive(time)) {
                packet::edyn_packet packet;
                if (decode(data, packet)) server_receive_packet(server, c->server_entity, packet);
            }
        }
        update_network_server(server);
        update(server, time);
        if (mode == execution_mode::asynchronous) wait_for_simulation(server);
        for (auto &c : clients) {
            for (auto &data : c->down.receive(time)) {
                c->bytes_received += data.size();
                packet::edyn_packet packet;
                if (decode(data, packet)) client_receive_packet(c->reg, packet);
            }
            update_network_client(c->reg);
            wait_for_network_client(c->reg);
            if (before_client_update) before_client_update(*c);
            update(c->reg, time);
            if (mode == execution_mode::asynchronous) wait_for_simulation(c->reg);
        }
    }

    void run(double seconds, const std::function<void()> &each_frame = {}) {
        auto frames = int(seconds / frame_dt + 0.5);
        for (int i = 0; i < frames; ++i) {
            frame();
            if (each_frame) each_frame();
        }
    }
};

} // namespace edyn::test

#endif // EDYN_TESTS_NETWORK_HARNESS_HPP
