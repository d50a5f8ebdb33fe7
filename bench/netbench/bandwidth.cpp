// The bandwidth scenario: the scene of Glenn Fiedler's "Snapshot Compression" article, 901
// cubes (a 30 by 30 grid of small cubes and one large cube a client drives into them), sent to
// that client 60 times a second. The server→client bytes are counted while the large cube is
// pushing cubes about and after everything has come to rest, and taken apart by packet kind
// and by the parts of the registry snapshots.
#include "netbench.hpp"
#include "session.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace edyn_netbench {

namespace {

// Longest wait for the scene to come to rest, before the drive and after it.
constexpr double max_settle_seconds = 20;

// What one UDP datagram safely holds on the internet.
constexpr double datagram_bytes = 1200;

// The article's figures, for reference: its uncompressed snapshots and its final result.
constexpr double article_uncompressed_mbps = 17.37;
constexpr double article_final_kbps = 256;

// Awake bodies that are not moving (below the speeds at which a body may sleep): kept awake by
// their island, and sent in every snapshot all the same.
std::size_t awake_still_bodies(const edyn::registry &server) {
    auto &settings = edyn::get_settings(server);
    auto lin = settings.sleep_linear_velocity * settings.sleep_linear_velocity;
    auto ang = settings.sleep_angular_velocity * settings.sleep_angular_velocity;
    auto count = std::size_t{0};
    for (auto [e, v, w] :
         server.view<edyn::dynamic_tag, edyn::linvel, edyn::angvel>(edyn::exclude<edyn::sleeping_tag>).each())
        count += edyn::length_sqr(v) <= lin && edyn::length_sqr(w) <= ang;
    return count;
}

struct phase_figures {
    std::string name;
    double seconds{0};
    traffic sent;
    std::vector<double> awake;       // per frame
    std::vector<double> awake_still; // per frame
    std::vector<double> client_network_ms, client_physics_ms;
};

double bytes_per_second(const phase_figures &p) {
    return p.seconds > 0 ? double(p.sent.bytes) / p.seconds : 0;
}

std::vector<double> as_doubles(const std::vector<std::uint32_t> &values) {
    return {values.begin(), values.end()};
}

void add_breakdown(const phase_figures &p, results &out) {
    auto row = [&](std::string part, std::uint64_t count, std::string count_of, std::uint64_t bytes) {
        if (count == 0 && bytes == 0) return;
        auto r = breakdown_row{};
        r.scenario = "bandwidth";
        r.phase = p.name;
        r.part = std::move(part);
        r.count = count;
        r.count_of = std::move(count_of);
        r.bytes = bytes;
        r.bytes_per_second = p.seconds > 0 ? double(bytes) / p.seconds : 0;
        r.share = p.sent.bytes > 0 ? double(bytes) / double(p.sent.bytes) : 0;
        out.breakdown.push_back(std::move(r));
    };
    auto &t = p.sent;
    row("all packets", t.packets, "packets", t.bytes);
    for (std::size_t k = 0; k < packet_kind_count; ++k)
        if (t.kind_packets[k] > 0) row(packet_kind_name(k), t.kind_packets[k], "packets", t.kind_bytes[k]);
    auto snapshots = t.kind_packets[packet_kind<edyn::packet::registry_snapshot>()];
    if (snapshots == 0) return;
    row("snapshot: kind byte and timestamp", snapshots, "packets", t.snapshot_header_bytes);
    row("snapshot: entity list", t.snapshot_entities, "entities", t.snapshot_entity_bytes);
    row("snapshot: pool framing (index, length)", snapshots, "packets", t.snapshot_pool_framing_bytes);
    // Besides edyn's own, the drive input is the only networked component in this scene.
    for (auto [index, bytes] : t.snapshot_pool_bytes) {
        if (index == motion_pool) continue;
        row("snapshot: pool " + std::to_string(index) +
                (index == body_pool ? " (rigidbody_def)" : " (drive input)"),
            0, "", bytes);
    }
    auto &m = t.motion;
    row("snapshot: motion pool, each value's place in the entity list", m.values, "values",
        m.position_in_list);
    row("snapshot: motion pool, position (3 varints, 1/1024 m)", m.values, "values", m.position);
    row("snapshot: motion pool, orientation (smallest three, 6 bytes)", m.values, "values", m.orientation);
    row("snapshot: motion pool, linear velocity (3 varints, 1/512 m/s)", m.values, "values", m.linvel);
    row("snapshot: motion pool, angular velocity (3 varints, 1/512 rad/s)", m.values, "values", m.angvel);
    if (m.unparsed > 0) row("snapshot: motion pool, not in the expected layout", 0, "", m.unparsed);
}

struct bandwidth_run {
    traffic join;
    phase_figures moving;
    phase_figures rest;
    double settle_seconds{0};
    bool settled{false};
};

// The client joins and the scene falls asleep; the client drives its cube through the grid;
// it stops and everything comes to rest; then nothing moves.
bandwidth_run run_phases(const options &opt, session &s, client_end &c, edyn::entity player) {
    auto &client = *c.reg;
    // A body that falls asleep has its last pose sent in the next few snapshots; a phase starts
    // once those are out, so that it counts only its own traffic.
    auto repeats_out = [&] {
        auto frames = std::llround((3 / opt.snapshot_rate) / s.dt()) + 2;
        for (long long f = 0; f < frames; ++f)
            s.frame();
    };
    auto run_phase = [&](const char *name, double seconds, auto &&each_frame) {
        c.sent = traffic{};
        auto p = phase_figures{};
        p.name = name;
        auto frames = std::llround(seconds / s.dt());
        for (long long f = 0; f < frames; ++f) {
            each_frame();
            s.frame();
            p.awake.push_back(double(awake_bodies(s.server)));
            p.awake_still.push_back(double(awake_still_bodies(s.server)));
            p.client_network_ms.push_back(s.last_frame().client_network_ms);
            p.client_physics_ms.push_back(s.last_frame().client_physics_ms);
        }
        p.seconds = double(frames) * s.dt();
        p.sent = std::move(c.sent);
        c.sent = traffic{};
        return p;
    };

    auto run = bandwidth_run{};
    auto local_player = edyn::entity{edyn::null};
    auto start = s.now();
    while (s.now() - start < max_settle_seconds) {
        s.frame();
        local_player = edyn::client_local_entity(client, player);
        if (local_player != edyn::null && awake_bodies(s.server) == 0) break;
    }
    if (local_player == edyn::null)
        throw std::runtime_error("edyn-netbench: the player's cube never reached the client");
    repeats_out();
    run.join = std::move(c.sent);

    auto drive_start = edyn::get_network_client_time(client);
    run.moving = run_phase("moving", opt.moving_seconds, [&] {
        auto t = edyn::get_network_client_time(client) - drive_start;
        set_drive(client, local_player, steer_player(client, local_player, opt.grid, 0, 1, t));
    });

    set_drive(client, local_player, edyn::vector3_zero);
    start = s.now();
    while (s.now() - start < max_settle_seconds && awake_bodies(s.server) > 0)
        s.frame();
    run.settle_seconds = s.now() - start;
    run.settled = awake_bodies(s.server) == 0;
    repeats_out();
    run.rest = run_phase("at rest", opt.rest_seconds, [] {});
    return run;
}

void report_sizes(const bandwidth_run &run, results &out) {
    auto snapshot_sizes = as_doubles(run.moving.sent.snapshot_sizes);
    if (!snapshot_sizes.empty()) {
        add_metric(out, "bandwidth", "snapshot size while moving, median", median(snapshot_sizes), "bytes");
        add_metric(out, "bandwidth", "snapshot size while moving, max",
                   *std::max_element(snapshot_sizes.begin(), snapshot_sizes.end()), "bytes");
        // A transport fragments larger packets, and losing any fragment loses the snapshot.
        auto over = std::count_if(snapshot_sizes.begin(), snapshot_sizes.end(),
                                  [](double size) { return size > datagram_bytes; });
        add_metric(out, "bandwidth", "snapshots while moving larger than one 1,200-byte datagram",
                   100 * double(over) / double(snapshot_sizes.size()), "%");
    }
    auto rest_sizes = as_doubles(run.rest.sent.snapshot_sizes);
    if (!rest_sizes.empty())
        add_metric(out, "bandwidth", "snapshot size at rest, median", median(rest_sizes), "bytes");
    auto &moving = run.moving.sent;
    auto snapshots = moving.kind_packets[packet_kind<edyn::packet::registry_snapshot>()];
    if (snapshots == 0) return;
    add_metric(out, "bandwidth", "bodies per snapshot while moving, mean",
               double(moving.snapshot_entities) / double(snapshots), "bodies");
    auto &m = moving.motion;
    if (m.values > 0 && moving.snapshot_entities > 0) {
        auto per_value =
            double(m.position_in_list + m.position + m.orientation + m.linvel + m.angvel) / double(m.values);
        auto per_entity = double(moving.snapshot_entity_bytes) / double(moving.snapshot_entities);
        add_metric(out, "bandwidth", "bytes per body per snapshot while moving (motion value + entity id)",
                   per_value + per_entity, "bytes");
    }
}

void report(const bandwidth_run &run, results &out) {
    auto &moving = run.moving;
    auto moving_bps = bytes_per_second(moving);
    auto rest_bps = bytes_per_second(run.rest);
    std::fprintf(stderr, "moving %.0f kbit/s, at rest %.0f B/s\n", moving_bps * 8 / 1000, rest_bps);

    add_metric(out, "bandwidth", "server→client while moving", moving_bps * 8 / 1000, "kbit/s");
    add_metric(out, "bandwidth", "server→client while moving", moving_bps * 8 / 1e6, "Mbit/s", "≤ 1 Mbit/s",
               moving_bps * 8 <= 1e6 ? 1 : 0);
    add_metric(out, "bandwidth", "server→client at rest", rest_bps / 1024, "KiB/s", "≤ 8 KiB/s",
               rest_bps <= 8 * 1024 ? 1 : 0);
    add_metric(out, "bandwidth", "server→client at rest", rest_bps * 8 / 1000, "kbit/s");
    report_sizes(run, out);
    add_metric(out, "bandwidth", "awake bodies while moving, median", median(moving.awake), "bodies");
    add_metric(out, "bandwidth", "awake bodies while moving, max",
               *std::max_element(moving.awake.begin(), moving.awake.end()), "bodies");
    add_metric(out, "bandwidth", "awake bodies not moving (below the sleep speeds) while moving, median",
               median(moving.awake_still), "bodies");
    add_metric(out, "bandwidth",
               "client: update_network_client + its extrapolation per frame while moving, median",
               median(moving.client_network_ms), "ms");
    add_metric(out, "bandwidth", "client: update() per frame while moving, median",
               median(moving.client_physics_ms), "ms");
    add_metric(out, "bandwidth", "joining: create_entity bytes",
               double(run.join.kind_bytes[packet_kind<edyn::packet::create_entity>()]), "bytes");
    add_metric(out, "bandwidth", "seconds to rest after the drive stopped", run.settle_seconds,
               run.settled ? "s" : "s (not all asleep)");
    add_metric(out, "bandwidth", "reference: the article's uncompressed snapshots", article_uncompressed_mbps,
               "Mbit/s");
    add_metric(out, "bandwidth", "reference: the article's final result", article_final_kbps, "kbit/s");
    add_breakdown(moving, out);
    add_breakdown(run.rest, out);
}

} // namespace

void run_bandwidth(const options &opt, results &out) {
    if (opt.grid == 0) throw std::invalid_argument("edyn-netbench: --grid must be at least 1");
    auto s = session(&setup_registry);
    s.detailed_traffic = true;
    auto built = build_cube_grid(s.server, opt.grid, 1);
    auto player = built.players.front();
    auto cube_count = built.cubes.size() + 1;
    std::fprintf(stderr, "edyn-netbench: bandwidth, %zu cubes at %.0f snapshots/s ... ", cube_count,
                 opt.snapshot_rate);
    std::fflush(stderr);

    auto link = edyn::simulated_link_settings{};
    link.latency = opt.latency;
    link.seed = opt.seed;
    auto &c = s.add_client(link);
    auto &rc = s.server.get<edyn::remote_client>(c.server_entity);
    rc.snapshot_rate = opt.snapshot_rate;
    // Kept centred on the player's cube, and wide enough to hold the whole grid wherever it goes.
    rc.aabb_of_interest = {{-100, -100, -100}, {100, 100, 100}};
    rc.owned_entities.push_back(player);

    auto run = run_phases(opt, s, c, player);
    report(run, out);

    char note[400];
    std::snprintf(
        note, sizeof note,
        "bandwidth: %zu cubes (%u×%u of %.2f m, one of %.0f m driven by the client), %.0f snapshots/s, "
        "link %.0f ms one way without loss; %.1f s moving, then %.1f s to rest, then %.1f s at rest",
        cube_count, opt.grid, opt.grid, double(2 * cube_half_extent), double(2 * player_half_extent),
        opt.snapshot_rate, opt.latency * 1000, run.moving.seconds, run.settle_seconds, run.rest.seconds);
    out.notes.push_back(note);
}

} // namespace edyn_netbench
