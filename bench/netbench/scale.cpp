// The scale scenario: one server, many clients, many bodies. Bodies dropped over a wide square
// of ground, each client's AABB of interest one cell of a grid laid over it. A few clients are
// real client registries over simulated links; the rest are byte sinks, which cost the server
// the same (it builds, encodes and hands over their packets) without a registry each here.
// The server's update_network_server and update() are timed every step.
#include "netbench.hpp"
#include "session.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace edyn_netbench {

namespace {

constexpr edyn::scalar body_spacing = 3;
// Steps in this first stretch are left out: every client is sent its whole part of the world
// in them.
constexpr double warmup_seconds = 0.5;
// Steps with at most this share of the bodies awake count as "at rest", reported apart when
// there are enough of them.
constexpr double resting_share = 0.01;
constexpr std::size_t min_resting_steps = 30;

struct scale_random {
    std::uint64_t state{0x9E3779B97F4A7C15ull};
    edyn::scalar between(double lo, double hi) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return edyn::scalar(lo + (hi - lo) * (double(state >> 11) * 0x1.0p-53));
    }
};

// Returns the side of the square the bodies cover.
// With `come_to_rest`, the spheres get rolling and spinning friction, so that everything stops and sleeps
// after a few seconds; without it they roll on for the whole run, keeping the world busy.
edyn::scalar build_scene(edyn::registry &server, unsigned bodies, bool come_to_rest) {
    auto ground = edyn::rigidbody_def{};
    ground.kind = edyn::rigidbody_kind::rb_static;
    ground.shape = edyn::plane_shape{{0, 1, 0}, 0};
    server.emplace<edyn::networked_tag>(edyn::make_rigidbody(server, ground));

    auto width = unsigned(std::ceil(std::sqrt(double(bodies))));
    auto side = edyn::scalar(width) * body_spacing;
    auto rng = scale_random{};
    for (unsigned i = 0; i < bodies; ++i) {
        auto def = edyn::rigidbody_def{};
        def.position = {(edyn::scalar(i % width) + 0.5f) * body_spacing - side / 2, rng.between(1, 6),
                        (edyn::scalar(i / width) + 0.5f) * body_spacing - side / 2};
        def.linvel = {rng.between(-2, 2), 0, rng.between(-2, 2)};
        def.angvel = {rng.between(-3, 3), rng.between(-3, 3), rng.between(-3, 3)};
        if (i % 2 == 0) {
            def.shape =
                edyn::box_shape{{rng.between(0.3, 0.6), rng.between(0.3, 0.6), rng.between(0.3, 0.6)}};
        } else {
            def.shape = edyn::sphere_shape{rng.between(0.3, 0.6)};
            if (come_to_rest) {
                def.material->roll_friction = edyn::scalar(0.05);
                def.material->spin_friction = edyn::scalar(0.05);
            }
        }
        def.mass = 2;
        server.emplace<edyn::networked_tag>(edyn::make_rigidbody(server, def));
    }
    return side;
}

struct step_sample {
    double network_ms;
    double sink_ms;
    double physics_ms;
    bool sent_snapshots;
    double awake_share;
};

double mean(const std::vector<double> &values) {
    auto sum = 0.0;
    for (auto v : values)
        sum += v;
    return values.empty() ? 0 : sum / double(values.size());
}

// Every snapshot is due on the same steps (every client joined at once and has the same
// rate), so the server's networking costs either almost nothing or everything: its median
// depends on which kind of step is the more numerous. The mean is what it costs over time.
// The target applies to the ratios of the means and of the 95th percentiles.
void report_steps(results &out, const std::vector<step_sample> &steps) {
    auto network = std::vector<double>{}, sink = std::vector<double>{}, physics = std::vector<double>{};
    auto snapshot_steps = std::vector<double>{};
    for (auto &s : steps) {
        network.push_back(s.network_ms);
        sink.push_back(s.sink_ms);
        physics.push_back(s.physics_ms);
        if (s.sent_snapshots) snapshot_steps.push_back(s.network_ms);
    }
    add_metric(out, "scale", "update_network_server per step, median", median(network), "ms");
    add_metric(out, "scale", "update_network_server per step, p95", percentile(network, 0.95), "ms");
    add_metric(out, "scale", "update_network_server per step, mean", mean(network), "ms");
    add_metric(out, "scale", "update_network_server in the steps that send snapshots, median",
               median(snapshot_steps), "ms");
    add_metric(out, "scale", "of which encoding the packets (in the packet sink), mean", mean(sink), "ms");
    add_metric(out, "scale", "update() per step, median", median(physics), "ms");
    add_metric(out, "scale", "update() per step, p95", percentile(physics, 0.95), "ms");
    add_metric(out, "scale", "update() per step, mean", mean(physics), "ms");
    auto ratio = [&](double a, double b) { return b > 0 ? a / b : 0; };
    add_metric(out, "scale", "networking / physics, medians", ratio(median(network), median(physics)), "");
    auto p95 = ratio(percentile(network, 0.95), percentile(physics, 0.95));
    add_metric(out, "scale", "networking / physics, p95s", p95, "", "< 1", p95 < 1 ? 1 : 0);
    auto means = ratio(mean(network), mean(physics));
    add_metric(out, "scale", "networking / physics, means", means, "", "< 1", means < 1 ? 1 : 0);
    add_metric(out, "scale", "networking / physics, snapshot steps' median / physics median",
               ratio(median(snapshot_steps), median(physics)), "");

    // Once the world has come to rest (--scale-rest), physics costs little; the interest and
    // snapshot work per client does not shrink with it.
    auto rest_network = std::vector<double>{}, rest_physics = std::vector<double>{};
    for (auto &s : steps) {
        if (s.awake_share > resting_share) continue;
        rest_network.push_back(s.network_ms);
        rest_physics.push_back(s.physics_ms);
    }
    if (rest_network.size() < min_resting_steps) return;
    auto suffix =
        " at rest (" + std::to_string(rest_network.size()) + " steps with 1% of the bodies awake or fewer)";
    add_metric(out, "scale", "update_network_server per step, mean," + suffix, mean(rest_network), "ms");
    add_metric(out, "scale", "update_network_server per step, p95," + suffix, percentile(rest_network, 0.95),
               "ms");
    add_metric(out, "scale", "update() per step, mean," + suffix, mean(rest_physics), "ms");
    add_metric(out, "scale", "networking / physics, means," + suffix,
               ratio(mean(rest_network), mean(rest_physics)), "");
}

} // namespace

void run_scale(const options &opt, results &out) {
    if (opt.scale_clients == 0)
        throw std::invalid_argument("edyn-netbench: --scale-clients must be at least 1");
    auto real = std::min(opt.scale_real_clients, opt.scale_clients);
    auto s = session(&setup_registry);
    auto side = build_scene(s.server, opt.scale_bodies, opt.scale_rest);
    std::fprintf(stderr, "edyn-netbench: scale, %u clients (%u real), %u bodies, %.1f s ... ",
                 opt.scale_clients, real, opt.scale_bodies, opt.scale_seconds);
    std::fflush(stderr);

    // The clients' AABBs tile the square in a grid of cells; the real ones are spread among them.
    auto cells = unsigned(std::ceil(std::sqrt(double(opt.scale_clients))));
    auto cell = side / edyn::scalar(cells);
    for (unsigned i = 0; i < opt.scale_clients; ++i) {
        auto is_real = real > 0 && i % std::max(1u, opt.scale_clients / real) == 0 &&
                       i / std::max(1u, opt.scale_clients / real) < real;
        auto link = edyn::simulated_link_settings{};
        link.latency = opt.latency;
        link.seed = opt.seed + i;
        auto &c = is_real ? s.add_client(link) : s.add_sink(2 * opt.latency);
        auto &rc = s.server.get<edyn::remote_client>(c.server_entity);
        rc.snapshot_rate = opt.scale_snapshot_rate;
        rc.aabb_follows_owned = false;
        auto x = edyn::scalar(i % cells) * cell - side / 2;
        auto z = edyn::scalar(i / cells) * cell - side / 2;
        rc.aabb_of_interest = {{x, -10, z}, {x + cell, 50, z + cell}};
    }

    auto frames = std::llround(opt.scale_seconds / s.dt());
    auto warmup = std::llround(warmup_seconds / s.dt());
    auto steps = std::vector<step_sample>{};
    auto join_network_ms = 0.0;
    auto odd_frames = 0;
    auto body_count = double(std::max(opt.scale_bodies, 1u));
    auto awake_share = std::vector<double>{};
    for (long long f = 0; f < frames; ++f) {
        s.frame();
        auto &t = s.last_frame();
        if (f < warmup) {
            join_network_ms = std::max(join_network_ms, t.network_ms);
            continue;
        }
        if (t.steps != 1) {
            ++odd_frames;
            continue;
        }
        auto awake = double(awake_bodies(s.server)) / body_count;
        steps.push_back({t.network_ms, t.sink_ms, t.physics_ms, t.packets > 0, awake});
        awake_share.push_back(awake);
    }
    if (steps.empty()) throw std::runtime_error("edyn-netbench: scale ran no step after its warm-up");

    auto bytes = std::uint64_t{0};
    for (auto &c : s.clients)
        bytes += c->sent.bytes;
    auto seconds = double(frames) * s.dt();

    report_steps(out, steps);
    add_metric(out, "scale", "update_network_server, slowest step of the first 0.5 s (clients join)",
               join_network_ms, "ms");
    add_metric(out, "scale", "server→client per client, mean over the run",
               double(bytes) * 8 / 1000 / seconds / double(opt.scale_clients), "kbit/s");
    auto network_ms = 0.0, physics_ms = 0.0;
    for (auto &x : steps) {
        network_ms += x.network_ms;
        physics_ms += x.physics_ms;
    }
    std::fprintf(stderr, "networking %.3f ms a step on average, physics %.3f ms\n",
                 network_ms / double(steps.size()), physics_ms / double(steps.size()));

    char note[800];
    std::snprintf(
        note, sizeof note,
        "scale: %u bodies (boxes and spheres dropped from 1-6 m, %.0f m apart over a %.0f m square, "
        "sleeping allowed%s), %u clients each with one cell of a %u×%u grid over it as AABB of "
        "interest, %.0f snapshots/s each; %u of them real client registries over %.0f ms links, the "
        "other %u byte sinks; %.1f s at 60 Hz, %zu steps timed after the first 0.5 s; %.0f%% of the "
        "bodies awake on average, %.0f%% at the end%s",
        opt.scale_bodies, double(body_spacing), double(side),
        opt.scale_rest ? ", spheres with rolling and spinning friction so that all comes to rest" : "",
        opt.scale_clients, cells, cells, opt.scale_snapshot_rate, real, opt.latency * 1000,
        opt.scale_clients - real, opt.scale_seconds, steps.size(), 100 * mean(awake_share),
        100 * double(awake_bodies(s.server)) / body_count,
        odd_frames > 0 ? "; some frames ran other than one step and were left out" : "");
    out.notes.push_back(note);
}

} // namespace edyn_netbench
