#include "bench.hpp"
#include <algorithm>
#include <cmath>
#include <edyn_scenes/scenes.hpp>
#include <stdexcept>

namespace edyn_bench {

std::vector<std::string> available_scenes() { return {"pyramid", "pile", "chain", "ragdolls", "mesh"}; }

std::string stability_metric(const std::string &scene) {
    if (scene == "pyramid") return "top_box_displacement_m";
    if (scene == "pile") return "max_penetration_m";
    if (scene == "chain" || scene == "ragdolls") return "max_joint_error_m";
    if (scene == "mesh") return "bodies_below_terrain";
    throw std::invalid_argument("stability_metric: unknown scene '" + scene + "'");
}

bool tracks_joint_error(const std::string &scene) { return scene == "chain" || scene == "ragdolls"; }

namespace {

// The mesh scene's terrain: the scene builder's default, 100 x 100 cells of 1.25 m, 20,000
// triangles, 125 m across.
const edyn::scenes::mesh_pile_terrain mesh_terrain{};

edyn::entity build_bodies(edyn::registry &registry, const scene_spec &spec) {
    if (spec.scene == "chain") {
        // A joint test only: the chain swings down from horizontal in empty space, with no
        // ground to land on, so that the solver's joint error is the whole of its stability
        // figure. The anchor sits at the origin, where floats are finest along the chain.
        edyn::scenes::make_chain(registry, spec.size, edyn::scalar(0.5), edyn::vector3_zero);
        return edyn::null;
    }
    if (spec.scene == "mesh") {
        // The terrain instead of a ground plane; the bodies 30 wide (900 to a layer, 64 m across
        // the 125 m terrain, so that what rolls down its slopes for the few seconds of the run
        // stays on it), fewer make a smaller square.
        auto width = std::min(30u, static_cast<unsigned>(std::ceil(std::sqrt(double(spec.size)))));
        edyn::scenes::make_mesh_pile(registry, spec.size, width, 2, mesh_terrain, 1);
        return edyn::null;
    }
    // Both engines get the ground's defaults from the scene builder: friction 0.6, no bounce.
    edyn::scenes::make_ground(registry);
    if (spec.scene == "pyramid") {
        auto boxes = edyn::scenes::make_pyramid(registry, spec.size);
        return boxes.empty() ? edyn::null : boxes.back();
    }
    if (spec.scene == "pile") {
        // The pile: boxes, spheres, capsules and cylinders in equal share, 16 wide.
        edyn::scenes::make_pile(registry, spec.size, 16, 2, edyn::scenes::pile_shapes::primitives, 1);
        return edyn::null;
    }
    if (spec.scene == "ragdolls") {
        // The 8 by 8 rag dolls in one layer; fewer make a smaller square.
        auto columns = std::min(8u, static_cast<unsigned>(std::ceil(std::sqrt(double(spec.size)))));
        edyn::scenes::make_ragdoll_pile(registry, spec.size, columns);
        return edyn::null;
    }
    throw std::invalid_argument("build_scene: unknown scene '" + spec.scene + "'");
}

} // namespace

edyn::entity build_scene(edyn::registry &registry, const scene_spec &spec) {
    auto tracked = build_bodies(registry, spec);
    if (!spec.sleeping) {
        // What rigidbody_def::sleeping_disabled does, for bodies the shared builders made.
        for (auto e : registry.view<edyn::dynamic_tag>()) {
            registry.emplace<edyn::sleeping_disabled_tag>(e);
        }
    }
    return tracked;
}

unsigned count_below_terrain(const std::vector<edyn::vector3> &centres) {
    unsigned count = 0;
    for (const auto &c : centres) {
        auto surface = edyn::scenes::terrain_surface_height(mesh_terrain, c.x, c.z);
        // A body beyond the terrain's edge rolled off it: it did not go through.
        if (surface && c.y < *surface) ++count;
    }
    return count;
}

step_stats summarize_steps(const std::vector<double> &step_ms, unsigned warmup) {
    step_stats stats;
    if (step_ms.empty()) return stats;
    // Keep at least one step even when the warm-up asks for all of them.
    auto skip = std::min<std::size_t>(warmup, step_ms.size() - 1);
    std::vector<double> sorted(step_ms.begin() + static_cast<std::ptrdiff_t>(skip), step_ms.end());
    std::sort(sorted.begin(), sorted.end());
    auto at = [&](double q) {
        // Nearest rank: the smallest value with at least q of the samples at or below it.
        auto rank = static_cast<std::size_t>(q * static_cast<double>(sorted.size()) + 0.999999);
        rank = std::clamp<std::size_t>(rank, 1, sorted.size());
        return sorted[rank - 1];
    };
    auto n = sorted.size();
    stats.median_ms = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    stats.p95_ms = at(0.95);
    stats.measured = static_cast<unsigned>(n);
    return stats;
}

} // namespace edyn_bench
