#ifndef EDYN_BENCH_BENCH_HPP
#define EDYN_BENCH_BENCH_HPP

// edyn-bench: the standard scenes simulated by edyn and by Bullet, one engine after the other,
// with the same bodies, masses, materials and time step, so that the figures are a ratio
// measured in one run on one machine.

#include <cstddef>
#include <cstdint>
#include <edyn/edyn.hpp>
#include <string>
#include <vector>

namespace edyn_bench {

// One scene at one size. `size` is the pyramid's base width, the pile's or the mesh scene's
// body count, the chain's number of links or the number of rag dolls.
struct scene_spec {
    std::string scene;
    unsigned size{0};
    unsigned steps{0};
    unsigned warmup{0};
    // Off by default in both engines: the figures are the cost of simulating the scene, not of
    // skipping the bodies that came to rest.
    bool sleeping{false};
    // Threads edyn runs on: above 1, execution_mode::sequential_multithreaded with that many.
    // Bullet's peer, btDiscreteDynamicsWorld, always runs on one.
    unsigned threads{1};
    // With threads above 1: init_config::min_parallel_bodies, below which a step keeps to the
    // calling thread.
    unsigned min_parallel_bodies{edyn::init_config::default_min_parallel_bodies};
};

// What one engine measured on one scene.
struct run_result {
    std::string scene;
    std::string engine;
    unsigned bodies{0}; // dynamic bodies
    unsigned threads{1};
    unsigned steps{0};    // steps simulated, warm-up included
    unsigned measured{0}; // steps timed (after warm-up)
    double median_ms{0};
    double p95_ms{0};
    double peak_rss_mb{0};
    std::size_t contacts{0}; // contact points at the end
    // Pyramid: top box displacement (m) at the end; pile: deepest penetration (m) at the end;
    // chain and ragdolls: largest distance between a joint's two pivots (m) after any step,
    // warm-up included (the rag dolls land during it); mesh: bodies whose centre is below the
    // terrain's surface at the end.
    double stability{0};
    std::string stability_metric;
    bool ok{false};
    std::string error;
};

// Builds `spec` in an attached edyn registry with the shared scene builders. Returns the body
// whose displacement is the scene's stability figure (the pyramid's top box), or edyn::null.
edyn::entity build_scene(edyn::registry &registry, const scene_spec &spec);

// Name of the stability figure of a scene ("top_box_displacement_m", ...).
std::string stability_metric(const std::string &scene);

// Whether the scene's stability figure is the worst joint error over the run, which the runners
// then measure after every step (outside the timed part).
bool tracks_joint_error(const std::string &scene);

// The mesh scene's stability figure: how many of these body centres lie over the terrain and
// below its surface. 0 when no body went through.
unsigned count_below_terrain(const std::vector<edyn::vector3> &centres);

// Scenes edyn-bench knows, in the order `--scene all` runs them.
std::vector<std::string> available_scenes();

// Per-step times in milliseconds to the median and 95th percentile of the steps after warm-up.
struct step_stats {
    double median_ms{0};
    double p95_ms{0};
    unsigned measured{0};
};
step_stats summarize_steps(const std::vector<double> &step_ms, unsigned warmup);

// Runs the scene with one engine in this process and fills every field but peak_rss_mb.
run_result run_edyn(const scene_spec &spec);

// The asynchronous mode on one scene (async_runner.cpp): update() as a 60 Hz game loop calls
// it on the main thread, the worker's own step times, and the sequential run beside them.
struct async_result {
    std::string scene;
    unsigned bodies{0};
    unsigned frames{0};
    double update_median_ms{0}; // main thread, inside update(), after warm-up
    double update_p99_ms{0};
    double worker_median_ms{0}; // one step in the worker
    std::uint64_t steps_run{0};
    double steps_per_second{0}; // the worker's, over the whole run
    run_result sequential;
    bool ok{false};
};
async_result run_edyn_async(const scene_spec &spec);
std::string async_table(const std::vector<async_result> &results);
run_result run_bullet(const scene_spec &spec);

// Peak resident memory of this process in MB (VmHWM), and a reset of that peak to the current
// resident size, so that a measurement counts only what comes after it.
double peak_rss_mb();
void reset_peak_rss();

// What independent work on several threads gains over one thread on this machine: the speed-up
// of an arithmetic kernel, a memory-latency kernel and a memory-bandwidth kernel for each thread
// count, and the time a cache line takes to go from one thread to another and back
// (machine_ceiling.cpp); each kernel takes a fraction of a second.
struct ceiling_row {
    unsigned threads{1};
    double arithmetic{0};
    double memory_latency{0};
    double memory_bandwidth{0};
    double round_trip_ns{0};
};
std::vector<ceiling_row> machine_ceiling(const std::vector<unsigned> &thread_counts);
std::string ceiling_table(const std::vector<ceiling_row> &rows);

// Writes the results as a JSON list of records.
void write_json(const std::string &path, const std::vector<run_result> &results);
// A markdown table of the results with the edyn/Bullet ratios of median time.
std::string markdown_table(const std::vector<run_result> &results);

} // namespace edyn_bench

#endif // EDYN_BENCH_BENCH_HPP
