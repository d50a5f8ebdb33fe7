#include <cmath>
#include <edyn/dynamics/visit_shape.hpp>
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace edyn {
namespace {

struct raycast_test : ::testing::Test {
    registry reg;
    void SetUp() override { attach(reg); }
    void TearDown() override { detach(reg); }

    entity make(const shapes_variant_t &shape, const vector3 &pos,
                rigidbody_kind kind = rigidbody_kind::rb_dynamic,
                const quaternion &orn = quaternion_identity) {
        rigidbody_def def;
        def.kind = kind;
        def.shape = shape;
        def.position = pos;
        def.orientation = orn;
        return make_rigidbody(reg, def);
    }
};

TEST_F(raycast_test, manual_example_reports_the_box_face_hit) {
    auto box = make(box_shape{0.5, 0.5, 0.5}, {0, 1, 0}, rigidbody_kind::rb_static);
    vector3 p0{0.2, 5, -0.1}, p1{0.2, -5, -0.1};

    auto result = raycast(reg, p0, p1);

    ASSERT_EQ(result.entity, box);
    EXPECT_NEAR(result.fraction, 0.35, 1e-5); // from y = 5 down to the top face at y = 1.5
    auto intersection = lerp(p0, p1, result.fraction);
    EXPECT_NEAR(intersection.y, 1.5, 1e-4);
    EXPECT_NEAR(result.normal.y, 1, 1e-5);
    ASSERT_TRUE(reg.any_of<box_shape>(result.entity));
    auto info = std::get<box_raycast_info>(result.info_var);
    EXPECT_EQ(info.face_index, 2u); // +Y
}

TEST_F(raycast_test, returns_the_first_body_along_the_ray) {
    auto a = make(sphere_shape{0.5}, {2, 0, 0});
    auto b = make(sphere_shape{0.5}, {5, 0, 0});
    auto c = make(sphere_shape{0.5}, {8, 0, 0});

    auto forward = raycast(reg, {0, 0, 0}, {10, 0, 0});
    EXPECT_EQ(forward.entity, a);
    EXPECT_NEAR(forward.fraction, 0.15, 1e-5);
    EXPECT_NEAR(forward.normal.x, -1, 1e-5);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(forward.info_var));

    auto backward = raycast(reg, {10, 0, 0}, {0, 0, 0});
    EXPECT_EQ(backward.entity, c);
    EXPECT_NEAR(backward.fraction, 0.15, 1e-5);

    auto ignoring = raycast(reg, {0, 0, 0}, {10, 0, 0}, {a});
    EXPECT_EQ(ignoring.entity, b);
    EXPECT_NEAR(ignoring.fraction, 0.45, 1e-5);

    auto ignoring_all = raycast(reg, {0, 0, 0}, {10, 0, 0}, {a, b, c});
    EXPECT_FALSE(ignoring_all.hit());
}

TEST_F(raycast_test, a_miss_reports_null) {
    make(sphere_shape{0.5}, {2, 0, 0});
    auto result = raycast(reg, {0, 2, 0}, {10, 2, 0});
    EXPECT_EQ(result.entity, null);
    EXPECT_FALSE(result.hit());
    EXPECT_EQ(result.fraction, raycast_miss_fraction);

    // The segment ends before the sphere.
    EXPECT_FALSE(raycast(reg, {0, 0, 0}, {1.4, 0, 0}).hit());
    // An empty world.
    registry empty;
    attach(empty);
    EXPECT_FALSE(raycast(empty, {0, 0, 0}, {1, 0, 0}).hit());
}

TEST_F(raycast_test, hits_planes_polyhedra_and_compounds_with_their_info) {
    auto ground = make(plane_shape{{0, 1, 0}, 0}, vector3_zero, rigidbody_kind::rb_static);
    auto down = raycast(reg, {3, 4, 3}, {3, -4, 3});
    ASSERT_EQ(down.entity, ground);
    EXPECT_NEAR(down.fraction, 0.5, 1e-5);

    auto tetra = make(polyhedron_shape{std::vector<vector3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                      {10, 1, 0}, rigidbody_kind::rb_static);
    auto hit_tetra = raycast(reg, {10.2, 1.2, -3}, {10.2, 1.2, 3});
    ASSERT_EQ(hit_tetra.entity, tetra);
    EXPECT_NEAR(lerp(vector3{10.2, 1.2, -3}, vector3{10.2, 1.2, 3}, hit_tetra.fraction).z, 0, 1e-4);
    ASSERT_TRUE(std::holds_alternative<polyhedron_raycast_info>(hit_tetra.info_var));
    auto &mesh = *reg.get<polyhedron_shape>(tetra).mesh;
    auto face = std::get<polyhedron_raycast_info>(hit_tetra.info_var).face_index;
    ASSERT_LT(face, mesh.num_faces());
    EXPECT_NEAR(hit_tetra.normal.z, -1, 1e-5);

    compound_shape compound;
    compound.add_shape(sphere_shape{0.5}, {-1, 0, 0}, quaternion_identity);
    compound.add_shape(box_shape{0.5, 0.5, 0.5}, {1, 0, 0}, quaternion_identity);
    compound.finish();
    auto body = make(compound, {0, 10, 0});
    auto hit_box = raycast(reg, {1, 20, 0}, {1, 5, 0});
    ASSERT_EQ(hit_box.entity, body);
    auto info = std::get<compound_raycast_info>(hit_box.info_var);
    EXPECT_EQ(info.child_index, 1u);
    EXPECT_EQ(std::get<box_raycast_info>(info.child_info_var).face_index, 2u);
}

TEST_F(raycast_test, a_ray_starting_inside_a_body_hits_it_at_zero) {
    auto body = make(box_shape{1, 1, 1}, {0, 0, 0});
    auto result = raycast(reg, {0.5, 0, 0}, {5, 0, 0});
    EXPECT_EQ(result.entity, body);
    EXPECT_EQ(result.fraction, 0);
    EXPECT_NEAR(result.normal.x, -1, 1e-5);
}

TEST_F(raycast_test, equal_fractions_go_to_the_lower_entity) {
    // Two identical boxes in the same place: the ray meets both at the same fraction.
    auto first = make(box_shape{0.5, 0.5, 0.5}, {3, 0, 0}, rigidbody_kind::rb_static);
    auto second = make(box_shape{0.5, 0.5, 0.5}, {3, 0, 0});
    ASSERT_LT(first, second);
    EXPECT_EQ(raycast(reg, {0, 0, 0}, {6, 0, 0}).entity, first);
    EXPECT_EQ(raycast(reg, {0, 0, 0}, {6, 0, 0}, {first}).entity, second);
}

TEST_F(raycast_test, sees_sleeping_bodies_sensors_and_bodies_after_they_move) {
    make(plane_shape{{0, 1, 0}, 0}, vector3_zero, rigidbody_kind::rb_static);
    auto ball = make(sphere_shape{0.5}, {0, 3, 0});

    rigidbody_def sensor_def;
    sensor_def.kind = rigidbody_kind::rb_static;
    sensor_def.shape = box_shape{1, 1, 1};
    sensor_def.position = {10, 1, 0};
    sensor_def.material.reset();
    auto sensor = make_rigidbody(reg, sensor_def);
    EXPECT_EQ(raycast(reg, {10, 5, 0}, {10, -5, 0}).entity, sensor);

    // The ball falls onto the ground and goes to sleep; the ray follows it.
    for (int i = 0; i < 400; ++i)
        step_simulation(reg);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(ball));
    auto result = raycast(reg, {0, 5, 0}, {0, -5, 0});
    ASSERT_EQ(result.entity, ball);
    EXPECT_NEAR(lerp(vector3{0, 5, 0}, vector3{0, -5, 0}, result.fraction).y, 1, 0.02);
}

TEST_F(raycast_test, skips_amorphous_bodies_and_forgets_destroyed_ones) {
    rigidbody_def def;
    def.inertia = matrix3x3_identity;
    def.position = {2, 0, 0};
    make_rigidbody(reg, def); // no shape: nothing to hit
    auto ball = make(sphere_shape{0.5}, {4, 0, 0});
    EXPECT_EQ(raycast(reg, {0, 0, 0}, {10, 0, 0}).entity, ball);
    reg.destroy(ball);
    EXPECT_FALSE(raycast(reg, {0, 0, 0}, {10, 0, 0}).hit());
}

TEST_F(raycast_test, rejects_a_detached_registry_and_non_finite_points) {
    registry detached;
    EXPECT_THROW(raycast(detached, {0, 0, 0}, {1, 0, 0}), std::invalid_argument);
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_THROW(raycast(reg, {0, nan, 0}, {1, 0, 0}), std::invalid_argument);
    EXPECT_THROW(raycast(reg, {0, 0, 0}, {std::numeric_limits<scalar>::infinity(), 0, 0}),
                 std::invalid_argument);
}

// The broadphase only prunes: every answer must equal the nearest hit over all bodies.
TEST_F(raycast_test, agrees_with_testing_every_body) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<scalar> coord(-20, 20), size(scalar(0.2), scalar(2)), angle(0, 6);
    std::vector<entity> bodies;
    for (int i = 0; i < 300; ++i) {
        vector3 pos{coord(rng), coord(rng), coord(rng)};
        auto orn =
            quaternion_axis_angle(normalize(vector3{coord(rng), coord(rng), coord(rng) + 50}), angle(rng));
        shapes_variant_t shape;
        switch (i % 4) {
        case 0:
            shape = sphere_shape{size(rng)};
            break;
        case 1:
            shape = box_shape{size(rng), size(rng), size(rng)};
            break;
        case 2:
            shape = capsule_shape{size(rng), size(rng)};
            break;
        default:
            shape = cylinder_shape{size(rng), size(rng)};
            break;
        }
        bodies.push_back(
            make(shape, pos, i % 3 == 0 ? rigidbody_kind::rb_static : rigidbody_kind::rb_dynamic, orn));
    }

    int hits = 0;
    for (int k = 0; k < 500; ++k) {
        vector3 p0{coord(rng), coord(rng), coord(rng)}, p1{coord(rng), coord(rng), coord(rng)};
        auto result = raycast(reg, p0, p1);
        auto best = raycast_miss_fraction;
        for (auto e : bodies) {
            raycast_context ctx{reg.get<position>(e), reg.get<orientation>(e), p0, p1};
            auto r = visit_shape(reg, e, [&](const auto &s) { return shape_raycast(s, ctx); });
            best = std::min(best, r.fraction);
        }
        ASSERT_EQ(result.fraction, best) << "ray " << k;
        hits += result.hit();
    }
    EXPECT_GT(hits, 100); // the scene is dense enough for the comparison to mean something
}

} // namespace
} // namespace edyn
