// edyn-netbench: an in-process server and clients over simulated links (latency, jitter, loss,
// duplication, reordering), all in execution_mode::sequential. Prints a markdown table of what
// each scenario measured, with its target where it has one; --json writes the records.
#include "netbench.hpp"
#include <CLI/CLI.hpp>
#include <cstdio>
#include <stdexcept>

namespace edyn_netbench {
namespace {

// --small: sizes for a smoke test of a few seconds; flags given explicitly still win.
void apply_small_sizes(options &opt, const CLI::App &app) {
    auto unset = [&](const char *flag) { return app.get_option(flag)->count() == 0; };
    if (unset("--clients")) opt.clients = 2;
    if (unset("--bodies")) opt.bodies = 6;
    if (unset("--seconds")) opt.seconds = 1.5;
    if (unset("--grid")) opt.grid = 5;
    if (unset("--moving-seconds")) opt.moving_seconds = 2;
    if (unset("--rest-seconds")) opt.rest_seconds = 0.5;
    if (unset("--scale-clients")) opt.scale_clients = 4;
    if (unset("--scale-real-clients")) opt.scale_real_clients = 1;
    if (unset("--scale-bodies")) opt.scale_bodies = 100;
    if (unset("--scale-seconds")) opt.scale_seconds = 1;
}

int run(const options &opt) {
    auto out = results{};
    auto all = opt.scenario == "all";
    if (all || opt.scenario == "convergence") run_convergence(opt, out);
    if (all || opt.scenario == "bandwidth") run_bandwidth(opt, out);
    if (all || opt.scenario == "scale") run_scale(opt, out);
    auto table = markdown_report(out);
    std::printf("%s", table.c_str());
    if (!opt.json.empty()) write_json(opt.json, out);
    if (!opt.markdown.empty()) {
        auto *file = std::fopen(opt.markdown.c_str(), "w");
        if (!file) throw std::runtime_error("edyn-netbench: cannot write " + opt.markdown);
        std::fputs(table.c_str(), file);
        std::fclose(file);
    }
    return 0;
}

} // namespace
} // namespace edyn_netbench

int main(int argc, char **argv) {
    edyn_netbench::options opt;
    CLI::App app{"edyn-netbench: a server and its clients in one process over simulated links"};
    app.add_option("--scenario", opt.scenario, "convergence, bandwidth, scale or all")
        ->check(CLI::IsMember({"all", "convergence", "bandwidth", "scale"}));
    app.add_option("--json", opt.json, "write the records to this file");
    app.add_option("--markdown", opt.markdown, "write the table to this file");
    app.add_flag("--small", opt.small,
                 "tiny sizes and short runs (the smoke test); explicit sizes still apply");

    app.add_option("--arena", opt.arena,
                   "convergence: the scene: walls (bodies thrown and bouncing in a walled arena, each client "
                   "driving a box by script) or cubes (Fiedler's grid of cubes, --grid wide, each client "
                   "steering a large cube through it)")
        ->check(CLI::IsMember({"walls", "cubes"}));
    app.add_option("--repeat", opt.repeat,
                   "convergence: runs, each with its own link seeds (the table: medians)")
        ->check(CLI::PositiveNumber);
    app.add_option("--clients", opt.clients, "convergence: clients, each driving a box")
        ->check(CLI::PositiveNumber);
    app.add_option("--bodies", opt.bodies,
                   "convergence: thrown and bouncing bodies besides the driven boxes");
    app.add_option("--seconds", opt.seconds, "convergence: simulated seconds per run (the first is left out)")
        ->check(CLI::PositiveNumber);
    app.add_option("--latency", opt.latency, "one-way latency in seconds (every scenario)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--jitter", opt.jitter, "convergence: each delay uniform in latency ± jitter, seconds")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--loss", opt.loss, "convergence: probability that a packet is lost")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--duplication", opt.duplication, "convergence: probability that a packet arrives twice")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--reordering", opt.reordering, "convergence: probability that a packet is held back")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--client-snapshot-rate", opt.client_snapshot_rate,
                   "convergence: snapshots of inputs each client sends per second (default: the library's)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--seed", opt.seed, "seed of the links' generators");

    app.add_option("--grid", opt.grid,
                   "bandwidth and the convergence's cube grid: small cubes per side of the grid (30: the "
                   "article's 900)")
        ->check(CLI::PositiveNumber);
    app.add_option("--snapshot-rate", opt.snapshot_rate, "bandwidth: snapshots per second to the client")
        ->check(CLI::PositiveNumber);
    app.add_option("--moving-seconds", opt.moving_seconds, "bandwidth: seconds the client drives its cube")
        ->check(CLI::PositiveNumber);
    app.add_option("--rest-seconds", opt.rest_seconds, "bandwidth: seconds measured once everything sleeps")
        ->check(CLI::PositiveNumber);

    app.add_option("--scale-clients", opt.scale_clients, "scale: clients")->check(CLI::PositiveNumber);
    app.add_option("--scale-real-clients", opt.scale_real_clients,
                   "scale: how many of them are real client registries (the rest only receive bytes)");
    app.add_option("--scale-bodies", opt.scale_bodies, "scale: bodies")->check(CLI::PositiveNumber);
    app.add_option("--scale-snapshot-rate", opt.scale_snapshot_rate,
                   "scale: snapshots per second to each client")
        ->check(CLI::PositiveNumber);
    app.add_option("--scale-seconds", opt.scale_seconds,
                   "scale: simulated seconds (the first half second is left out)")
        ->check(CLI::PositiveNumber);
    app.add_flag("--scale-rest", opt.scale_rest,
                 "scale: spheres with rolling and spinning friction, so that the world comes to rest (the "
                 "costs at rest "
                 "are then reported apart)");
    CLI11_PARSE(app, argc, argv);
    if (opt.small) edyn_netbench::apply_small_sizes(opt, app);
    try {
        return edyn_netbench::run(opt);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
