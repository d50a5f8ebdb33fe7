#include "edyn/shapes/polyhedron_shape.hpp"
#include "edyn/shapes/validate_shape.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <limits>

using namespace edyn;
using edyn::test::cube_faces;
using edyn::test::cube_vertices;
using edyn::test::expect_invalid_argument;
using edyn::test::expect_vector_near;

namespace {

// Octahedron with the +y apex pushed below the centre: a dented, non-convex solid whose
// triangular faces are planar and consistently wound.
polyhedron_shape dented_octahedron() {
    std::vector<vector3> vertices{{1, 0, 0},  {-1, 0, 0}, {0, -scalar(0.5), 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    // Faces of a regular octahedron (apex 2 = +y, 3 = -y), counter-clockwise from outside.
    std::vector<std::vector<std::uint32_t>> faces{{2, 4, 0}, {2, 1, 4}, {2, 5, 1}, {2, 0, 5},
                                                  {3, 0, 4}, {3, 4, 1}, {3, 1, 5}, {3, 5, 0}};
    return {vertices, faces};
}

} // namespace

TEST(polyhedron_shape_test, cube_from_explicit_faces) {
    auto shape = polyhedron_shape(cube_vertices(1), cube_faces());
    const auto &mesh = *shape.mesh;
    ASSERT_EQ(mesh.num_faces(), 6u);
    EXPECT_EQ(mesh.num_vertices(), 8u);
    EXPECT_EQ(mesh.num_edges(), 12u);
    EXPECT_EQ(mesh.unique_edge_directions.size(), 3u);
    EXPECT_NEAR(mesh.bounding_radius, std::sqrt(scalar(3)), 1e-6);
    // The faces keep the given order: -z, +z, -y, +y, -x, +x.
    vector3 expected[] = {-vector3_z, vector3_z, -vector3_y, vector3_y, -vector3_x, vector3_x};
    for (std::size_t f = 0; f < 6; ++f) {
        expect_vector_near(mesh.normals[f], expected[f], 1e-6, "normal of face " + std::to_string(f));
        EXPECT_NEAR(mesh.plane_constants[f], 1, 1e-6) << "face " << f;
    }
    // Each edge runs edges[e][0] -> edges[e][1] in edge_faces[e][0] and backwards in the other.
    for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
        auto [a, b] = mesh.edges[e];
        auto runs = [&](std::uint32_t face, std::uint32_t from, std::uint32_t to) {
            auto idx = mesh.face_indices(face);
            for (std::size_t i = 0; i < idx.size(); ++i) {
                if (idx[i] == from && idx[(i + 1) % idx.size()] == to) return true;
            }
            return false;
        };
        EXPECT_TRUE(runs(mesh.edge_faces[e][0], a, b)) << "edge " << e;
        EXPECT_TRUE(runs(mesh.edge_faces[e][1], b, a)) << "edge " << e;
        // A cube edge joins faces with perpendicular normals.
        EXPECT_NEAR(dot(mesh.normals[mesh.edge_faces[e][0]], mesh.normals[mesh.edge_faces[e][1]]), 0, 1e-6);
    }
    EXPECT_EQ(mesh.support_vertex({1, 1, 1}), 6u);
    EXPECT_EQ(mesh.support_vertex({-1, -1, -1}), 0u);
    EXPECT_NO_THROW(validate_shape(shape));
}

TEST(polyhedron_shape_test, copies_share_the_mesh) {
    auto shape = polyhedron_shape(cube_vertices(1), cube_faces());
    auto copy = shape;
    EXPECT_EQ(copy.mesh.get(), shape.mesh.get());
}

TEST(polyhedron_shape_test, non_planar_face_throws) {
    auto vertices = cube_vertices(1);
    vertices[6].z = scalar(1.3);
    expect_invalid_argument([&] { polyhedron_shape(vertices, cube_faces()); },
                            {"polyhedron_shape", "faces[", "not planar"});
}

TEST(polyhedron_shape_test, concave_mesh_throws) {
    expect_invalid_argument([] { dented_octahedron(); }, {"polyhedron_shape", "not convex", "vertices["});
}

TEST(polyhedron_shape_test, clockwise_winding_throws) {
    auto faces = cube_faces();
    for (auto &f : faces)
        std::reverse(f.begin(), f.end());
    expect_invalid_argument([&] { polyhedron_shape(cube_vertices(1), faces); },
                            {"polyhedron_shape", "clockwise", "signed volume -8"});
}

TEST(polyhedron_shape_test, inconsistent_winding_throws) {
    auto faces = cube_faces();
    std::reverse(faces[3].begin(), faces[3].end());
    expect_invalid_argument([&] { polyhedron_shape(cube_vertices(1), faces); },
                            {"polyhedron_shape", "inconsistent winding", "faces[3]"});
}

TEST(polyhedron_shape_test, bad_index_throws) {
    auto faces = cube_faces();
    faces[2][1] = 9;
    expect_invalid_argument([&] { polyhedron_shape(cube_vertices(1), faces); },
                            {"polyhedron_shape", "faces[2][1] = 9", "out of range"});
}

TEST(polyhedron_shape_test, malformed_inputs_throw) {
    auto faces = cube_faces();
    faces[0] = {0, 3};
    expect_invalid_argument([&] { polyhedron_shape(cube_vertices(1), faces); },
                            {"faces[0]", "at least 3 vertices", "got 2"});
    faces = cube_faces();
    faces[1] = {4, 5, 5, 7};
    expect_invalid_argument([&] { polyhedron_shape(cube_vertices(1), faces); },
                            {"faces[1]", "repeats vertex 5"});
    expect_invalid_argument(
        [] {
            polyhedron_shape({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}});
        },
        {"vertices", "at least 4", "got 3"});
    auto vertices = cube_vertices(1);
    vertices[3].y = std::numeric_limits<scalar>::quiet_NaN();
    expect_invalid_argument([&] { polyhedron_shape(vertices, cube_faces()); },
                            {"vertices[3].y", "finite", "nan"});
    vertices = cube_vertices(1);
    vertices.push_back({5, 5, 5});
    expect_invalid_argument([&] { polyhedron_shape(vertices, cube_faces()); },
                            {"vertices[8]", "used by no face"});
    faces = cube_faces();
    faces.pop_back();
    expect_invalid_argument([&] { polyhedron_shape(cube_vertices(1), faces); }, {"no opposite edge"});
    expect_invalid_argument(
        [] {
            polyhedron_shape(cube_vertices(1), {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}});
        },
        {"faces", "at least 4 faces", "got 3"});
}

TEST(polyhedron_shape_test, flat_tetrahedron_throws) {
    std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {scalar(0.2), scalar(0.2), 0}};
    std::vector<std::vector<std::uint32_t>> faces{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    expect_invalid_argument([&] { polyhedron_shape(vertices, faces); }, {"polyhedron_shape", "degenerate"});
}

TEST(polyhedron_shape_test, collinear_face_throws) {
    // A "face" whose vertices lie on a line.
    std::vector<vector3> vertices{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 1}};
    std::vector<std::vector<std::uint32_t>> faces{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    expect_invalid_argument([&] { polyhedron_shape(vertices, faces); }, {"faces[0]", "degenerate"});
}

TEST(polyhedron_shape_test, default_shape_fails_validation) {
    expect_invalid_argument([] { validate_shape(polyhedron_shape{}); }, {"polyhedron_shape", "mesh is null"});
}

TEST(polyhedron_shape_test, validate_convex_mesh_checks_derived_arrays) {
    auto mesh = make_convex_mesh(cube_vertices(1), cube_faces());
    EXPECT_NO_THROW(validate_convex_mesh(mesh));
    mesh.normals.pop_back();
    expect_invalid_argument([&] { validate_convex_mesh(mesh); }, {"normals", "5", "expected 6"});
    mesh = make_convex_mesh(cube_vertices(1), cube_faces());
    mesh.normals[2] = -mesh.normals[2];
    expect_invalid_argument([&] { validate_convex_mesh(mesh); }, {"normals[2]", "does not match the face"});
    mesh = make_convex_mesh(cube_vertices(1), cube_faces());
    mesh.plane_constants[4] = 2;
    expect_invalid_argument([&] { validate_convex_mesh(mesh); }, {"plane_constants[4] = 2", "expected 1"});
}
