#include "edyn/collision/broadphase.hpp"
#include "edyn/collision/dynamic_tree.hpp"
#include "edyn/ecs/registry.hpp"
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using edyn::AABB;
using edyn::scalar;
using edyn::vector3;

// Boxes of half-size 0.25 to 0.5 m spread over a cube sized so that each one has a few
// neighbours, like a large pile of debris.
struct scene_boxes {
    std::vector<AABB> boxes;
    scalar side;

    scene_boxes(std::size_t count, unsigned seed)
        : side(std::cbrt(scalar(count) * scalar(2))) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<scalar> pos(0, side), half(scalar(0.25), scalar(0.5));
        boxes.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            auto c = vector3{pos(rng), pos(rng), pos(rng)};
            auto h = vector3{half(rng), half(rng), half(rng)};
            boxes.push_back({c - h, c + h});
        }
    }
};

// Random per-step displacements of up to 2 cm per axis (a body at about 1 m/s at 60 Hz),
// precomputed so that generating them is not what gets measured.
std::vector<vector3> random_offsets(std::size_t count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<scalar> d(scalar(-0.02), scalar(0.02));
    std::vector<vector3> out(count);
    for (auto &v : out)
        v = {d(rng), d(rng), d(rng)};
    return out;
}

void broadphase_update(benchmark::State &state) {
    auto count = static_cast<std::size_t>(state.range(0));
    scene_boxes scene(count, 7);
    auto offsets = random_offsets(4099, 11);
    edyn::registry registry;
    edyn::broadphase bp;
    std::vector<edyn::entity> bodies;
    bodies.reserve(count);

    for (auto &box : scene.boxes) {
        auto e = registry.create();
        registry.emplace<AABB>(e, box);
        bp.insert(e, box, false);
        bodies.push_back(e);
    }
    bp.update(registry);

    std::size_t step = 0;
    for (auto _ : state) {
        state.PauseTiming();
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            auto &box = registry.get<AABB>(bodies[i]);
            auto d = offsets[(i + step * 31) % offsets.size()];
            box = {box.min + d, box.max + d};
        }
        ++step;
        state.ResumeTiming();

        bp.update(registry);
    }

    state.counters["manifolds"] = static_cast<double>(bp.num_manifolds());
    state.counters["tree_height"] = bp.get_dynamic_tree().height();
}

void dynamic_tree_query(benchmark::State &state) {
    auto count = static_cast<std::size_t>(state.range(0));
    scene_boxes scene(count, 3);
    edyn::dynamic_tree tree;
    for (std::size_t i = 0; i < count; ++i) {
        tree.create(scene.boxes[i], edyn::make_entity(static_cast<std::uint32_t>(i), 0));
    }

    scene_boxes queries(1024, 5);
    std::size_t next = 0;
    std::size_t hits = 0;
    for (auto _ : state) {
        tree.query(queries.boxes[next++ % queries.boxes.size()],
                   [&](edyn::dynamic_tree::node_id) { ++hits; });
    }
    benchmark::DoNotOptimize(hits);
    state.counters["hits_per_query"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
    state.counters["tree_height"] = tree.height();
}

void dynamic_tree_raycast(benchmark::State &state) {
    auto count = static_cast<std::size_t>(state.range(0));
    scene_boxes scene(count, 3);
    edyn::dynamic_tree tree;
    for (std::size_t i = 0; i < count; ++i) {
        tree.create(scene.boxes[i], edyn::make_entity(static_cast<std::uint32_t>(i), 0));
    }

    // Rays 10 m long from random points.
    std::mt19937 rng(9);
    std::uniform_real_distribution<scalar> pos(0, scene.side), dir(-1, 1);
    std::vector<std::pair<vector3, vector3>> rays(1024);
    for (auto &[p0, p1] : rays) {
        p0 = {pos(rng), pos(rng), pos(rng)};
        auto d = vector3{dir(rng), dir(rng), dir(rng)};
        if (!edyn::try_normalize(d)) d = edyn::vector3_x;
        p1 = p0 + d * scalar(10);
    }

    std::size_t next = 0;
    std::size_t hits = 0;
    for (auto _ : state) {
        auto &[p0, p1] = rays[next++ % rays.size()];
        tree.raycast(p0, p1, [&](edyn::dynamic_tree::node_id) { ++hits; });
    }
    benchmark::DoNotOptimize(hits);
    state.counters["hits_per_ray"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}

void dynamic_tree_create(benchmark::State &state) {
    auto count = static_cast<std::size_t>(state.range(0));
    scene_boxes scene(count, 3);
    for (auto _ : state) {
        edyn::dynamic_tree tree;
        for (std::size_t i = 0; i < count; ++i) {
            tree.create(scene.boxes[i], edyn::make_entity(static_cast<std::uint32_t>(i), 0));
        }
        benchmark::DoNotOptimize(tree.height());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

} // namespace

BENCHMARK(broadphase_update)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(dynamic_tree_query)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(dynamic_tree_raycast)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(dynamic_tree_create)->Arg(100000)->Unit(benchmark::kMillisecond);
