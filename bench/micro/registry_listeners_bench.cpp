#include <benchmark/benchmark.h>
#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>

// What it costs the simulation's listeners to build a jointed scene and clear it body by body.

namespace {

void chain_build_and_destroy(benchmark::State &state) {
    auto links = static_cast<unsigned>(state.range(0));
    for (auto _ : state) {
        edyn::registry registry;
        edyn::attach(registry);
        auto chain = edyn::scenes::make_chain(registry, links);
        for (auto link : chain.links)
            registry.destroy(link);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(chain_build_and_destroy)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

} // namespace
