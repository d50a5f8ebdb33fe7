#include "edyn/shapes/convex_hull.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include "edyn/shapes/polyhedron_shape.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using namespace edyn;
using edyn::test::expect_invalid_argument;
using edyn::test::expect_vector_near;

namespace {

// Checks the invariants of any hull: Euler's formula, convex faces, every point inside.
void expect_valid_hull(const convex_mesh &mesh, const std::vector<vector3> &points, scalar tolerance) {
    auto v = int(mesh.num_vertices()), e = int(mesh.num_edges()), f = int(mesh.num_faces());
    EXPECT_EQ(v - e + f, 2) << "V " << v << " E " << e << " F " << f;
    EXPECT_NO_THROW(validate_convex_mesh(mesh));
    for (std::size_t face = 0; face < mesh.num_faces(); ++face) {
        auto n = mesh.normals[face];
        auto count = mesh.faces[face].count;
        EXPECT_NEAR(length(n), 1, 1e-5) << "face " << face;
        for (std::uint32_t i = 0; i < count; ++i) {
            auto a = mesh.face_vertex(face, i);
            auto b = mesh.face_vertex(face, (i + 1) % count);
            auto c = mesh.face_vertex(face, (i + 2) % count);
            // Each corner turns counter-clockwise about the outward normal.
            EXPECT_GE(dot(cross(b - a, c - b), n), -tolerance) << "face " << face << " corner " << i;
        }
        for (std::size_t p = 0; p < points.size(); ++p) {
            auto dist = dot(n, points[p]) - mesh.plane_constants[face];
            EXPECT_LE(dist, tolerance)
                << "point " << p << " " << edyn::test::str(points[p]) << " in front of face " << face;
        }
    }
}

std::vector<vector3> cube_cloud(std::mt19937 &rng) {
    auto points = edyn::test::cube_vertices(1);
    std::uniform_real_distribution<scalar> u(-1, 1);
    // Interior points.
    for (int i = 0; i < 50; ++i)
        points.push_back({u(rng) * scalar(0.99), u(rng) * scalar(0.99), u(rng) * scalar(0.99)});
    // Points on the faces (coplanar with them) and in the middle of edges.
    for (int i = 0; i < 30; ++i) {
        auto axis = i % 3;
        vector3 p{u(rng), u(rng), u(rng)};
        p[axis] = (i % 2) ? scalar(1) : scalar(-1);
        points.push_back(p);
        vector3 q{u(rng), 1, -1};
        points.push_back(q);
    }
    // Duplicates of every corner, inserted in the middle of the cloud.
    auto corners = edyn::test::cube_vertices(1);
    points.insert(points.begin() + 20, corners.begin(), corners.end());
    std::shuffle(points.begin(), points.end(), rng);
    return points;
}

} // namespace

TEST(convex_hull_test, cube_cloud_gives_eight_vertices_and_six_quads) {
    std::mt19937 rng(7);
    auto points = cube_cloud(rng);
    auto mesh = convex_hull(points);
    EXPECT_EQ(mesh.num_vertices(), 8u);
    EXPECT_EQ(mesh.num_faces(), 6u);
    EXPECT_EQ(mesh.num_edges(), 12u);
    EXPECT_EQ(mesh.unique_edge_directions.size(), 3u);
    for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
        EXPECT_EQ(mesh.faces[f].count, 4u) << "face " << f;
        // Every face of the cube lies on a coordinate plane at distance 1.
        auto n = mesh.normals[f];
        EXPECT_NEAR(std::abs(n[max_index(abs(n))]), 1, 1e-6) << "face " << f;
        EXPECT_NEAR(mesh.plane_constants[f], 1, 1e-6) << "face " << f;
    }
    for (auto &v : mesh.vertices) {
        expect_vector_near(abs(v), vector3_one, 0, "hull vertex");
    }
    EXPECT_NEAR(shape_volume(polyhedron_shape{std::make_shared<const convex_mesh>(mesh)}), 8, 1e-5);
    expect_valid_hull(mesh, points, scalar(1e-5));
}

TEST(convex_hull_test, rotated_offset_cube_cloud_merges_faces) {
    std::mt19937 rng(11);
    auto points = cube_cloud(rng);
    auto orn = edyn::test::random_orientation(rng);
    auto offset = vector3{10, -20, 5};
    for (auto &p : points)
        p = offset + rotate(orn, p * scalar(0.5));
    auto mesh = convex_hull(points);
    EXPECT_EQ(mesh.num_vertices(), 8u);
    EXPECT_EQ(mesh.num_faces(), 6u);
    EXPECT_NEAR(shape_volume(polyhedron_shape{std::make_shared<const convex_mesh>(mesh)}), 1, 1e-4);
    expect_valid_hull(mesh, points, scalar(1e-4));
}

TEST(convex_hull_test, random_points_on_sphere) {
    std::mt19937 rng(3);
    std::normal_distribution<scalar> n(0, 1);
    std::vector<vector3> points;
    for (int i = 0; i < 600; ++i) {
        vector3 p{n(rng), n(rng), n(rng)};
        points.push_back(normalize(p) * 2);
    }
    auto mesh = convex_hull(points);
    // Points on a sphere are all extreme.
    EXPECT_EQ(mesh.num_vertices(), points.size());
    expect_valid_hull(mesh, points, scalar(1e-5));
    // Triangulated: E = 3F / 2, F = 2V - 4.
    EXPECT_EQ(mesh.num_faces(), 2 * points.size() - 4);
    auto volume = shape_volume(polyhedron_shape{std::make_shared<const convex_mesh>(mesh)});
    auto sphere_volume = scalar(4) / 3 * pi * 8;
    EXPECT_LT(volume, sphere_volume);
    EXPECT_GT(volume, sphere_volume * scalar(0.97));
}

TEST(convex_hull_test, random_cloud_keeps_every_point_inside) {
    std::mt19937 rng(5);
    std::vector<vector3> points;
    for (int i = 0; i < 2000; ++i)
        points.push_back(edyn::test::random_vector(rng, -3, 3));
    auto mesh = convex_hull(points);
    expect_valid_hull(mesh, points, scalar(1e-5));
    // The vertices are input points.
    for (auto &v : mesh.vertices) {
        EXPECT_NE(std::find(points.begin(), points.end(), v), points.end());
    }
}

TEST(convex_hull_test, prism_gives_polygonal_caps) {
    std::vector<vector3> points;
    constexpr int sides = 32;
    for (int i = 0; i < sides; ++i) {
        auto angle = pi2 * scalar(i) / sides;
        points.push_back({std::cos(angle), std::sin(angle), 1});
        points.push_back({std::cos(angle), std::sin(angle), -1});
    }
    auto mesh = convex_hull(points);
    EXPECT_EQ(mesh.num_vertices(), std::size_t(2 * sides));
    EXPECT_EQ(mesh.num_faces(), std::size_t(sides + 2));
    std::multiset<std::uint32_t> counts;
    for (auto &f : mesh.faces)
        counts.insert(f.count);
    EXPECT_EQ(counts.count(sides), 2u);
    EXPECT_EQ(counts.count(4), std::size_t(sides));
    expect_valid_hull(mesh, points, scalar(1e-5));
}

TEST(convex_hull_test, lattice_keeps_only_corners) {
    // Every point of a lattice is coplanar with many others and collinear along the edges.
    std::mt19937 rng(13);
    for (int n : {2, 3, 5, 8}) {
        std::vector<vector3> points;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                for (int k = 0; k < n; ++k)
                    points.push_back({scalar(i), scalar(j), scalar(k)});
            }
        }
        std::shuffle(points.begin(), points.end(), rng);
        auto mesh = convex_hull(points);
        EXPECT_EQ(mesh.num_vertices(), 8u) << "lattice " << n;
        EXPECT_EQ(mesh.num_faces(), 6u) << "lattice " << n;
        auto side = scalar(n - 1);
        EXPECT_NEAR(shape_volume(polyhedron_shape{std::make_shared<const convex_mesh>(mesh)}),
                    side * side * side, 1e-4);
        expect_valid_hull(mesh, points, scalar(1e-5));
    }
}

TEST(convex_hull_test, prism_with_points_on_its_sides) {
    // Three rings of points, the middle one on the side faces, the top one duplicated: the
    // middle points lie in the planes of side faces next to which they get added.
    std::mt19937 rng(19);
    for (int sides = 3; sides < 24; ++sides) {
        std::vector<vector3> points;
        for (int i = 0; i < sides; ++i) {
            auto angle = pi2 * scalar(i) / scalar(sides);
            for (scalar z : {-1, 0, 1, 1})
                points.push_back({std::cos(angle), std::sin(angle), z});
        }
        std::shuffle(points.begin(), points.end(), rng);
        auto mesh = convex_hull(points);
        EXPECT_EQ(mesh.num_vertices(), std::size_t(2 * sides)) << sides << " sides";
        EXPECT_EQ(mesh.num_faces(), std::size_t(sides + 2)) << sides << " sides";
        expect_valid_hull(mesh, points, scalar(1e-5));
    }
}

TEST(convex_hull_test, tetrahedron_of_four_points) {
    std::vector<vector3> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    auto mesh = convex_hull(points);
    EXPECT_EQ(mesh.num_vertices(), 4u);
    EXPECT_EQ(mesh.num_faces(), 4u);
    EXPECT_EQ(mesh.num_edges(), 6u);
    EXPECT_EQ(mesh.vertices, points);
    expect_valid_hull(mesh, points, scalar(1e-6));
}

TEST(convex_hull_test, degenerate_inputs_throw) {
    expect_invalid_argument(
        [] {
            convex_hull(std::vector<vector3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        },
        {"convex_hull", "at least 4", "got 3"});
    std::vector<vector3> coplanar;
    std::mt19937 rng(1);
    for (int i = 0; i < 40; ++i) {
        auto p = edyn::test::random_vector(rng, -1, 1);
        p.z = scalar(0.5);
        coplanar.push_back(p);
    }
    expect_invalid_argument([&] { convex_hull(coplanar); }, {"convex_hull", "coplanar"});
    std::vector<vector3> collinear;
    for (int i = 0; i < 10; ++i)
        collinear.push_back(vector3{1, 2, 3} * scalar(i));
    expect_invalid_argument([&] { convex_hull(collinear); }, {"collinear"});
    std::vector<vector3> same(5, vector3{1, 1, 1});
    expect_invalid_argument([&] { convex_hull(same); }, {"coincide"});
    auto with_nan = edyn::test::cube_vertices();
    with_nan[2].y = std::numeric_limits<scalar>::quiet_NaN();
    expect_invalid_argument([&] { convex_hull(with_nan); }, {"points[2].y", "finite", "nan"});
    auto with_inf = edyn::test::cube_vertices();
    with_inf[5].z = std::numeric_limits<scalar>::infinity();
    expect_invalid_argument([&] { convex_hull(with_inf); }, {"points[5].z", "inf"});
}

TEST(convex_hull_test, polyhedron_from_points_names_itself_in_errors) {
    std::vector<vector3> coplanar{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}};
    expect_invalid_argument([&] { polyhedron_shape{coplanar}; }, {"polyhedron_shape", "coplanar"});
    std::vector<vector3> with_nan{
        {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::numeric_limits<scalar>::quiet_NaN()}};
    expect_invalid_argument([&] { polyhedron_shape{with_nan}; }, {"polyhedron_shape", "points[3].z", "nan"});
}
