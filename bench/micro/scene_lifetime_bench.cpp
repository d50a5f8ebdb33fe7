#include <benchmark/benchmark.h>
#include <edyn/edyn.hpp>
#include <vector>

// Building and clearing a scene: n bodies joined in a ring by n point constraints, made and
// then destroyed body by body (each taking its constraints with it). Should grow linearly.

namespace {

void build_and_destroy_ring(benchmark::State &state) {
    auto n = static_cast<int>(state.range(0));
    for (auto _ : state) {
        edyn::registry reg;
        edyn::attach(reg, edyn::init_config{edyn::execution_mode::sequential});
        std::vector<edyn::entity> bodies;
        for (int i = 0; i < n; ++i) {
            edyn::rigidbody_def def;
            def.shape = edyn::sphere_shape{edyn::scalar(0.1)};
            def.position = {edyn::scalar(i), 0, 0};
            bodies.push_back(edyn::make_rigidbody(reg, def));
        }
        for (int i = 0; i < n; ++i)
            edyn::make_constraint<edyn::point_constraint>(reg, bodies[i], bodies[(i + 1) % n]);
        for (auto e : bodies)
            reg.destroy(e);
        benchmark::DoNotOptimize(reg.view<edyn::point_constraint>().size());
        edyn::detach(reg);
    }
    state.SetItemsProcessed(state.iterations() * n);
}

} // namespace

BENCHMARK(build_and_destroy_ring)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
