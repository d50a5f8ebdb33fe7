// edyn-demo: a pyramid, a pile of mixed shapes, bouncing balls, a chain, a bridge, a pile of
// rag dolls on a floor, and mixed piles on two hilly terrains (a triangle mesh and a paged one),
// simulated for a while in fixed steps, with a progress line and a summary of what happened.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <edyn/edyn.hpp>
#include <edyn_scenes/pivot_separation.hpp>
#include <edyn_scenes/scenes.hpp>
#include <string>
#include <vector>

namespace {

struct options {
    std::string scene{"all"};
    unsigned pyramid_base{20};
    unsigned pile_count{512};
    unsigned balls{8};
    unsigned ragdolls{10};
    unsigned terrain_bodies{225};
    double seconds{10};
    bool quiet{false};
};

struct summary {
    std::size_t bodies{0};
    std::size_t manifolds{0};
    std::size_t contact_points{0};
    std::size_t islands{0};
    std::size_t sleeping_islands{0};
};

// Largest distance between the two pivots of the rag dolls' hinges and CV joints, in metres:
// how far their joints are pulled apart.
double worst_joint_separation(const edyn::registry &registry,
                              const std::vector<edyn::ragdoll_entities> &ragdolls) {
    double worst = 0;
    for (auto &ragdoll : ragdolls) {
        for (auto e : ragdoll.constraints()) {
            if (auto *hinge = registry.try_get<edyn::hinge_constraint>(e)) {
                worst = std::max(worst, double(edyn::scenes::pivot_separation(registry, *hinge)));
            } else if (auto *cv = registry.try_get<edyn::cvjoint_constraint>(e)) {
                worst = std::max(worst, double(edyn::scenes::pivot_separation(registry, *cv)));
            }
        }
    }
    return worst;
}

summary summarize(edyn::registry &registry) {
    summary s;
    s.bodies = registry.storage<edyn::rigidbody_tag>().size();
    registry.view<edyn::contact_manifold>().each([&](const edyn::contact_manifold &m) {
        ++s.manifolds;
        s.contact_points += m.num_points;
    });
    s.islands = registry.storage<edyn::island>().size();
    for (auto e : registry.view<edyn::island, edyn::sleeping_tag>()) {
        (void)e;
        ++s.sleeping_islands;
    }
    return s;
}

} // namespace

int main(int argc, char **argv) {
    options opt;
    CLI::App app{"edyn-demo: rigid bodies falling, stacking, bouncing and sleeping"};
    app.add_option("--scene", opt.scene,
                   "all, pyramid, pile, balls, chain, bridge, ragdolls, terrain or paged")
        ->check(CLI::IsMember(
            {"all", "pyramid", "pile", "balls", "chain", "bridge", "ragdolls", "terrain", "paged"}));
    app.add_option("--pyramid-base", opt.pyramid_base, "boxes in the pyramid's bottom row")
        ->check(CLI::Range(1u, 200u));
    app.add_option("--pile-count", opt.pile_count, "bodies in the pile")->check(CLI::Range(1u, 100000u));
    app.add_option("--balls", opt.balls, "bouncing balls")->check(CLI::Range(1u, 1000u));
    app.add_option("--ragdolls", opt.ragdolls, "rag dolls in their pile")->check(CLI::Range(1u, 1000u));
    app.add_option("--terrain-bodies", opt.terrain_bodies, "bodies dropped on each terrain")
        ->check(CLI::Range(1u, 100000u));
    app.add_option("--seconds", opt.seconds, "simulated time")->check(CLI::Range(0.0, 3600.0));
    app.add_flag("--quiet", opt.quiet, "no progress line");
    CLI11_PARSE(app, argc, argv);

    // Sequential: each step runs inside step_simulation() on this thread, so that the demo can
    // time it (the default asynchronous mode would only hand it to the worker).
    edyn::registry registry;
    edyn::init_config config;
    config.execution_mode = edyn::execution_mode::sequential;
    edyn::attach(registry, config);
    edyn::scenes::make_ground(registry);

    bool all = opt.scene == "all";
    edyn::entity top = edyn::null;
    edyn::vector3 top_start{};
    if (all || opt.scene == "pyramid") {
        auto boxes = edyn::scenes::make_pyramid(registry, opt.pyramid_base);
        top = boxes.back();
        top_start = registry.get<edyn::position>(top);
    }
    if (all || opt.scene == "pile") {
        edyn::scenes::make_pile(registry, opt.pile_count, 16, 2, edyn::scenes::pile_shapes::with_polyhedra,
                                1);
    }
    if (all || opt.scene == "balls") {
        // Beside the pyramid, on the far side of the pile.
        edyn::scenes::make_bouncing_balls(registry, opt.balls, 4, {-8, 0, 30});
    }
    // Joints; a handful of bodies each, cheap enough for `all`. Placed apart from the others.
    if (all || opt.scene == "chain") {
        edyn::scenes::make_chain(registry, 20, edyn::scalar(0.5), {-30, 12, -30});
    }
    if (all || opt.scene == "bridge") {
        auto bridge = edyn::scenes::make_bridge(registry, 16, edyn::scalar(0.5), 3, {30, 0, -30});
        edyn::rigidbody_def box;
        box.mass = 20;
        box.shape = edyn::box_shape{{edyn::scalar(0.3), edyn::scalar(0.3), edyn::scalar(0.3)}};
        box.position = {34, 5, -30};
        edyn::make_rigidbody(registry, box);
    }
    std::vector<edyn::ragdoll_entities> ragdolls;
    if (all || opt.scene == "ragdolls") {
        // Twenty bodies each; beyond the bridge, on the side away from the pile.
        ragdolls = edyn::scenes::make_ragdoll_pile(registry, opt.ragdolls, 2, edyn::scalar(0.5), {30, 0, 30});
    }

    // Terrains of 256 x 256 one-metre cells (131,072 triangles), raised above the ground plane,
    // each with a mixed pile dropped on it: one a mesh, one paged in pages of 2,000 triangles.
    std::vector<std::pair<const char *, edyn::scenes::mesh_pile_terrain>> terrains;
    std::vector<std::vector<edyn::entity>> terrain_bodies;
    auto add_terrain = [&](const char *name, bool paged, edyn::vector3 origin) {
        edyn::scenes::mesh_pile_terrain terrain;
        terrain.cells = 256;
        terrain.cell_size = 1;
        terrain.origin = origin;
        terrain.paged = paged;
        auto scene = edyn::scenes::make_mesh_pile(registry, opt.terrain_bodies, 15, 2, terrain);
        terrains.emplace_back(name, terrain);
        terrain_bodies.push_back(std::move(scene.bodies));
    };
    if (all || opt.scene == "terrain") add_terrain("terrain (mesh)", false, {0, 4, 300});
    if (all || opt.scene == "paged") add_terrain("terrain (paged)", true, {300, 4, 300});

    auto dt = double(edyn::get_fixed_dt(registry));
    auto steps = static_cast<std::size_t>(opt.seconds / dt + 0.5);
    std::vector<double> step_ms;
    step_ms.reserve(steps);
    double worst_separation = 0;
    std::printf("edyn-demo: %zu bodies, %zu steps of %.4f s\n",
                registry.storage<edyn::rigidbody_tag>().size(), steps, dt);

    for (std::size_t i = 0; i < steps; ++i) {
        auto start = std::chrono::steady_clock::now();
        edyn::step_simulation(registry);
        auto end = std::chrono::steady_clock::now();
        step_ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        if (!ragdolls.empty()) {
            worst_separation = std::max(worst_separation, worst_joint_separation(registry, ragdolls));
        }
        if (!opt.quiet && (i % 30 == 29 || i + 1 == steps)) {
            auto s = summarize(registry);
            std::printf("\r  t = %6.2f s  contacts %6zu  islands %5zu (%5zu asleep)  last step %7.3f ms",
                        (i + 1) * dt, s.contact_points, s.islands, s.sleeping_islands, step_ms.back());
            std::fflush(stdout);
        }
    }
    if (!opt.quiet) std::printf("\n");

    auto s = summarize(registry);
    std::vector<double> sorted = step_ms;
    std::sort(sorted.begin(), sorted.end());
    auto median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
    std::printf("summary\n");
    std::printf("  bodies            %zu\n", s.bodies);
    std::printf("  manifolds         %zu\n", s.manifolds);
    std::printf("  contact points    %zu\n", s.contact_points);
    std::printf("  islands           %zu (%zu sleeping)\n", s.islands, s.sleeping_islands);
    std::printf("  median step       %.3f ms\n", median);
    if (top != edyn::null) {
        auto moved = edyn::length(registry.get<edyn::position>(top) - top_start);
        std::printf("  pyramid           %s (top box moved %.2f cm in %.1f s)\n",
                    moved < 0.01 ? "stood" : "did not stand", moved * 100, opt.seconds);
    }
    if (!ragdolls.empty()) {
        std::printf("  rag dolls         %zu, joints %s (pivots at most %.2f mm apart)\n", ragdolls.size(),
                    worst_separation < 0.01 ? "held" : "were pulled apart", worst_separation * 1000);
    }
    for (std::size_t k = 0; k < terrains.size(); ++k) {
        // Bodies still over the terrain, and any of them below its surface (fallen through).
        std::size_t over = 0, below = 0;
        for (auto e : terrain_bodies[k]) {
            auto p = registry.get<edyn::position>(e);
            auto surface = edyn::scenes::terrain_surface_height(terrains[k].second, p.x, p.z);
            if (!surface) continue;
            ++over;
            if (p.y < *surface) ++below;
        }
        std::printf("  %-17s %zu bodies over it, %zu below its surface\n", terrains[k].first, over, below);
    }
    edyn::detach(registry);
    return 0;
}
