#ifndef EDYN_NETBENCH_NETBENCH_HPP
#define EDYN_NETBENCH_NETBENCH_HPP

// edyn-netbench: a server and its clients in one process, over simulated links, measuring how
// close the clients' views stay to the server, how many bytes the server sends and what its
// networking costs next to its physics.

#include <cstdint>
#include <edyn/edyn.hpp>
#include <edyn/networking/networked_components.hpp>
#include <string>
#include <vector>

namespace edyn_netbench {

struct options {
    std::string scenario{"all"};
    std::string json;
    std::string markdown;
    bool small{false};

    // convergence
    std::string arena{"walls"}; // the scene: "walls" (thrown and bouncing bodies) or "cubes" (Fiedler's)
    unsigned repeat{1};         // runs, each with its own link seeds; the table shows their median
    unsigned clients{3};
    unsigned bodies{30}; // thrown and bouncing, besides one driven box per client
    double seconds{10};
    double latency{0.05}; // one way
    double jitter{0.02};
    double loss{0.1};
    double duplication{0.01};
    double reordering{0.01};
    double client_snapshot_rate{0}; // inputs sent per second by each client; 0: the library's default
    std::uint64_t seed{1};

    // bandwidth
    unsigned grid{30}; // cubes per side of the grid (the convergence's too, with arena "cubes")
    double snapshot_rate{60};
    double moving_seconds{10};
    double rest_seconds{5};

    // scale
    unsigned scale_clients{64};
    unsigned scale_real_clients{4};
    unsigned scale_bodies{10000};
    double scale_snapshot_rate{30};
    double scale_seconds{6};
    bool scale_rest{false}; // a world that comes to rest instead of one that keeps rolling
};

// One figure of one scenario. `target` is empty when the figure has none; `met` is then unset.
struct metric {
    std::string scenario;
    std::string name;
    double value{0};
    std::string unit;
    std::string target;
    int met{-1}; // -1 no target, 0 missed, 1 met
    // With several runs, each run's value (`value` is their median).
    std::vector<double> runs;
};

// A line of a byte breakdown: where a phase's server→client bytes went.
struct breakdown_row {
    std::string scenario;
    std::string phase;
    std::string part;
    std::uint64_t count{0}; // packets or values, as `count_of` says
    std::string count_of;
    std::uint64_t bytes{0};
    double bytes_per_second{0};
    double share{0}; // of the phase's bytes
};

struct results {
    std::vector<metric> metrics;
    std::vector<breakdown_row> breakdown;
    std::vector<std::string> notes; // what was run, in words
};

void run_convergence(const options &opt, results &out);
void run_bandwidth(const options &opt, results &out);
void run_scale(const options &opt, results &out);

// A client's input: a force on the body it drives, applied before every step by drive_bodies,
// on the server, in the clients and in their extrapolations alike.
struct drive : edyn::network_input {
    edyn::vector3 force{edyn::vector3_zero};
};

template<typename Archive>
void serialize(Archive &archive, drive &d) {
    archive(d.force);
}

// Registers the drive input and the step callback that applies it.
void setup_registry(edyn::registry &registry);

// Sets `local`'s drive in a client, waking the body (the step callback's push is invisible to
// the simulation); nothing when the force is the same as before, so that a constant input
// does not keep the body awake.
void set_drive(edyn::registry &client, edyn::entity local, const edyn::vector3 &force);

// The scene of Glenn Fiedler's "Snapshot Compression" article: a grid of `grid` by `grid` small
// cubes (1 kg, a metre apart) on the ground, and one large cube (80 kg) per player just off the
// grid's edge, spread round it.
inline constexpr edyn::scalar cube_half_extent = 0.25f;
inline constexpr edyn::scalar player_half_extent = 1;
struct cube_grid {
    std::vector<edyn::entity> cubes;
    std::vector<edyn::entity> players;
};
cube_grid build_cube_grid(edyn::registry &server, unsigned grid, unsigned players);

// The force with which player `k` of `players` steers its cube, from where `registry` shows it,
// `time` seconds into the drive: after a point going round a circle in the middle of the grid,
// each player's a share of a turn ahead of the last's, with a spring and damper, capped.
edyn::vector3 steer_player(const edyn::registry &registry, edyn::entity cube, unsigned grid, unsigned k,
                           unsigned players, double time);

// Bodies of `server` that are dynamic and awake.
std::size_t awake_bodies(const edyn::registry &server);

// Appends a figure of `scenario` to `out`; `met` is 1 or 0 where the figure has a target, -1 where
// it has none.
void add_metric(results &out, const char *scenario, std::string name, double value, std::string unit,
                std::string target = {}, int met = -1);

// The value below which a fraction `p` (in [0, 1]) of `values` lie, interpolated between ranks.
double percentile(std::vector<double> values, double p);
double median(std::vector<double> values);

std::string markdown_report(const results &r);
void write_json(const std::string &path, const results &r);

} // namespace edyn_netbench

#endif // EDYN_NETBENCH_NETBENCH_HPP
