// The edyn side of edyn-bench: the scene from the shared builders, stepped with
// edyn::step_simulation one fixed step at a time.
#include "bench.hpp"
#include <algorithm>
#include <chrono>
#include <edyn_scenes/pivot_separation.hpp>

namespace edyn_bench {

namespace {

struct contact_figures {
    std::size_t points{0};
    double deepest_penetration{0};
};

contact_figures count_contacts(edyn::registry &registry) {
    contact_figures figures;
    registry.view<edyn::contact_manifold>().each([&](const edyn::contact_manifold &manifold) {
        figures.points += manifold.num_points;
        manifold.each_point([&](const edyn::contact_point &point) {
            figures.deepest_penetration = std::max(figures.deepest_penetration, -double(point.distance));
        });
    });
    return figures;
}

} // namespace

run_result run_edyn(const scene_spec &spec) {
    run_result result;
    result.scene = spec.scene;
    result.engine = "edyn";
    result.stability_metric = stability_metric(spec.scene);

    edyn::registry registry;
    edyn::init_config config;
    config.execution_mode = edyn::execution_mode::sequential;
    if (spec.threads > 1) {
        config.execution_mode = edyn::execution_mode::sequential_multithreaded;
        config.num_worker_threads = spec.threads;
        config.min_parallel_bodies = spec.min_parallel_bodies;
    }
    edyn::attach(registry, config);
    auto tracked = build_scene(registry, spec);
    result.bodies = static_cast<unsigned>(registry.storage<edyn::dynamic_tag>().size());
    edyn::vector3 tracked_start{};
    if (tracked != edyn::null) tracked_start = registry.get<edyn::position>(tracked);

    auto joints = tracks_joint_error(spec.scene);
    auto joint_error = [&] { return double(edyn::scenes::max_pivot_separation(registry)); };
    double worst_joint_error = joints ? joint_error() : 0;
    std::vector<double> step_ms;
    step_ms.reserve(spec.steps);
    for (unsigned i = 0; i < spec.steps; ++i) {
        auto start = std::chrono::steady_clock::now();
        edyn::step_simulation(registry);
        auto end = std::chrono::steady_clock::now();
        step_ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        if (joints) worst_joint_error = std::max(worst_joint_error, joint_error());
    }

    auto stats = summarize_steps(step_ms, spec.warmup);
    result.steps = spec.steps;
    result.measured = stats.measured;
    result.median_ms = stats.median_ms;
    result.p95_ms = stats.p95_ms;
    auto contacts = count_contacts(registry);
    result.contacts = contacts.points;
    if (joints) {
        result.stability = worst_joint_error;
    } else if (spec.scene == "mesh") {
        std::vector<edyn::vector3> centres;
        for (auto e : registry.view<edyn::dynamic_tag>())
            centres.push_back(registry.get<edyn::position>(e));
        result.stability = count_below_terrain(centres);
    } else if (tracked != edyn::null) {
        result.stability = double(edyn::length(registry.get<edyn::position>(tracked) - tracked_start));
    } else {
        result.stability = contacts.deepest_penetration;
    }
    edyn::detach(registry);
    result.ok = true;
    return result;
}

} // namespace edyn_bench
