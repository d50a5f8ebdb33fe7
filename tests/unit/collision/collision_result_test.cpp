#include "edyn/collision/collision_result.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/math/geom.hpp"
#include <gtest/gtest.h>

using namespace edyn;

namespace {

collision_result::collision_point make(const vector3 &pivot, scalar distance) {
    collision_result::collision_point p;
    p.pivotA = pivot;
    p.pivotB = pivot - vector3_y * distance;
    p.normal = vector3_y;
    p.distance = distance;
    return p;
}

bool contains(const collision_result &r, const vector3 &pivot) {
    for (std::size_t i = 0; i < r.num_points; ++i) {
        if (distance(r.point[i].pivotA, pivot) < scalar(1e-6)) return true;
    }
    return false;
}

} // namespace

TEST(collision_result_test, appends_until_full) {
    collision_result r;
    r.add_point(make({0, 0, 0}, -0.1));
    r.add_point(make({1, 0, 0}, -0.2));
    EXPECT_EQ(r.num_points, 2u);
    EXPECT_EQ(r.point[1].distance, scalar(-0.2));
}

TEST(collision_result_test, merges_close_points_keeping_the_deeper) {
    auto half_merge = detail::contact_merge_distance * scalar(0.5);
    collision_result r;
    r.add_point(make({0, 0, 0}, -0.1));
    r.add_point(make({half_merge, 0, 0}, -0.05));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_EQ(r.point[0].distance, scalar(-0.1));
    r.add_point(make({0, 0, half_merge}, -0.3));
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_EQ(r.point[0].distance, scalar(-0.3));
    EXPECT_NEAR(r.point[0].pivotA.z, half_merge, 1e-7);
    // Three merge distances apart: two contacts.
    r.add_point(make({0, 0, 3 * half_merge * 2}, -0.3));
    EXPECT_EQ(r.num_points, 2u);
    // Same spot on B only (pivots on A far apart): still one contact.
    auto p = make({5, 0, 0}, -0.01);
    p.pivotB = r.point[1].pivotB;
    r.add_point(p);
    EXPECT_EQ(r.num_points, 2u);
    EXPECT_EQ(r.point[1].distance, scalar(-0.3));
}

TEST(collision_result_test, full_manifold_keeps_deepest_and_grows_area) {
    collision_result r;
    r.add_point(make({0, 0, 0}, -0.01));
    r.add_point(make({1, 0, 0}, -0.01));
    r.add_point(make({1, 0, 1}, -0.01));
    r.add_point(make({0.5, 0, 0.2}, -0.5)); // deepest, inside the triangle of the others
    ASSERT_EQ(r.num_points, 4u);
    auto area_before =
        quadrilateral_area(r.point[0].pivotA, r.point[1].pivotA, r.point[2].pivotA, r.point[3].pivotA);
    // The missing corner of the square increases the area: it replaces a point, never the deepest.
    r.add_point(make({0, 0, 1}, -0.01));
    ASSERT_EQ(r.num_points, 4u);
    EXPECT_TRUE(contains(r, {0.5, 0, 0.2}));
    EXPECT_TRUE(contains(r, {0, 0, 1}));
    auto area_after =
        quadrilateral_area(r.point[0].pivotA, r.point[1].pivotA, r.point[2].pivotA, r.point[3].pivotA);
    EXPECT_GT(area_after, area_before + scalar(0.05));
}

TEST(collision_result_test, full_manifold_rejects_point_that_shrinks_area) {
    collision_result r;
    vector3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    for (auto &c : corners)
        r.add_point(make(c, -0.1));
    r.add_point(make({0.5, 0, 0.5}, -0.05));
    ASSERT_EQ(r.num_points, 4u);
    for (auto &c : corners)
        EXPECT_TRUE(contains(r, c));
}

TEST(collision_result_test, full_manifold_always_takes_a_new_deepest_point) {
    collision_result r;
    vector3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    for (auto &c : corners)
        r.add_point(make(c, -0.1));
    r.add_point(make({0.5, 0, 0.5}, -0.2));
    ASSERT_EQ(r.num_points, 4u);
    EXPECT_TRUE(contains(r, {0.5, 0, 0.5}));
    // Three corners remain.
    int kept = 0;
    for (auto &c : corners)
        kept += contains(r, c);
    EXPECT_EQ(kept, 3);
}

TEST(collision_result_test, reduction_of_an_octagon_keeps_a_large_quad) {
    collision_result r;
    for (int i = 0; i < 8; ++i) {
        auto angle = pi2 * scalar(i) / 8;
        r.add_point(make({std::cos(angle), 0, std::sin(angle)}, i == 3 ? scalar(-0.2) : scalar(-0.1)));
    }
    ASSERT_EQ(r.num_points, 4u);
    EXPECT_TRUE(contains(r, {std::cos(pi2 * 3 / 8), 0, std::sin(pi2 * 3 / 8)}));
    vector3 v[4];
    for (int i = 0; i < 4; ++i)
        v[i] = r.point[i].pivotA;
    // The largest quad in a unit octagon is the square of area 2; greedy insertion must get
    // close to it.
    EXPECT_GE(quadrilateral_area(v[0], v[1], v[2], v[3]), scalar(1.7));
}

TEST(collision_result_test, swap_exchanges_roles) {
    collision_result r;
    auto p = make({1, 2, 3}, -0.25);
    p.featureA = collision_feature{box_feature::face, 2};
    p.featureB = collision_feature{capsule_feature::side, 0};
    r.add_point(p);
    r.swap();
    ASSERT_EQ(r.num_points, 1u);
    auto &q = r.point[0];
    EXPECT_EQ(q.pivotA, p.pivotB);
    EXPECT_EQ(q.pivotB, p.pivotA);
    EXPECT_EQ(q.normal, -p.normal);
    EXPECT_EQ(q.distance, p.distance);
    EXPECT_EQ(q.featureA, p.featureB);
    EXPECT_EQ(q.featureB, p.featureA);
    r.swap();
    EXPECT_EQ(r.point[0].pivotA, p.pivotA);
    EXPECT_EQ(r.point[0].normal, p.normal);
}
