// The convergence scenario: clients over a bad network (latency, jitter, loss, duplication,
// reordering) watching a scene that keeps moving, each driving a body of its own. Two scenes:
// a walled arena of bodies thrown about and bouncing, each client driving a box with a scripted
// input (--arena walls), and the cube grid of Glenn Fiedler's "Snapshot Compression" article,
// each client steering a large cube through it (--arena cubes). Two figures: how far each
// client's copy of every body is from the server's body at the same server time, and how far
// the server's path of each driven body strays from the path the same drive gives over a clean
// link (same latency, nothing lost or late). Beside them, the floor under the first: how far a
// world rebuilt from the bodies' motion strays from the original.
#include "netbench.hpp"
#include "session.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <edyn/collision/contact_manifold.hpp>
#include <edyn/serialization/memory_archive.hpp>
#include <edyn/serialization/quantize.hpp>
#include <edyn/simulation/world_state.hpp>
#include <stdexcept>

namespace edyn_netbench {

namespace {

// Samples before this time (seconds) are left out: the clients join, synchronise their clocks
// and receive the scene during it.
constexpr double settle_time = 1;
constexpr edyn::scalar arena_half_width = 10;
constexpr edyn::scalar wall_half_height = 5;
// Driven boxes: heavy enough to push the others about, driven hard enough to beat friction.
constexpr edyn::scalar driven_mass = 10;
constexpr double drive_newtons = 160;

enum body_kind : std::uint8_t { own_box, other_driven_box, free_body, kind_count };

bool in_cube_grid(const options &opt) { return opt.arena == "cubes"; }

const char *kind_name(const options &opt, body_kind kind) {
    switch (kind) {
    case own_box:
        return in_cube_grid(opt) ? "its own cube" : "its own driven box";
    case other_driven_box:
        return in_cube_grid(opt) ? "other players' cubes" : "other clients' driven boxes";
    default:
        return in_cube_grid(opt) ? "the grid's small cubes" : "thrown and bouncing bodies";
    }
}

// A fixed generator for the scene, so that every run builds the same one.
struct scene_random {
    std::uint64_t state{0x2545F4914F6CDD1Dull};
    double next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1.0p-53;
    }
    edyn::scalar between(double lo, double hi) { return edyn::scalar(lo + (hi - lo) * next()); }
};

edyn::entity add_networked(edyn::registry &registry, const edyn::rigidbody_def &def) {
    auto e = edyn::make_rigidbody(registry, def);
    registry.emplace<edyn::networked_tag>(e);
    return e;
}

void add_static_box(edyn::registry &registry, const edyn::vector3 &pos, const edyn::vector3 &half) {
    auto def = edyn::rigidbody_def{};
    def.kind = edyn::rigidbody_kind::rb_static;
    def.shape = edyn::box_shape{half};
    def.position = pos;
    def.material->restitution = edyn::scalar(0.8);
    add_networked(registry, def);
}

struct scene {
    std::vector<edyn::entity> free_bodies;
    std::vector<edyn::entity> driven; // one per client
};

// A walled arena; spheres bouncing (restitution 0.9) and boxes thrown tumbling, all with
// velocities of a few metres a second; one box per client on a circle, for it to drive.
scene build_arena(edyn::registry &server, unsigned bodies, unsigned clients) {
    auto ground = edyn::rigidbody_def{};
    ground.kind = edyn::rigidbody_kind::rb_static;
    ground.shape = edyn::plane_shape{{0, 1, 0}, 0};
    add_networked(server, ground);
    // Walls higher than anything is thrown, so that the bodies stay in the arena.
    auto a = arena_half_width;
    auto h = wall_half_height;
    add_static_box(server, {a + 0.5f, h, 0}, {0.5f, h, a + 1});
    add_static_box(server, {-a - 0.5f, h, 0}, {0.5f, h, a + 1});
    add_static_box(server, {0, h, a + 0.5f}, {a + 1, h, 0.5f});
    add_static_box(server, {0, h, -a - 0.5f}, {a + 1, h, 0.5f});

    auto out = scene{};
    auto rng = scene_random{};
    for (unsigned i = 0; i < bodies; ++i) {
        auto def = edyn::rigidbody_def{};
        // Spread over a grid inside the arena, at different heights so that they do not
        // start in contact.
        auto column = i % 6, row = i / 6;
        def.position = {edyn::scalar(-7.5 + 3 * column) + rng.between(-0.5, 0.5), rng.between(1, 5),
                        edyn::scalar(-7.5 + 3 * (row % 6)) + rng.between(-0.5, 0.5)};
        def.position.y += edyn::scalar(2 * (row / 6));
        def.linvel = {rng.between(-4, 4), rng.between(0, 5), rng.between(-4, 4)};
        if (i % 2 == 0) {
            def.shape = edyn::sphere_shape{rng.between(0.3, 0.5)};
            def.mass = 2;
            def.material->restitution = edyn::scalar(0.9);
        } else {
            auto half = rng.between(0.3, 0.5);
            def.shape = edyn::box_shape{{half, rng.between(0.3, 0.5), half}};
            def.mass = 3;
            def.angvel = {rng.between(-5, 5), rng.between(-5, 5), rng.between(-5, 5)};
            def.material->restitution = edyn::scalar(0.3);
        }
        out.free_bodies.push_back(add_networked(server, def));
    }
    for (unsigned i = 0; i < clients; ++i) {
        auto angle = 2 * 3.14159265358979 * i / std::max(clients, 1u);
        auto def = edyn::rigidbody_def{};
        def.shape = edyn::box_shape{{0.5f, 0.5f, 0.5f}};
        def.mass = driven_mass;
        def.position = {edyn::scalar(6 * std::cos(angle)), 0.5f, edyn::scalar(6 * std::sin(angle))};
        out.driven.push_back(add_networked(server, def));
    }
    return out;
}

scene build_scene(edyn::registry &server, const options &opt) {
    if (!in_cube_grid(opt)) return build_arena(server, opt.bodies, opt.clients);
    auto grid = build_cube_grid(server, opt.grid, opt.clients);
    return {std::move(grid.cubes), std::move(grid.players)};
}

// The script each client follows in the arena: a force turning in the horizontal plane, a
// function of the client's time only (the server time at which it applies), so that it is the
// same in every run whatever the network does. It starts at a fixed time, by which every client
// has joined over any link the benchmark simulates, rather than whenever the client gets its box.
constexpr double drive_start = 1;

edyn::vector3 scripted_force(unsigned client, double time) {
    if (time < drive_start) return edyn::vector3_zero;
    auto phase = 2.1 * client;
    return {edyn::scalar(drive_newtons * std::cos(2 * time + phase)), 0,
            edyn::scalar(drive_newtons * std::sin(1.6 * time + phase))};
}

// The drive of client `client`'s body `driven`, as `registry` shows it, at the client's time
// `time`: the arena's script, or in the cube grid the player's steering from where it sees its
// cube (which therefore depends on what the network did).
edyn::vector3 drive_force(const options &opt, const edyn::registry &registry, edyn::entity driven,
                          unsigned client, double time) {
    if (!in_cube_grid(opt)) return scripted_force(client, time);
    if (time < drive_start) return edyn::vector3_zero;
    return steer_player(registry, driven, opt.grid, client, opt.clients, time - drive_start);
}

// The server's positions of the tracked bodies after each step.
struct server_history {
    double dt{};
    std::vector<std::vector<edyn::vector3>> by_step; // empty where no step was recorded

    void record(const edyn::registry &server, const std::vector<edyn::entity> &bodies) {
        auto step = std::size_t(edyn::get_step_count(server));
        if (step >= by_step.size()) by_step.resize(step + 1);
        auto &positions = by_step[step];
        positions.clear();
        for (auto e : bodies)
            positions.push_back(server.get<edyn::position>(e));
    }
    // Body `i` at server time `time`, between the two steps around it; false outside the record.
    bool at(double time, std::size_t i, edyn::vector3 &out) const {
        auto x = time / dt;
        if (!(x >= 0)) return false;
        auto s0 = std::size_t(std::floor(x));
        if (s0 + 1 >= by_step.size() || by_step[s0].empty() || by_step[s0 + 1].empty()) return false;
        auto w = edyn::scalar(x - double(s0));
        out = by_step[s0][i] + (by_step[s0 + 1][i] - by_step[s0][i]) * w;
        return true;
    }
    // Body `i` after the step nearest `time`.
    bool nearest(double time, std::size_t i, edyn::vector3 &out) const {
        auto x = std::llround(time / dt);
        if (x < 0 || std::size_t(x) >= by_step.size() || by_step[std::size_t(x)].empty()) return false;
        out = by_step[std::size_t(x)][i];
        return true;
    }
};

struct sample {
    double time;
    std::uint32_t body;
    body_kind kind;
    edyn::vector3 pos;
};

struct run_figures {
    std::vector<double> errors[kind_count]; // metres
    std::vector<double> all_errors;
    // Against the server after the step nearest the client's time rather than at that time: the
    // extrapolations run whole steps from a snapshot, so a client's time that is not on the
    // server's step grid leaves its view up to half a step off.
    std::vector<double> nearest_step_errors;
    std::vector<double> off_grid_ms; // each sample's client time from the nearest server step
    std::vector<std::vector<edyn::vector3>> driven_paths;  // per client, by server step
    std::vector<std::vector<edyn::vector3>> driven_forces; // the drive the server applied
    std::uint64_t late_inputs{0};
    edyn::simulated_link_stats down{};
    double dt{0};
};

void add_stats(edyn::simulated_link_stats &sum, const edyn::simulated_link_stats &s) {
    sum.packets_sent += s.packets_sent;
    sum.bytes_sent += s.bytes_sent;
    sum.packets_lost += s.packets_lost;
    sum.packets_duplicated += s.packets_duplicated;
    sum.packets_reordered += s.packets_reordered;
    sum.retransmissions += s.retransmissions;
}

template<typename T>
void set_at(std::vector<T> &list, std::size_t i, const T &value) {
    if (i >= list.size()) list.resize(i + 1, T{});
    list[i] = value;
}

run_figures run_once(const options &opt, unsigned run, bool lossy) {
    auto s = session(&setup_registry);
    auto built = build_scene(s.server, opt);
    auto tracked = built.free_bodies;
    tracked.insert(tracked.end(), built.driven.begin(), built.driven.end());

    for (unsigned i = 0; i < opt.clients; ++i) {
        auto link = edyn::simulated_link_settings{};
        link.latency = opt.latency;
        if (lossy) {
            link.jitter = opt.jitter;
            link.loss = opt.loss;
            link.duplication = opt.duplication;
            link.reordering = opt.reordering;
        }
        link.seed = opt.seed + 1000 * std::uint64_t(run) + i;
        auto &c = s.add_client(link);
        s.server.get<edyn::remote_client>(c.server_entity).owned_entities.push_back(built.driven[i]);
        if (opt.client_snapshot_rate > 0)
            edyn::set_network_client_snapshot_rate(*c.reg, opt.client_snapshot_rate);
    }

    auto history = server_history{s.dt(), {}};
    auto samples = std::vector<sample>{};
    auto figures = run_figures{};
    figures.dt = s.dt();
    figures.driven_paths.resize(opt.clients);
    figures.driven_forces.resize(opt.clients);
    auto frames = std::llround(opt.seconds / s.dt());
    for (long long f = 0; f < frames; ++f) {
        s.frame();
        history.record(s.server, tracked);
        auto step = std::size_t(edyn::get_step_count(s.server));
        for (unsigned i = 0; i < opt.clients; ++i) {
            auto box = built.driven[i];
            set_at(figures.driven_paths[i], step, edyn::vector3(s.server.get<edyn::position>(box)));
            auto *d = s.server.try_get<drive>(box);
            set_at(figures.driven_forces[i], step, d ? d->force : edyn::vector3_zero);
        }
        for (unsigned i = 0; i < opt.clients; ++i) {
            auto &reg = *s.clients[i]->reg;
            auto client_time = edyn::get_network_client_time(reg);
            auto own = edyn::client_local_entity(reg, built.driven[i]);
            if (own != edyn::null) set_drive(reg, own, drive_force(opt, reg, own, i, client_time));
            if (s.now() < settle_time) continue;
            for (std::uint32_t b = 0; b < tracked.size(); ++b) {
                auto local = edyn::client_local_entity(reg, tracked[b]);
                if (local == edyn::null) continue;
                auto kind = b < built.free_bodies.size()    ? free_body
                            : tracked[b] == built.driven[i] ? own_box
                                                            : other_driven_box;
                samples.push_back({client_time, b, kind, reg.get<edyn::position>(local)});
            }
        }
    }

    for (auto &smp : samples) {
        auto server_pos = edyn::vector3{};
        // Samples past the end of the server's record (the clients run ahead of it) are left out.
        if (!history.at(smp.time, smp.body, server_pos)) continue;
        auto error = double(edyn::length(smp.pos - server_pos));
        figures.errors[smp.kind].push_back(error);
        figures.all_errors.push_back(error);
        if (history.nearest(smp.time, smp.body, server_pos))
            figures.nearest_step_errors.push_back(double(edyn::length(smp.pos - server_pos)));
        figures.off_grid_ms.push_back(std::abs(smp.time - double(std::llround(smp.time / s.dt())) * s.dt()) *
                                      1000);
    }
    for (auto &c : s.clients) {
        add_stats(figures.down, c->down->stats());
        auto &rc = s.server.get<edyn::remote_client>(c->server_entity);
        figures.late_inputs += rc.rejected.late;
        if (rc.rejected.total() > 0)
            throw std::runtime_error("edyn-netbench: the server refused " +
                                     std::to_string(rc.rejected.total()) +
                                     " packets of a client that sent only its own inputs");
    }
    return figures;
}

double max_of(const std::vector<double> &values) {
    return values.empty() ? 0 : *std::max_element(values.begin(), values.end());
}

struct path_comparison {
    double max_distance{0};  // metres
    double first_apart{-1};  // seconds of server time when a path first strayed 1 mm; -1 never
    double inputs_differ{0}; // share of the driven steps whose applied drive differed
};

path_comparison compare_paths(const run_figures &a, const run_figures &b) {
    auto dt = a.dt;
    auto out = path_comparison{};
    auto driven_steps = std::size_t{0}, differing = std::size_t{0};
    for (std::size_t i = 0; i < a.driven_paths.size(); ++i) {
        auto &pa = a.driven_paths[i];
        auto &pb = b.driven_paths[i];
        for (std::size_t k = 0; k < std::min(pa.size(), pb.size()); ++k) {
            auto distance = double(edyn::length(pa[k] - pb[k]));
            out.max_distance = std::max(out.max_distance, distance);
            if (distance > 0.001 && (out.first_apart < 0 || double(k) * dt < out.first_apart))
                out.first_apart = double(k) * dt;
        }
        auto &fa = a.driven_forces[i];
        auto &fb = b.driven_forces[i];
        for (std::size_t k = 0; k < std::min(fa.size(), fb.size()); ++k) {
            if (fa[k] == edyn::vector3_zero && fb[k] == edyn::vector3_zero) continue;
            ++driven_steps;
            differing += fa[k] != fb[k];
        }
    }
    out.inputs_differ = driven_steps > 0 ? double(differing) / double(driven_steps) : 0;
    return out;
}

// The floor under the view error: how far the scene's bodies are, `horizon` steps on, in a world
// rebuilt from their motion alone (position, orientation and velocities, what a snapshot
// carries, rounded as snapshots round it with `quantised`), from where they are in the world that
// ran on. A client with exact snapshots and every input can extrapolate no better: contact
// points, their impulses, ages and order, and sleep timers are not carried. With `contacts` the
// rebuilt world also starts with the original's contact points as they were (what no snapshot
// carries): what is then left is the rounding's share. With `driven` the driven bodies get the
// clients' drives in both worlds, the rebuilt world the very forces the original had at each
// step: every input known at its step, what is left is what the scene's collisions make of the
// rebuild alone. Rebuilt every third step after the first second;
// metres, one value per body and rebuild.
struct motion_record {
    edyn::vector3 position, linvel, angvel;
    edyn::quaternion orientation;
};

// Gives the rebuilt world's pairs the original's contact points, impulses and ages. The two
// worlds were built alike, so that their bodies are the same entities.
void seed_contacts(edyn::registry &rebuilt, const std::vector<edyn::contact_manifold> &manifolds) {
    auto &world = rebuilt.ctx().get<edyn::world_state>();
    world.broadphase.update(rebuilt);
    for (auto &m : manifolds) {
        auto e = world.broadphase.get_manifold(m.body[0], m.body[1]);
        if (e == edyn::null) continue;
        rebuilt.replace<edyn::contact_manifold>(e, m);
        // The narrowphase links a pair to its island when its first point appears; these came
        // with their points.
        world.islands.link_edge(rebuilt, e, m.body[0], m.body[1]);
    }
}

// Sets each driven body's drive to its force in `forces`, as the server applies the inputs
// stamped with a step, waking the body as an input does.
void set_drives(edyn::registry &registry, const std::vector<edyn::entity> &driven,
                const std::vector<edyn::vector3> &forces) {
    for (unsigned i = 0; i < driven.size(); ++i) {
        registry.emplace_or_replace<drive>(driven[i], drive{{}, forces[i]});
        if (registry.all_of<edyn::sleeping_tag>(driven[i])) edyn::wake_up_entity(registry, driven[i]);
    }
}

std::vector<double> rebuild_errors(const options &opt, unsigned horizon, bool quantised, bool contacts,
                                   bool driven) {
    auto make_world = [&](edyn::registry &registry) {
        edyn::attach(registry, edyn::init_config{edyn::execution_mode::sequential});
        setup_registry(registry);
        auto built = build_scene(registry, opt);
        auto bodies = built.free_bodies;
        bodies.insert(bodies.end(), built.driven.begin(), built.driven.end());
        return bodies;
    };
    auto record = [](const edyn::registry &registry, const std::vector<edyn::entity> &bodies) {
        auto motions = std::vector<motion_record>{};
        for (auto e : bodies)
            motions.push_back({registry.get<edyn::position>(e), registry.get<edyn::linvel>(e),
                               registry.get<edyn::angvel>(e), registry.get<edyn::orientation>(e)});
        return motions;
    };

    auto original = edyn::registry{};
    auto bodies = make_world(original);
    auto dt = double(edyn::get_fixed_dt(original));
    auto steps = std::size_t(std::llround(opt.seconds / dt));
    auto first = std::size_t(std::llround(settle_time / dt));
    auto rebuilt_at = [&](std::size_t k) { return k >= first && (k - first) % 3 == 0; };
    auto history = std::vector<std::vector<motion_record>>{record(original, bodies)};
    // The driven boxes are the last of the bodies.
    auto boxes_of = [&](const std::vector<edyn::entity> &all) {
        return std::vector<edyn::entity>(all.end() - std::ptrdiff_t(opt.clients), all.end());
    };
    auto boxes = boxes_of(bodies);
    // The manifolds with points at each step a world is rebuilt at.
    auto touching = std::vector<std::vector<edyn::contact_manifold>>(steps + 1);
    // The drives of the step that led to each state, which the rebuilt worlds apply again.
    auto drives = std::vector<std::vector<edyn::vector3>>(steps + 1);
    for (std::size_t k = 1; k <= steps; ++k) {
        if (driven) {
            for (unsigned i = 0; i < boxes.size(); ++i)
                drives[k].push_back(drive_force(opt, original, boxes[i], i, double(k - 1) * dt));
            set_drives(original, boxes, drives[k]);
        }
        edyn::step_simulation(original);
        history.push_back(record(original, bodies));
        if (!contacts || !rebuilt_at(k)) continue;
        for (auto [e, manifold] : original.view<edyn::contact_manifold>().each())
            if (manifold.num_points > 0) touching[k].push_back(manifold);
    }

    auto errors = std::vector<double>{};
    for (auto k = first; k + horizon < history.size(); ++k) {
        if (!rebuilt_at(k)) continue;
        auto rebuilt = edyn::registry{};
        auto copies = make_world(rebuilt);
        for (std::size_t i = 0; i < copies.size(); ++i) {
            auto m = history[k][i];
            if (quantised) {
                // Written and read back with the quanta of a snapshot's motion pool.
                auto fields = [&m](auto &archive) {
                    edyn::serialize_quantized(archive, m.position, edyn::position_quantum);
                    edyn::serialize_quantized(archive, m.orientation);
                    edyn::serialize_quantized(archive, m.linvel, edyn::velocity_quantum);
                    edyn::serialize_quantized(archive, m.angvel, edyn::velocity_quantum);
                };
                auto bytes = std::vector<std::uint8_t>{};
                auto write = edyn::memory_output_archive(bytes);
                fields(write);
                auto read = edyn::memory_input_archive(bytes.data(), bytes.size());
                fields(read);
            }
            rebuilt.replace<edyn::position>(copies[i], m.position);
            rebuilt.replace<edyn::orientation>(copies[i], m.orientation);
            rebuilt.replace<edyn::linvel>(copies[i], m.linvel);
            rebuilt.replace<edyn::angvel>(copies[i], m.angvel);
        }
        if (contacts) seed_contacts(rebuilt, touching[k]);
        auto copied_boxes = boxes_of(copies);
        for (unsigned h = 0; h < horizon; ++h) {
            if (driven) set_drives(rebuilt, copied_boxes, drives[k + h + 1]);
            edyn::step_simulation(rebuilt);
        }
        for (std::size_t i = 0; i < copies.size(); ++i)
            errors.push_back(double(
                edyn::length(rebuilt.get<edyn::position>(copies[i]) - history[k + horizon][i].position)));
    }
    return errors;
}

} // namespace

void run_convergence(const options &opt, results &out) {
    if (opt.clients == 0) throw std::invalid_argument("edyn-netbench: convergence needs at least one client");
    if (in_cube_grid(opt) && opt.grid == 0)
        throw std::invalid_argument("edyn-netbench: --grid must be at least 1");
    if (opt.seconds <= settle_time)
        throw std::invalid_argument("edyn-netbench: convergence must run longer than its first second");

    struct figure {
        std::string name;
        std::string unit;
        std::string target;
        double limit; // in `unit`; 0 without a target
        std::vector<double> runs;
    };
    auto figures = std::vector<figure>{
        {"client view error, max", "cm", "≤ 5 cm", 5, {}},
        {"client view error, p99", "cm", "", 0, {}},
        {"client view error, median", "cm", "", 0, {}},
        {std::string("max error on ") + kind_name(opt, own_box), "cm", "", 0, {}},
        {std::string("max error on ") + kind_name(opt, other_driven_box), "cm", "", 0, {}},
        {std::string("max error on ") + kind_name(opt, free_body), "cm", "", 0, {}},
        {"client view error against the server's nearest step, max", "cm", "", 0, {}},
        {"client view error against the server's nearest step, p99", "cm", "", 0, {}},
        {"client time's distance from the server's step grid, median", "ms", "", 0, {}},
        // In the cube grid a player steers from what it sees, which the network changes: its
        // path has no reason to be the clean link's, and the target is the arena's.
        {"driven path vs clean link, max distance",
         "cm",
         in_cube_grid(opt) ? "" : "≤ 10 cm",
         in_cube_grid(opt) ? 0.0 : 10.0,
         {}},
        {"driven paths first 1 mm apart at server time", "s", "", 0, {}},
        {"driven steps whose applied input differs from the clean link's", "%", "", 0, {}},
        {"input snapshots that reached the server after their time", "packets", "", 0, {}},
        {"client view error over the clean link, max", "cm", "", 0, {}},
        {"server → client, per client", "kbit/s", "", 0, {}},
    };
    auto compared = std::size_t{0};
    for (unsigned run = 0; run < opt.repeat; ++run) {
        std::fprintf(stderr,
                     "edyn-netbench: convergence (%s), run %u of %u: %u clients, %u bodies, %.1f s ... ",
                     opt.arena.c_str(), run + 1, opt.repeat, opt.clients,
                     in_cube_grid(opt) ? opt.grid * opt.grid : opt.bodies, opt.seconds);
        std::fflush(stderr);
        auto lossy = run_once(opt, run, true);
        auto clean = run_once(opt, run, false);
        if (lossy.all_errors.empty()) throw std::runtime_error("edyn-netbench: no client ever saw a body");
        auto paths = compare_paths(lossy, clean);
        auto kbits_per_client = double(lossy.down.bytes_sent) * 8 / 1000 / opt.seconds / opt.clients;
        auto values = std::vector<double>{max_of(lossy.all_errors) * 100,
                                          percentile(lossy.all_errors, 0.99) * 100,
                                          median(lossy.all_errors) * 100,
                                          max_of(lossy.errors[own_box]) * 100,
                                          max_of(lossy.errors[other_driven_box]) * 100,
                                          max_of(lossy.errors[free_body]) * 100,
                                          max_of(lossy.nearest_step_errors) * 100,
                                          percentile(lossy.nearest_step_errors, 0.99) * 100,
                                          median(lossy.off_grid_ms),
                                          paths.max_distance * 100,
                                          paths.first_apart,
                                          paths.inputs_differ * 100,
                                          double(lossy.late_inputs),
                                          max_of(clean.all_errors) * 100,
                                          kbits_per_client};
        for (std::size_t i = 0; i < figures.size(); ++i)
            figures[i].runs.push_back(values[i]);
        compared = lossy.all_errors.size();
        std::fprintf(stderr, "view max %.2f cm, p99 %.2f cm; driven path %.2f cm\n", values[0], values[1],
                     values[9]);
        if (run == 0) {
            auto &d = lossy.down;
            char rate[64] = "the library's default rate";
            if (opt.client_snapshot_rate > 0)
                std::snprintf(rate, sizeof rate, "%.0f a second", opt.client_snapshot_rate);
            char scene[160];
            if (in_cube_grid(opt)) {
                std::snprintf(scene, sizeof scene,
                              "%u×%u small cubes + %u large cubes the clients steer through them", opt.grid,
                              opt.grid, opt.clients);
            } else {
                std::snprintf(scene, sizeof scene,
                              "%u thrown/bouncing bodies + %u driven boxes in a walled arena", opt.bodies,
                              opt.clients);
            }
            char note[800];
            std::snprintf(note, sizeof note,
                          "convergence: %u clients, %s, %.1f s, driven from 1 s on, inputs sent at %s; link "
                          "%.0f ms one way ± %.0f ms, %.0f%% loss, "
                          "%.0f%% duplication, %.0f%% reordering, against a clean link of the same latency; "
                          "%zu samples (client, body, frame) compared per run after the first second; "
                          "server→client in run 1: %llu packets, %llu lost, %llu duplicated, %llu held back, "
                          "%llu reliable resends",
                          opt.clients, scene, opt.seconds, rate, opt.latency * 1000, opt.jitter * 1000,
                          opt.loss * 100, opt.duplication * 100, opt.reordering * 100, compared,
                          (unsigned long long)d.packets_sent, (unsigned long long)d.packets_lost,
                          (unsigned long long)d.packets_duplicated, (unsigned long long)d.packets_reordered,
                          (unsigned long long)d.retransmissions);
            out.notes.push_back(note);
        }
    }
    // The same for every run: the floor needs no link.
    struct floor_case {
        unsigned horizon;
        bool quantised;
        bool contacts;
        bool driven;
    };
    for (auto c : {floor_case{6, false, false, false}, floor_case{12, false, false, false},
                   floor_case{12, true, false, false}, floor_case{12, false, true, false},
                   floor_case{12, true, true, false}, floor_case{12, false, false, true},
                   floor_case{12, true, false, true}, floor_case{12, false, true, true}}) {
        auto errors = rebuild_errors(opt, c.horizon, c.quantised, c.contacts, c.driven);
        if (errors.empty()) continue;
        auto name = std::string(c.driven ? "driven " : "") + "world rebuilt from " +
                    (c.quantised ? "quantised" : "exact") + " motion" +
                    (c.contacts ? " and the original's contact points" : "") + " vs the original, " +
                    std::to_string(c.horizon) + " steps on, ";
        figures.push_back({name + "max", "cm", "", 0, {max_of(errors) * 100}});
        figures.push_back({name + "p99", "cm", "", 0, {percentile(errors, 0.99) * 100}});
    }
    for (auto &f : figures) {
        auto m = metric{};
        m.scenario = "convergence";
        m.name = f.name;
        m.value = median(f.runs);
        m.unit = f.unit;
        m.target = f.target;
        if (f.limit > 0) m.met = m.value <= f.limit ? 1 : 0;
        if (f.runs.size() > 1) m.runs = f.runs;
        out.metrics.push_back(std::move(m));
    }
}

} // namespace edyn_netbench
