#include "edyn/ecs/registry.hpp"
#include <benchmark/benchmark.h>
#include <cstdint>
#include <vector>

// Micro-benchmarks of the ecs layer. Each reports items_per_second over one million entities.

namespace {

constexpr std::int64_t entity_count = 1'000'000;

struct bench_position {
    float x, y, z;
};

struct bench_velocity {
    float x, y, z;
};

struct bench_mass {
    float value;
};

void ecs_create(benchmark::State &state) {
    for (auto _ : state) {
        edyn::registry reg;
        for (std::int64_t i = 0; i < entity_count; ++i) {
            benchmark::DoNotOptimize(reg.create());
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * entity_count);
}
BENCHMARK(ecs_create)->Unit(benchmark::kMillisecond);

void ecs_create_destroy(benchmark::State &state) {
    std::vector<edyn::entity> entities(entity_count);
    for (auto _ : state) {
        edyn::registry reg;
        for (auto &e : entities) {
            e = reg.create();
        }
        for (auto e : entities) {
            reg.destroy(e);
        }
        benchmark::DoNotOptimize(reg.alive());
    }
    state.SetItemsProcessed(state.iterations() * entity_count);
}
BENCHMARK(ecs_create_destroy)->Unit(benchmark::kMillisecond);

void ecs_emplace(benchmark::State &state) {
    std::vector<edyn::entity> entities(entity_count);
    for (auto _ : state) {
        state.PauseTiming();
        {
            edyn::registry reg;
            for (auto &e : entities) {
                e = reg.create();
            }
            state.ResumeTiming();
            for (auto e : entities) {
                reg.emplace<bench_position>(e, 1.f, 2.f, 3.f);
            }
            benchmark::ClobberMemory();
            state.PauseTiming();
        }
        state.ResumeTiming();
    }
    state.SetItemsProcessed(state.iterations() * entity_count);
}
BENCHMARK(ecs_emplace)->Unit(benchmark::kMillisecond);

// One million entities with all three components.
edyn::registry make_populated() {
    edyn::registry reg;
    for (std::int64_t i = 0; i < entity_count; ++i) {
        const auto e = reg.create();
        reg.emplace<bench_position>(e, float(i), 0.f, 0.f);
        reg.emplace<bench_velocity>(e, 1.f, 0.f, 0.f);
        reg.emplace<bench_mass>(e, 2.f);
    }
    return reg;
}

void ecs_view_1(benchmark::State &state) {
    auto reg = make_populated();
    for (auto _ : state) {
        float sum = 0;
        reg.view<bench_position>().each([&](const bench_position &p) { sum += p.x; });
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * entity_count);
}
BENCHMARK(ecs_view_1)->Unit(benchmark::kMillisecond);

void ecs_view_2(benchmark::State &state) {
    auto reg = make_populated();
    for (auto _ : state) {
        float sum = 0;
        reg.view<bench_position, bench_velocity>().each(
            [&](const bench_position &p, const bench_velocity &v) { sum += p.x + v.x; });
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * entity_count);
}
BENCHMARK(ecs_view_2)->Unit(benchmark::kMillisecond);

void ecs_view_3(benchmark::State &state) {
    auto reg = make_populated();
    for (auto _ : state) {
        float sum = 0;
        reg.view<bench_position, bench_velocity, bench_mass>().each(
            [&](const bench_position &p, const bench_velocity &v, const bench_mass &m) {
                sum += p.x + v.x * m.value;
            });
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * entity_count);
}
BENCHMARK(ecs_view_3)->Unit(benchmark::kMillisecond);

// The same as ecs_view_2 through range-for and view.get, for comparison with `each`.
void ecs_view_2_range_for(benchmark::State &state) {
    auto reg = make_populated();
    for (auto _ : state) {
        float sum = 0;
        auto view = reg.view<bench_position, bench_velocity>();
        for (auto e : view) {
            auto [p, v] = view.get<bench_position, bench_velocity>(e);
            sum += p.x + v.x;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * entity_count);
}
BENCHMARK(ecs_view_2_range_for)->Unit(benchmark::kMillisecond);

} // namespace
