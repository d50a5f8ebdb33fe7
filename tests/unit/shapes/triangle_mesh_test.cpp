// triangle_mesh: insertion, initialize() (normals, adjacency, edge activity, degenerate
// triangles), queries, per-vertex coefficients, bad input; and the static_tree it is built on.
// Expected values come from geometry written out here (cross products, edge counts, brute-force
// overlap tests), not from the mesh's own routines.
#include "edyn/math/math.hpp"
#include "edyn/shapes/static_tree.hpp"
#include "edyn/shapes/triangle_mesh.hpp"
#include "support/grid_mesh.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <vector>

using namespace edyn;
using edyn::test::expect_invalid_argument;
using edyn::test::expect_vector_near;

namespace {

constexpr scalar qnan = std::numeric_limits<scalar>::quiet_NaN();
constexpr scalar pinf = std::numeric_limits<scalar>::infinity();

triangle_mesh make_mesh(const std::vector<vector3> &vertices, const std::vector<int> &indices) {
    triangle_mesh mesh;
    mesh.insert_vertices(vertices.begin(), vertices.end());
    mesh.insert_indices(indices.begin(), indices.end());
    mesh.initialize();
    return mesh;
}

// Floor of n x n unit cells in the xz plane at height y(i, j), front +y. Cell (i, j) gives
// triangles 2 * (i * n + j) and 2 * (i * n + j) + 1 (support/grid_mesh.hpp).
triangle_mesh grid_mesh(int n, const test::grid_height &height) {
    std::vector<vector3> vertices;
    std::vector<int> indices;
    test::append_grid(vertices, indices, n, 1, vector3_zero, height);
    return make_mesh(vertices, indices);
}

triangle_mesh flat_grid(int n) {
    return grid_mesh(n, [](int, int) { return scalar(0); });
}

// Two triangles meeting along the ridge from (0, h, -1) to (0, h, 1); h > 0 is a roof (convex
// edge), h < 0 a valley (concave). Triangle 0 is on the -x side, triangle 1 on the +x side; the
// ridge is edge 1 of both. With `flip_right`, triangle 1 is wound the other way.
triangle_mesh roof(scalar h, bool flip_right = false) {
    std::vector<vector3> v{{-1, 0, 0}, {0, h, 1}, {0, h, -1}, {1, 0, 0}};
    std::vector<int> idx{0, 1, 2, 3, 2, 1};
    if (flip_right) idx = {0, 1, 2, 3, 1, 2};
    return make_mesh(v, idx);
}

vector3 unit_normal(const vector3 &a, const vector3 &b, const vector3 &c) {
    return normalize(cross(b - a, c - a));
}

bool aabb_overlap(const AABB &a, const AABB &b) {
    for (int k = 0; k < 3; ++k) {
        if (a.min[k] > b.max[k] || b.min[k] > a.max[k]) return false;
    }
    return true;
}

std::vector<std::size_t> visited(const triangle_mesh &mesh, const AABB &aabb) {
    std::vector<std::size_t> out;
    mesh.visit_triangles(aabb, [&](std::size_t t) { out.push_back(t); });
    return out;
}

} // namespace

TEST(triangle_mesh_test, normals_are_unit_and_follow_counter_clockwise_winding) {
    std::mt19937 rng(11);
    std::vector<vector3> vertices;
    std::vector<int> indices;
    for (int t = 0; t < 20; ++t) {
        for (int k = 0; k < 3; ++k)
            vertices.push_back(edyn::test::random_vector(rng, -3, 3));
        indices.insert(indices.end(), {3 * t, 3 * t + 1, 3 * t + 2});
    }
    auto mesh = make_mesh(vertices, indices);
    ASSERT_TRUE(mesh.initialized());
    ASSERT_EQ(mesh.num_triangles(), 20u);
    EXPECT_EQ(mesh.num_vertices(), 60u);
    EXPECT_EQ(mesh.num_degenerate_triangles(), 0u);
    for (std::size_t t = 0; t < 20; ++t) {
        auto expected = unit_normal(vertices[3 * t], vertices[3 * t + 1], vertices[3 * t + 2]);
        expect_vector_near(mesh.get_triangle_normal(t), expected, scalar(1e-5), "triangle normal");
        auto tri = mesh.get_triangle_vertices(t);
        for (int k = 0; k < 3; ++k)
            expect_vector_near(tri[k], vertices[3 * t + k], 0, "triangle vertex");
    }

    // A floor wound counter-clockwise seen from above faces +y.
    auto floor = flat_grid(1);
    expect_vector_near(floor.get_triangle_normal(0), vector3_y, scalar(1e-6));
    expect_vector_near(floor.get_triangle_normal(1), vector3_y, scalar(1e-6));
}

TEST(triangle_mesh_test, adjacency_of_a_quad_and_a_grid) {
    // Quad: triangle 0 = (0, 1, 2), triangle 1 = (0, 2, 3); they share vertices 0 and 2, which
    // are edge 2 of triangle 0 (2 -> 0) and edge 0 of triangle 1 (0 -> 2).
    auto quad = make_mesh({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, {0, 1, 2, 0, 2, 3});
    EXPECT_EQ(quad.get_adjacent_triangle(0, 0), -1);
    EXPECT_EQ(quad.get_adjacent_triangle(0, 1), -1);
    EXPECT_EQ(quad.get_adjacent_triangle(0, 2), 1);
    EXPECT_EQ(quad.get_adjacent_triangle(1, 0), 0);
    EXPECT_EQ(quad.get_adjacent_triangle(1, 1), -1);
    EXPECT_EQ(quad.get_adjacent_triangle(1, 2), -1);

    // Grid: compare with adjacency found by brute force over vertex pairs.
    auto grid = flat_grid(4);
    ASSERT_EQ(grid.num_triangles(), 32u);
    for (std::size_t t = 0; t < 32; ++t) {
        for (std::size_t e = 0; e < 3; ++e) {
            auto a = grid.get_vertex_index(t, e), b = grid.get_vertex_index(t, (e + 1) % 3);
            std::int64_t expected = -1;
            for (std::size_t u = 0; u < 32; ++u) {
                if (u == t) continue;
                std::set<std::uint32_t> vs{grid.get_vertex_index(u, 0), grid.get_vertex_index(u, 1),
                                           grid.get_vertex_index(u, 2)};
                if (vs.count(a) && vs.count(b)) expected = std::int64_t(u);
            }
            EXPECT_EQ(grid.get_adjacent_triangle(t, e), expected) << "triangle " << t << " edge " << e;
        }
    }
}

TEST(triangle_mesh_test, flat_neighbours_inactive_boundary_active) {
    auto grid = flat_grid(4);
    // An edge is on the boundary when exactly one triangle uses its vertex pair.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (std::size_t t = 0; t < grid.num_triangles(); ++t) {
        for (std::size_t e = 0; e < 3; ++e) {
            auto a = grid.get_vertex_index(t, e), b = grid.get_vertex_index(t, (e + 1) % 3);
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    int boundary = 0;
    for (std::size_t t = 0; t < grid.num_triangles(); ++t) {
        for (std::size_t e = 0; e < 3; ++e) {
            auto a = grid.get_vertex_index(t, e), b = grid.get_vertex_index(t, (e + 1) % 3);
            bool on_boundary = uses[{std::min(a, b), std::max(a, b)}] == 1;
            boundary += on_boundary;
            EXPECT_EQ(grid.is_edge_active(t, e), on_boundary) << "triangle " << t << " edge " << e;
        }
    }
    EXPECT_EQ(boundary, 16); // 4 sides of 4 cells.
}

TEST(triangle_mesh_test, convex_edges_active_above_five_degrees) {
    // The normals of a roof of height h differ by 2 atan(h).
    auto sharp = roof(std::tan(to_radians(4))); // 8 degrees.
    EXPECT_TRUE(sharp.is_edge_active(0, 1));
    EXPECT_TRUE(sharp.is_edge_active(1, 1));
    EXPECT_EQ(sharp.get_adjacent_triangle(0, 1), 1);
    EXPECT_EQ(sharp.get_adjacent_triangle(1, 1), 0);

    auto steep = roof(1); // 90 degrees.
    EXPECT_TRUE(steep.is_edge_active(0, 1));
    EXPECT_TRUE(steep.is_edge_active(1, 1));

    auto gentle = roof(std::tan(to_radians(1.5))); // 3 degrees: nearly flat.
    EXPECT_FALSE(gentle.is_edge_active(0, 1));
    EXPECT_FALSE(gentle.is_edge_active(1, 1));

    // The other edges are on the boundary.
    for (std::size_t t = 0; t < 2; ++t) {
        EXPECT_TRUE(gentle.is_edge_active(t, 0));
        EXPECT_TRUE(gentle.is_edge_active(t, 2));
    }
}

TEST(triangle_mesh_test, concave_edges_inactive) {
    for (scalar h : {scalar(-0.1), scalar(-1), scalar(-5)}) {
        auto valley = roof(h);
        EXPECT_GT(valley.get_triangle_normal(0).x, 0) << "triangle 0 leans towards +x in a valley, h " << h;
        EXPECT_FALSE(valley.is_edge_active(0, 1)) << "h " << h;
        EXPECT_FALSE(valley.is_edge_active(1, 1)) << "h " << h;
    }
}

TEST(triangle_mesh_test, inconsistent_winding_keeps_the_edge_active) {
    auto flat_flipped = roof(0, true);
    EXPECT_NEAR(flat_flipped.get_triangle_normal(1).y, -1, 1e-6);
    EXPECT_EQ(flat_flipped.get_adjacent_triangle(0, 1), 1);
    // Triangle 1 is (3, 1, 2): the shared edge 1 -> 2 is its edge 1 as well.
    EXPECT_TRUE(flat_flipped.is_edge_active(0, 1));
    EXPECT_TRUE(flat_flipped.is_edge_active(1, 1));

    auto valley_flipped = roof(-1, true);
    EXPECT_TRUE(valley_flipped.is_edge_active(0, 1));
    EXPECT_TRUE(valley_flipped.is_edge_active(1, 1));

    // Consistent flat pair for comparison: inactive.
    auto flat = roof(0);
    EXPECT_FALSE(flat.is_edge_active(0, 1));
}

TEST(triangle_mesh_test, vertex_activity) {
    auto grid = flat_grid(2);
    // Vertex (1, 0, 1) is index 4: every edge through it is internal and flat.
    const std::uint32_t centre = 4;
    int seen_centre = 0, seen_corner = 0;
    for (std::size_t t = 0; t < grid.num_triangles(); ++t) {
        for (std::size_t v = 0; v < 3; ++v) {
            auto index = grid.get_vertex_index(t, v);
            if (index == centre) {
                ++seen_centre;
                EXPECT_FALSE(grid.is_vertex_active(t, v)) << "triangle " << t;
            }
            // Corners of the grid: 0, 2, 6, 8. Each triangle through one has a boundary edge there.
            if (index == 0 || index == 2 || index == 6 || index == 8) {
                ++seen_corner;
                EXPECT_TRUE(grid.is_vertex_active(t, v)) << "triangle " << t << " vertex " << index;
            }
        }
    }
    EXPECT_EQ(seen_centre, 6); // The diagonals meet at the centre from two cells.
    EXPECT_EQ(seen_corner, 6);

    // The apex of a roof: active on the ridge.
    auto sharp = roof(1);
    EXPECT_TRUE(sharp.is_vertex_active(0, 1));
    // A vertex whose only edges are inactive: none on a two-triangle mesh; on a gentle roof the
    // ridge is inactive but the vertices still touch boundary edges.
    auto gentle = roof(std::tan(to_radians(1)));
    EXPECT_TRUE(gentle.is_vertex_active(0, 1));
}

TEST(triangle_mesh_test, degenerate_triangles_are_dropped_and_the_rest_renumbered) {
    std::vector<vector3> v{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
    // 0: good; 1: collinear (3, 4, 5); 2: repeated index; 3: good (shares edge 0-2 with 0);
    // 4: all one vertex.
    std::vector<int> idx{0, 1, 2, 3, 4, 5, 0, 0, 1, 0, 2, 3, 2, 2, 2};
    auto mesh = make_mesh(v, idx);
    ASSERT_TRUE(mesh.initialized());
    EXPECT_EQ(mesh.num_degenerate_triangles(), 3u);
    ASSERT_EQ(mesh.num_triangles(), 2u);
    std::vector<std::uint32_t> expected{0, 1, 2, 0, 2, 3};
    auto indices = mesh.get_indices();
    ASSERT_EQ(indices.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_EQ(indices[i], expected[i]) << "index " << i;
    EXPECT_EQ(mesh.get_adjacent_triangle(0, 2), 1);
    EXPECT_EQ(mesh.get_adjacent_triangle(1, 0), 0);
    EXPECT_FALSE(mesh.is_edge_active(0, 2));
    EXPECT_FALSE(mesh.is_edge_active(1, 0));
    expect_vector_near(mesh.get_triangle_normal(1), vector3_y, scalar(1e-6));
    // The AABB covers the triangles kept, not the unused vertices at x = 2, 3.
    expect_vector_near(mesh.get_aabb().max, {1, 0, 1}, 0);
    // Tiny but real triangles stay: area 1e-6 of a mesh of size ~1.
    auto small = make_mesh({{0, 0, 0}, {0, 0, 1}, {scalar(1e-6), 0, 0}, {1, 0, 0}}, {0, 1, 2, 0, 1, 3});
    EXPECT_EQ(small.num_triangles(), 2u);
    EXPECT_EQ(small.num_degenerate_triangles(), 0u);
}

TEST(triangle_mesh_test, visit_triangles_matches_brute_force) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<scalar> height(-0.5, 0.5);
    std::vector<std::vector<scalar>> heights(9, std::vector<scalar>(9));
    for (auto &row : heights)
        for (auto &h : row)
            h = height(rng);
    auto mesh = grid_mesh(8, [&](int i, int j) { return heights[i][j]; });
    ASSERT_EQ(mesh.num_triangles(), 128u);

    // Triangle AABBs from the vertices.
    std::vector<AABB> boxes;
    for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
        auto tri = mesh.get_triangle_vertices(t);
        AABB box{min(min(tri[0], tri[1]), tri[2]), max(max(tri[0], tri[1]), tri[2])};
        EXPECT_EQ(mesh.get_triangle_aabb(t), box) << "triangle " << t;
        boxes.push_back(box);
    }
    EXPECT_FLOAT_EQ(mesh.get_aabb().min.x, 0);
    EXPECT_FLOAT_EQ(mesh.get_aabb().max.x, 8);
    EXPECT_FLOAT_EQ(mesh.get_aabb().max.z, 8);

    std::uniform_real_distribution<scalar> pos(-1, 9), size(0, 2);
    std::size_t total = 0;
    for (int q = 0; q < 500; ++q) {
        vector3 c{pos(rng), height(rng), pos(rng)};
        vector3 he{size(rng), size(rng) * scalar(0.3), size(rng)};
        if (q % 10 == 0) he = vector3_zero; // A point.
        AABB query{c - he, c + he};
        std::vector<std::size_t> expected;
        for (std::size_t t = 0; t < boxes.size(); ++t) {
            if (aabb_overlap(boxes[t], query)) expected.push_back(t);
        }
        auto got = visited(mesh, query);
        auto again = visited(mesh, query);
        EXPECT_EQ(got, again) << "order must be fixed";
        auto sorted = got;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "visited twice";
        EXPECT_EQ(sorted, expected) << "query " << q;
        total += expected.size();
    }
    EXPECT_GT(total, 500u); // The queries do hit triangles.

    // Far away: nothing.
    EXPECT_TRUE(visited(mesh, AABB{{20, 20, 20}, {21, 21, 21}}).empty());
}

TEST(triangle_mesh_test, visit_triangles_segment_includes_every_triangle_crossed) {
    auto mesh = flat_grid(4);
    // A vertical segment through the middle of cell (1, 2) crosses both its AABBs only.
    std::vector<std::size_t> got;
    mesh.visit_triangles_segment({1.3, 1, 2.6}, {1.3, -1, 2.6}, [&](std::size_t t) { got.push_back(t); });
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, (std::vector<std::size_t>{2 * (1 * 4 + 2), 2 * (1 * 4 + 2) + 1}));
    // A segment above the floor touches nothing.
    got.clear();
    mesh.visit_triangles_segment({-1, 1, -1}, {5, 1, 5}, [&](std::size_t t) { got.push_back(t); });
    EXPECT_TRUE(got.empty());
}

TEST(triangle_mesh_test, per_vertex_coefficients_interpolate_barycentrically) {
    std::vector<vector3> v{{0, 0, 0}, {0, 0, 2}, {2, 0, 0}, {2, 0, 2}};
    std::vector<scalar> friction{0.1, 0.5, 0.9, 0.3};
    std::vector<scalar> restitution{0, 1, 0.5, 0.25};
    triangle_mesh mesh;
    mesh.insert_vertices(v.begin(), v.end());
    std::vector<int> idx{0, 1, 2, 2, 1, 3};
    mesh.insert_indices(idx.begin(), idx.end());
    EXPECT_FALSE(mesh.has_per_vertex_friction());
    mesh.insert_friction_coefficients(friction.begin(), friction.end());
    mesh.insert_restitution_coefficients(restitution.begin(), restitution.end());
    mesh.initialize();
    ASSERT_TRUE(mesh.has_per_vertex_friction());
    ASSERT_TRUE(mesh.has_per_vertex_restitution());

    std::mt19937 rng(3);
    std::uniform_real_distribution<scalar> u(0, 1);
    for (int k = 0; k < 100; ++k) {
        std::size_t t = k % 2;
        scalar w1 = u(rng), w2 = u(rng);
        if (w1 + w2 > 1) {
            w1 = 1 - w1;
            w2 = 1 - w2;
        }
        scalar w0 = 1 - w1 - w2;
        auto tri = mesh.get_triangle_vertices(t);
        std::uint32_t i0 = idx[3 * t], i1 = idx[3 * t + 1], i2 = idx[3 * t + 2];
        // A point off the plane projects to the same coordinates.
        auto p = tri[0] * w0 + tri[1] * w1 + tri[2] * w2 + vector3_y * (u(rng) - scalar(0.5));
        auto w = barycentric_coordinates(p, tri[0], tri[1], tri[2]);
        expect_vector_near(w, {w0, w1, w2}, scalar(1e-5), "barycentric");
        EXPECT_NEAR(mesh.get_friction(t, w), friction[i0] * w0 + friction[i1] * w1 + friction[i2] * w2, 1e-5);
        EXPECT_NEAR(mesh.get_restitution(t, w),
                    restitution[i0] * w0 + restitution[i1] * w1 + restitution[i2] * w2, 1e-5);
    }
    // At the vertices: the vertex's own value.
    for (std::size_t t = 0; t < 2; ++t) {
        for (int k = 0; k < 3; ++k) {
            vector3 w = vector3_zero;
            w[k] = 1;
            EXPECT_NEAR(mesh.get_friction(t, w), friction[mesh.get_vertex_index(t, k)], 1e-6);
        }
    }
    // Negative extrapolation is clamped at zero: outside the triangle beyond the 0.1 vertex.
    EXPECT_FLOAT_EQ(mesh.get_friction(0, {3, -1, -1}), 0);
}

TEST(triangle_mesh_test, insert_vertices_rejects_non_finite_and_appends_nothing) {
    triangle_mesh mesh;
    std::vector<vector3> good{{0, 0, 0}, {1, 0, 0}};
    mesh.insert_vertices(good.begin(), good.end());
    std::vector<vector3> bad{{0, 0, 1}, {1, qnan, 0}, {2, 2, 2}};
    expect_invalid_argument([&] { mesh.insert_vertices(bad.begin(), bad.end()); },
                            {"triangle_mesh::insert_vertices", "nan", "3"});
    EXPECT_EQ(mesh.num_vertices(), 2u);
    std::vector<vector3> inf{{pinf, 0, 0}};
    expect_invalid_argument([&] { mesh.insert_vertices(inf.begin(), inf.end()); },
                            {"triangle_mesh::insert_vertices", "inf"});
    EXPECT_EQ(mesh.num_vertices(), 2u);
    EXPECT_FALSE(mesh.initialized());
}

TEST(triangle_mesh_test, insert_indices_rejects_negative_and_huge) {
    triangle_mesh mesh;
    std::vector<int> idx{0, 1, -4};
    expect_invalid_argument([&] { mesh.insert_indices(idx.begin(), idx.end()); },
                            {"triangle_mesh::insert_indices", "-4"});
    EXPECT_EQ(mesh.get_indices().size(), 0u);
    std::vector<long long> huge{0, 1, 4294967295LL};
    expect_invalid_argument([&] { mesh.insert_indices(huge.begin(), huge.end()); },
                            {"triangle_mesh::insert_indices", "4294967295"});
    EXPECT_EQ(mesh.get_indices().size(), 0u);
    EXPECT_FALSE(mesh.initialized());
}

TEST(triangle_mesh_test, insert_coefficients_rejects_negative_and_nan) {
    triangle_mesh mesh;
    std::vector<scalar> neg{0.5, -0.5};
    expect_invalid_argument([&] { mesh.insert_friction_coefficients(neg.begin(), neg.end()); },
                            {"insert_friction_coefficients", "-0.5"});
    std::vector<scalar> nan_values{qnan};
    expect_invalid_argument(
        [&] { mesh.insert_restitution_coefficients(nan_values.begin(), nan_values.end()); },
        {"insert_restitution_coefficients", "nan"});
    std::vector<scalar> inf_values{pinf};
    expect_invalid_argument([&] { mesh.insert_friction_coefficients(inf_values.begin(), inf_values.end()); },
                            {"insert_friction_coefficients", "inf"});
    EXPECT_TRUE(mesh.get_friction_coefficients().empty());
    EXPECT_TRUE(mesh.get_restitution_coefficients().empty());
    EXPECT_FALSE(mesh.has_per_vertex_friction());
}

namespace {

// Builds a mesh from the pieces and expects initialize() to throw naming it and `value`.
void expect_initialize_throws(const std::vector<vector3> &v, const std::vector<int> &idx,
                              const std::vector<scalar> &friction, const std::vector<scalar> &restitution,
                              const std::vector<std::string> &parts) {
    triangle_mesh mesh;
    mesh.insert_vertices(v.begin(), v.end());
    mesh.insert_indices(idx.begin(), idx.end());
    mesh.insert_friction_coefficients(friction.begin(), friction.end());
    mesh.insert_restitution_coefficients(restitution.begin(), restitution.end());
    auto before = mesh.get_indices().size();
    std::vector<std::string> all{"triangle_mesh::initialize"};
    all.insert(all.end(), parts.begin(), parts.end());
    expect_invalid_argument([&] { mesh.initialize(); }, all);
    EXPECT_FALSE(mesh.initialized());
    EXPECT_EQ(mesh.get_indices().size(), before) << "indices changed by a failed initialize()";
    EXPECT_EQ(mesh.num_vertices(), v.size());
}

} // namespace

TEST(triangle_mesh_test, initialize_rejects_bad_meshes) {
    std::vector<vector3> quad{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    // Empty.
    expect_initialize_throws({}, {}, {}, {}, {"vertices"});
    expect_initialize_throws(quad, {}, {}, {}, {"indices"});
    // Not a multiple of 3.
    expect_initialize_throws(quad, {0, 1, 2, 0}, {}, {}, {"multiple of 3", "4"});
    // Out of range.
    expect_initialize_throws(quad, {0, 1, 2, 0, 2, 7}, {}, {}, {"7", "out of range"});
    expect_initialize_throws(quad, {0, 1, 4}, {}, {}, {"4", "out of range"});
    // Coefficient counts.
    expect_initialize_throws(quad, {0, 1, 2}, {0.5, 0.5}, {}, {"friction", "2"});
    expect_initialize_throws(quad, {0, 1, 2}, {}, {0.1, 0.1, 0.1, 0.1, 0.1}, {"restitution", "5"});
    // Every triangle degenerate.
    expect_initialize_throws(quad, {0, 0, 1, 2, 2, 2}, {}, {}, {"2", "zero area"});
    std::vector<vector3> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    expect_initialize_throws(line, {0, 1, 2}, {}, {}, {"1", "zero area"});
}

TEST(triangle_mesh_test, inserting_after_initialize_is_refused) {
    auto mesh = make_mesh({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}}, {0, 1, 2});
    ASSERT_TRUE(mesh.initialized());
    std::vector<vector3> more{{1, 0, 0}};
    std::vector<int> idx{0, 2, 3};
    std::vector<scalar> coefficients{scalar(0.5)};
    expect_invalid_argument([&] { mesh.insert_vertices(more.begin(), more.end()); },
                            {"triangle_mesh::insert_vertices", "initialized"});
    expect_invalid_argument([&] { mesh.insert_indices(idx.begin(), idx.end()); },
                            {"triangle_mesh::insert_indices", "initialized"});
    expect_invalid_argument(
        [&] { mesh.insert_friction_coefficients(coefficients.begin(), coefficients.end()); },
        {"triangle_mesh::insert_friction_coefficients", "initialized"});
    expect_invalid_argument(
        [&] { mesh.insert_restitution_coefficients(coefficients.begin(), coefficients.end()); },
        {"triangle_mesh::insert_restitution_coefficients", "initialized"});
    // The mesh is as it was, still initialized.
    EXPECT_TRUE(mesh.initialized());
    EXPECT_EQ(mesh.num_vertices(), 3u);
    EXPECT_EQ(mesh.num_triangles(), 1u);
    EXPECT_FALSE(mesh.has_per_vertex_friction());
}

// static_tree

namespace {

std::vector<std::size_t> visit_all(const static_tree &tree) {
    std::vector<std::size_t> out;
    tree.visit([](const AABB &) { return true; }, [&](std::size_t i) { out.push_back(i); });
    return out;
}

std::size_t depth(const static_tree &tree, std::uint32_t node) {
    const auto &n = tree.nodes[node];
    if (n.leaf) return 1;
    return 1 + std::max(depth(tree, n.index), depth(tree, n.index + 1));
}

} // namespace

TEST(static_tree_test, empty_tree_visits_nothing) {
    static_tree tree;
    tree.build({});
    EXPECT_TRUE(tree.empty());
    EXPECT_TRUE(visit_all(tree).empty());
}

TEST(static_tree_test, single_item_is_a_leaf_root) {
    static_tree tree;
    std::vector<AABB> items{{{-1, 0, 2}, {3, 4, 5}}};
    tree.build(items);
    ASSERT_FALSE(tree.empty());
    ASSERT_EQ(tree.nodes.size(), 1u);
    EXPECT_TRUE(tree.nodes[0].leaf);
    EXPECT_EQ(tree.nodes[0].index, 0u);
    EXPECT_EQ(tree.root_aabb(), items[0]);
    EXPECT_EQ(visit_all(tree), (std::vector<std::size_t>{0}));
    std::vector<std::size_t> none;
    tree.visit([](const AABB &b) { return b.min.x > 0; }, [&](std::size_t i) { none.push_back(i); });
    EXPECT_TRUE(none.empty());
}

TEST(static_tree_test, nodes_contain_children_and_visit_is_deterministic) {
    std::mt19937 rng(9);
    for (std::size_t n : {2u, 3u, 7u, 64u, 100u}) {
        std::vector<AABB> items;
        for (std::size_t i = 0; i < n; ++i) {
            auto c = edyn::test::random_vector(rng, -10, 10);
            auto he = edyn::test::random_vector(rng, 0, 1);
            items.push_back({c - he, c + he});
        }
        static_tree tree;
        tree.build(items);
        ASSERT_EQ(tree.nodes.size(), 2 * n - 1) << "n " << n;
        std::vector<int> leaf_count(n, 0);
        for (std::size_t k = 0; k < tree.nodes.size(); ++k) {
            const auto &node = tree.nodes[k];
            if (node.leaf) {
                ASSERT_LT(node.index, n);
                ++leaf_count[node.index];
                EXPECT_EQ(node.aabb, items[node.index]);
            } else {
                ASSERT_LT(node.index + 1, tree.nodes.size());
                EXPECT_GT(node.index, k) << "children come after their parent";
                EXPECT_TRUE(contains(node.aabb, tree.nodes[node.index].aabb)) << "node " << k;
                EXPECT_TRUE(contains(node.aabb, tree.nodes[node.index + 1].aabb)) << "node " << k;
            }
        }
        for (std::size_t i = 0; i < n; ++i)
            EXPECT_EQ(leaf_count[i], 1) << "item " << i;
        // Median splits: balanced.
        EXPECT_LE(depth(tree, 0), std::size_t(std::ceil(std::log2(double(n)))) + 1) << "n " << n;

        auto first = visit_all(tree);
        EXPECT_EQ(first.size(), n);
        static_tree rebuilt;
        rebuilt.build(items);
        EXPECT_EQ(visit_all(rebuilt), first) << "same items, same order";

        // A query equals brute force.
        AABB query{{-3, -3, -3}, {4, 2, 5}};
        std::vector<std::size_t> got, expected;
        tree.visit([&](const AABB &b) { return aabb_overlap(b, query); },
                   [&](std::size_t i) { got.push_back(i); });
        for (std::size_t i = 0; i < n; ++i) {
            if (aabb_overlap(items[i], query)) expected.push_back(i);
        }
        std::sort(got.begin(), got.end());
        EXPECT_EQ(got, expected) << "n " << n;
    }
}
