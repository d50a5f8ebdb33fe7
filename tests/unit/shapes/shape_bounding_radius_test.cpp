#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/shapes/shape_bounding_radius.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <gtest/gtest.h>
#include <random>

using namespace edyn;

namespace {

// The farthest any point of the shape reaches along x over many orientations, measured with
// shape_aabb: never beyond the bounding radius, and close to it when the bound is tight.
template<typename Shape>
scalar farthest_reach(const Shape &shape) {
    std::mt19937 rng(7);
    scalar reach = 0;
    for (int i = 0; i < 20000; ++i) {
        auto aabb = shape_aabb(shape, vector3_zero, edyn::test::random_orientation(rng));
        reach = std::max({reach, aabb.max.x, -aabb.min.x});
    }
    return reach;
}

template<typename Shape>
void expect_tight_bound(const Shape &shape, scalar expected) {
    auto radius = shape_bounding_radius(shape);
    EXPECT_NEAR(radius, expected, scalar(1e-5));
    auto reach = farthest_reach(shape);
    EXPECT_LE(reach, radius * (1 + scalar(1e-5)));
    EXPECT_GE(reach, radius * scalar(0.99)) << "the bound should be the farthest point, not more";
}

} // namespace

TEST(shape_bounding_radius_test, holds_each_convex_shape_tightly) {
    expect_tight_bound(sphere_shape{scalar(0.7)}, scalar(0.7));
    expect_tight_bound(box_shape{vector3{scalar(0.5), scalar(0.4), scalar(0.3)}}, std::sqrt(scalar(0.5)));
    expect_tight_bound(capsule_shape{scalar(0.25), scalar(0.6), coordinate_axis::z}, scalar(0.85));
    expect_tight_bound(cylinder_shape{scalar(0.3), scalar(0.4), coordinate_axis::y}, scalar(0.5));
    // A cube of half size 0.5 moved off its origin by 0.25 along x: its far corners are at
    // |(0.75, 0.5, 0.5)| from the origin.
    auto cube = polyhedron_shape(edyn::test::cube_vertices(scalar(0.5), {scalar(0.25), 0, 0}),
                                 edyn::test::cube_faces());
    expect_tight_bound(cube, std::sqrt(scalar(0.75 * 0.75 + 0.5)));
}

TEST(shape_bounding_radius_test, shapes_without_a_bound_rule_nothing_out) {
    EXPECT_EQ(shape_bounding_radius(plane_shape{vector3_y, 0}), large_scalar);
    EXPECT_EQ(shape_bounding_radius(compound_shape{}), large_scalar);
    EXPECT_EQ(shape_bounding_radius(polyhedron_shape{}), large_scalar);
}
