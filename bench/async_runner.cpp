// edyn-bench --mode async: what the asynchronous mode costs the program's thread. A game loop
// at 60 frames a second on the steady clock calls update() once a frame while the worker steps
// the scene; the figures are the main thread's time inside update() and the worker's time per
// step, beside the sequential mode's time per step on the same scene.
#include "bench.hpp"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>
#include <vector>

namespace edyn_bench {

namespace {

using clock_type = std::chrono::steady_clock;

// Written by the worker thread only, inside its step callbacks; read after detach().
clock_type::time_point step_start;
std::vector<double> worker_step_ms;

void before_step(edyn::registry &) { step_start = clock_type::now(); }
void after_step(edyn::registry &) {
    worker_step_ms.push_back(
        std::chrono::duration<double, std::milli>(clock_type::now() - step_start).count());
}

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    auto index = static_cast<std::size_t>(fraction * double(values.size() - 1) + 0.5);
    return values[std::min(index, values.size() - 1)];
}

double seconds(clock_type::time_point t) {
    return std::chrono::duration<double>(t.time_since_epoch()).count();
}

} // namespace

async_result run_edyn_async(const scene_spec &spec) {
    async_result result;
    result.scene = spec.scene;
    result.sequential = run_edyn(spec);
    result.bodies = result.sequential.bodies;

    edyn::registry registry;
    edyn::attach(registry, edyn::init_config{edyn::execution_mode::asynchronous});
    build_scene(registry, spec);
    worker_step_ms.clear();
    worker_step_ms.reserve(spec.steps * 2);
    edyn::set_pre_step_callback(registry, &before_step);
    edyn::set_post_step_callback(registry, &after_step);

    // As many frames as the scene has steps, one frame per fixed step of real time.
    auto frame = std::chrono::duration_cast<clock_type::duration>(
        std::chrono::duration<double>(double(edyn::get_fixed_dt(registry))));
    std::vector<double> update_ms;
    update_ms.reserve(spec.steps);
    auto start = clock_type::now();
    auto next = start;
    for (unsigned i = 0; i < spec.steps; ++i) {
        auto before = clock_type::now();
        edyn::update(registry, seconds(before));
        auto after = clock_type::now();
        update_ms.push_back(std::chrono::duration<double, std::milli>(after - before).count());
        next += frame;
        std::this_thread::sleep_until(next);
    }
    auto elapsed = std::chrono::duration<double>(clock_type::now() - start).count();
    auto steps_run = edyn::get_step_count(registry);
    edyn::detach(registry); // joins the worker: its figures are complete

    std::vector<double> measured(update_ms.begin() + std::min<std::size_t>(spec.warmup, update_ms.size()),
                                 update_ms.end());
    result.frames = static_cast<unsigned>(update_ms.size());
    result.update_median_ms = percentile(measured, 0.5);
    result.update_p99_ms = percentile(measured, 0.99);
    result.worker_median_ms = percentile(worker_step_ms, 0.5);
    result.steps_run = steps_run;
    result.steps_per_second = double(steps_run) / elapsed;
    result.ok = true;
    return result;
}

std::string async_table(const std::vector<async_result> &results) {
    std::ostringstream out;
    char line[512];
    out << "| scene | bodies | frames | update() median ms | update() p99 ms | worker ms/step | "
           "worker steps/s | sequential ms/step | sequential steps/s |\n";
    out << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto &r : results) {
        auto sequential_rate = r.sequential.median_ms > 0 ? 1000.0 / r.sequential.median_ms : 0.0;
        // The sequential mode cannot step faster than real time: 60 steps a second at most.
        sequential_rate = std::min(sequential_rate, 60.0);
        std::snprintf(line, sizeof line, "| %s | %u | %u | %.3f | %.3f | %.3f | %.1f | %.3f | %.1f |\n",
                      r.scene.c_str(), r.bodies, r.frames, r.update_median_ms, r.update_p99_ms,
                      r.worker_median_ms, r.steps_per_second, r.sequential.median_ms, sequential_rate);
        out << line;
    }
    return out.str();
}

} // namespace edyn_bench
