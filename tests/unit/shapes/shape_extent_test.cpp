#include "edyn/collision/collide.hpp"
#include "edyn/math/math.hpp"
#include "edyn/shapes/shape_extent.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

// shape_extent, the shapes' support function, against the farthest of many points of each shape,
// and the bound it gives the narrowphase against collide().
namespace {

using namespace edyn;
using edyn::test::random_direction;
using edyn::test::random_orientation;

// The shapes' surface samples (edyn::test::surface_samples) hold each shape's farthest point
// along any direction to within `sample_tolerance`.
constexpr scalar sample_tolerance = scalar(1e-4);

template<typename Shape>
void expect_support(const Shape &shape, scalar tolerance = sample_tolerance) {
    auto points = edyn::test::surface_samples(shape);
    std::mt19937 rng(11);
    for (int i = 0; i < 200; ++i) {
        auto orn = random_orientation(rng);
        auto dir = random_direction(rng);
        // dot(rotate(orn, p), dir), with the direction taken into object space once.
        auto local = rotate(conjugate(orn), dir);
        auto farthest = -large_scalar;
        for (const auto &p : points)
            farthest = std::max(farthest, dot(p, local));
        auto extent = shape_extent(shape, orn, dir);
        // Never short of a point of the shape, and no farther than its farthest point.
        EXPECT_GE(extent, farthest - scalar(1e-5)) << "direction " << edyn::test::str(dir);
        EXPECT_LE(extent, farthest + tolerance) << "direction " << edyn::test::str(dir);
    }
}

TEST(shape_extent_test, is_the_farthest_point_of_each_convex_shape) {
    expect_support(sphere_shape{scalar(0.7)}, scalar(2e-3));
    expect_support(box_shape{vector3{scalar(0.5), scalar(0.4), scalar(0.3)}});
    expect_support(cylinder_shape{scalar(0.3), scalar(0.4), coordinate_axis::y});
    expect_support(cylinder_shape{scalar(0.5), scalar(0.1), coordinate_axis::x});
    expect_support(capsule_shape{scalar(0.25), scalar(0.6), coordinate_axis::z}, scalar(2e-3));
}

TEST(shape_extent_test, a_polyhedron_reaches_its_farthest_vertex_from_its_origin) {
    // A cube of half size 0.5 whose centre is 0.25 along x from its origin: it reaches 0.75 along
    // +x and 0.25 along -x.
    auto cube = polyhedron_shape(edyn::test::cube_vertices(scalar(0.5), {scalar(0.25), 0, 0}),
                                 edyn::test::cube_faces());
    EXPECT_NEAR(shape_extent(cube, quaternion_identity, vector3_x), scalar(0.75), scalar(1e-6));
    EXPECT_NEAR(shape_extent(cube, quaternion_identity, -vector3_x), scalar(0.25), scalar(1e-6));
    // Turned half a turn about y, the far side is the other.
    auto half_turn = quaternion_axis_angle(vector3_y, pi);
    EXPECT_NEAR(shape_extent(cube, half_turn, -vector3_x), scalar(0.75), scalar(1e-5));
    std::mt19937 rng(13);
    auto vertices = edyn::test::cube_vertices(scalar(0.5), {scalar(0.25), 0, 0});
    for (int i = 0; i < 200; ++i) {
        auto orn = random_orientation(rng);
        auto dir = random_direction(rng);
        auto farthest = -large_scalar;
        for (const auto &v : vertices)
            farthest = std::max(farthest, dot(rotate(orn, v), dir));
        EXPECT_NEAR(shape_extent(cube, orn, dir), farthest, scalar(1e-5));
    }
}

TEST(shape_extent_test, a_compound_reaches_as_far_as_its_farthest_child) {
    compound_shape compound;
    compound.add_shape(box_shape{vector3{scalar(0.2), scalar(0.3), scalar(0.4)}}, vector3{1, 0, 0},
                       quaternion_axis_angle(vector3_z, scalar(0.5)));
    compound.add_shape(sphere_shape{scalar(0.5)}, vector3{-1, scalar(0.5), 0});
    compound.finish();
    std::mt19937 rng(17);
    for (int i = 0; i < 200; ++i) {
        auto orn = random_orientation(rng);
        auto dir = random_direction(rng);
        auto box_orn = orn * compound.children[0].orientation;
        auto box_extent =
            dot(rotate(orn, compound.children[0].position), dir) +
            shape_extent(box_shape{vector3{scalar(0.2), scalar(0.3), scalar(0.4)}}, box_orn, dir);
        auto sphere_extent = dot(rotate(orn, compound.children[1].position), dir) + scalar(0.5);
        EXPECT_NEAR(shape_extent(compound, orn, dir), std::max(box_extent, sphere_extent), scalar(1e-5));
    }
}

TEST(shape_extent_test, shapes_without_a_bound_rule_nothing_out) {
    EXPECT_EQ(shape_extent(plane_shape{vector3_y, 0}, quaternion_identity, vector3_y), large_scalar);
    EXPECT_EQ(shape_extent(mesh_shape{}, quaternion_identity, vector3_y), large_scalar);
    EXPECT_EQ(shape_extent(paged_mesh_shape{}, quaternion_identity, vector3_y), large_scalar);
    EXPECT_EQ(shape_extent(compound_shape{}, quaternion_identity, vector3_y), large_scalar);
    EXPECT_EQ(shape_extent(polyhedron_shape{}, quaternion_identity, vector3_y), large_scalar);
    // Nor do compounds with a tree over their children, which may be many.
    compound_shape large;
    for (std::size_t i = 0; i <= compound_shape::max_children_without_tree; ++i)
        large.add_shape(sphere_shape{scalar(0.1)}, vector3{scalar(i), 0, 0});
    large.finish();
    EXPECT_EQ(shape_extent(large, quaternion_identity, vector3_x), large_scalar);
}

// The narrowphase skips a pair whose gap along the line between the origins exceeds its
// threshold: collide() must give such a pair no point.
template<typename A, typename B>
void expect_no_points_beyond_the_gap(const A &a, const B &b, scalar reach) {
    std::mt19937 rng(19);
    std::uniform_real_distribution<scalar> offset(scalar(0.3), scalar(1.2));
    int ruled_out = 0;
    for (int i = 0; i < 4000; ++i) {
        auto orn_a = random_orientation(rng), orn_b = random_orientation(rng);
        auto pos_b = random_direction(rng) * (offset(rng) * reach);
        auto threshold = scalar(0.02);
        auto distance = length(pos_b);
        auto dir = pos_b / distance;
        auto gap = distance - shape_extent(a, orn_a, dir) - shape_extent(b, orn_b, -dir);
        if (!(gap > threshold)) continue;
        ++ruled_out;
        collision_result result;
        collide(a, b, collision_context{vector3_zero, orn_a, pos_b, orn_b, threshold}, result);
        EXPECT_EQ(result.num_points, 0u) << "a pair " << gap << " m apart along the line between them";
    }
    EXPECT_GT(ruled_out, 100) << "the placements should test the bound";
}

TEST(shape_extent_test, pairs_it_rules_out_have_no_contact_point) {
    cylinder_shape cylinder{scalar(0.3), scalar(0.5), coordinate_axis::y};
    box_shape box{vector3{scalar(0.5), scalar(0.3), scalar(0.4)}};
    capsule_shape capsule{scalar(0.2), scalar(0.4), coordinate_axis::x};
    sphere_shape sphere{scalar(0.35)};
    auto cube = polyhedron_shape(edyn::test::cube_vertices(scalar(0.4), {scalar(0.1), 0, 0}),
                                 edyn::test::cube_faces());
    expect_no_points_beyond_the_gap(cylinder, cylinder, scalar(1.6));
    expect_no_points_beyond_the_gap(cylinder, box, scalar(1.6));
    expect_no_points_beyond_the_gap(cylinder, capsule, scalar(1.6));
    expect_no_points_beyond_the_gap(box, box, scalar(1.6));
    expect_no_points_beyond_the_gap(capsule, sphere, scalar(1.4));
    expect_no_points_beyond_the_gap(cube, cylinder, scalar(1.6));
}

} // namespace
