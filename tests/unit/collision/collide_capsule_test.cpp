#include "collide_test_helpers.hpp"

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar capsule_tol = scalar(1e-5);

// Distance between the capsules' segments by ternary search along A (independent of edyn).
scalar segment_distance(const vector3 &a0, const vector3 &a1, const vector3 &b0, const vector3 &b1) {
    return convex_min([&](scalar s) { return point_segment_distance(b0, b1, lerp(a0, a1, s)); });
}

} // namespace

TEST(collide_capsule_test, parallel_capsules_side_by_side_give_two_points) {
    collision_context ctx;
    ctx.posB = {0.5, 0.39, 0};
    capsule_shape capsule{0.2, 1, coordinate_axis::x};
    auto r = collide_pair(capsule, capsule, ctx);
    ASSERT_EQ(r.num_points, 2u);
    scalar xs[2];
    for (std::size_t i = 0; i < 2; ++i) {
        auto &p = r.point[i];
        EXPECT_NEAR(p.distance, -0.01, capsule_tol);
        expect_vec_near(p.normal, -vector3_y, capsule_tol);
        EXPECT_NEAR(p.pivotA.y, 0.2, capsule_tol);
        EXPECT_NEAR(p.pivotB.y, -0.2, capsule_tol);
        expect_feature(p.featureA, capsule_feature::side, 0);
        expect_feature(p.featureB, capsule_feature::side, 0);
        xs[i] = p.pivotA.x;
    }
    // The overlap of [-1, 1] and [-0.5, 1.5] along x.
    EXPECT_NEAR(std::min(xs[0], xs[1]), -0.5, capsule_tol);
    EXPECT_NEAR(std::max(xs[0], xs[1]), 1, capsule_tol);
    expect_consistent(r, ctx, capsule_tol);
}

TEST(collide_capsule_test, crossing_capsules_one_point) {
    collision_context ctx;
    ctx.threshold = 0.1;
    ctx.posA = {1, 2, 3};
    ctx.posB = ctx.posA + vector3{0.2, 0.45, -0.1};
    auto r = collide_pair(capsule_shape{0.2, 1, coordinate_axis::x},
                          capsule_shape{0.2, 1, coordinate_axis::z}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, 0.05, capsule_tol);
    expect_vec_near(p.normal, -vector3_y, capsule_tol);
    expect_vec_near(p.pivotA, {0.2, 0.2, 0}, capsule_tol);
    expect_vec_near(p.pivotB, {0, -0.2, 0.1}, capsule_tol);
    expect_feature(p.featureA, capsule_feature::side, 0);
    expect_feature(p.featureB, capsule_feature::side, 0);
    expect_consistent(r, ctx, capsule_tol);
}

TEST(collide_capsule_test, end_to_end_hemispheres) {
    collision_context ctx;
    ctx.threshold = 0.1;
    ctx.posB = {2.45, 0, 0};
    capsule_shape capsule{0.2, 1, coordinate_axis::x};
    auto r = collide_pair(capsule, capsule, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.05, capsule_tol);
    expect_vec_near(r.point[0].normal, -vector3_x, capsule_tol);
    expect_feature(r.point[0].featureA, capsule_feature::hemisphere, 0);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 1);
    expect_vec_near(r.point[0].pivotA, {1.2, 0, 0}, capsule_tol);
    expect_vec_near(r.point[0].pivotB, {-1.2, 0, 0}, capsule_tol);
    ctx.posB.x += scalar(0.06);
    EXPECT_EQ(collide_pair(capsule, capsule, ctx).num_points, 0u);
}

TEST(collide_capsule_test, end_on_side_rotated) {
    collision_context ctx;
    // B along its y axis, standing on A's side with its lower end (hemisphere 1).
    ctx.ornA = quaternion_axis_angle(vector3_y, 0.4);
    ctx.posB = rotate(ctx.ornA, vector3{0.5, 0, 0}) + vector3{0, 1.395, 0};
    auto r = collide_pair(capsule_shape{0.2, 2, coordinate_axis::x},
                          capsule_shape{0.2, 1, coordinate_axis::y}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.005, capsule_tol);
    expect_vec_near(r.point[0].normal, -vector3_y, capsule_tol);
    expect_feature(r.point[0].featureA, capsule_feature::side, 0);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 1);
    expect_consistent(r, ctx, capsule_tol);
}

TEST(collide_capsule_test, intersecting_axes_deep_penetration) {
    collision_context ctx;
    auto r = collide_pair(capsule_shape{0.2, 1, coordinate_axis::x},
                          capsule_shape{0.3, 1, coordinate_axis::z}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.5, capsule_tol);
    // The only direction leaving both axes: along y.
    EXPECT_NEAR(std::abs(r.point[0].normal.y), 1, capsule_tol);
    expect_consistent(r, ctx, capsule_tol);

    // Coincident parallel capsules: any direction orthogonal to the axes.
    r = collide_pair(capsule_shape{0.2, 1, coordinate_axis::x}, capsule_shape{0.2, 0.5, coordinate_axis::x},
                     ctx);
    ASSERT_GE(r.num_points, 1u);
    for (std::size_t i = 0; i < r.num_points; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.4, capsule_tol);
        EXPECT_NEAR(r.point[i].normal.x, 0, capsule_tol);
    }
    expect_consistent(r, ctx, capsule_tol);
}

TEST(collide_capsule_test, swapped_order_mirrors) {
    collision_context ctx;
    ctx.threshold = 0.1;
    ctx.posB = {0.2, 0.45, -0.1};
    capsule_shape a{0.2, 1, coordinate_axis::x}, b{0.2, 1, coordinate_axis::z};
    auto r = collide_pair(a, b, ctx);
    auto s = collide_pair(b, a, swap_context(ctx));
    ASSERT_EQ(r.num_points, 1u);
    ASSERT_EQ(s.num_points, 1u);
    EXPECT_NEAR(s.point[0].distance, r.point[0].distance, capsule_tol);
    expect_vec_near(s.point[0].normal, -r.point[0].normal, capsule_tol);
    expect_vec_near(s.point[0].pivotA, r.point[0].pivotB, capsule_tol);
    expect_vec_near(s.point[0].pivotB, r.point[0].pivotA, capsule_tol);
}

TEST(collide_capsule_test, random_matches_segment_distance) {
    rng random(31);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        capsule_shape a{random.uniform(0.05, 0.4), random.uniform(0, 1), coordinate_axis(i % 3)};
        capsule_shape b{random.uniform(0.05, 0.4), random.uniform(0, 1), coordinate_axis((i / 3) % 3)};
        collision_context ctx{random.vec(-0.8, 0.8), random.orientation(), random.vec(-0.8, 0.8),
                              random.orientation(), random.uniform(0, 0.2)};
        vector3 a0, a1, b0, b1;
        capsule_ends(a, ctx.posA, ctx.ornA, a0, a1);
        capsule_ends(b, ctx.posB, ctx.ornB, b0, b1);
        auto expected = segment_distance(a0, a1, b0, b1) - a.radius - b.radius;
        auto r = collide_pair(a, b, ctx);
        if (expected > ctx.threshold + capsule_tol) {
            EXPECT_EQ(r.num_points, 0u) << "case " << i;
            continue;
        }
        if (expected < ctx.threshold - capsule_tol) {
            ASSERT_GE(r.num_points, 1u) << "case " << i << " distance " << expected;
        }
        if (r.num_points == 0) continue;
        ++hits;
        EXPECT_NEAR(min_distance(r), expected, 1e-4) << "case " << i;
        for (std::size_t k = 0; k < r.num_points; ++k) {
            auto w = world_points(r.point[k], ctx);
            EXPECT_NEAR(point_segment_distance(a0, a1, w.a), a.radius, 1e-4) << "pivot A on the surface";
            EXPECT_NEAR(point_segment_distance(b0, b1, w.b), b.radius, 1e-4) << "pivot B on the surface";
        }
        expect_consistent(r, ctx, 1e-4);
        auto s = collide_pair(b, a, swap_context(ctx));
        ASSERT_EQ(s.num_points, r.num_points);
        EXPECT_NEAR(min_distance(s), min_distance(r), 1e-4);
    }
    EXPECT_GT(hits, 200);
}
