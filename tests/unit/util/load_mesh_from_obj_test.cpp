// OBJ loading against small fixture files in tests/data: vertices, triangulated faces, vertex
// colours, transforms, objects as separate meshes, hulls and compounds, and bad files.
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <string>

using namespace edyn;

namespace {

std::string data(const char *name) { return std::string(EDYN_TEST_DATA_DIR) + "/" + name; }

void expect_near(const vector3 &a, const vector3 &b, scalar tol = scalar(1e-5)) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

} // namespace

TEST(load_mesh_from_obj_test, reads_vertices_triangles_and_colours) {
    std::vector<vector3> vertices, colors;
    std::vector<std::uint32_t> indices;
    ASSERT_TRUE(load_tri_mesh_from_obj(data("colored_quad.obj"), vertices, indices, &colors));
    ASSERT_EQ(vertices.size(), 4u);
    ASSERT_EQ(indices.size(), 6u);
    ASSERT_EQ(colors.size(), 4u);
    expect_near(vertices[2], {1, 0, 1});
    expect_near(colors[2], {1, scalar(0.5), 0});
    EXPECT_EQ(indices, (std::vector<std::uint32_t>{0, 3, 2, 0, 2, 1}));

    // Red as friction, green as restitution, as the manual describes.
    std::vector<scalar> friction, restitution;
    for (const auto &c : colors) {
        friction.push_back(c.x);
        restitution.push_back(c.y);
    }
    triangle_mesh mesh;
    mesh.insert_vertices(vertices.begin(), vertices.end());
    mesh.insert_indices(indices.begin(), indices.end());
    mesh.insert_friction_coefficients(friction.begin(), friction.end());
    mesh.insert_restitution_coefficients(restitution.begin(), restitution.end());
    mesh.initialize();
    ASSERT_EQ(mesh.num_triangles(), 2u);
    expect_near(mesh.get_triangle_normal(0), vector3_y);
    // Vertex 2 of triangle 0 is file vertex 3 (x = 1, z = 1): friction 1, restitution 0.5.
    EXPECT_NEAR(mesh.get_friction(0, {0, 0, 1}), 1, 1e-6);
    EXPECT_NEAR(mesh.get_restitution(0, {0, 0, 1}), scalar(0.5), 1e-6);
}

TEST(load_mesh_from_obj_test, applies_scale_then_orientation_then_position) {
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
    auto orn = quaternion_axis_angle(vector3_y, pi / 2);
    ASSERT_TRUE(load_tri_mesh_from_obj(data("colored_quad.obj"), vertices, indices, nullptr, {10, 0, 0}, orn,
                                       {2, 1, 3}));
    // (1, 0, 1) scaled to (2, 0, 3), turned a quarter about +y to (3, 0, -2), moved by 10 in x.
    expect_near(vertices[2], {13, 0, -2});
}

TEST(load_mesh_from_obj_test, files_without_colours_give_white) {
    std::vector<vector3> vertices, colors;
    std::vector<std::uint32_t> indices;
    ASSERT_TRUE(load_tri_mesh_from_obj(data("two_boxes.obj"), vertices, indices, &colors));
    ASSERT_EQ(colors.size(), vertices.size());
    for (const auto &c : colors)
        expect_near(c, vector3_one);
}

TEST(load_mesh_from_obj_test, quads_are_triangulated_and_objects_kept_apart) {
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
    ASSERT_TRUE(load_tri_mesh_from_obj(data("two_boxes.obj"), vertices, indices));
    EXPECT_EQ(vertices.size(), 16u);
    EXPECT_EQ(indices.size(), 2u * 12 * 3);

    std::vector<obj_mesh> meshes;
    ASSERT_TRUE(load_meshes_from_obj(data("two_boxes.obj"), meshes));
    ASSERT_EQ(meshes.size(), 2u);
    EXPECT_EQ(meshes[0].name, "left");
    EXPECT_EQ(meshes[1].name, "right");
    for (const auto &m : meshes) {
        EXPECT_EQ(m.vertices.size(), 8u);
        EXPECT_EQ(m.indices.size(), 36u);
        EXPECT_EQ(m.colors.size(), 8u);
        for (auto i : m.indices)
            EXPECT_LT(i, m.vertices.size());
    }
    EXPECT_LT(meshes[0].vertices[0].x, 0);
    EXPECT_GT(meshes[1].vertices[0].x, 0);
}

TEST(load_mesh_from_obj_test, polyhedron_is_the_hull_of_every_vertex) {
    auto hull = load_polyhedron_from_obj(data("two_boxes.obj"));
    ASSERT_TRUE(hull);
    // Both cubes span x in [-2, 2], y and z in [0, 1].
    EXPECT_NEAR(shape_volume(*hull), 4, 1e-4);
    auto aabb = shape_aabb(*hull, vector3_zero, quaternion_identity);
    expect_near(aabb.min, {-2, 0, 0});
    expect_near(aabb.max, {2, 1, 1});
    // A flat quad spans no volume.
    EXPECT_FALSE(load_polyhedron_from_obj(data("colored_quad.obj")));
}

TEST(load_mesh_from_obj_test, compound_has_one_hull_per_object_at_its_centroid) {
    auto compound =
        load_compound_from_obj(data("two_boxes.obj"), vector3_zero, quaternion_identity, {1, 2, 1});
    ASSERT_TRUE(compound);
    ASSERT_EQ(compound->children.size(), 2u);
    EXPECT_TRUE(compound->finished);
    expect_near(compound->children[0].position, {scalar(-1.5), 1, scalar(0.5)});
    expect_near(compound->children[1].position, {scalar(1.5), 1, scalar(0.5)});
    for (const auto &child : compound->children)
        EXPECT_NEAR(shape_volume(child.shape), 2, 1e-4);
    // Usable as a dynamic body's shape.
    registry reg;
    attach(reg);
    rigidbody_def def;
    def.mass = 1;
    def.shape = *compound;
    EXPECT_NO_THROW(make_rigidbody(reg, def));
    detach(reg);
}

TEST(load_mesh_from_obj_test, bad_files_give_false_and_empty_outputs) {
    for (auto name : {"missing.obj", "bad_index.obj", "no_faces.obj", "garbage.obj"}) {
        std::vector<vector3> vertices{vector3_one}, colors{vector3_one};
        std::vector<std::uint32_t> indices{1};
        EXPECT_FALSE(load_tri_mesh_from_obj(data(name), vertices, indices, &colors)) << name;
        EXPECT_TRUE(vertices.empty()) << name;
        EXPECT_TRUE(indices.empty()) << name;
        EXPECT_TRUE(colors.empty()) << name;
        std::vector<obj_mesh> meshes(1);
        EXPECT_FALSE(load_meshes_from_obj(data(name), meshes)) << name;
        EXPECT_TRUE(meshes.empty()) << name;
        EXPECT_FALSE(load_polyhedron_from_obj(data(name))) << name;
        EXPECT_FALSE(load_compound_from_obj(data(name))) << name;
    }
}

TEST(load_mesh_from_obj_test, bad_transforms_throw) {
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
    EXPECT_THROW(load_tri_mesh_from_obj(data("colored_quad.obj"), vertices, indices, nullptr, vector3_zero,
                                        quaternion_identity, {1, 0, 1}),
                 std::invalid_argument);
    EXPECT_THROW(load_tri_mesh_from_obj(data("colored_quad.obj"), vertices, indices, nullptr, vector3_zero,
                                        quaternion{0, 0, 0, 2}, vector3_one),
                 std::invalid_argument);
}
