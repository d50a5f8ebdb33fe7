// Bodies on triangle meshes: internal edges must not show. A box pushed across a floor
// tessellated into 5,000 triangles, without friction, keeps its height and speed as on a single
// quad; a sphere rolling across it goes straight; bodies dropped on rolling terrain stay on it.
#include "behaviour_support.hpp"
#include <cstdio>
#include <edyn_scenes/scenes.hpp>

using namespace edyn;
using edyn::test::world_fixture;

namespace {

struct mesh_floor : world_fixture {
    // Slides a 1 m box without friction at 5 m/s along +x (slightly across the grid, so that it
    // crosses edges and vertices at every angle) for `seconds`; reports the largest deviations.
    struct slide_result {
        scalar max_height_error{0};
        scalar max_speed_error{0};
        scalar distance{0};
    };

    slide_result slide_box(unsigned cells, scalar cell_size, scalar seconds) {
        scenes::make_mesh_floor(reg, cells, cell_size, 0);
        auto def =
            edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {-20, scalar(0.5), scalar(-0.37)});
        def.material->friction = 0;
        def.linvel = {5, 0, 0};
        def.sleeping_disabled = true;
        auto box = make_rigidbody(reg, def);
        // Let it settle on the floor first.
        for (int i = 0; i < 10; ++i)
            edyn::test::step(reg);
        slide_result r;
        auto x0 = pos(box).x;
        // Resting contacts sink slightly (as on a plane); the height must stay where it settled.
        auto y0 = pos(box).y;
        auto steps = int(std::lround(seconds / get_fixed_dt(reg)));
        for (int i = 0; i < steps; ++i) {
            edyn::test::step(reg);
            r.max_height_error = std::max(r.max_height_error, std::abs(pos(box).y - y0));
            r.max_speed_error = std::max(r.max_speed_error, std::abs(length(vel(box)) - 5) / 5);
        }
        r.distance = pos(box).x - x0;
        return r;
    }
};

} // namespace

TEST_F(mesh_floor, a_box_slides_across_5000_triangles_at_constant_height_and_speed) {
    auto r = slide_box(50, 1, 4);
    EXPECT_GT(r.distance, scalar(19));
    EXPECT_LT(r.max_height_error, scalar(0.001)) << "height deviates by " << r.max_height_error << " m";
    EXPECT_LT(r.max_speed_error, scalar(0.01)) << "speed deviates by " << r.max_speed_error * 100 << "%";
}

TEST_F(mesh_floor, a_box_slides_across_a_single_quad_alike) {
    auto r = slide_box(1, 50, 4);
    EXPECT_GT(r.distance, scalar(19));
    EXPECT_LT(r.max_height_error, scalar(0.001)) << "height deviates by " << r.max_height_error << " m";
    EXPECT_LT(r.max_speed_error, scalar(0.01)) << "speed deviates by " << r.max_speed_error * 100 << "%";
}

TEST_F(mesh_floor, a_sphere_rolls_straight_across_the_tessellated_floor) {
    scenes::make_mesh_floor(reg, 50, 1, 1);
    const scalar r = scalar(0.5), v = 5;
    auto def = edyn::test::sphere_def(r, {-20, r, scalar(0.13)});
    def.material->friction = 1;
    def.linvel = {v, 0, 0};
    def.angvel = {0, 0, -v / r};
    def.sleeping_disabled = true;
    auto ball = make_rigidbody(reg, def);
    for (int i = 0; i < 10; ++i)
        edyn::test::step(reg);
    auto y0 = pos(ball).y;
    scalar max_height_error = 0;
    // 40 m at 5 m/s takes 8 s.
    for (int i = 0; i < 600 && pos(ball).x < 20; ++i) {
        edyn::test::step(reg);
        max_height_error = std::max(max_height_error, std::abs(pos(ball).y - y0));
        ASSERT_LT(reg.get<present_position>(ball).x, 30) << "rolled off";
    }
    ASSERT_GE(pos(ball).x, 20) << "stopped at " << pos(ball).x;
    EXPECT_LT(std::abs(pos(ball).z - scalar(0.13)), scalar(0.01))
        << "lateral drift " << pos(ball).z - scalar(0.13);
    EXPECT_LT(max_height_error, scalar(0.001));
    EXPECT_NEAR(vel(ball).x, v, scalar(0.01) * v);
}

TEST_F(mesh_floor, per_vertex_friction_stops_a_box_where_the_closed_form_says) {
    // Friction rises linearly from 0 at x = -10 to 1 at x = 10 (exact between the 1 m grid's
    // vertices). The box's own friction is 1, so the default mixing (the geometric mean) gives
    // mu(x) = sqrt((x + 10) / 20). Sliding from x0 at v0 it stops at x1 where
    // v0^2 / 2 = g * integral of mu = g sqrt(1/20) (2/3) ((x1 + 10)^1.5 - (x0 + 10)^1.5).
    auto mesh = scenes::make_grid_mesh(20, 1, [](scalar, scalar) { return scalar(0); });
    std::vector<scalar> friction;
    for (std::size_t i = 0; i < mesh->num_vertices(); ++i)
        friction.push_back(std::clamp((mesh->get_vertex(i).x + 10) / 20, scalar(0), scalar(1)));
    auto textured = std::make_shared<triangle_mesh>();
    auto vertices = mesh->get_vertices();
    auto indices = mesh->get_indices();
    textured->insert_vertices(vertices.begin(), vertices.end());
    textured->insert_indices(indices.begin(), indices.end());
    textured->insert_friction_coefficients(friction.begin(), friction.end());
    textured->initialize();
    rigidbody_def floor;
    floor.kind = rigidbody_kind::rb_static;
    floor.shape = mesh_shape{textured};
    make_rigidbody(reg, floor);

    const scalar x0 = -5, v0 = 5, h = scalar(0.25);
    auto def = edyn::test::box_def({h, h, h}, {x0, h, 0});
    def.material->friction = 1;
    def.sleeping_disabled = true;
    auto box = make_rigidbody(reg, def);
    for (int i = 0; i < 5; ++i)
        edyn::test::step(reg);
    auto start = pos(box).x;
    reg.replace<linvel>(box, vector3{v0, 0, 0});
    for (int i = 0; i < 600 && (i < 10 || std::abs(vel(box).x) > scalar(1e-3)); ++i)
        edyn::test::step(reg);

    auto g = length(get_gravity(reg));
    auto factor = g * std::sqrt(scalar(1) / 20) * 2 / 3;
    auto u1 = std::pow(std::pow(start + 10, scalar(1.5)) + v0 * v0 / 2 / factor, scalar(2) / 3);
    auto expected = u1 - 10 - start;
    auto travelled = pos(box).x - start;
    EXPECT_NEAR(travelled, expected, scalar(0.05) * expected)
        << "expected to stop after " << expected << " m";
    std::printf("per-vertex friction: stopped after %.3f m, closed form %.3f m\n", double(travelled),
                double(expected));
    // The same box on uniform friction 0.5 (sqrt(0.25)) would stop after v0^2 / (2 g 0.5) = 2.55 m;
    // rising friction stops it sooner than that.
    EXPECT_LT(travelled, v0 * v0 / (2 * g * scalar(0.5)));
}

TEST_F(world_fixture, nothing_falls_through_rolling_terrain) {
    // 1,000 boxes, spheres, capsules, cylinders and polyhedra dropped from 20 m onto a terrain of
    // 8,192 triangles; after 10 s every centre is above the surface under it.
    auto terrain = scenes::make_terrain(reg, 64, 1, 3);
    const auto &terrain_shape = reg.get<mesh_shape>(terrain);
    auto hull = polyhedron_shape(std::vector<vector3>{{scalar(0.4), 0, 0},
                                                      {scalar(-0.3), 0, scalar(0.3)},
                                                      {scalar(-0.3), 0, scalar(-0.3)},
                                                      {0, scalar(0.5), 0},
                                                      {0, scalar(-0.3), 0}});
    std::vector<entity> bodies;
    for (int i = 0; i < 1000; ++i) {
        rigidbody_def def;
        def.mass = 1;
        switch (i % 5) {
        case 0:
            def.shape = box_shape{scalar(0.3), scalar(0.25), scalar(0.35)};
            break;
        case 1:
            def.shape = sphere_shape{scalar(0.3)};
            break;
        case 2:
            def.shape = capsule_shape{scalar(0.2), scalar(0.3)};
            break;
        case 3:
            def.shape = cylinder_shape{scalar(0.3), scalar(0.25)};
            break;
        default:
            def.shape = hull;
            break;
        }
        auto layer = i / 100, cell = i % 100;
        def.position = {scalar(cell % 10) * scalar(2.5) - scalar(11.25), 20 + scalar(layer) * scalar(1.5),
                        scalar(cell / 10) * scalar(2.5) - scalar(11.25)};
        def.orientation =
            normalize(quaternion{scalar(0.1) * scalar(i % 7), scalar(0.2), scalar(0.05) * scalar(i % 3), 1});
        bodies.push_back(make_rigidbody(reg, def));
    }
    run_for(10);
    // Bodies that rolled off the terrain's edge (it has no walls) are not counted; one that fell
    // through stays over the terrain, below its surface.
    int below = 0, over = 0;
    for (auto e : bodies) {
        auto p = pos(e);
        ASSERT_TRUE(isfinite(p));
        auto hit = shape_raycast(terrain_shape,
                                 {vector3_zero, quaternion_identity, {p.x, 100, p.z}, {p.x, -100, p.z}});
        if (!hit.hit()) continue;
        ++over;
        auto surface = 100 - hit.fraction * 200;
        if (p.y < surface) ++below;
    }
    EXPECT_GT(over, 900);
    EXPECT_EQ(below, 0);
}
