// Bodies with a mesh_shape: only static and kinematic ones, checked at creation, on a change of
// kind and on a change of shape; their AABB; a kinematic mesh carries its contacts when moved.
#include "support/grid_mesh.hpp"
#include <cmath>
#include <edyn/edyn.hpp>
#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace edyn;

namespace {

vector3 vec(double x, double y, double z) { return {scalar(x), scalar(y), scalar(z)}; }

// n x n cells of size `cell` in the xz plane at y = 0, centred on the origin, facing +y.
mesh_shape floor_mesh(int n, scalar cell) {
    auto half = scalar(n) * cell / 2;
    return mesh_shape{test::make_grid(n, cell, {-half, 0, -half})};
}

void expect_invalid_argument(const std::function<void()> &fn, const std::vector<std::string> &parts) {
    try {
        fn();
        ADD_FAILURE() << "nothing was thrown";
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        for (auto &part : parts)
            EXPECT_NE(what.find(part), std::string::npos)
                << "message '" << what << "' lacks '" << part << "'";
    } catch (...) {
        ADD_FAILURE() << "threw something other than std::invalid_argument";
    }
}

struct mesh_body_test : ::testing::Test {
    registry reg;
    void SetUp() override { attach(reg); }
    void TearDown() override { detach(reg); }

    rigidbody_def mesh_def(rigidbody_kind kind, const vector3 &pos = vector3_zero,
                           const quaternion &orn = quaternion_identity) {
        rigidbody_def def;
        def.kind = kind;
        def.shape = floor_mesh(4, 1);
        def.position = pos;
        def.orientation = orn;
        return def;
    }
};

} // namespace

TEST_F(mesh_body_test, a_dynamic_mesh_body_is_rejected) {
    auto before = reg.alive();
    auto def = mesh_def(rigidbody_kind::rb_dynamic);
    expect_invalid_argument([&] { make_rigidbody(reg, def); }, {"make_rigidbody", "mesh_shape"});
    EXPECT_EQ(reg.alive(), before) << "a rejected body left an entity behind";
    expect_invalid_argument([&] { validate_rigidbody_def(def); }, {"mesh_shape"});
    auto e = reg.create();
    expect_invalid_argument([&] { make_rigidbody(e, reg, def); }, {"mesh_shape"});
    EXPECT_FALSE(reg.all_of<rigidbody_tag>(e));
    EXPECT_FALSE(reg.all_of<mesh_shape>(e));
    EXPECT_FALSE(reg.all_of<AABB>(e));
}

TEST_F(mesh_body_test, static_and_kinematic_mesh_bodies_are_accepted) {
    entity s{null}, k{null};
    ASSERT_NO_THROW(s = make_rigidbody(reg, mesh_def(rigidbody_kind::rb_static)));
    ASSERT_NO_THROW(k = make_rigidbody(reg, mesh_def(rigidbody_kind::rb_kinematic)));
    EXPECT_TRUE(reg.all_of<static_tag>(s));
    EXPECT_TRUE(reg.all_of<kinematic_tag>(k));
    EXPECT_TRUE(reg.all_of<mesh_shape>(s));
    EXPECT_TRUE(reg.all_of<mesh_shape>(k));
    // Static to kinematic and back is fine.
    EXPECT_NO_THROW(rigidbody_set_kind(reg, s, rigidbody_kind::rb_kinematic));
    EXPECT_TRUE(reg.all_of<kinematic_tag>(s));
    EXPECT_NO_THROW(rigidbody_set_kind(reg, s, rigidbody_kind::rb_static));
    EXPECT_TRUE(reg.all_of<static_tag>(s));
}

TEST_F(mesh_body_test, an_uninitialized_or_null_mesh_is_rejected) {
    auto def = mesh_def(rigidbody_kind::rb_static);
    auto raw = std::make_shared<triangle_mesh>();
    std::vector<vector3> v{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}};
    raw->insert_vertices(v.begin(), v.end());
    def.shape = mesh_shape{raw};
    expect_invalid_argument([&] { make_rigidbody(reg, def); }, {"mesh_shape", "initialize"});
    def.shape = mesh_shape{};
    expect_invalid_argument([&] { make_rigidbody(reg, def); }, {"mesh_shape"});
}

TEST_F(mesh_body_test, becoming_dynamic_is_rejected) {
    auto e = make_rigidbody(reg, mesh_def(rigidbody_kind::rb_kinematic));
    expect_invalid_argument([&] { rigidbody_set_kind(reg, e, rigidbody_kind::rb_dynamic); },
                            {"rigidbody_set_kind", "mesh_shape"});
    EXPECT_TRUE(reg.all_of<kinematic_tag>(e));
    EXPECT_FALSE(reg.all_of<dynamic_tag>(e));
    EXPECT_TRUE(reg.all_of<mesh_shape>(e));

    auto s = make_rigidbody(reg, mesh_def(rigidbody_kind::rb_static));
    expect_invalid_argument([&] { rigidbody_set_kind(reg, s, rigidbody_kind::rb_dynamic); }, {"mesh_shape"});
    EXPECT_TRUE(reg.all_of<static_tag>(s));
}

TEST_F(mesh_body_test, setting_a_mesh_shape_on_a_dynamic_body_is_rejected) {
    rigidbody_def def;
    def.shape = sphere_shape{scalar(0.5)};
    auto e = make_rigidbody(reg, def);
    expect_invalid_argument([&] { rigidbody_set_shape(reg, e, shapes_variant_t{floor_mesh(2, 1)}); },
                            {"rigidbody_set_shape", "mesh_shape"});
    ASSERT_TRUE(reg.all_of<sphere_shape>(e)) << "the old shape was lost";
    EXPECT_FALSE(reg.all_of<mesh_shape>(e));
    EXPECT_TRUE(reg.all_of<dynamic_tag>(e));

    // On a kinematic body it is fine, and the shape is replaced.
    def.kind = rigidbody_kind::rb_kinematic;
    auto k = make_rigidbody(reg, def);
    ASSERT_NO_THROW(rigidbody_set_shape(reg, k, shapes_variant_t{floor_mesh(2, 1)}));
    EXPECT_TRUE(reg.all_of<mesh_shape>(k));
    EXPECT_FALSE(reg.all_of<sphere_shape>(k));
    // And once it has a mesh, it cannot become dynamic.
    EXPECT_THROW(rigidbody_set_kind(reg, k, rigidbody_kind::rb_dynamic), std::invalid_argument);
}

TEST_F(mesh_body_test, the_aabb_component_is_the_shapes) {
    auto orn = normalize(quaternion_axis_angle(normalize(vec(1, 2, 3)), scalar(0.7)));
    auto pos = vec(3, -1, 2);
    auto e = make_rigidbody(reg, mesh_def(rigidbody_kind::rb_static, pos, orn));
    const auto &shape = reg.get<mesh_shape>(e);
    auto expected = shape_aabb(shape, pos, orn);
    const auto &aabb = reg.get<AABB>(e);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(aabb.min[k], expected.min[k], 1e-5) << "min " << k;
        EXPECT_NEAR(aabb.max[k], expected.max[k], 1e-5) << "max " << k;
    }
    // And shape_aabb bounds every vertex, tightly: each face of the box touches a vertex.
    const auto &mesh = *shape.trimesh;
    vector3 lo = vector3_max, hi = -vector3_max;
    for (std::size_t i = 0; i < mesh.num_vertices(); ++i) {
        auto w = to_world_space(mesh.get_vertex(i), pos, orn);
        lo = min(lo, w);
        hi = max(hi, w);
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_LE(expected.min[k], lo[k] + scalar(1e-5));
        EXPECT_GE(expected.max[k], hi[k] - scalar(1e-5));
    }
    // The floor is a flat square: a quarter turn about y gives the same bounds.
    auto yaw = quaternion_axis_angle(vector3_y, pi / 2);
    auto flat = shape_aabb(shape, pos, yaw);
    EXPECT_NEAR(flat.min.x, pos.x - 2, 1e-5);
    EXPECT_NEAR(flat.max.x, pos.x + 2, 1e-5);
    EXPECT_NEAR(flat.min.y, pos.y, 1e-5);
    EXPECT_NEAR(flat.max.y, pos.y, 1e-5);
}

TEST_F(mesh_body_test, a_sphere_rests_on_a_static_mesh) {
    make_rigidbody(reg, mesh_def(rigidbody_kind::rb_static));
    rigidbody_def ball;
    ball.shape = sphere_shape{scalar(0.5)};
    ball.position = vec(0.3, 1, -0.4);
    auto b = make_rigidbody(reg, ball);
    for (int i = 0; i < 120; ++i)
        step_simulation(reg);
    auto p = reg.get<position>(b);
    EXPECT_NEAR(p.y, 0.5, 0.02) << "the sphere did not come to rest on the mesh";
    EXPECT_NEAR(p.x, 0.3, 0.01);
    EXPECT_NEAR(p.z, -0.4, 0.01);
}

TEST_F(mesh_body_test, moving_a_kinematic_mesh_moves_its_contacts) {
    auto floor = make_rigidbody(reg, mesh_def(rigidbody_kind::rb_kinematic));
    rigidbody_def ball;
    ball.shape = sphere_shape{scalar(0.5)};
    ball.position = vec(0.3, 0.6, -0.4);
    // Awake throughout: this test is about the mesh's contacts (see the next test for sleep).
    ball.sleeping_disabled = true;
    auto b = make_rigidbody(reg, ball);
    for (int i = 0; i < 60; ++i)
        step_simulation(reg);
    ASSERT_NEAR(reg.get<position>(b).y, 0.5, 0.02) << "the sphere is not resting on the kinematic mesh";

    // Raise the mesh by 0.3 m (teleported, as a program placing it): the sphere is pushed up.
    reg.replace<position>(floor, vec(0, 0.3, 0));
    for (int i = 0; i < 60; ++i)
        step_simulation(reg);
    EXPECT_NEAR(reg.get<position>(b).y, 0.8, 0.03) << "the sphere did not follow the raised mesh";
    auto aabb = reg.get<AABB>(floor);
    EXPECT_NEAR(aabb.min.y, 0.3, 1e-4);
    EXPECT_NEAR(aabb.max.y, 0.3, 1e-4);

    // Move the mesh far away: nothing holds the sphere any more.
    reg.replace<position>(floor, vec(100, 0.3, 0));
    for (int i = 0; i < 30; ++i)
        step_simulation(reg);
    EXPECT_LT(reg.get<position>(b).y, 0.5) << "the sphere is still held by a mesh that moved away";
    EXPECT_NEAR(reg.get<AABB>(floor).min.x, 98, 1e-4);
}

TEST_F(mesh_body_test, moving_a_kinematic_mesh_wakes_a_body_asleep_on_it) {
    // A body that fell asleep on the mesh must follow it when the program moves the mesh with
    // replace<position> (a change the simulation sees through its listeners).
    auto floor = make_rigidbody(reg, mesh_def(rigidbody_kind::rb_kinematic));
    rigidbody_def ball;
    ball.shape = sphere_shape{scalar(0.5)};
    ball.position = vec(0.3, 0.6, -0.4);
    auto b = make_rigidbody(reg, ball);
    for (int i = 0; i < 240; ++i)
        step_simulation(reg);
    ASSERT_TRUE(reg.all_of<sleeping_tag>(b)) << "the sphere should have fallen asleep after 4 s at rest";
    reg.replace<position>(floor, vec(0, 0.3, 0));
    for (int i = 0; i < 60; ++i)
        step_simulation(reg);
    EXPECT_NEAR(reg.get<position>(b).y, 0.8, 0.03) << "the sleeping sphere was left inside the raised mesh";
}
