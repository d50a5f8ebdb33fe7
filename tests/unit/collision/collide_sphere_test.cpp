#include "collide_test_helpers.hpp"

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar sphere_tol = scalar(1e-5);

} // namespace

// Sphere–sphere.

TEST(collide_sphere_test, spheres_apart_within_threshold) {
    collision_context ctx;
    ctx.posA = {0, 0, 0};
    ctx.ornA = quaternion_axis_angle(vector3_z, half_pi);
    ctx.posB = {1.01, 0, 0};
    ctx.threshold = 0.02;
    auto r = collide_pair(sphere_shape{0.5}, sphere_shape{0.5}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, 0.01, sphere_tol);
    expect_vec_near(p.normal, {-1, 0, 0}, sphere_tol);
    // A is turned 90 degrees about z: world +x is its -y.
    expect_vec_near(p.pivotA, {0, -0.5, 0}, sphere_tol);
    expect_vec_near(p.pivotB, {-0.5, 0, 0}, sphere_tol);
    EXPECT_FALSE(p.featureA.has_value());
    EXPECT_FALSE(p.featureB.has_value());
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, spheres_beyond_threshold) {
    collision_context ctx;
    ctx.posB = {1.03, 0, 0};
    ctx.threshold = 0.02;
    EXPECT_EQ(collide_pair(sphere_shape{0.5}, sphere_shape{0.5}, ctx).num_points, 0u);
}

TEST(collide_sphere_test, spheres_penetrating_off_axis) {
    collision_context ctx;
    ctx.posA = {1, 2, 3};
    ctx.posB = ctx.posA + normalize(vector3{1, -2, 2}) * scalar(0.6);
    auto r = collide_pair(sphere_shape{0.4}, sphere_shape{0.3}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.1, sphere_tol);
    expect_vec_near(r.point[0].normal, -normalize(vector3{1, -2, 2}), sphere_tol);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, concentric_spheres_separate_upwards) {
    collision_context ctx;
    ctx.posA = ctx.posB = {3, 1, 2};
    auto r = collide_pair(sphere_shape{0.4}, sphere_shape{0.3}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.7, sphere_tol);
    expect_vec_near(r.point[0].normal, vector3_y, sphere_tol);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_sphere_random_matches_closed_form) {
    rng random(11);
    for (int i = 0; i < 500; ++i) {
        collision_context ctx{random.vec(-1, 1), random.orientation(), random.vec(-1, 1),
                              random.orientation(), random.uniform(0, 0.3)};
        sphere_shape a{random.uniform(0.05, 0.6)}, b{random.uniform(0.05, 0.6)};
        auto expected = distance(ctx.posA, ctx.posB) - a.radius - b.radius;
        auto r = collide_pair(a, b, ctx);
        ASSERT_EQ(r.num_points, expected <= ctx.threshold ? 1u : 0u)
            << "case " << i << " distance " << expected;
        if (r.num_points == 0) continue;
        EXPECT_NEAR(r.point[0].distance, expected, sphere_tol) << "case " << i;
        EXPECT_NEAR(length(r.point[0].pivotA), a.radius, sphere_tol);
        EXPECT_NEAR(length(r.point[0].pivotB), b.radius, sphere_tol);
        expect_consistent(r, ctx, sphere_tol);
        auto s = collide_pair(b, a, swap_context(ctx));
        ASSERT_EQ(s.num_points, 1u);
        expect_vec_near(s.point[0].normal, -r.point[0].normal, sphere_tol);
    }
}

// Sphere–box.

TEST(collide_sphere_test, sphere_resting_on_box_face) {
    collision_context ctx;
    ctx.posA = {0.3, 0.9, 0.2};
    ctx.posB = {0, 0, 0};
    auto r = collide_pair(sphere_shape{0.4}, box_shape{1, 0.5, 2}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, 0, sphere_tol);
    expect_vec_near(p.normal, vector3_y, sphere_tol);
    expect_vec_near(p.pivotB, {0.3, 0.5, 0.2}, sphere_tol);
    expect_vec_near(p.pivotA, {0, -0.4, 0}, sphere_tol);
    EXPECT_FALSE(p.featureA.has_value());
    expect_feature(p.featureB, box_feature::face, 2);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_near_box_edge_and_vertex) {
    collision_context ctx;
    ctx.threshold = 0.1;
    ctx.posA = {1.1, 0.6, 0};
    auto r = collide_pair(sphere_shape{0.1}, box_shape{1, 0.5, 2}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, std::sqrt(scalar(0.02)) - scalar(0.1), sphere_tol);
    expect_vec_near(r.point[0].normal, normalize(vector3{1, 1, 0}), sphere_tol);
    // Edge along z on the +x, +y side.
    expect_feature(r.point[0].featureB, box_feature::edge, 8);
    expect_consistent(r, ctx, sphere_tol);

    ctx.posA = {-1.05, -0.55, -2.05};
    r = collide_pair(sphere_shape{0.05}, box_shape{1, 0.5, 2}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, std::sqrt(scalar(3)) * scalar(0.05) - scalar(0.05), sphere_tol);
    expect_feature(r.point[0].featureB, box_feature::vertex, 7);
    expect_vec_near(r.point[0].pivotB, {-1, -0.5, -2}, sphere_tol);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_centre_inside_box_leaves_through_nearest_face) {
    collision_context ctx;
    ctx.posB = {5, 0, 0};
    ctx.ornB = quaternion_axis_angle(vector3_y, half_pi); // box -x face looks towards world +z
    ctx.posA = ctx.posB + rotate(ctx.ornB, vector3{-0.9, 0.1, 0});
    auto r = collide_pair(sphere_shape{0.2}, box_shape{1, 0.5, 2}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, -0.3, sphere_tol);
    expect_vec_near(p.normal, rotate(ctx.ornB, vector3{-1, 0, 0}), sphere_tol);
    expect_vec_near(p.normal, vector3_z, sphere_tol);
    expect_feature(p.featureB, box_feature::face, 1);
    expect_vec_near(p.pivotB, {-1, 0.1, 0}, sphere_tol);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_over_rotated_box_edge) {
    collision_context ctx;
    // Box turned 45 degrees about z: its +x+y edge along z points straight up.
    ctx.ornB = quaternion_axis_angle(vector3_z, pi / 4);
    ctx.threshold = 0.1;
    auto top = std::sqrt(scalar(2));
    ctx.posA = {0, top + scalar(0.25), 0.3};
    auto r = collide_pair(sphere_shape{0.2}, box_shape{1, 1, 1}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.05, sphere_tol);
    expect_vec_near(r.point[0].normal, vector3_y, sphere_tol);
    expect_feature(r.point[0].featureB, box_feature::edge, 8);
    expect_vec_near(r.point[0].pivotB, {1, 1, 0.3}, sphere_tol);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_box_beyond_threshold) {
    collision_context ctx;
    ctx.posA = {0, 1.5 + 0.021, 0};
    ctx.threshold = 0.02;
    EXPECT_EQ(collide_pair(sphere_shape{0.5}, box_shape{1, 1, 1}, ctx).num_points, 0u);
    ctx.posA.y -= scalar(0.002);
    EXPECT_EQ(collide_pair(sphere_shape{0.5}, box_shape{1, 1, 1}, ctx).num_points, 1u);
}

TEST(collide_sphere_test, box_sphere_is_the_swap_of_sphere_box) {
    collision_context ctx;
    ctx.posA = {0, 0, 0};
    ctx.posB = {0.3, 0.9, 0.2};
    auto r = collide_pair(box_shape{1, 0.5, 2}, sphere_shape{0.4}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, 0, sphere_tol);
    expect_vec_near(p.normal, -vector3_y, sphere_tol);
    expect_vec_near(p.pivotA, {0.3, 0.5, 0.2}, sphere_tol);
    expect_vec_near(p.pivotB, {0, -0.4, 0}, sphere_tol);
    expect_feature(p.featureA, box_feature::face, 2);
    EXPECT_FALSE(p.featureB.has_value());
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_box_random_matches_signed_distance) {
    rng random(12);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        box_shape box{random.vec(0.1, 1)};
        sphere_shape sphere{random.uniform(0.05, 0.6)};
        collision_context ctx{random.vec(-1.5, 1.5), random.orientation(), random.vec(-0.5, 0.5),
                              random.orientation(), random.uniform(0, 0.2)};
        auto expected =
            box_sdf(box.half_extents, to_object_space(ctx.posA, ctx.posB, ctx.ornB)) - sphere.radius;
        auto r = collide_pair(sphere, box, ctx);
        ASSERT_EQ(r.num_points, expected <= ctx.threshold ? 1u : 0u)
            << "case " << i << " distance " << expected;
        if (r.num_points == 0) continue;
        ++hits;
        auto &p = r.point[0];
        EXPECT_NEAR(p.distance, expected, sphere_tol) << "case " << i;
        EXPECT_NEAR(box_sdf(box.half_extents, p.pivotB), 0, sphere_tol)
            << "pivot on the box surface, case " << i;
        EXPECT_NEAR(length(p.pivotA), sphere.radius, sphere_tol);
        expect_consistent(r, ctx, sphere_tol);
        auto s = collide_pair(box, sphere, swap_context(ctx));
        ASSERT_EQ(s.num_points, 1u);
        EXPECT_NEAR(s.point[0].distance, p.distance, sphere_tol);
        expect_vec_near(s.point[0].normal, -p.normal, sphere_tol);
        expect_vec_near(s.point[0].pivotA, p.pivotB, sphere_tol);
    }
    EXPECT_GT(hits, 200);
}

// Sphere–capsule.

TEST(collide_sphere_test, sphere_beside_capsule_side) {
    collision_context ctx;
    ctx.threshold = 0.2;
    ctx.posA = {0.3, 0.6, 0};
    auto r = collide_pair(sphere_shape{0.3}, capsule_shape{0.2, 1, coordinate_axis::x}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, 0.1, sphere_tol);
    expect_vec_near(p.normal, vector3_y, sphere_tol);
    expect_vec_near(p.pivotB, {0.3, 0.2, 0}, sphere_tol);
    expect_feature(p.featureB, capsule_feature::side, 0);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_at_capsule_hemispheres) {
    collision_context ctx;
    ctx.threshold = 0.1;
    // Capsule along its z axis, turned so that z points along world y.
    ctx.ornB = quaternion_axis_angle(vector3_x, -half_pi);
    capsule_shape capsule{0.2, 1, coordinate_axis::z};
    ctx.posA = {0, 1.45, 0};
    auto r = collide_pair(sphere_shape{0.2}, capsule, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.05, sphere_tol);
    expect_vec_near(r.point[0].normal, vector3_y, sphere_tol);
    expect_vec_near(r.point[0].pivotB, {0, 0, 1.2}, sphere_tol);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 0);
    expect_consistent(r, ctx, sphere_tol);

    ctx.posA = {0.1, -1.3, 0};
    r = collide_pair(sphere_shape{0.2}, capsule, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, std::sqrt(scalar(0.1)) - scalar(0.4), sphere_tol);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 1);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, sphere_centre_on_capsule_axis) {
    collision_context ctx;
    ctx.posA = {0.5, 0, 0};
    auto r = collide_pair(sphere_shape{0.1}, capsule_shape{0.2, 1, coordinate_axis::x}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.3, sphere_tol);
    EXPECT_NEAR(dot(r.point[0].normal, vector3_x), 0, sphere_tol);
    expect_consistent(r, ctx, sphere_tol);
}

TEST(collide_sphere_test, capsule_sphere_is_the_swap_of_sphere_capsule) {
    collision_context ctx;
    ctx.threshold = 0.2;
    ctx.posB = {0.3, 0.6, 0};
    auto r = collide_pair(capsule_shape{0.2, 1, coordinate_axis::x}, sphere_shape{0.3}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.1, sphere_tol);
    expect_vec_near(r.point[0].normal, -vector3_y, sphere_tol);
    expect_vec_near(r.point[0].pivotA, {0.3, 0.2, 0}, sphere_tol);
    expect_feature(r.point[0].featureA, capsule_feature::side, 0);
    EXPECT_FALSE(r.point[0].featureB.has_value());
    ctx.posB = {0.3, 0.72, 0};
    EXPECT_EQ(collide_pair(capsule_shape{0.2, 1, coordinate_axis::x}, sphere_shape{0.3}, ctx).num_points, 0u);
}

TEST(collide_sphere_test, sphere_capsule_random_matches_segment_distance) {
    rng random(13);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        capsule_shape capsule{random.uniform(0.05, 0.5), random.uniform(0, 1), coordinate_axis(i % 3)};
        sphere_shape sphere{random.uniform(0.05, 0.5)};
        collision_context ctx{random.vec(-1, 1), random.orientation(), random.vec(-0.5, 0.5),
                              random.orientation(), random.uniform(0, 0.2)};
        vector3 p0, p1;
        capsule_ends(capsule, ctx.posB, ctx.ornB, p0, p1);
        auto expected = point_segment_distance(p0, p1, ctx.posA) - capsule.radius - sphere.radius;
        auto r = collide_pair(sphere, capsule, ctx);
        ASSERT_EQ(r.num_points, expected <= ctx.threshold ? 1u : 0u)
            << "case " << i << " distance " << expected;
        if (r.num_points == 0) continue;
        ++hits;
        auto &p = r.point[0];
        EXPECT_NEAR(p.distance, expected, sphere_tol) << "case " << i;
        auto on_b = to_world_space(p.pivotB, ctx.posB, ctx.ornB);
        EXPECT_NEAR(point_segment_distance(p0, p1, on_b), capsule.radius, sphere_tol)
            << "pivot on the capsule";
        expect_consistent(r, ctx, sphere_tol);
        auto s = collide_pair(capsule, sphere, swap_context(ctx));
        ASSERT_EQ(s.num_points, 1u);
        EXPECT_NEAR(s.point[0].distance, p.distance, sphere_tol);
        expect_vec_near(s.point[0].normal, -p.normal, sphere_tol);
    }
    EXPECT_GT(hits, 200);
}
