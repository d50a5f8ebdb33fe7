#ifndef EDYN_BENCH_MICRO_COLLIDE_BENCH_SUPPORT_HPP
#define EDYN_BENCH_MICRO_COLLIDE_BENCH_SUPPORT_HPP

#include "edyn/collision/collide.hpp"
#include <benchmark/benchmark.h>
#include <random>
#include <span>
#include <vector>

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

// 64 placements of B about A, both turned at random, B's centre in a random direction at
// `min_offset` to `max_offset` times `reach` from A's: from overlapping to just apart when
// `reach` is about the sum of the shapes' bounding radii.
inline std::vector<collision_context> random_placements(scalar reach, scalar min_offset, scalar max_offset,
                                                        unsigned seed = 5) {
    std::mt19937 rng(seed);
    std::normal_distribution<scalar> g(0, 1);
    std::uniform_real_distribution<scalar> offset(min_offset, max_offset);
    std::vector<collision_context> out;
    for (int i = 0; i < 64; ++i) {
        auto orn_a = normalize(quaternion{g(rng), g(rng), g(rng), g(rng)});
        auto orn_b = normalize(quaternion{g(rng), g(rng), g(rng), g(rng)});
        auto dir = normalize(vector3{g(rng), g(rng), g(rng)});
        out.push_back({dir * (offset(rng) * reach), orn_a, vector3_zero, orn_b, scalar(0.02)});
    }
    return out;
}

// Times collide(a, b) over random_placements(reach, min_offset, max_offset).
template<typename A, typename B>
void run_collide_random(benchmark::State &state, const A &a, const B &b, scalar reach, scalar min_offset,
                        scalar max_offset) {
    auto placements = random_placements(reach, min_offset, max_offset);
    run_collide(state, a, b, std::span<const collision_context>(placements));
}

} // namespace edyn::bench

#endif // EDYN_BENCH_MICRO_COLLIDE_BENCH_SUPPORT_HPP
