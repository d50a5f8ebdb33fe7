// The scene of Glenn Fiedler's "Snapshot Compression" article, shared by the bandwidth and
// convergence scenarios: a grid of small cubes, and large cubes that players drive through it.
#include "netbench.hpp"
#include <algorithm>
#include <cmath>

namespace edyn_netbench {

namespace {

constexpr edyn::scalar cube_spacing = 1;
constexpr edyn::scalar player_mass = 80;
// A player steers its cube after a point going round a circle in the middle of the grid at
// this rate (rad/s), so that the cube keeps ploughing through cubes, as in the article. The
// circle's radius is this share of the grid's half width, at most the second figure (m): about
// 4 m/s round the 30 by 30 grid.
constexpr double path_rate = 0.5;
constexpr double path_radius_share = 0.55;
constexpr double max_path_radius = 8;
// A spring and damper towards that point, capped: about 14 m/s² left after friction.
constexpr double steer_stiffness = 400;
constexpr double steer_damping = 250;
constexpr double max_steer_newtons = 1500;

edyn::scalar grid_half_width(unsigned grid) { return edyn::scalar(grid - 1) * cube_spacing / 2; }

// How far round its circle player `k` of `players` starts, from the first player's start at
// -x.
double player_angle(unsigned k, unsigned players) {
    return 2 * 3.14159265358979 * double(k) / std::max(players, 1u);
}

} // namespace

cube_grid build_cube_grid(edyn::registry &server, unsigned grid, unsigned players) {
    auto ground = edyn::rigidbody_def{};
    ground.kind = edyn::rigidbody_kind::rb_static;
    ground.shape = edyn::plane_shape{{0, 1, 0}, 0};
    auto g = edyn::make_rigidbody(server, ground);
    server.emplace<edyn::networked_tag>(g);

    auto out = cube_grid{};
    auto half_width = grid_half_width(grid);
    for (unsigned i = 0; i < grid; ++i) {
        for (unsigned j = 0; j < grid; ++j) {
            auto def = edyn::rigidbody_def{};
            def.shape = edyn::box_shape{{cube_half_extent, cube_half_extent, cube_half_extent}};
            def.mass = 1;
            def.position = {edyn::scalar(i) * cube_spacing - half_width, cube_half_extent,
                            edyn::scalar(j) * cube_spacing - half_width};
            auto e = edyn::make_rigidbody(server, def);
            server.emplace<edyn::networked_tag>(e);
            out.cubes.push_back(e);
        }
    }
    // Each player just off the grid's edge, a quarter metre from the nearest cubes, in the
    // direction of its circle's starting point.
    auto off = double(half_width + cube_half_extent + player_half_extent + 0.25f);
    for (unsigned k = 0; k < players; ++k) {
        auto angle = player_angle(k, players);
        auto x = 0.0 - std::cos(angle), z = 0.0 - std::sin(angle); // +0, not -0, on the axes
        auto reach = off / std::max(std::abs(x), std::abs(z));
        auto def = edyn::rigidbody_def{};
        def.shape = edyn::box_shape{{player_half_extent, player_half_extent, player_half_extent}};
        def.mass = player_mass;
        def.position = {edyn::scalar(x * reach), player_half_extent, edyn::scalar(z * reach)};
        auto e = edyn::make_rigidbody(server, def);
        server.emplace<edyn::networked_tag>(e);
        out.players.push_back(e);
    }
    return out;
}

edyn::vector3 steer_player(const edyn::registry &registry, edyn::entity cube, unsigned grid, unsigned k,
                           unsigned players, double time) {
    auto radius = std::min(max_path_radius, path_radius_share * double(grid_half_width(grid)));
    auto angle = player_angle(k, players) + path_rate * time;
    auto target = edyn::vector3{edyn::scalar(-radius * std::cos(angle)), player_half_extent,
                                edyn::scalar(-radius * std::sin(angle))};
    auto force = (target - registry.get<edyn::position>(cube)) * edyn::scalar(steer_stiffness) -
                 registry.get<edyn::linvel>(cube) * edyn::scalar(steer_damping);
    force.y = 0;
    auto magnitude = edyn::length(force);
    if (magnitude > edyn::scalar(max_steer_newtons)) force *= edyn::scalar(max_steer_newtons) / magnitude;
    return force;
}

} // namespace edyn_netbench
