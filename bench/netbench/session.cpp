#include "session.hpp"
#include <chrono>
#include <edyn/serialization/memory_archive.hpp>
#include <edyn/serialization/quantize.hpp>
#include <stdexcept>

namespace edyn_netbench {

namespace {

using clock_type = std::chrono::steady_clock;

double elapsed_ms(clock_type::time_point start) {
    return std::chrono::duration<double, std::milli>(clock_type::now() - start).count();
}

// The bytes memory_output_archive writes for `value`: each part of a packet is measured by
// encoding it alone, so that the breakdown follows the archive's format wherever it goes.
template<typename T>
std::uint64_t encoded_size(const T &value) {
    static thread_local std::vector<std::uint8_t> bytes;
    bytes.clear();
    auto archive = edyn::memory_output_archive(bytes);
    archive(value);
    return bytes.size();
}

// One value of the motion pool is its index into the entity list, then the position and the
// two velocities as three zig-zag varints each and the orientation in six bytes.
void count_motion(const std::vector<std::uint8_t> &data, std::size_t entity_count, motion_bytes &out) {
    auto archive = edyn::memory_input_archive(data.data(), data.size());
    auto varints = [&](int count) {
        auto start = archive.position();
        for (int i = 0; i < count; ++i)
            archive.read_varint(~std::uint64_t{0});
        return std::uint64_t(archive.position() - start);
    };
    auto parsed = motion_bytes{};
    while (archive.remaining() > 0 && !archive.failed()) {
        auto start = archive.position();
        archive.read_size(entity_count);
        parsed.position_in_list += archive.position() - start;
        parsed.position += varints(3);
        auto orientation_start = archive.position();
        auto orientation = edyn::quaternion_identity;
        edyn::serialize_quantized(archive, orientation);
        parsed.orientation += archive.position() - orientation_start;
        parsed.linvel += varints(3);
        parsed.angvel += varints(3);
        parsed.values += 1;
    }
    if (archive.failed()) {
        out.unparsed += data.size();
        return;
    }
    out.values += parsed.values;
    out.position_in_list += parsed.position_in_list;
    out.position += parsed.position;
    out.orientation += parsed.orientation;
    out.linvel += parsed.linvel;
    out.angvel += parsed.angvel;
}

} // namespace

const char *packet_kind_name(std::size_t index) {
    // In the order of edyn_packet_variant, which only ever grows at its end.
    static constexpr const char *names[] = {
        "registry_snapshot", "create_entity",     "destroy_entity",      "entity_entered", "entity_exited",
        "entity_request",    "asset_sync",        "asset_sync_response", "time_request",   "time_response",
        "server_settings",   "set_playout_delay", "client_created"};
    return index < std::size(names) ? names[index] : "packet kind unknown to edyn-netbench";
}

void traffic::add(const edyn::packet::edyn_packet &packet, std::size_t size, bool detailed) {
    auto kind = packet.var.index();
    packets += 1;
    bytes += size;
    kind_packets[kind] += 1;
    kind_bytes[kind] += size;
    if (std::holds_alternative<edyn::packet::create_entity>(packet.var)) {
        create_sizes.push_back(std::uint32_t(size));
        return;
    }
    auto *snapshot = std::get_if<edyn::packet::registry_snapshot>(&packet.var);
    if (!snapshot) return;
    snapshot_sizes.push_back(std::uint32_t(size));
    if (!detailed) return;
    auto entity_bytes = encoded_size(snapshot->entities);
    // The pool list's count, and each pool's index and length.
    auto framing = encoded_size(snapshot->pools);
    auto data = std::uint64_t{0};
    for (auto &pool : snapshot->pools) {
        data += pool.data.size();
        snapshot_pool_bytes[pool.component_index] += pool.data.size();
        if (pool.component_index == motion_pool) count_motion(pool.data, snapshot->entities.size(), motion);
    }
    framing -= data;
    snapshot_entities += snapshot->entities.size();
    snapshot_entity_bytes += entity_bytes;
    snapshot_pool_framing_bytes += framing;
    snapshot_header_bytes += size - entity_bytes - framing - data;
}

bool decode_packet(const std::vector<std::uint8_t> &data, edyn::packet::edyn_packet &packet) {
    auto archive = edyn::memory_input_archive(data.data(), data.size());
    archive(packet);
    return !archive.failed();
}

session::session(setup_fn setup_function)
    : setup(setup_function) {
    edyn::attach(server, edyn::init_config{edyn::execution_mode::sequential});
    if (setup) setup(server);
    frame_dt = double(edyn::get_fixed_dt(server));
    edyn::init_network_server(server);
    edyn::network_server_packet_sink(server).connect<&session::on_server_packet>(*this);
    // Every registry starts its clock half a frame early, so that each frame's update() runs
    // exactly one step rather than rounding to none or two now and then.
    edyn::update(server, time - frame_dt / 2);
}

session::~session() {
    for (auto &c : clients)
        if (c->reg) edyn::deinit_network_client(*c->reg);
}

client_end *session::find(edyn::entity server_entity) {
    auto i = edyn::to_index(server_entity);
    if (i < client_by_index.size() && client_by_index[i] >= 0)
        return clients[std::size_t(client_by_index[i])].get();
    // server_make_client sends its first packets before it returns the entity.
    return joining;
}

client_end &session::make_client(std::unique_ptr<client_end> owned, double rtt) {
    auto &c = *clients.emplace_back(std::move(owned));
    joining = &c;
    c.server_entity = edyn::server_make_client(server);
    joining = nullptr;
    auto i = edyn::to_index(c.server_entity);
    if (i >= client_by_index.size()) client_by_index.resize(std::size_t(i) + 1, -1);
    client_by_index[i] = std::int32_t(clients.size() - 1);
    edyn::server_set_client_round_trip_time(server, c.server_entity, rtt);
    return c;
}

client_end &session::add_client(const edyn::simulated_link_settings &link) {
    auto c = std::make_unique<client_end>();
    auto down = link;
    down.seed = link.seed * 7919 + 13;
    c->up = std::make_unique<edyn::simulated_link>(link);
    c->down = std::make_unique<edyn::simulated_link>(down);
    c->reg = std::make_unique<edyn::registry>();
    c->now = time;
    auto &reg = *c->reg;
    edyn::attach(reg, edyn::init_config{edyn::execution_mode::sequential});
    if (setup) setup(reg);
    edyn::init_network_client(reg);
    edyn::set_network_client_round_trip_time(reg, 2 * link.latency);
    edyn::network_client_packet_sink(reg).connect<&session::on_client_packet>(*c);
    edyn::update(reg, time - frame_dt / 2);
    return make_client(std::move(c), 2 * link.latency);
}

client_end &session::add_sink(double rtt) { return make_client(std::make_unique<client_end>(), rtt); }

void session::on_server_packet(session &s, edyn::entity client, const edyn::packet::edyn_packet &packet) {
    auto start = clock_type::now();
    auto *c = s.find(client);
    if (!c) throw std::logic_error("edyn-netbench: the server sent a packet to a client it never made");
    s.scratch.clear();
    auto archive = edyn::memory_output_archive(s.scratch);
    archive(packet);
    c->sent.add(packet, s.scratch.size(), s.detailed_traffic);
    s.times.packets += 1;
    if (c->down) c->down->send(s.time, s.scratch, edyn::should_send_reliably(packet));
    s.sink_seconds += std::chrono::duration<double>(clock_type::now() - start).count();
}

void session::on_client_packet(client_end &c, const edyn::packet::edyn_packet &packet) {
    auto data = std::vector<std::uint8_t>{};
    auto archive = edyn::memory_output_archive(data);
    archive(packet);
    c.up->send(c.now, std::move(data), edyn::should_send_reliably(packet));
}

void session::frame() {
    ++frame_count;
    // A product rather than a running sum, so that frame times do not drift from the steps.
    time = double(frame_count) * frame_dt;
    for (auto &c : clients) {
        if (!c->reg) continue;
        c->now = time;
        for (auto &data : c->up->receive(time)) {
            auto packet = edyn::packet::edyn_packet{};
            if (!decode_packet(data, packet))
                throw std::runtime_error("edyn-netbench: a packet a client sent did not decode");
            edyn::server_receive_packet(server, c->server_entity, packet);
        }
    }

    sink_seconds = 0;
    times.packets = 0;
    auto start = clock_type::now();
    edyn::update_network_server(server);
    times.network_ms = elapsed_ms(start);
    times.sink_ms = sink_seconds * 1000;
    auto steps_before = edyn::get_step_count(server);
    start = clock_type::now();
    edyn::update(server, time);
    times.physics_ms = elapsed_ms(start);
    times.steps = edyn::get_step_count(server) - steps_before;

    times.client_network_ms = 0;
    times.client_physics_ms = 0;
    for (auto &c : clients) {
        if (!c->reg) continue;
        auto &reg = *c->reg;
        for (auto &data : c->down->receive(time)) {
            auto packet = edyn::packet::edyn_packet{};
            if (!decode_packet(data, packet))
                throw std::runtime_error("edyn-netbench: a packet the server sent did not decode");
            edyn::client_receive_packet(reg, packet);
        }
        start = clock_type::now();
        edyn::update_network_client(reg);
        edyn::wait_for_network_client(reg);
        times.client_network_ms += elapsed_ms(start);
        start = clock_type::now();
        edyn::update(reg, time);
        times.client_physics_ms += elapsed_ms(start);
    }
}

} // namespace edyn_netbench
