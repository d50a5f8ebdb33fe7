#ifndef EDYN_NETBENCH_SESSION_HPP
#define EDYN_NETBENCH_SESSION_HPP

// An in-process server and its clients for edyn-netbench. Every packet the server sends is
// encoded to bytes and counted, as a transport would see it. A client is either a real client
// registry, reached through simulated links (latency, jitter, loss, duplication, reordering)
// that carry the encoded bytes, which it decodes, or a byte sink that only counts them: many
// clients then cost the server what they would, without a registry each on this side.

#include <array>
#include <cstdint>
#include <edyn/edyn.hpp>
#include <edyn/networking/client.hpp>
#include <edyn/networking/remote_client.hpp>
#include <edyn/networking/server.hpp>
#include <edyn/networking/simulated_link.hpp>
#include <map>
#include <memory>
#include <variant>
#include <vector>

namespace edyn_netbench {

inline constexpr std::size_t packet_kind_count = std::variant_size_v<edyn::packet::edyn_packet_variant>;
const char *packet_kind_name(std::size_t index);

// The index of packet kind T in edyn_packet_variant.
template<typename T>
constexpr std::size_t packet_kind() {
    return edyn::packet::edyn_packet_variant{T{}}.index();
}

// Where the bytes of the motion pool of registry snapshots go, field by field. Decoded with the
// layout serialization/quantize.hpp describes; what does not decode so is counted as unparsed.
struct motion_bytes {
    std::uint64_t values{0};
    std::uint64_t position_in_list{0}; // each value's index into the packet's entity list
    std::uint64_t position{0};
    std::uint64_t orientation{0};
    std::uint64_t linvel{0};
    std::uint64_t angvel{0};
    std::uint64_t unparsed{0};
};

// What the server sent one client: packets and bytes by kind and, with `detailed`, the parts of
// its registry snapshots.
struct traffic {
    std::uint64_t packets{0};
    std::uint64_t bytes{0};
    std::array<std::uint64_t, packet_kind_count> kind_packets{};
    std::array<std::uint64_t, packet_kind_count> kind_bytes{};
    std::vector<std::uint32_t> snapshot_sizes; // every registry snapshot's encoded size
    std::vector<std::uint32_t> create_sizes;   // every create_entity's

    // Registry snapshots taken apart (with `detailed` only): the kind byte and timestamp, the
    // entity list, each pool's index and length, and the pools' values by component index.
    std::uint64_t snapshot_header_bytes{0};
    std::uint64_t snapshot_entity_bytes{0};
    std::uint64_t snapshot_entities{0};
    std::uint64_t snapshot_pool_framing_bytes{0};
    std::map<std::uint16_t, std::uint64_t> snapshot_pool_bytes;
    motion_bytes motion;

    void add(const edyn::packet::edyn_packet &packet, std::size_t size, bool detailed);
};

// edyn's own networked types come first in the list both ends share: rigid-body definitions,
// then transforms and velocities. The program's follow (networking/networked_components.hpp).
inline constexpr std::uint16_t body_pool = 0;
inline constexpr std::uint16_t motion_pool = 1;

struct client_end {
    std::unique_ptr<edyn::registry> reg; // null for a byte sink
    edyn::entity server_entity{edyn::null};
    std::unique_ptr<edyn::simulated_link> up;   // client → server
    std::unique_ptr<edyn::simulated_link> down; // server → client
    traffic sent;
    double now{0}; // for the packets it sends
};

// Times of the server's calls in the last frame, in milliseconds.
struct frame_times {
    double network_ms{0};     // update_network_server, the packet sink included
    double sink_ms{0};        // of which: encoding and handing the bytes to the links
    std::uint64_t packets{0}; // sent by the server
    double physics_ms{0};     // update()
    std::uint64_t steps{0};
    // The real clients' update_network_client and wait_for_network_client (their
    // extrapolations), and their update(), summed over the clients.
    double client_network_ms{0};
    double client_physics_ms{0};
};

class session {
public:
    using setup_fn = void (*)(edyn::registry &);

    // `setup` runs on every registry (server and clients) right after attach, to register
    // components and step callbacks.
    explicit session(setup_fn setup);
    ~session();
    session(const session &) = delete;
    session &operator=(const session &) = delete;

    // A real client; the same settings for both directions, the downlink with its own seed.
    client_end &add_client(const edyn::simulated_link_settings &link);
    // A client that only counts what the server sends it, `rtt` seconds away.
    client_end &add_sink(double rtt);

    // One frame: packets due reach the server, the server runs update_network_server and
    // update(), then every real client receives, runs update_network_client, waits for its
    // extrapolation and runs update().
    void frame();

    double now() const noexcept { return time; }
    double dt() const noexcept { return frame_dt; }
    const frame_times &last_frame() const noexcept { return times; }

    edyn::registry server;
    std::vector<std::unique_ptr<client_end>> clients;
    // Take registry snapshots apart in the traffic counts (costs time in the packet sink).
    bool detailed_traffic{false};

private:
    static void on_server_packet(session &s, edyn::entity client, const edyn::packet::edyn_packet &packet);
    static void on_client_packet(client_end &c, const edyn::packet::edyn_packet &packet);
    client_end &make_client(std::unique_ptr<client_end> c, double rtt);
    client_end *find(edyn::entity server_entity);

    setup_fn setup;
    double time{0};
    std::uint64_t frame_count{0};
    double frame_dt;
    frame_times times;
    double sink_seconds{0};
    std::vector<std::int32_t> client_by_index; // by the index of the client's server entity
    client_end *joining{nullptr};
    std::vector<std::uint8_t> scratch;
};

// Decodes bytes as edyn packets; false when they do not decode.
bool decode_packet(const std::vector<std::uint8_t> &data, edyn::packet::edyn_packet &packet);

} // namespace edyn_netbench

#endif // EDYN_NETBENCH_SESSION_HPP
