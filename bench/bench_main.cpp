// edyn-bench: runs the standard scenes with edyn and with Bullet, one engine after the other,
// and prints a markdown table of ms/step, peak memory, contacts, stability and the edyn/Bullet
// ratio; --json writes the records. Each (scene, engine) runs in a forked child process so that
// its peak memory is its own and a crash in one engine does not hide the other's figures.
#include "bench.hpp"
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace edyn_bench {
namespace {

struct options {
    std::string scene{"all"};
    std::vector<std::string> bodies{"standard"};
    unsigned steps{0};
    int warmup{-1};
    unsigned threads{1};
    unsigned min_parallel_bodies{edyn::init_config::default_min_parallel_bodies};
    std::string engine{"both"};
    std::string json;
    std::string markdown;
    bool no_fork{false};
    bool sleeping{false};
    bool machine_ceiling{false};
    unsigned repeat{1};
    std::string mode{"sequential"};
};

// Sizes of the standard set and of the quick set CTest runs.
std::vector<unsigned> sizes_for(const std::string &scene, const std::string &set) {
    if (set == "small") {
        if (scene == "pyramid") return {4};
        if (scene == "chain") return {10};
        if (scene == "ragdolls") return {2};
        if (scene == "mesh") return {16};
        return {64};
    }
    if (scene == "pyramid") return {20, 40, 100};
    // The chain: a hundred links is long enough for the error to build up along it.
    if (scene == "chain") return {100};
    if (scene == "ragdolls") return {64};
    // The mesh scene: about 1,800 bodies on a 20,000-triangle terrain, two layers of 900.
    if (scene == "mesh") return {1800};
    return {1024, 4096, 16384};
}

// Past these sizes a run is no longer a few minutes, or the chain no longer a chain in float
// precision (its far end would be kilometres from the anchor).
unsigned max_size(const std::string &scene) {
    if (scene == "pyramid") return 200;
    if (scene == "chain") return 2000;
    if (scene == "ragdolls") return 1024;
    if (scene == "mesh") return 16384;
    return 65536;
}

// Steps of the standard set. 10 s for the pyramids, so that the top box's displacement is the
// issue's figure, and for the chain. 8 s for every pile, so that all of them have landed (see
// default_warmup) and the whole run stays within a few minutes on two cores.
// The mesh scene's two layers have landed after about 1.5 s; 6 s lets them roll into the
// terrain's hollows and settle.
unsigned default_steps(const std::string &scene) {
    if (scene == "pile") return 480;
    if (scene == "mesh") return 360;
    return 600;
}

// Steps left out of the timings. The piles' layers are dropped from 2 m up, 3.3 m apart: the
// 16,384-body pile's top layer starts 210 m up and reaches the heap after about 6.5 s, the
// 4,096-body pile's after 3.2 s, the 1,024-body pile's after 1.6 s. Timed from the start, the
// large pile would be measured while most of its bodies fall freely, touching nothing, and its
// figure would say little about the cost of 16,384 bodies. So every pile is timed over the
// same last eighth of its run, the 60 steps from 7 s to 8 s by default, when every pile lies
// on the ground as a heap with all its contacts. A window of the same length at the same time
// (rather than one starting a fixed delay after each pile lands) keeps the measured steps the
// same; the smaller piles spend more of the run at rest before it, which costs little. Their
// heaps still differ in height and the largest is still slumping, so the growth exponents
// include that: the largest pile is the least settled of the three.
// The mesh scene is timed as the piles are, over its last 60 steps (5 s to 6 s by default), when
// every body lies on the terrain with all its contacts.
// Other scenes leave out a tenth, at most 60 steps: the start-up only.
unsigned default_warmup(const std::string &scene, unsigned steps) {
    if (scene == "pile") return steps - steps / 8;
    if (scene == "mesh") return steps - steps / 6;
    return std::min(60u, steps / 10);
}

std::vector<scene_spec> make_specs(const options &opt) {
    std::vector<std::string> scenes;
    if (opt.scene == "all") {
        scenes = available_scenes();
    } else {
        scenes = {opt.scene};
    }
    std::vector<scene_spec> specs;
    for (const auto &scene : scenes) {
        std::vector<unsigned> sizes;
        for (const auto &b : opt.bodies) {
            if (b == "standard" || b == "small") {
                auto set = sizes_for(scene, b);
                sizes.insert(sizes.end(), set.begin(), set.end());
            } else {
                sizes.push_back(static_cast<unsigned>(std::stoul(b)));
            }
        }
        for (auto size : sizes) {
            if (size > max_size(scene)) {
                throw std::invalid_argument("edyn-bench: --bodies " + std::to_string(size) +
                                            " is more than the " + scene + " scene takes (" +
                                            std::to_string(max_size(scene)) + ")");
            }
            scene_spec spec;
            spec.scene = scene;
            spec.threads = opt.threads;
            spec.min_parallel_bodies = opt.min_parallel_bodies;
            spec.size = size;
            spec.sleeping = opt.sleeping;
            spec.steps = opt.steps > 0 ? opt.steps : default_steps(scene);
            spec.warmup =
                opt.warmup >= 0 ? static_cast<unsigned>(opt.warmup) : default_warmup(scene, spec.steps);
            specs.push_back(spec);
        }
    }
    return specs;
}

run_result run_engine(const scene_spec &spec, const std::string &engine) {
    run_result result;
    try {
        reset_peak_rss();
        result = engine == "edyn" ? run_edyn(spec) : run_bullet(spec);
        result.peak_rss_mb = peak_rss_mb();
    } catch (const std::exception &e) {
        result.scene = spec.scene;
        result.engine = engine;
        result.ok = false;
        result.error = e.what();
    }
    return result;
}

// Fields cross the pipe one per line, in this order.
std::string serialize(const run_result &r) {
    std::ostringstream out;
    out.precision(17);
    auto error = r.error;
    std::replace(error.begin(), error.end(), '\n', ' ');
    out << r.ok << '\n'
        << r.bodies << '\n'
        << r.threads << '\n'
        << r.steps << '\n'
        << r.measured << '\n'
        << r.median_ms << '\n'
        << r.p95_ms << '\n'
        << r.peak_rss_mb << '\n'
        << r.contacts << '\n'
        << r.stability << '\n'
        << r.stability_metric << '\n'
        << error << '\n';
    return out.str();
}

run_result deserialize(const std::string &text, const scene_spec &spec, const std::string &engine) {
    run_result r;
    r.scene = spec.scene;
    r.engine = engine;
    std::istringstream in(text);
    in >> r.ok >> r.bodies >> r.threads >> r.steps >> r.measured >> r.median_ms >> r.p95_ms >>
        r.peak_rss_mb >> r.contacts >> r.stability;
    in.ignore(1);
    std::getline(in, r.stability_metric);
    std::getline(in, r.error);
    if (!in && !r.ok && r.error.empty()) r.error = "the child process sent no result";
    return r;
}

run_result run_forked(const scene_spec &spec, const std::string &engine) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error(std::string("edyn-bench: pipe: ") + std::strerror(errno));
    std::fflush(stdout);
    std::fflush(stderr);
    auto pid = fork();
    if (pid < 0) throw std::runtime_error(std::string("edyn-bench: fork: ") + std::strerror(errno));
    if (pid == 0) {
        close(fds[0]);
        auto text = serialize(run_engine(spec, engine));
        std::size_t written = 0;
        while (written < text.size()) {
            auto n = write(fds[1], text.data() + written, text.size() - written);
            if (n <= 0) _exit(3);
            written += static_cast<std::size_t>(n);
        }
        close(fds[1]);
        _exit(0);
    }
    close(fds[1]);
    std::string text;
    char buffer[4096];
    ssize_t n;
    while ((n = read(fds[0], buffer, sizeof buffer)) > 0)
        text.append(buffer, static_cast<std::size_t>(n));
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    auto result = deserialize(text, spec, engine);
    if (WIFSIGNALED(status)) {
        result.ok = false;
        result.error = std::string("killed by signal ") + std::to_string(WTERMSIG(status));
    }
    return result;
}

// --mode async: edyn alone, in real time (see async_runner.cpp); with --repeat, the run whose
// update() median is lowest is kept.
int run_async(const options &opt) {
    std::vector<async_result> results;
    for (const auto &spec : make_specs(opt)) {
        async_result best;
        for (unsigned repetition = 0; repetition < opt.repeat; ++repetition) {
            std::fprintf(stderr, "edyn-bench: %s %u, edyn asynchronous, %u frames of real time ... ",
                         spec.scene.c_str(), spec.size, spec.steps);
            std::fflush(stderr);
            auto r = run_edyn_async(spec);
            std::fprintf(stderr, "update() median %.3f ms, p99 %.3f ms; worker %.3f ms/step, %.1f steps/s\n",
                         r.update_median_ms, r.update_p99_ms, r.worker_median_ms, r.steps_per_second);
            if (repetition == 0 || r.update_median_ms < best.update_median_ms) best = std::move(r);
        }
        results.push_back(std::move(best));
    }
    auto table = async_table(results);
    std::printf("%s", table.c_str());
    if (!opt.markdown.empty()) {
        auto *file = std::fopen(opt.markdown.c_str(), "w");
        if (!file) throw std::runtime_error("edyn-bench: cannot write " + opt.markdown);
        std::fputs(table.c_str(), file);
        std::fclose(file);
    }
    return 0;
}

// --machine-ceiling: no scene, only what this machine gives to 2, 4, 8... threads of independent
// work, up to --threads.
int run_machine_ceiling(const options &opt) {
    if (opt.threads < 2)
        throw std::invalid_argument("edyn-bench: --machine-ceiling needs --threads of at least 2");
    std::vector<unsigned> counts;
    for (unsigned threads = 2; threads < opt.threads; threads *= 2)
        counts.push_back(threads);
    counts.push_back(opt.threads);
    std::fprintf(stderr, "edyn-bench: independent work on %u threads against one ...\n", opt.threads);
    auto table = ceiling_table(machine_ceiling(counts));
    std::printf("%s", table.c_str());
    return 0;
}

int run(const options &opt) {
    if (opt.threads == 0) throw std::invalid_argument("edyn-bench: --threads must be at least 1");
    if (opt.machine_ceiling) return run_machine_ceiling(opt);
    if (opt.mode == "async") {
        if (opt.threads > 1 || opt.engine == "bullet" || !opt.json.empty())
            throw std::invalid_argument("edyn-bench: --mode async runs edyn alone, on its worker thread "
                                        "(no --threads, --engine bullet or --json)");
        return run_async(opt);
    }
    if (opt.threads > 1) {
        std::fprintf(stderr,
                     "edyn-bench: edyn on %u threads (sequential_multithreaded); the Bullet peer, "
                     "btDiscreteDynamicsWorld, on one\n",
                     opt.threads);
    }
    std::vector<std::string> engines;
    if (opt.engine == "edyn" || opt.engine == "both") engines.push_back("edyn");
    if (opt.engine == "bullet" || opt.engine == "both") engines.push_back("bullet");

    std::vector<run_result> results;
    bool failed = false;
    for (const auto &spec : make_specs(opt)) {
        // With --repeat, the engines take turns so that both see the same load on a shared
        // machine, and each keeps its run with the lowest median: the least disturbed one.
        std::vector<run_result> best(engines.size());
        for (unsigned repetition = 0; repetition < opt.repeat; ++repetition) {
            for (std::size_t i = 0; i < engines.size(); ++i) {
                const auto &engine = engines[i];
                std::fprintf(stderr, "edyn-bench: %s %u, %s, %u steps ... ", spec.scene.c_str(), spec.size,
                             engine.c_str(), spec.steps);
                std::fflush(stderr);
                auto r = opt.no_fork ? run_engine(spec, engine) : run_forked(spec, engine);
                r.threads = engine == "edyn" ? spec.threads : 1;
                if (r.ok) {
                    std::fprintf(stderr, "%u bodies, median %.3f ms/step, p95 %.3f, %.1f MB, %zu contacts\n",
                                 r.bodies, r.median_ms, r.p95_ms, r.peak_rss_mb, r.contacts);
                } else {
                    std::fprintf(stderr, "failed: %s\n", r.error.c_str());
                    failed = true;
                }
                bool first = repetition == 0;
                if (first || (best[i].ok && (!r.ok || r.median_ms < best[i].median_ms)))
                    best[i] = std::move(r);
            }
        }
        for (auto &r : best)
            results.push_back(std::move(r));
    }

    auto table = markdown_table(results);
    std::printf("%s", table.c_str());
    if (!opt.json.empty()) write_json(opt.json, results);
    if (!opt.markdown.empty()) {
        auto *file = std::fopen(opt.markdown.c_str(), "w");
        if (!file) throw std::runtime_error("edyn-bench: cannot write " + opt.markdown);
        std::fputs(table.c_str(), file);
        std::fclose(file);
    }
    return failed ? 1 : 0;
}

} // namespace
} // namespace edyn_bench

int main(int argc, char **argv) {
    edyn_bench::options opt;
    CLI::App app{"edyn-bench: the standard scenes in edyn and in Bullet, side by side"};
    app.add_option("--scene", opt.scene, "pyramid, pile, chain, ragdolls, mesh or all")
        ->check(CLI::IsMember({"all", "pyramid", "pile", "chain", "ragdolls", "mesh"}));
    app.add_option("--bodies", opt.bodies,
                   "sizes: the pyramid's base width, the pile's or the mesh scene's body count, the chain's "
                   "links or the rag doll count; 'standard' (pyramid 20 40 100, pile 1024 4096 16384, chain "
                   "100, ragdolls 64, mesh 1800) or 'small' (a quick check)")
        ->check(CLI::IsMember({"standard", "small"}) | CLI::PositiveNumber);
    app.add_option("--steps", opt.steps, "steps per run, warm-up included (0: each scene's default)");
    app.add_option("--warmup", opt.warmup,
                   "steps left out of the timings (default: the piles' first seven eighths, the mesh "
                   "scene's first five sixths; other scenes' first tenth, at most 60)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--threads", opt.threads,
                   "threads edyn runs on (sequential_multithreaded above 1); Bullet runs on one")
        ->check(CLI::PositiveNumber);
    app.add_option("--min-parallel-bodies", opt.min_parallel_bodies,
                   "with --threads above 1: the fewest moving bodies for a step to use the threads "
                   "(init_config::min_parallel_bodies; 0: every step)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--engine", opt.engine, "edyn, bullet or both")
        ->check(CLI::IsMember({"edyn", "bullet", "both"}));
    app.add_option("--json", opt.json, "write the records to this file");
    app.add_option("--markdown", opt.markdown, "write the table to this file");
    app.add_option("--repeat", opt.repeat,
                   "runs of each scene and engine, taking turns; the one with the lowest median is kept")
        ->check(CLI::PositiveNumber);
    app.add_option("--mode", opt.mode,
                   "sequential (default: step_simulation timed, beside Bullet) or async (a 60 Hz game loop "
                   "in real time: the main thread's time in update() and the worker's per step)")
        ->check(CLI::IsMember({"sequential", "async"}));
    app.add_flag("--sleeping", opt.sleeping,
                 "let bodies at rest sleep in both engines (off: the figures are the cost of simulating)");
    app.add_flag("--machine-ceiling", opt.machine_ceiling,
                 "instead of the scenes: the speed-up that 2, 4, 8... threads (up to --threads) of "
                 "independent arithmetic, memory-latency and memory-bandwidth work get on this machine");
    app.add_flag("--no-fork", opt.no_fork,
                 "run everything in this process (for profilers; peak memory is then the process's)");
    CLI11_PARSE(app, argc, argv);
    try {
        return edyn_bench::run(opt);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
