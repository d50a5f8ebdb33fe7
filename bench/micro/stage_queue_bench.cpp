#include "edyn/parallel/stage_queue.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <algorithm>
#include <benchmark/benchmark.h>
#include <cstdint>
#include <thread>
#include <vector>

// What a solver stage costs beyond its work: a run of 256 stages, each of `blocks` blocks of the
// same fixed arithmetic, on `threads` threads (the contact solver's colour passes are such a run,
// 300 to 900 stages a step). A stage's time is the inverse of items_per_second. Compare a row
// with the one-thread row of the same blocks and work: on T threads a stage of B blocks can take
// no less than ceil(B / T) blocks' time (a block's time is the one-thread stage's over B), and
// what it takes beyond that is the hand-over between stages.
namespace {

constexpr std::uint32_t stages_per_run = 256;

// A block's work: a chain of multiply-adds on the block's own cache line, `steps` long.
struct alignas(64) block_state {
    float value{1};
};

void run_stages(benchmark::State &state) {
    auto threads = static_cast<unsigned>(state.range(0));
    auto blocks = static_cast<std::uint32_t>(state.range(1));
    auto steps = static_cast<std::uint32_t>(state.range(2));
    edyn::task_scheduler scheduler(threads);
    edyn::stage_queue queue;
    std::vector<block_state> work(blocks);
    auto *data = work.data();
    for (auto _ : state) {
        for (std::uint32_t s = 0; s < stages_per_run; ++s) {
            queue.add(blocks, [data, steps](std::uint32_t b) {
                auto v = data[b].value;
                for (std::uint32_t i = 0; i < steps; ++i)
                    v = v * 0.999999f + 1e-7f;
                data[b].value = v;
            });
        }
        queue.run(&scheduler); // with one thread, on this one
        benchmark::DoNotOptimize(data[0].value);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * stages_per_run);
}

// Threads, up to the machine's; blocks a stage (a small colour, one a thread, a large colour);
// work a block (one to a few bundles of contacts: about 0.06, 0.6 and 3 µs on the 2-core machine
// of the performance guide).
void stage_arguments(benchmark::internal::Benchmark *b) {
    auto cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    for (auto threads : {1, 2, 4, 8, 16}) {
        if (threads > cores) break;
        for (auto blocks : {1, 2, 8})
            for (auto steps : {25, 250, 1250})
                b->Args({threads, blocks, steps});
    }
}

} // namespace

BENCHMARK(run_stages)->Apply(stage_arguments)->ArgNames({"threads", "blocks", "steps"})->UseRealTime();
