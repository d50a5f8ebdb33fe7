// Bodies on a paged terrain: pages load before bodies arrive and unload after they leave; a
// fast body never falls through; resident triangles stay a small part of the whole.
#include "behaviour_support.hpp"
#include <edyn_scenes/scenes.hpp>

using namespace edyn;
using edyn::test::world_fixture;

namespace {

// The surface height under (x, z) of the paged mesh's loaded pages, or nullopt off them.
std::optional<scalar> surface_under(const paged_mesh_shape &shape, scalar x, scalar z) {
    auto hit = shape_raycast(shape, {vector3_zero, quaternion_identity, {x, 100, z}, {x, -100, z}});
    if (!hit.hit()) return std::nullopt;
    return 100 - hit.fraction * 200;
}

entity make_paged_terrain(registry &reg, unsigned cells, std::size_t page_size, scalar hill_height = 2) {
    auto mesh = scenes::make_grid_mesh(
        cells, 1, [&](scalar x, scalar z) { return scenes::terrain_height(x, z, hill_height); });
    auto v = mesh->get_vertices();
    auto i = mesh->get_indices();
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.shape =
        paged_mesh_shape{create_paged_triangle_mesh({v.begin(), v.end()}, {i.begin(), i.end()}, page_size)};
    return make_rigidbody(reg, def);
}

} // namespace

TEST_F(world_fixture, a_body_launched_across_a_paged_terrain_never_falls_through) {
    // 200 m x 200 m, 80,000 triangles in pages of 500. A sphere launched at 30 m/s rolls and
    // bounces over the hills for 5 s.
    auto terrain = make_paged_terrain(reg, 200, 500);
    auto &shape = reg.get<paged_mesh_shape>(terrain);
    auto &paged = *shape.trimesh;
    auto def = edyn::test::sphere_def(scalar(0.5), {-90, scenes::terrain_height(-90, 0, 2) + 1, 0});
    def.linvel = {30, 0, 0};
    def.sleeping_disabled = true;
    auto ball = make_rigidbody(reg, def);
    std::size_t max_loaded = 0;
    for (int i = 0; i < 300; ++i) {
        edyn::test::step(reg);
        if (!edyn::test::simulates_here(reg)) continue; // The pages are the worker's; checked below.
        auto p = pos(ball);
        if (p.x > 95) break;
        // Above the surface where its page is loaded, and above the terrain's exact height
        // (the triangles differ from it by millimetres) everywhere.
        if (auto surface = surface_under(shape, p.x, p.z)) {
            ASSERT_GT(p.y, *surface) << "fell through at x = " << p.x;
        }
        ASSERT_GT(p.y, scenes::terrain_height(p.x, p.z, 2) + scalar(0.4)) << "sank at x = " << p.x;
        max_loaded = std::max(max_loaded, paged.num_loaded_triangles());
    }
    auto p = pos(ball);
    // Uphill and downhill, it slows to about 20 m/s: 100 m in 5 s.
    EXPECT_GT(p.x, 0) << "the ball did not get far";
    EXPECT_GT(p.y, scenes::terrain_height(p.x, p.z, 2) - scalar(0.6));
    if (edyn::test::simulates_here(reg)) {
        EXPECT_LT(max_loaded, paged.num_triangles() / 4);
    }
}

TEST_F(world_fixture, pages_load_where_bodies_are_and_unload_when_they_leave) {
    if (!edyn::test::simulates_here(reg))
        GTEST_SKIP() << "the pages are loaded by the worker's copy of the world";
    auto terrain = make_paged_terrain(reg, 100, 200); // 20,000 triangles.
    auto &paged = *reg.get<paged_mesh_shape>(terrain).trimesh;
    paged.unload_delay = 30;
    // A few bodies in one corner, kept awake: a body asleep holds no page, and these come to
    // rest within the two seconds.
    std::vector<entity> bodies;
    for (int i = 0; i < 9; ++i) {
        auto x = scalar(-45 + (i % 3) * 2), z = scalar(-45 + (i / 3) * 2);
        auto def = edyn::test::box_def({scalar(0.4), scalar(0.4), scalar(0.4)},
                                       {x, scenes::terrain_height(x, z, 2) + 1, z});
        def.sleeping_disabled = true;
        bodies.push_back(make_rigidbody(reg, def));
    }
    run_for(2);
    auto loaded = paged.num_loaded_triangles();
    EXPECT_GT(loaded, 0u);
    EXPECT_LT(loaded, paged.num_triangles() / 4);
    for (auto e : bodies)
        EXPECT_GT(pos(e).y, scenes::terrain_height(pos(e).x, pos(e).z, 2) - scalar(0.4));

    // The bodies leave (destroyed): after unload_delay steps their pages are gone.
    for (auto e : bodies)
        reg.destroy(e);
    run_for(1);
    EXPECT_EQ(paged.num_loaded_triangles(), 0u);
}

// A body asleep holds the pages under it (they unloaded once it slept, and a ray cast down at a
// parked body found no ground). When a kinematic body the box rests against starts to move, the
// box is pushed along the ground without sinking into it.
TEST_F(world_fixture, a_box_asleep_on_a_paged_terrain_keeps_its_ground_and_is_pushed_along_it) {
    auto terrain = make_paged_terrain(reg, 40, 50, 0);
    auto &paged = *reg.get<paged_mesh_shape>(terrain).trimesh;
    auto box = make_rigidbody(reg, edyn::test::box_def(test::unit_half, {0, scalar(0.5), 0}));
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_kinematic;
    def.shape = box_shape{test::unit_half};
    // Touching the box's side, 1 cm above the ground: kinematic and static bodies do not meet.
    def.position = {-1, scalar(0.51), 0};
    auto pusher = make_rigidbody(reg, def);
    // Asleep after 0.5 s, and for more than unload_delay steps after.
    run_for(3);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(box));
    if (edyn::test::simulates_here(reg)) {
        EXPECT_GT(paged.num_loaded_triangles(), 0u) << "the pages under the sleeping box unloaded";
        auto hit = raycast(reg, {scalar(0.3), 2, scalar(0.3)}, {scalar(0.3), -2, scalar(0.3)}, {box});
        EXPECT_EQ(hit.entity, terrain) << "a ray cast down through the sleeping box found no ground";
        EXPECT_NEAR(hit.fraction, scalar(0.5), scalar(1e-3));
    }

    reg.patch<linvel>(pusher, [](linvel &v) { v = vector3{1, 0, 0}; });
    auto lowest = pos(box).y;
    for (int i = 0; i < 30; ++i) {
        edyn::test::step(reg);
        lowest = std::min(lowest, pos(box).y);
    }
    EXPECT_GT(pos(box).x, scalar(0.3)) << "the box was not pushed";
    EXPECT_GT(lowest, scalar(0.5) - scalar(0.002)) << "the box sank into the ground while its pages loaded";
}
