// shape_raycast() against triangle meshes (surfaces hit from either side, the first triangle
// along the ray, the lowest index on ties) and edyn::raycast() through a registry with a mesh
// body. Expected fractions come from plane intersections written out here.
#include "collide_test_helpers.hpp"
#include "edyn/collision/shape_raycast.hpp"
#include "edyn/edyn.hpp"
#include "edyn/math/transform.hpp"
#include "support/grid_mesh.hpp"
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar mesh_raycast_tol = scalar(1e-5);

// n x n unit cells in the xz plane at height y, front +y, appended to (vertices, indices). Cell
// (i, j) gives triangles first + 2 (i n + j) (where z - j >= x - i) and first + 2 (i n + j) + 1.
void add_floor(std::vector<vector3> &vertices, std::vector<int> &indices, int n, scalar y) {
    test::append_grid(vertices, indices, n, 1, {0, y, 0});
}

// Two 4 x 4 floors: triangles 0..31 at y = 0, 32..63 at y = 1.
mesh_shape two_floors() {
    std::vector<vector3> v;
    std::vector<int> idx;
    add_floor(v, idx, 4, 0);
    add_floor(v, idx, 4, 1);
    return test::make_mesh(v, idx);
}

// The triangle of a 4 x 4 floor containing (x, z) strictly inside a cell.
std::size_t floor_triangle(scalar x, scalar z, std::size_t first = 0) {
    int i = int(std::floor(x)), j = int(std::floor(z));
    return first + 2 * std::size_t(i * 4 + j) + (z - scalar(j) >= x - scalar(i) ? 0 : 1);
}

shape_raycast_result cast(const mesh_shape &mesh, const vector3 &p0, const vector3 &p1,
                          const vector3 &pos = vector3_zero, const quaternion &orn = quaternion_identity) {
    return shape_raycast(mesh, raycast_context{pos, orn, p0, p1});
}

std::size_t triangle_of(const shape_raycast_result &r) {
    auto *info = std::get_if<mesh_raycast_info>(&r.info_var);
    EXPECT_NE(info, nullptr) << "no mesh_raycast_info";
    return info ? info->triangle_index : ~std::size_t(0);
}

} // namespace

TEST(mesh_raycast_test, hits_the_first_triangle_from_above_and_below) {
    auto mesh = two_floors();
    std::mt19937 rng(17);
    std::uniform_real_distribution<scalar> u(scalar(0.05), scalar(3.95));
    for (int k = 0; k < 100; ++k) {
        auto x = u(rng), z = u(rng);
        // Down from y = 5 to y = -5: the upper floor at fraction 0.4, facing up.
        auto down = cast(mesh, vec(x, 5, z), vec(x, -5, z));
        ASSERT_TRUE(down.hit()) << x << ", " << z;
        EXPECT_NEAR(down.fraction, 0.4, mesh_raycast_tol);
        expect_vec_near(down.normal, vector3_y, mesh_raycast_tol);
        EXPECT_EQ(triangle_of(down), floor_triangle(x, z, 32)) << x << ", " << z;

        // Up from below: the lower floor at fraction 0.5, the normal facing the ray's start.
        auto up = cast(mesh, vec(x, -5, z), vec(x, 5, z));
        ASSERT_TRUE(up.hit());
        EXPECT_NEAR(up.fraction, 0.5, mesh_raycast_tol);
        expect_vec_near(up.normal, -vector3_y, mesh_raycast_tol);
        EXPECT_EQ(triangle_of(up), floor_triangle(x, z, 0));

        // Between the floors, upwards: the upper floor from behind.
        auto between = cast(mesh, vec(x, 0.5, z), vec(x, 1.5, z));
        ASSERT_TRUE(between.hit());
        EXPECT_NEAR(between.fraction, 0.5, mesh_raycast_tol);
        expect_vec_near(between.normal, -vector3_y, mesh_raycast_tol);
        EXPECT_EQ(triangle_of(between), floor_triangle(x, z, 32));
    }
}

TEST(mesh_raycast_test, slanted_rays_match_the_plane_intersection) {
    auto mesh = two_floors();
    std::mt19937 rng(2);
    std::uniform_real_distribution<scalar> u(0, 4), h(2, 6);
    int hits = 0;
    for (int k = 0; k < 200; ++k) {
        auto p0 = vec(u(rng), h(rng), u(rng));
        auto p1 = vec(u(rng), -h(rng), u(rng));
        auto r = cast(mesh, p0, p1);
        // The upper plane y = 1 is crossed at t = (p0.y - 1) / (p0.y - p1.y).
        auto t = (p0.y - 1) / (p0.y - p1.y);
        auto q = p0 + (p1 - p0) * t;
        bool inside =
            q.x > scalar(1e-3) && q.x < 4 - scalar(1e-3) && q.z > scalar(1e-3) && q.z < 4 - scalar(1e-3);
        if (!inside) continue;
        ++hits;
        ASSERT_TRUE(r.hit()) << str(p0) << " -> " << str(p1);
        EXPECT_NEAR(r.fraction, t, mesh_raycast_tol);
        expect_vec_near(r.normal, vector3_y, mesh_raycast_tol);
        auto hit_point = p0 + (p1 - p0) * r.fraction;
        EXPECT_EQ(triangle_of(r), floor_triangle(hit_point.x, hit_point.z, 32)) << str(hit_point);
    }
    EXPECT_GT(hits, 50);
}

TEST(mesh_raycast_test, misses) {
    auto mesh = two_floors();
    // Beside the mesh.
    auto beside = cast(mesh, vec(5, 5, 2), vec(5, -5, 2));
    EXPECT_FALSE(beside.hit());
    EXPECT_EQ(beside.fraction, raycast_miss_fraction);
    expect_vec_near(beside.normal, vector3_zero, 0);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(beside.info_var));
    // Stops short of the upper floor.
    EXPECT_FALSE(cast(mesh, vec(2.3, 5, 1.1), vec(2.3, 1.01, 1.1)).hit());
    // Goes away from it.
    EXPECT_FALSE(cast(mesh, vec(2.3, 2, 1.1), vec(2.3, 7, 1.1)).hit());
    // Parallel to the floors, between them.
    EXPECT_FALSE(cast(mesh, vec(-1, 0.5, 1.1), vec(6, 0.5, 2.2)).hit());
    // Zero length, on the surface and away from it.
    EXPECT_FALSE(cast(mesh, vec(2.3, 1, 1.1), vec(2.3, 1, 1.1)).hit());
    EXPECT_FALSE(cast(mesh, vec(2.3, 3, 1.1), vec(2.3, 3, 1.1)).hit());
}

TEST(mesh_raycast_test, rays_through_edges_and_vertices_hit) {
    std::vector<vector3> v;
    std::vector<int> idx;
    add_floor(v, idx, 4, 0);
    auto mesh = test::make_mesh(v, idx);
    // On the line x = 2 between cell (1, 1)'s second triangle (11) and cell (2, 1)'s first (18).
    auto edge = cast(mesh, vec(2, 1, 1.5), vec(2, -1, 1.5));
    ASSERT_TRUE(edge.hit());
    EXPECT_NEAR(edge.fraction, 0.5, mesh_raycast_tol);
    expect_vec_near(edge.normal, vector3_y, mesh_raycast_tol);
    EXPECT_EQ(triangle_of(edge), 11u) << "the lowest index on equal fractions";
    // On a diagonal: both triangles of cell (2, 3) (22 and 23).
    auto diagonal = cast(mesh, vec(2.25, 1, 3.25), vec(2.25, -1, 3.25));
    ASSERT_TRUE(diagonal.hit());
    EXPECT_EQ(triangle_of(diagonal), 22u);
    // Through vertex (2, 0, 2), shared by triangles 10, 11, 13, 18, 20, 21 (the lowest is 10).
    auto vertex = cast(mesh, vec(2, 1, 2), vec(2, -1, 2));
    ASSERT_TRUE(vertex.hit());
    EXPECT_NEAR(vertex.fraction, 0.5, mesh_raycast_tol);
    EXPECT_EQ(triangle_of(vertex), 10u);
    // On the outer boundary edge x = 0 and the corner (4, 0, 4).
    EXPECT_TRUE(cast(mesh, vec(0, 1, 2.5), vec(0, -1, 2.5)).hit());
    EXPECT_TRUE(cast(mesh, vec(4, 1, 4), vec(4, -1, 4)).hit());
    // Just outside them.
    EXPECT_FALSE(cast(mesh, vec(-1e-3, 1, 2.5), vec(-1e-3, -1, 2.5)).hit());
}

TEST(mesh_raycast_test, the_mesh_body_transform_is_honoured) {
    auto mesh = two_floors();
    auto orn = normalize(quaternion_axis_angle(normalize(vec(0.2, 1, -0.4)), scalar(1.3)));
    auto pos = vec(-3, 2, 7);
    std::mt19937 rng(29);
    // The ray drifts by (0.04, -0.08) before the upper floor: keep it inside.
    std::uniform_real_distribution<scalar> u(scalar(0.2), scalar(3.8));
    for (int k = 0; k < 50; ++k) {
        auto x = u(rng), z = u(rng);
        auto local_p0 = vec(x, 5, z), local_p1 = vec(x + 0.1, -5, z - 0.2);
        auto world_p0 = to_world_space(local_p0, pos, orn), world_p1 = to_world_space(local_p1, pos, orn);
        auto local = cast(mesh, local_p0, local_p1);
        auto world = cast(mesh, world_p0, world_p1, pos, orn);
        ASSERT_TRUE(world.hit());
        EXPECT_NEAR(world.fraction, local.fraction, mesh_raycast_tol);
        EXPECT_NEAR(world.fraction, 0.4, mesh_raycast_tol);
        expect_vec_near(world.normal, rotate(orn, vector3_y), mesh_raycast_tol);
        EXPECT_EQ(triangle_of(world), triangle_of(local));
        // The untransformed world ray misses the mesh at the origin, or hits something else.
        auto untransformed = cast(mesh, world_p0, world_p1);
        EXPECT_FALSE(untransformed.hit() &&
                     std::abs(untransformed.fraction - scalar(0.4)) < mesh_raycast_tol);
    }
}

TEST(mesh_raycast_test, through_the_shape_variant) {
    auto mesh = two_floors();
    shapes_variant_t var{mesh};
    auto r = shape_raycast(
        var, raycast_context{vec(0, -1, 0), quaternion_identity, vec(1.2, 5, 0.3), vec(1.2, -5, 0.3)});
    ASSERT_TRUE(r.hit());
    // The mesh moved down by 1: the upper floor at y = 0.
    EXPECT_NEAR(r.fraction, 0.5, mesh_raycast_tol);
    EXPECT_EQ(triangle_of(r), floor_triangle(1.2, 0.3, 32));
}

namespace {

struct mesh_raycast_registry_test : ::testing::Test {
    registry reg;
    void SetUp() override { attach(reg); }
    void TearDown() override { detach(reg); }
};

} // namespace

TEST_F(mesh_raycast_registry_test, raycast_finds_a_static_mesh_body) {
    auto mesh = two_floors();
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.shape = mesh;
    def.position = vec(10, 0, 0);
    auto body = make_rigidbody(reg, def);

    // A sphere above the mesh, first along the ray.
    rigidbody_def ball;
    ball.kind = rigidbody_kind::rb_static;
    ball.shape = sphere_shape{scalar(0.25)};
    ball.position = vec(12.5, 3, 2.5);
    auto sphere = make_rigidbody(reg, ball);

    auto hit_mesh = raycast(reg, vec(11.7, 5, 1.2), vec(11.7, -5, 1.2));
    ASSERT_EQ(hit_mesh.entity, body);
    EXPECT_NEAR(hit_mesh.fraction, 0.4, mesh_raycast_tol);
    expect_vec_near(hit_mesh.normal, vector3_y, mesh_raycast_tol);
    auto *info = std::get_if<mesh_raycast_info>(&hit_mesh.info_var);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->triangle_index, floor_triangle(1.7, 1.2, 32));

    auto hit_sphere = raycast(reg, vec(12.5, 5, 2.5), vec(12.5, -5, 2.5));
    EXPECT_EQ(hit_sphere.entity, sphere);
    EXPECT_NEAR(hit_sphere.fraction, (5 - 3.25) / 10, mesh_raycast_tol);

    auto ignoring = raycast(reg, vec(12.5, 5, 2.5), vec(12.5, -5, 2.5), {sphere});
    EXPECT_EQ(ignoring.entity, body);
    EXPECT_NEAR(ignoring.fraction, 0.4, mesh_raycast_tol);

    // Upwards from between the floors: the upper floor's back at y = 1.
    auto from_between = raycast(reg, vec(11.7, 0.5, 1.2), vec(11.7, 3, 1.2));
    ASSERT_EQ(from_between.entity, body);
    EXPECT_NEAR(from_between.fraction, 0.2, mesh_raycast_tol);
    expect_vec_near(from_between.normal, -vector3_y, mesh_raycast_tol);

    auto miss = raycast(reg, vec(0, 5, 1.5), vec(0, -5, 1.5));
    EXPECT_FALSE(miss.hit());
}
