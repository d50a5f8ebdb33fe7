#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include "math_test_helpers.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace edyn;
using namespace math_test;

namespace {

struct random_source {
    std::mt19937 engine{1234};
    scalar uniform(scalar lo, scalar hi) { return std::uniform_real_distribution<scalar>(lo, hi)(engine); }
    vector3 vec(scalar lo, scalar hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
};

// Brute force: distance between segments sampled densely, then refined around the best sample.
scalar sampled_segment_distance(const vector3 &a0, const vector3 &a1, const vector3 &b0, const vector3 &b1) {
    auto best = large_scalar;
    constexpr int n = 400;
    for (int i = 0; i <= n; ++i) {
        auto p = lerp(a0, a1, scalar(i) / n);
        best = std::min(best, std::sqrt(distance_sqr_point_segment(b0, b1, p)));
    }
    return best;
}

} // namespace

TEST(geom_test, closest_point_segment_interior_and_ends) {
    scalar t;
    expect_near(closest_point_segment({0, 0, 0}, {2, 0, 0}, {1, 3, 0}, t), {1, 0, 0});
    EXPECT_NEAR(t, 0.5, tol);
    expect_near(closest_point_segment({0, 0, 0}, {2, 0, 0}, {-1, 1, 0}, t), {0, 0, 0});
    EXPECT_EQ(t, 0);
    expect_near(closest_point_segment({0, 0, 0}, {2, 0, 0}, {5, 1, 1}, t), {2, 0, 0});
    EXPECT_EQ(t, 1);
    // Degenerate segment.
    expect_near(closest_point_segment({1, 1, 1}, {1, 1, 1}, {5, 1, 1}, t), {1, 1, 1});
    EXPECT_EQ(t, 0);
    EXPECT_NEAR(distance_sqr_point_segment({0, 0, 0}, {2, 0, 0}, {1, 3, 4}), 25, tol);
}

TEST(geom_test, closest_point_line_unclamped) {
    scalar t;
    expect_near(closest_point_line({0, 0, 0}, {2, 0, 0}, {5, 1, 0}, t), {5, 0, 0});
    EXPECT_NEAR(t, 2.5, tol);
}

TEST(geom_test, segment_segment_crossing) {
    auto r = closest_points_segment_segment({-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1});
    ASSERT_EQ(r.num_points, 1u);
    expect_near(r.pointA[0], {0, 0, 0});
    expect_near(r.pointB[0], {0, 0, 1});
    EXPECT_NEAR(r.sA[0], 0.5, tol);
    EXPECT_NEAR(r.sB[0], 0.5, tol);
    EXPECT_NEAR(r.distance_sqr, 1, tol);
}

TEST(geom_test, segment_segment_clamped_ends) {
    // B lies beyond A's end: the closest pair joins A's end to B's nearest point.
    auto r = closest_points_segment_segment({0, 0, 0}, {1, 0, 0}, {3, -1, 2}, {3, 1, 2});
    ASSERT_EQ(r.num_points, 1u);
    expect_near(r.pointA[0], {1, 0, 0});
    expect_near(r.pointB[0], {3, 0, 2});
    EXPECT_EQ(r.sA[0], 1);
    EXPECT_NEAR(r.distance_sqr, 8, tol);
}

TEST(geom_test, segment_segment_parallel_overlap_gives_two_points) {
    auto r = closest_points_segment_segment({0, 0, 0}, {4, 0, 0}, {3, 1, 0}, {-2, 1, 0});
    ASSERT_EQ(r.num_points, 2u);
    EXPECT_NEAR(r.distance_sqr, 1, tol);
    // Overlap of [0, 4] and [-2, 3] on A's line is [0, 3].
    expect_near(r.pointA[0], {0, 0, 0});
    expect_near(r.pointB[0], {0, 1, 0});
    expect_near(r.pointA[1], {3, 0, 0});
    expect_near(r.pointB[1], {3, 1, 0});
    EXPECT_NEAR(r.sB[0], 0.6, tol);
    EXPECT_NEAR(r.sB[1], 0, tol);
}

TEST(geom_test, segment_segment_parallel_disjoint_gives_nearest_ends) {
    auto r = closest_points_segment_segment({0, 0, 0}, {1, 0, 0}, {3, 1, 0}, {2, 1, 0});
    ASSERT_EQ(r.num_points, 1u);
    expect_near(r.pointA[0], {1, 0, 0});
    expect_near(r.pointB[0], {2, 1, 0});
    EXPECT_NEAR(r.distance_sqr, 2, tol);
}

TEST(geom_test, segment_segment_degenerate) {
    auto r = closest_points_segment_segment({1, 1, 1}, {1, 1, 1}, {0, 0, 0}, {2, 0, 0});
    ASSERT_EQ(r.num_points, 1u);
    expect_near(r.pointB[0], {1, 0, 0});
    EXPECT_NEAR(r.distance_sqr, 2, tol);
    r = closest_points_segment_segment({0, 0, 0}, {2, 0, 0}, {1, 1, 1}, {1, 1, 1});
    expect_near(r.pointA[0], {1, 0, 0});
    r = closest_points_segment_segment({0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {1, 1, 1});
    EXPECT_NEAR(r.distance_sqr, 3, tol);
}

TEST(geom_test, segment_segment_random_matches_sampling) {
    random_source random;
    for (int i = 0; i < 300; ++i) {
        auto a0 = random.vec(-1, 1), a1 = random.vec(-1, 1), b0 = random.vec(-1, 1), b1 = random.vec(-1, 1);
        auto r = closest_points_segment_segment(a0, a1, b0, b1);
        auto expected = sampled_segment_distance(a0, a1, b0, b1);
        // Sampling overestimates by at most half a step along A.
        EXPECT_LE(std::sqrt(r.distance_sqr), expected + tol) << "case " << i;
        EXPECT_GE(std::sqrt(r.distance_sqr), expected - distance(a0, a1) / 400 - tol) << "case " << i;
        EXPECT_NEAR(std::sqrt(r.distance_sqr), distance(r.pointA[0], r.pointB[0]), tol);
        expect_near(r.pointA[0], lerp(a0, a1, r.sA[0]));
        expect_near(r.pointB[0], lerp(b0, b1, r.sB[0]));
    }
}

TEST(geom_test, clip_interval_and_segment) {
    scalar t0 = 0, t1 = 1;
    EXPECT_TRUE(clip_line_interval({0, 0, 0}, {4, 0, 0}, {1, 0, 0}, 1, t0, t1));
    EXPECT_NEAR(t1, 0.25, tol);
    EXPECT_TRUE(clip_line_interval({0, 0, 0}, {4, 0, 0}, {-1, 0, 0}, -0.5, t0, t1));
    EXPECT_NEAR(t0, 0.125, tol);
    EXPECT_FALSE(clip_line_interval({0, 0, 0}, {4, 0, 0}, {-1, 0, 0}, -2, t0, t1));
    // Parallel to the plane: all or nothing.
    t0 = 0, t1 = 1;
    EXPECT_TRUE(clip_line_interval({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, t0, t1));
    EXPECT_FALSE(clip_line_interval({0, 2, 0}, {1, 0, 0}, {0, 1, 0}, 1, t0, t1));

    vector3 p0{-2, 0, 0}, p1{2, 0, 0};
    EXPECT_TRUE(clip_segment_half_space(p0, p1, {1, 0, 0}, 1));
    expect_near(p0, {-2, 0, 0});
    expect_near(p1, {1, 0, 0});
    EXPECT_FALSE(clip_segment_half_space(p0, p1, {1, 0, 0}, -3));
}

TEST(geom_test, plane_helpers) {
    vector3 n{0, 1, 0};
    EXPECT_NEAR(distance_point_plane(n, 2, {5, 3, 1}), 1, tol);
    expect_near(project_point_plane(n, 2, {5, 3, 1}), {5, 2, 1});
}

TEST(geom_test, box_helpers) {
    vector3 he{1, 2, 3};
    expect_near(closest_point_box(he, {5, -1, -9}), {1, -1, -3});
    expect_near(closest_point_box(he, {0.5, 0.5, 0.5}), {0.5, 0.5, 0.5});
    EXPECT_TRUE(point_in_box(he, {1, 2, 3}));
    EXPECT_FALSE(point_in_box(he, {1.01, 0, 0}));
    EXPECT_TRUE(point_in_box(he, {1.01, 0, 0}, 0.02));
    expect_near(support_point_box(he, {1, -1, 0}), {1, -2, 3});
    EXPECT_NEAR(box_projection_radius(he, normalize(vector3{1, 1, 0})), 3 / std::sqrt(scalar(2)), tol);

    scalar sign, depth;
    EXPECT_EQ(nearest_box_face(he, {0.2, -1.9, 0}, sign, depth), 1);
    EXPECT_EQ(sign, -1);
    EXPECT_NEAR(depth, 0.1, tol);
    EXPECT_EQ(nearest_box_face(he, {-0.95, 0, 2.9}, sign, depth), 0);
    EXPECT_EQ(sign, -1);
    EXPECT_NEAR(depth, 0.05, tol);
}

TEST(geom_test, segment_box_cases) {
    vector3 he{1, 1, 1};
    scalar t;
    vector3 on_seg, on_box;
    // Above the top face, parallel to it.
    auto d2 = closest_points_segment_box(he, {-3, 2, 0}, {3, 2, 0}, t, on_seg, on_box);
    EXPECT_NEAR(d2, 1, tol);
    EXPECT_NEAR(on_seg.y, 2, tol);
    EXPECT_NEAR(on_box.y, 1, tol);
    EXPECT_LE(std::abs(on_box.x), 1 + tol);
    // Diagonal past the edge x = 1, y = 1.
    d2 = closest_points_segment_box(he, {3, 0, -0.5}, {0, 3, -0.5}, t, on_seg, on_box);
    EXPECT_NEAR(d2, 0.5, tol);
    expect_near(on_box, {1, 1, -0.5});
    expect_near(on_seg, {1.5, 1.5, -0.5});
    EXPECT_NEAR(t, 0.5, tol);
    // Through the box.
    d2 = closest_points_segment_box(he, {-3, 0, 0}, {3, 0.5, 0}, t, on_seg, on_box);
    EXPECT_EQ(d2, 0);
    // End near a vertex.
    d2 = closest_points_segment_box(he, {2, 2, 2}, {5, 5, 5}, t, on_seg, on_box);
    EXPECT_NEAR(d2, 3, tol);
    EXPECT_EQ(t, 0);
    expect_near(on_box, {1, 1, 1});
}

TEST(geom_test, segment_box_random_matches_sampling) {
    random_source random;
    for (int i = 0; i < 300; ++i) {
        auto he = random.vec(0.1, 1);
        auto p0 = random.vec(-2, 2), p1 = random.vec(-2, 2);
        scalar t;
        vector3 on_seg, on_box;
        auto d = std::sqrt(closest_points_segment_box(he, p0, p1, t, on_seg, on_box));
        auto best = large_scalar;
        constexpr int n = 2000;
        for (int k = 0; k <= n; ++k) {
            auto p = lerp(p0, p1, scalar(k) / n);
            best = std::min(best, distance(p, closest_point_box(he, p)));
        }
        EXPECT_LE(d, best + tol) << "case " << i;
        EXPECT_GE(d, best - distance(p0, p1) / n - tol) << "case " << i;
        EXPECT_NEAR(d, distance(on_seg, on_box), tol);
        expect_near(on_seg, lerp(p0, p1, t));
    }
}

TEST(geom_test, disc_and_circle) {
    vector3 c{0, 1, 0}, n{0, 1, 0};
    expect_near(closest_point_disc(c, n, 2, {1, 5, 0}), {1, 1, 0});
    expect_near(closest_point_disc(c, n, 2, {4, 5, 0}), {2, 1, 0});
    expect_near(closest_point_circle(c, n, 2, {1, 5, 0}), {2, 1, 0});
    auto on_axis = closest_point_circle(c, n, 2, {0, 3, 0});
    EXPECT_NEAR(distance(on_axis, c), 2, tol);
    EXPECT_NEAR(on_axis.y, 1, tol);
}

TEST(geom_test, clip_square_by_half_plane) {
    vector2 square[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    vector2 out[5];
    auto n = clip_polygon_half_plane(square, 4, {1, 0}, 0.5, out);
    ASSERT_EQ(n, 4u);
    EXPECT_NEAR(polygon_signed_area(out, n), 3, tol);
    for (std::size_t i = 0; i < n; ++i)
        EXPECT_LE(out[i].x, 0.5 + tol);
    // Cutting off a corner adds a vertex.
    n = clip_polygon_half_plane(square, 4, normalize(vector2{1, 1}), std::sqrt(scalar(2)) * scalar(0.5), out);
    ASSERT_EQ(n, 5u);
    EXPECT_NEAR(polygon_signed_area(out, n), 4 - 0.5, tol);
    // Wholly outside.
    EXPECT_EQ(clip_polygon_half_plane(square, 4, {1, 0}, -2, out), 0u);
    // A vertex exactly on the line is kept once.
    vector2 tri[3] = {{0, 0}, {1, -1}, {1, 1}};
    n = clip_polygon_half_plane(tri, 3, {-1, 0}, 0, out);
    EXPECT_EQ(n, 3u);
}

TEST(geom_test, clip_half_space_3d) {
    vector3 square[4] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
    vector3 out[5];
    auto n = clip_polygon_half_space(square, 4, {0, 0, 1}, 0, out);
    ASSERT_EQ(n, 4u);
    for (std::size_t i = 0; i < n; ++i)
        EXPECT_LE(out[i].z, tol);
}

TEST(geom_test, clip_convex_polygons) {
    vector2 a[4] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    vector2 b[3] = {{1, 1}, {3, 1}, {1, 3}};
    vector2 out[7], scratch[7];
    auto n = clip_polygon_convex(a, 4, b, 3, out, scratch);
    // The triangle is x >= 1, y >= 1, x + y <= 4: it covers the square's [1, 2] x [1, 2] corner.
    EXPECT_NEAR(polygon_signed_area(out, n), 1, tol);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_TRUE(point_in_convex_polygon(a, 4, out[i], tol));
        EXPECT_TRUE(point_in_convex_polygon(b, 3, out[i], tol));
    }
    // Even number of clip edges lands in `out` too.
    vector2 c[4] = {{1, -1}, {3, -1}, {3, 1}, {1, 1}};
    n = clip_polygon_convex(a, 4, c, 4, out, scratch);
    EXPECT_NEAR(polygon_signed_area(out, n), 1, tol);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_TRUE(point_in_convex_polygon(c, 4, out[i], tol));
        EXPECT_GE(out[i].y, -tol);
    }
    // No clip edges: the subject is copied.
    n = clip_polygon_convex(a, 4, c, 0, out, scratch);
    ASSERT_EQ(n, 4u);
    expect_near(out[2], a[2]);
}

TEST(geom_test, point_in_polygon_and_area) {
    vector2 tri[3] = {{0, 0}, {2, 0}, {0, 2}};
    EXPECT_TRUE(point_in_convex_polygon(tri, 3, {0.5, 0.5}));
    EXPECT_FALSE(point_in_convex_polygon(tri, 3, {1.5, 1.5}));
    EXPECT_TRUE(point_in_convex_polygon(tri, 3, {1.01, 1.01}, 0.02));
    EXPECT_NEAR(polygon_signed_area(tri, 3), 2, tol);
    vector2 cw[3] = {{0, 0}, {0, 2}, {2, 0}};
    EXPECT_NEAR(polygon_signed_area(cw, 3), -2, tol);
}

TEST(geom_test, quadrilateral_area_any_order) {
    vector3 a{0, 0, 0}, b{2, 0, 0}, c{2, 0, 1}, d{0, 0, 1};
    EXPECT_NEAR(quadrilateral_area(a, b, c, d), 2, tol);
    EXPECT_NEAR(quadrilateral_area(a, c, b, d), 2, tol);
    EXPECT_NEAR(quadrilateral_area(a, b, d, c), 2, tol);
    EXPECT_NEAR(quadrilateral_area(a, a, a, b), 0, tol);
}

TEST(geom_test, closest_point_triangle_in_each_voronoi_region) {
    vector3 a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
    // Above the face: straight down onto it.
    EXPECT_EQ(closest_point_triangle({scalar(0.5), scalar(0.5), 3}, a, b, c),
              (vector3{scalar(0.5), scalar(0.5), 0}));
    // Beyond each vertex.
    EXPECT_EQ(closest_point_triangle({-1, -1, 1}, a, b, c), a);
    EXPECT_EQ(closest_point_triangle({3, -1, 0}, a, b, c), b);
    EXPECT_EQ(closest_point_triangle({-1, 3, -2}, a, b, c), c);
    // Beyond each edge: its foot on the edge.
    EXPECT_EQ(closest_point_triangle({1, -1, 1}, a, b, c), (vector3{1, 0, 0}));
    EXPECT_EQ(closest_point_triangle({-1, 1, 0}, a, b, c), (vector3{0, 1, 0}));
    auto on_bc = closest_point_triangle({2, 2, 0}, a, b, c);
    EXPECT_NEAR(on_bc.x, 1, 1e-6);
    EXPECT_NEAR(on_bc.y, 1, 1e-6);
}

TEST(geom_test, closest_point_triangle_is_nearer_than_any_point_of_the_triangle) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<scalar> u(-2, 2);
    for (int n = 0; n < 500; ++n) {
        vector3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
        vector3 p{2 * u(rng), 2 * u(rng), 2 * u(rng)};
        auto q = closest_point_triangle(p, a, b, c);
        // q lies in the triangle: in its plane and with barycentric coordinates in [0, 1].
        auto normal = cross(b - a, c - a);
        ASSERT_NEAR(dot(q - a, normal) / length(normal), 0, 1e-4) << "case " << n;
        auto best = distance(p, q);
        for (int i = 0; i <= 40; ++i) {
            for (int j = 0; i + j <= 40; ++j) {
                auto s = a + (b - a) * (scalar(i) / 40) + (c - a) * (scalar(j) / 40);
                ASSERT_LE(best, distance(p, s) + scalar(1e-4))
                    << "case " << n << " sample " << i << ", " << j;
            }
        }
    }
}

TEST(geom_test, closest_point_triangle_of_a_degenerate_triangle_is_on_its_edges) {
    // All three vertices on the x axis: the nearest point of the segment they span.
    vector3 a{0, 0, 0}, b{1, 0, 0}, c{3, 0, 0};
    auto q = closest_point_triangle({2, 1, 0}, a, b, c);
    EXPECT_NEAR(q.x, 2, 1e-6);
    EXPECT_NEAR(q.y, 0, 1e-6);
    EXPECT_EQ(closest_point_triangle({5, 0, 1}, a, b, c), c);
}
