#include "collide_test_helpers.hpp"
#include "edyn/math/geom.hpp"

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar plane_tol = scalar(1e-5);

const plane_shape ground{vector3_y, 0};

// A plane's own transform must not matter: put it somewhere odd (near enough for the pivot on
// the plane, in its body's object space, to keep the tests' precision).
collision_context with_plane_b(const vector3 &pos, const quaternion &orn, scalar threshold = scalar(0.02)) {
    return {pos, orn, {10, -5, 3}, quaternion_axis_angle(normalize(vector3{1, 2, 3}), 1), threshold};
}

scalar lowest_vertex(const vector3 &he, const collision_context &ctx) {
    auto lowest = large_scalar;
    for (auto &v : box_vertices(he, ctx.posA, ctx.ornA))
        lowest = std::min(lowest, v.y);
    return lowest;
}

bool has_vertex(const collision_result &r, std::uint32_t index) {
    for (std::size_t i = 0; i < r.num_points; ++i) {
        auto &f = r.point[i].featureA;
        if (f && std::get<box_feature>(f->feature) == box_feature::vertex && f->index == index) return true;
    }
    return false;
}

} // namespace

// Sphere.

TEST(collide_plane_test, sphere_touching_plane) {
    auto ctx = with_plane_b({1, 0.49, 2}, quaternion_axis_angle(vector3_x, 1));
    auto r = collide_pair(sphere_shape{0.5}, ground, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, -0.01, plane_tol);
    expect_vec_near(p.normal, vector3_y, plane_tol);
    // Every pivot is in its body's object space, the plane's too.
    expect_vec_near(world_points(p, ctx).b, {1, 0, 2}, plane_tol);
    expect_vec_near(to_world_space(p.pivotA, ctx.posA, ctx.ornA), {1, -0.01, 2}, plane_tol);
    EXPECT_FALSE(p.featureA.has_value());
    EXPECT_FALSE(p.featureB.has_value());
    expect_consistent(r, ctx, plane_tol);
}

TEST(collide_plane_test, plane_sphere_tilted_plane_and_threshold) {
    auto n = normalize(vector3{1, 1, 0});
    plane_shape plane{n, 1};
    collision_context ctx;
    ctx.posA = {7, 7, 7}; // ignored
    ctx.posB = n * scalar(1.3) + vector3{-2, 2, 5};
    ctx.threshold = 0.05;
    auto r = collide_pair(plane, sphere_shape{0.26}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.04, plane_tol);
    expect_vec_near(r.point[0].normal, -n, plane_tol);
    expect_vec_near(world_points(r.point[0], ctx).a, n + vector3{-2, 2, 5}, plane_tol);
    expect_consistent(r, ctx, plane_tol);
    ctx.posB += n * scalar(0.02);
    EXPECT_EQ(collide_pair(plane, sphere_shape{0.26}, ctx).num_points, 0u);
}

TEST(collide_plane_test, sphere_deep_below_plane) {
    auto ctx = with_plane_b({0, -3, 0}, quaternion_identity);
    auto r = collide_pair(sphere_shape{0.5}, ground, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -3.5, plane_tol);
    expect_vec_near(r.point[0].normal, vector3_y, plane_tol);
}

// Box.

TEST(collide_plane_test, box_resting_face_down_gives_four_vertices) {
    auto ctx = with_plane_b({2, 0.5, -1}, quaternion_identity);
    auto r = collide_pair(box_shape{0.5, 0.5, 0.5}, ground, ctx);
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(r.point[i].distance, 0, plane_tol);
        expect_vec_near(r.point[i].normal, vector3_y, plane_tol);
        EXPECT_NEAR(r.point[i].pivotA.y, -0.5, plane_tol);
        EXPECT_NEAR(world_points(r.point[i], ctx).b.y, 0, plane_tol);
    }
    // Lower vertices: y negative, bit 1 set.
    for (auto v : {2u, 3u, 6u, 7u})
        EXPECT_TRUE(has_vertex(r, v)) << "vertex " << v;
    expect_consistent(r, ctx, plane_tol);
}

TEST(collide_plane_test, box_on_edge_and_on_vertex) {
    auto half_diag = std::sqrt(scalar(2)) * scalar(0.5);
    auto ctx = with_plane_b({0, half_diag - scalar(0.01), 0}, quaternion_axis_angle(vector3_z, pi / 4));
    auto r = collide_pair(box_shape{0.5, 0.5, 0.5}, ground, ctx);
    ASSERT_EQ(r.num_points, 2u);
    for (std::size_t i = 0; i < 2; ++i)
        EXPECT_NEAR(r.point[i].distance, -0.01, plane_tol);
    // Rotated +45 degrees about z, world height is (x + y) / sqrt2: the lowest edge is at -x, -y.
    EXPECT_TRUE(has_vertex(r, 3u));
    EXPECT_TRUE(has_vertex(r, 7u));
    expect_consistent(r, ctx, plane_tol);

    // A vertex pointing down: the rotation taking (-1,-1,-1)/sqrt3 to -y.
    auto orn = shortest_arc(normalize(vector3{-1, -1, -1}), -vector3_y);
    ctx = with_plane_b({0.3, std::sqrt(scalar(3)) * scalar(0.5) + scalar(0.005), 0}, orn);
    r = collide_pair(box_shape{0.5, 0.5, 0.5}, ground, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.005, plane_tol);
    expect_feature(r.point[0].featureA, box_feature::vertex, 7);
    expect_vec_near(world_points(r.point[0], ctx).b, {0.3, 0, 0}, plane_tol);
}

TEST(collide_plane_test, box_beyond_threshold_and_deep) {
    auto ctx = with_plane_b({0, 0.53, 0}, quaternion_identity);
    EXPECT_EQ(collide_pair(box_shape{0.5, 0.5, 0.5}, ground, ctx).num_points, 0u);
    ctx = with_plane_b({0, -2, 0}, quaternion_axis_angle(vector3_x, 0.3));
    auto r = collide_pair(box_shape{0.5, 0.5, 0.5}, ground, ctx);
    ASSERT_EQ(r.num_points, 4u);
    EXPECT_NEAR(min_distance(r), lowest_vertex({0.5, 0.5, 0.5}, ctx), plane_tol);
}

TEST(collide_plane_test, thin_box_with_large_threshold_keeps_four) {
    // All eight vertices within the threshold: the four kept include the deepest and span the
    // whole bottom.
    auto ctx = with_plane_b({0, 0.05, 0}, quaternion_axis_angle(vector3_x, 0.01), 0.5);
    auto r = collide_pair(box_shape{1, 0.05, 1}, ground, ctx);
    ASSERT_EQ(r.num_points, 4u);
    EXPECT_NEAR(min_distance(r), lowest_vertex({1, 0.05, 1}, ctx), plane_tol);
    vector3 v[4];
    for (int i = 0; i < 4; ++i)
        v[i] = world_points(r.point[i], ctx).b;
    EXPECT_GT(quadrilateral_area(v[0], v[1], v[2], v[3]), scalar(3.5));
}

TEST(collide_plane_test, plane_box_is_the_swap_of_box_plane) {
    collision_context ctx{{5, 5, 5}, quaternion_identity, {2, 0.49, -1}, quaternion_identity, 0.02};
    auto r = collide_pair(ground, box_shape{0.5, 0.5, 0.5}, ctx);
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.01, plane_tol);
        expect_vec_near(r.point[i].normal, -vector3_y, plane_tol);
        EXPECT_NEAR(world_points(r.point[i], ctx).a.y, 0, plane_tol);
        EXPECT_NEAR(r.point[i].pivotB.y, -0.5, plane_tol);
        EXPECT_FALSE(r.point[i].featureA.has_value());
        ASSERT_TRUE(r.point[i].featureB.has_value());
    }
    expect_consistent(r, ctx, plane_tol);
}

// Capsule.

TEST(collide_plane_test, capsule_lying_gives_both_ends) {
    auto ctx = with_plane_b({0, 0.19, 0}, quaternion_axis_angle(vector3_y, 0.7));
    auto r = collide_pair(capsule_shape{0.2, 1, coordinate_axis::x}, ground, ctx);
    ASSERT_EQ(r.num_points, 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.01, plane_tol);
        expect_vec_near(r.point[i].normal, vector3_y, plane_tol);
        // Flat on the plane, the points are where the side meets the hemispheres: side.
        expect_feature(r.point[i].featureA, capsule_feature::side, 0);
        EXPECT_NEAR(std::abs(r.point[i].pivotA.x), 1, plane_tol);
        EXPECT_NEAR(r.point[i].pivotA.y, -0.2, plane_tol);
    }
    expect_consistent(r, ctx, plane_tol);
}

TEST(collide_plane_test, capsule_tilted_lower_end_is_hemisphere) {
    // Tilted down towards -x: hemisphere 1 (at -half_length) is lowest.
    auto ctx = with_plane_b({0, 0.25, 0}, quaternion_axis_angle(vector3_z, 0.05), 0.2);
    auto r = collide_pair(capsule_shape{0.2, 1, coordinate_axis::x}, ground, ctx);
    ASSERT_EQ(r.num_points, 2u);
    auto k = deepest_index(r);
    EXPECT_NEAR(r.point[k].distance, 0.05 - std::sin(scalar(0.05)), plane_tol);
    expect_feature(r.point[k].featureA, capsule_feature::hemisphere, 1);
    expect_feature(r.point[1 - k].featureA, capsule_feature::side, 0);
    EXPECT_NEAR(r.point[1 - k].distance, 0.05 + std::sin(scalar(0.05)), plane_tol);
    expect_consistent(r, ctx, plane_tol);
}

TEST(collide_plane_test, capsule_standing_gives_lower_hemisphere) {
    // Capsule along y standing upright.
    auto ctx = with_plane_b({0.5, 1.2, 0.5}, quaternion_identity);
    auto r = collide_pair(capsule_shape{0.2, 1, coordinate_axis::y}, ground, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0, plane_tol);
    expect_feature(r.point[0].featureA, capsule_feature::hemisphere, 1);
    expect_vec_near(r.point[0].pivotA, {0, -1.2, 0}, plane_tol);
    expect_vec_near(world_points(r.point[0], ctx).b, {0.5, 0, 0.5}, plane_tol);
    ctx.posA.y += scalar(0.03);
    EXPECT_EQ(collide_pair(capsule_shape{0.2, 1, coordinate_axis::y}, ground, ctx).num_points, 0u);
}

TEST(collide_plane_test, plane_capsule_is_the_swap_of_capsule_plane) {
    collision_context ctx{{}, quaternion_identity, {0, 1.2, 0}, quaternion_identity, 0.02};
    auto r = collide_pair(ground, capsule_shape{0.2, 1, coordinate_axis::y}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    expect_vec_near(r.point[0].normal, -vector3_y, plane_tol);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 1);
    expect_vec_near(world_points(r.point[0], ctx).a, {0, 0, 0}, plane_tol);
}

// Randomised: every pair against closed forms, both argument orders.

TEST(collide_plane_test, random_pairs_match_closed_forms) {
    rng random(21);
    int box_hits = 0, capsule_hits = 0, sphere_hits = 0;
    for (int i = 0; i < 1000; ++i) {
        plane_shape plane{random.unit(), random.uniform(-0.5, 0.5)};
        auto ctx = with_plane_b(random.vec(-1, 1), random.orientation(), random.uniform(0, 0.2));
        auto swapped = swap_context(ctx);

        box_shape box{random.vec(0.05, 0.8)};
        auto lowest = large_scalar;
        int under = 0;
        for (auto &v : box_vertices(box.half_extents, ctx.posA, ctx.ornA)) {
            auto d = dot(plane.normal, v) - plane.constant;
            lowest = std::min(lowest, d);
            under += d <= ctx.threshold;
        }
        auto r = collide_pair(box, plane, ctx);
        ASSERT_EQ(r.num_points, std::size_t(std::min(under, 4))) << "case " << i;
        if (r.num_points > 0) {
            ++box_hits;
            EXPECT_NEAR(min_distance(r), lowest, plane_tol) << "case " << i;
            expect_consistent(r, ctx, plane_tol);
            auto s = collide_pair(plane, box, swapped);
            ASSERT_EQ(s.num_points, r.num_points);
            EXPECT_NEAR(min_distance(s), lowest, plane_tol);
            expect_consistent(s, swapped, plane_tol);
        }

        capsule_shape capsule{random.uniform(0.05, 0.5), random.uniform(0.05, 1), coordinate_axis(i % 3)};
        vector3 p0, p1;
        capsule_ends(capsule, ctx.posA, ctx.ornA, p0, p1);
        auto d0 = dot(plane.normal, p0) - plane.constant - capsule.radius;
        auto d1 = dot(plane.normal, p1) - plane.constant - capsule.radius;
        r = collide_pair(capsule, plane, ctx);
        ASSERT_EQ(r.num_points, std::size_t((d0 <= ctx.threshold) + (d1 <= ctx.threshold))) << "case " << i;
        if (r.num_points > 0) {
            ++capsule_hits;
            EXPECT_NEAR(min_distance(r), std::min(d0, d1), plane_tol) << "case " << i;
            expect_consistent(r, ctx, plane_tol);
            auto s = collide_pair(plane, capsule, swapped);
            ASSERT_EQ(s.num_points, r.num_points);
            EXPECT_NEAR(min_distance(s), std::min(d0, d1), plane_tol);
        }

        sphere_shape sphere{random.uniform(0.05, 0.5)};
        auto ds = dot(plane.normal, ctx.posA) - plane.constant - sphere.radius;
        r = collide_pair(sphere, plane, ctx);
        ASSERT_EQ(r.num_points, ds <= ctx.threshold ? 1u : 0u) << "case " << i;
        if (r.num_points > 0) {
            ++sphere_hits;
            EXPECT_NEAR(r.point[0].distance, ds, plane_tol);
            expect_consistent(r, ctx, plane_tol);
            auto s = collide_pair(plane, sphere, swapped);
            ASSERT_EQ(s.num_points, 1u);
            expect_vec_near(s.point[0].normal, -plane.normal, plane_tol);
        }
    }
    EXPECT_GT(box_hits, 200);
    EXPECT_GT(capsule_hits, 200);
    EXPECT_GT(sphere_hits, 200);
}
