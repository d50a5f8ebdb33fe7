#include "edyn/shapes/compound_shape.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/shapes/validate_shape.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace edyn;
using edyn::test::expect_invalid_argument;
using edyn::test::expect_vector_near;

namespace {

// A 6 x 5 x 4 grid of mixed shapes with random orientations.
compound_shape grid_compound(std::mt19937 &rng) {
    compound_shape compound;
    auto poly = polyhedron_shape(edyn::test::cube_vertices(scalar(0.3)), edyn::test::cube_faces());
    for (int x = 0; x < 6; ++x) {
        for (int y = 0; y < 5; ++y) {
            for (int z = 0; z < 4; ++z) {
                auto pos = vector3{scalar(x), scalar(y), scalar(z)} * scalar(1.5);
                auto orn = edyn::test::random_orientation(rng);
                switch ((x + y + z) % 5) {
                case 0:
                    compound.add_shape(sphere_shape{scalar(0.4)}, pos, orn);
                    break;
                case 1:
                    compound.add_shape(box_shape{scalar(0.2), scalar(0.4), scalar(0.5)}, pos, orn);
                    break;
                case 2:
                    compound.add_shape(cylinder_shape{scalar(0.3), scalar(0.5), coordinate_axis::y}, pos,
                                       orn);
                    break;
                case 3:
                    compound.add_shape(capsule_shape{scalar(0.2), scalar(0.4), coordinate_axis::z}, pos, orn);
                    break;
                default:
                    compound.add_shape(poly, pos, orn);
                    break;
                }
            }
        }
    }
    compound.finish();
    return compound;
}

std::size_t tree_depth(const compound_shape &compound, std::uint32_t node) {
    const auto &n = compound.tree.nodes[node];
    if (n.leaf) return 1;
    return 1 + std::max(tree_depth(compound, n.index), tree_depth(compound, n.index + 1));
}

} // namespace

TEST(compound_shape_test, children_store_transform_and_aabb) {
    compound_shape compound;
    auto orn = quaternion_axis_angle(vector3_z, pi / 4);
    compound.add_shape(box_shape{1, 1, 1}, {2, 0, 0}, orn * scalar(1.0002));
    compound.add_shape(sphere_shape{scalar(0.5)}, {-2, 1, 0});
    compound.finish();
    ASSERT_EQ(compound.children.size(), 2u);
    EXPECT_TRUE(compound.tree.nodes.empty());
    // The orientation is stored normalised.
    EXPECT_NEAR(length(compound.children[0].orientation), 1, 1e-6);
    auto diag = std::sqrt(scalar(2));
    expect_vector_near(compound.children[0].aabb.min, {2 - diag, -diag, -1}, 1e-5, "box min");
    expect_vector_near(compound.children[0].aabb.max, {2 + diag, diag, 1}, 1e-5, "box max");
    EXPECT_EQ(compound.children[1].aabb,
              (AABB{{scalar(-2.5), scalar(0.5), scalar(-0.5)}, {scalar(-1.5), scalar(1.5), scalar(0.5)}}));
    EXPECT_NO_THROW(validate_shape(compound));
}

TEST(compound_shape_test, add_shape_validates) {
    compound_shape compound;
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    expect_invalid_argument(
        [&] {
            compound.add_shape(sphere_shape{1}, {0, nan, 0});
        },
        {"compound_shape", "position", "nan"});
    expect_invalid_argument(
        [&] {
            compound.add_shape(sphere_shape{1}, vector3_zero, {0, 0, 0, 2});
        },
        {"compound_shape", "orientation", "unit", "length 2"});
    expect_invalid_argument([&] { compound.add_shape(sphere_shape{-1}, vector3_zero); },
                            {"compound_shape", "sphere_shape", "radius", "got -1"});
    expect_invalid_argument([&] { compound.add_shape(polyhedron_shape{}, vector3_zero); },
                            {"compound_shape", "polyhedron_shape", "null"});
    EXPECT_TRUE(compound.children.empty());
    expect_invalid_argument([&] { compound.finish(); }, {"compound_shape", "finish", "empty"});
}

TEST(compound_shape_test, finish_is_required_after_add_shape) {
    compound_shape compound;
    compound.add_shape(sphere_shape{1});
    expect_invalid_argument([&] { validate_shape(compound); }, {"compound_shape", "finish()"});
    compound.finish();
    EXPECT_NO_THROW(validate_shape(compound));
    compound.add_shape(sphere_shape{1}, {1, 0, 0});
    EXPECT_FALSE(compound.finished);
}

TEST(compound_shape_test, tree_is_built_beyond_eight_children) {
    std::mt19937 rng(2);
    compound_shape small;
    for (int i = 0; i < 8; ++i)
        small.add_shape(sphere_shape{1}, {scalar(i) * 3, 0, 0});
    small.finish();
    EXPECT_TRUE(small.tree.empty());

    auto compound = grid_compound(rng);
    auto n = compound.children.size();
    ASSERT_EQ(n, 120u);
    ASSERT_EQ(compound.tree.nodes.size(), 2 * n - 1);
    // Balanced: depth ceil(log2(120)) + 1 = 8.
    EXPECT_LE(tree_depth(compound, 0), 8u);
    // Every node bounds its subtree; every child is a leaf exactly once.
    std::vector<int> leaf_count(n, 0);
    for (const auto &node : compound.tree.nodes) {
        if (node.leaf) {
            ++leaf_count[node.index];
            EXPECT_EQ(node.aabb, compound.children[node.index].aabb);
        } else {
            EXPECT_TRUE(contains(node.aabb, compound.tree.nodes[node.index].aabb));
            EXPECT_TRUE(contains(node.aabb, compound.tree.nodes[node.index + 1].aabb));
        }
    }
    EXPECT_TRUE(std::all_of(leaf_count.begin(), leaf_count.end(), [](int c) { return c == 1; }));
}

TEST(compound_shape_test, visit_reports_exactly_the_overlapping_children) {
    std::mt19937 rng(4);
    for (bool with_tree : {false, true}) {
        compound_shape compound;
        if (with_tree) {
            compound = grid_compound(rng);
        } else {
            for (int i = 0; i < 7; ++i)
                compound.add_shape(box_shape{1, 1, 1}, {scalar(i) * 3, 0, 0});
            compound.finish();
        }
        for (int q = 0; q < 200; ++q) {
            auto centre = edyn::test::random_vector(rng, -1, 9);
            auto half = edyn::test::random_vector(rng, 0, 2);
            AABB query{centre - half, centre + half};
            std::vector<std::size_t> visited, expected;
            compound.visit(query, [&](std::size_t i) { visited.push_back(i); });
            for (std::size_t i = 0; i < compound.children.size(); ++i) {
                if (intersect(compound.children[i].aabb, query)) expected.push_back(i);
            }
            std::sort(visited.begin(), visited.end());
            EXPECT_EQ(visited, expected) << "query " << q << (with_tree ? " with tree" : " without tree");

            auto p0 = edyn::test::random_vector(rng, -3, 11);
            auto p1 = edyn::test::random_vector(rng, -3, 11);
            visited.clear();
            expected.clear();
            compound.visit_ray(p0, p1, [&](std::size_t i) { visited.push_back(i); });
            for (std::size_t i = 0; i < compound.children.size(); ++i) {
                if (intersect_segment(compound.children[i].aabb, p0, p1)) expected.push_back(i);
            }
            std::sort(visited.begin(), visited.end());
            EXPECT_EQ(visited, expected) << "ray " << q << (with_tree ? " with tree" : " without tree");
        }
    }
}

TEST(compound_shape_test, segment_aabb_intersection) {
    AABB box{{-1, -1, -1}, {1, 1, 1}};
    EXPECT_TRUE(intersect_segment(box, {-5, 0, 0}, {5, 0, 0}));
    EXPECT_TRUE(intersect_segment(box, {0, 0, 0}, {0, 0, 0}));
    EXPECT_FALSE(intersect_segment(box, {-5, 0, 0}, {-2, 0, 0}));
    // Parallel to a face, outside and touching.
    EXPECT_FALSE(intersect_segment(box, {-5, scalar(1.01), 0}, {5, scalar(1.01), 0}));
    EXPECT_TRUE(intersect_segment(box, {-5, 1, 0}, {5, 1, 0}));
    // Passing by a corner diagonally.
    EXPECT_FALSE(intersect_segment(box, {-3, 0, 0}, {0, 3, 0}));
    EXPECT_TRUE(intersect_segment(box, {-2, 0, 0}, {0, 2, 0}));
}

TEST(compound_shape_test, validate_reports_bad_children) {
    compound_shape compound;
    compound.add_shape(sphere_shape{1});
    compound.add_shape(box_shape{1, 1, 1}, {3, 0, 0});
    compound.finish();
    std::get<box_shape>(compound.children[1].shape).half_extents.z = 0;
    expect_invalid_argument([&] { validate_shape(compound); },
                            {"compound_shape", "children[1]", "box_shape", "half_extents.z", "got 0"});
    std::get<box_shape>(compound.children[1].shape).half_extents.z = 1;
    compound.children[0].orientation = {0, 0, 0, 3};
    expect_invalid_argument([&] { validate_shape(compound); }, {"children[0].orientation", "unit"});
    compound.children[0].orientation = quaternion_identity;
    compound.children[0].position.x = std::numeric_limits<scalar>::infinity();
    expect_invalid_argument([&] { validate_shape(compound); }, {"children[0].position", "inf"});
    expect_invalid_argument([] { validate_shape(compound_shape{}); }, {"compound_shape", "empty"});
}

// Children changed in place: validate_shape refuses the compound until finish() takes their
// bounds and its tree again, after which queries see the change.
TEST(compound_shape_test, children_changed_in_place_need_finish_again) {
    compound_shape compound;
    compound.add_shape(box_shape{scalar(0.1), scalar(0.1), scalar(0.1)});
    compound.finish();
    std::get<box_shape>(compound.children[0].shape).half_extents = {1, scalar(0.1), 1};
    expect_invalid_argument([&] { validate_shape(compound); }, {"compound_shape", "children[0]", "finish()"});
    std::vector<std::size_t> seen;
    auto far_corner = AABB{{scalar(0.8), -1, scalar(0.8)}, {scalar(0.9), 1, scalar(0.9)}};
    compound.visit(far_corner, [&](std::size_t i) { seen.push_back(i); });
    EXPECT_TRUE(seen.empty()) << "the stale bounds were expected to hide the grown child";
    compound.finish();
    EXPECT_NO_THROW(validate_shape(compound));
    expect_vector_near(compound.children[0].aabb.max, {1, scalar(0.1), 1}, scalar(1e-6));
    compound.visit(far_corner, [&](std::size_t i) { seen.push_back(i); });
    EXPECT_EQ(seen, std::vector<std::size_t>{0});

    // Twelve children, one removed: the tree still names it until finish() builds it again.
    std::mt19937 rng(3);
    auto grid = grid_compound(rng);
    grid.children.resize(12);
    grid.finish();
    grid.children.pop_back();
    expect_invalid_argument([&] { validate_shape(grid); }, {"compound_shape", "removed", "finish()"});
    grid.finish();
    EXPECT_NO_THROW(validate_shape(grid));
    std::size_t most = 0;
    grid.visit(AABB{vector3{-100, -100, -100}, vector3{100, 100, 100}},
               [&](std::size_t i) { most = std::max(most, i); });
    EXPECT_EQ(most, 10u);
    // Down to eight: no tree is left.
    grid.children.resize(8);
    expect_invalid_argument([&] { validate_shape(grid); }, {"compound_shape", "finish()"});
    grid.finish();
    EXPECT_TRUE(grid.tree.empty());
    EXPECT_NO_THROW(validate_shape(grid));
}
