#ifndef EDYN_BENCH_MICRO_COLLIDE_BENCH_SUPPORT_HPP
#define EDYN_BENCH_MICRO_COLLIDE_BENCH_SUPPORT_HPP

#include "edyn/collision/collide.hpp"
#include <benchmark/benchmark.h>
#include <span>

namespace edyn::bench {

// Times collide(a, b) over the given placements in turn (one placement: the same call every
// time) and reports the average number of points as the counter "points".
template<typename A, typename B>
void run_collide(benchmark::State &state, const A &a, const B &b,
                 std::span<const collision_context> contexts) {
    std::size_t i = 0, points = 0;
    for (auto _ : state) {
        collision_result result;
        collide(a, b, contexts[i], result);
        points += result.num_points;
        benchmark::DoNotOptimize(result);
        if (++i == contexts.size()) i = 0;
    }
    state.counters["points"] = benchmark::Counter(double(points), benchmark::Counter::kAvgIterations);
}

template<typename A, typename B>
void run_collide(benchmark::State &state, const A &a, const B &b, const collision_context &ctx) {
    run_collide(state, a, b, std::span<const collision_context>(&ctx, 1));
}

} // namespace edyn::bench

#endif // EDYN_BENCH_MICRO_COLLIDE_BENCH_SUPPORT_HPP
