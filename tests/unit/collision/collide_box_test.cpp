#include "collide_test_helpers.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/clip.hpp"

using namespace edyn;
using namespace collide_test;

namespace {

constexpr scalar box_tol = scalar(1e-5);

// Exact distance between disjoint boxes: the smallest distance from an edge of one to the other,
// each by ternary search over the box's signed distance along the edge.
scalar box_box_distance(const box_shape &a, const box_shape &b, const collision_context &ctx) {
    auto best = large_scalar;
    for (auto [e0, e1] : box_edges(b.half_extents, ctx.posB, ctx.ornB)) {
        auto p0 = to_object_space(e0, ctx.posA, ctx.ornA), p1 = to_object_space(e1, ctx.posA, ctx.ornA);
        best = std::min(best, convex_min([&](scalar t) { return box_sdf(a.half_extents, lerp(p0, p1, t)); }));
    }
    for (auto [e0, e1] : box_edges(a.half_extents, ctx.posA, ctx.ornA)) {
        auto p0 = to_object_space(e0, ctx.posB, ctx.ornB), p1 = to_object_space(e1, ctx.posB, ctx.ornB);
        best = std::min(best, convex_min([&](scalar t) { return box_sdf(b.half_extents, lerp(p0, p1, t)); }));
    }
    return best;
}

std::vector<vector3> axes_of(const quaternion &orn) {
    return {rotate(orn, vector3_x), rotate(orn, vector3_y), rotate(orn, vector3_z)};
}

} // namespace

// Box–box.

TEST(collide_box_test, manual_example_box_on_box) {
    auto box = box_shape{vector3{0.5, 0.5, 0.5}};
    auto ctx = collision_context{};
    ctx.posA = vector3{0, 0, 0};
    ctx.ornA = quaternion_identity;
    ctx.posB = vector3{0, 2 * box.half_extents.y, 0};
    ctx.ornB = quaternion_identity;
    ctx.threshold = 0.2;
    auto result = collision_result{};
    collide(box, box, ctx, result);
    ASSERT_EQ(result.num_points, 4u);
    auto &point = result.point[0];
    auto featureA = std::get<box_feature>(point.featureA->feature);
    EXPECT_EQ(featureA, box_feature::face);
    EXPECT_EQ(point.featureA->index, 2u);
    for (std::size_t i = 0; i < 4; ++i) {
        auto &p = result.point[i];
        expect_feature(p.featureA, box_feature::face, 2);
        EXPECT_NEAR(p.distance, 0, box_tol);
        expect_vec_near(p.normal, -vector3_y, box_tol);
        EXPECT_NEAR(std::abs(p.pivotA.x), 0.5, box_tol);
        EXPECT_NEAR(p.pivotA.y, 0.5, box_tol);
        EXPECT_NEAR(std::abs(p.pivotA.z), 0.5, box_tol);
        EXPECT_NEAR(p.pivotB.y, -0.5, box_tol);
        // B's lower corners: y negative.
        ASSERT_TRUE(p.featureB.has_value());
        EXPECT_EQ(std::get<box_feature>(p.featureB->feature), box_feature::vertex);
        EXPECT_TRUE(p.featureB->index & 2u);
    }
    expect_consistent(result, ctx, box_tol);
}

TEST(collide_box_test, manual_example_under_a_common_transform) {
    // The same pair moved and turned as a whole: same distances and features, rotated normal.
    auto box = box_shape{0.5, 0.5, 0.5};
    auto orn = quaternion_axis_angle(normalize(vector3{1, -2, 0.5}), 2.1);
    vector3 offset{3, -4, 7};
    collision_context ctx{offset, orn, offset + rotate(orn, vector3{0, 1.01, 0}), orn, 0.2};
    auto r = collide_pair(box, box, ctx);
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(r.point[i].distance, 0.01, 1e-4);
        expect_vec_near(r.point[i].normal, rotate(orn, -vector3_y), 1e-4);
        expect_feature(r.point[i].featureA, box_feature::face, 2);
    }
    expect_consistent(r, ctx, 1e-4);
}

TEST(collide_box_test, small_box_resting_rotated_on_large_box) {
    collision_context ctx;
    ctx.posA = {0, 0, 0};
    ctx.posB = {0.1, 0.5 + 0.2 - 0.01, -0.2};
    ctx.ornB = quaternion_axis_angle(vector3_y, 0.3);
    auto r = collide_pair(box_shape{1, 0.5, 1}, box_shape{0.2, 0.2, 0.2}, ctx);
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        auto &p = r.point[i];
        EXPECT_NEAR(p.distance, -0.01, box_tol);
        expect_vec_near(p.normal, -vector3_y, box_tol);
        EXPECT_NEAR(p.pivotA.y, 0.5, box_tol);
        EXPECT_NEAR(p.pivotB.y, -0.2, box_tol);
        expect_feature(p.featureA, box_feature::face, 2);
        ASSERT_TRUE(p.featureB.has_value());
        EXPECT_EQ(std::get<box_feature>(p.featureB->feature), box_feature::vertex);
    }
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, large_box_on_small_box_clips_to_the_small_face) {
    // B is the large one on top: A's top face is the reference, B's bottom face is clipped to
    // A's face, and the clipped corners lie inside B's face.
    collision_context ctx;
    ctx.posB = {0.3, 0.2 + 0.5 - 0.02, 0};
    ctx.ornB = quaternion_axis_angle(vector3_y, 0.2);
    auto r = collide_pair(box_shape{0.2, 0.2, 0.2}, box_shape{1, 0.5, 1}, ctx);
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        auto &p = r.point[i];
        EXPECT_NEAR(p.distance, -0.02, box_tol);
        expect_vec_near(p.normal, -vector3_y, box_tol);
        EXPECT_NEAR(std::abs(p.pivotA.x), 0.2, box_tol);
        EXPECT_NEAR(std::abs(p.pivotA.z), 0.2, box_tol);
        expect_feature(p.featureA, box_feature::face, 2);
        expect_feature(p.featureB, box_feature::face, 3);
    }
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, edge_on_edge) {
    collision_context ctx;
    ctx.threshold = 0.05;
    // A turned about z puts its +x+y edge (along z) on top; B turned about x puts its edge along
    // x with y-, z+ at the bottom.
    ctx.ornA = quaternion_axis_angle(vector3_z, pi / 4);
    ctx.ornB = quaternion_axis_angle(vector3_x, pi / 4);
    auto half_diag = std::sqrt(scalar(2)) * scalar(0.5);
    ctx.posB = {0, 2 * half_diag - scalar(0.01), 0};
    box_shape box{0.5, 0.5, 0.5};
    auto r = collide_pair(box, box, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, -0.01, box_tol);
    expect_vec_near(p.normal, -vector3_y, box_tol);
    expect_feature(p.featureA, box_feature::edge, 8);
    expect_feature(p.featureB, box_feature::edge, 1);
    expect_vec_near(p.pivotA, {0.5, 0.5, 0}, box_tol);
    expect_vec_near(p.pivotB, {0, -0.5, 0.5}, box_tol);
    expect_consistent(r, ctx, box_tol);

    // Same, apart by 0.03.
    ctx.posB.y += scalar(0.04);
    r = collide_pair(box, box, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.03, box_tol);
    expect_consistent(r, ctx, box_tol);
    ctx.posB.y += scalar(0.03);
    EXPECT_EQ(collide_pair(box, box, ctx).num_points, 0u);
}

TEST(collide_box_test, vertex_on_face) {
    collision_context ctx;
    ctx.ornB = shortest_arc(normalize(vector3{-1, -1, -1}), -vector3_y);
    ctx.posB = {0.1, scalar(0.5) + std::sqrt(scalar(3)) * scalar(0.25) - scalar(0.003), 0.2};
    auto r = collide_pair(box_shape{1, 0.5, 1}, box_shape{0.25, 0.25, 0.25}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, -0.003, box_tol);
    expect_vec_near(p.normal, -vector3_y, box_tol);
    expect_feature(p.featureA, box_feature::face, 2);
    expect_feature(p.featureB, box_feature::vertex, 7);
    expect_vec_near(p.pivotA, {0.1, 0.5, 0.2}, box_tol);
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, apart_within_and_beyond_threshold) {
    collision_context ctx;
    ctx.threshold = 0.02;
    box_shape box{0.5, 0.5, 0.5};
    ctx.posB = {0.2, 1.015, -0.1};
    auto r = collide_pair(box, box, ctx);
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(r.point[i].distance, 0.015, box_tol);
    expect_consistent(r, ctx, box_tol);
    ctx.posB.y = scalar(1.021);
    EXPECT_EQ(collide_pair(box, box, ctx).num_points, 0u);
}

TEST(collide_box_test, apart_corner_to_corner_is_exact) {
    // The best separating axis (a face) underestimates the corner-to-corner distance; the
    // reported distance must be the true one.
    collision_context ctx;
    ctx.threshold = 0.02;
    ctx.posB = {1.005, 1.005, 1.005};
    box_shape box{0.5, 0.5, 0.5};
    auto r = collide_pair(box, box, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, std::sqrt(scalar(3)) * scalar(0.005), box_tol);
    expect_vec_near(p.normal, -normalize(vector3_one), 1e-3);
    expect_feature(p.featureA, box_feature::vertex, 0);
    expect_feature(p.featureB, box_feature::vertex, 7);
    expect_consistent(r, ctx, box_tol);
    // Just beyond the threshold along the diagonal although every face gap is below it.
    ctx.posB = vector3_one * scalar(1.0125);
    EXPECT_EQ(collide_pair(box, box, ctx).num_points, 0u);
}

TEST(collide_box_test, deep_penetration_uses_least_penetrating_face) {
    collision_context ctx;
    ctx.posA = {0, 0, 0};
    ctx.posB = {0.1, 0.2, 0};
    auto r = collide_pair(box_shape{0.5, 0.5, 0.5}, box_shape{0.2, 0.2, 0.2}, ctx);
    ASSERT_EQ(r.num_points, 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        // Leaving through A's top face takes 0.5 + 0.2 - 0.2 = 0.5: the least of the axes.
        EXPECT_NEAR(r.point[i].distance, -0.5, box_tol);
        expect_vec_near(r.point[i].normal, -vector3_y, box_tol);
    }
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, reference_face_on_b_when_b_face_is_better) {
    // A tilted box pokes a corner into B's top face from above: B's face is the reference.
    collision_context ctx;
    ctx.ornA = shortest_arc(normalize(vector3{1, 1, 1}), vector3_y);
    ctx.posA = {0, std::sqrt(scalar(3)) * scalar(0.25) - scalar(0.004), 0};
    ctx.posB = {0, -0.5, 0};
    auto r = collide_pair(box_shape{0.25, 0.25, 0.25}, box_shape{1, 0.5, 1}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.004, box_tol);
    expect_vec_near(r.point[0].normal, vector3_y, box_tol);
    expect_feature(r.point[0].featureA, box_feature::vertex, 7);
    expect_feature(r.point[0].featureB, box_feature::face, 2);
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, random_box_box_matches_brute_force) {
    rng random(41);
    int apart = 0, overlapping = 0;
    for (int i = 0; i < 600; ++i) {
        box_shape a{random.vec(0.1, 0.6)}, b{random.vec(0.1, 0.6)};
        collision_context ctx{random.vec(-0.7, 0.7), random.orientation(), random.vec(-0.7, 0.7),
                              random.orientation(), random.uniform(0, 0.2)};
        auto r = collide_pair(a, b, ctx);
        auto va = box_vertices(a.half_extents, ctx.posA, ctx.ornA);
        auto vb = box_vertices(b.half_extents, ctx.posB, ctx.ornB);
        auto dirs = candidate_directions(ctx.ornA, axes_of(ctx.ornB), random);
        auto max_sep = max_separation(va, 0, vb, 0, dirs);

        if (max_sep > 0) {
            auto expected = box_box_distance(a, b, ctx);
            if (expected > ctx.threshold + 1e-4) {
                EXPECT_EQ(r.num_points, 0u) << "case " << i;
                continue;
            }
            if (expected < ctx.threshold - 1e-4) {
                ASSERT_GE(r.num_points, 1u) << "case " << i;
            }
            if (r.num_points == 0) continue;
            ++apart;
            EXPECT_NEAR(min_distance(r), expected, 1e-4) << "case " << i;
        } else {
            ASSERT_GE(r.num_points, 1u) << "case " << i;
            ++overlapping;
            auto d = min_distance(r);
            // Not deeper than the least penetration plus the face bias, and not shallower
            // than the separation along the reported normal allows.
            EXPECT_GE(d, max_sep - sat_bias(d)) << "case " << i;
            EXPECT_LE(d, max_sep + 1e-4) << "case " << i;
            // Along the reported normal the shapes overlap by the reported depth, up to the bias
            // (a face axis kept over a slightly better edge axis clips to a shallower manifold).
            auto n = r.point[deepest_index(r)].normal;
            EXPECT_NEAR(separation_along(project(va, n), project(vb, n)), d, sat_bias(d)) << "case " << i;
        }
        for (std::size_t k = 0; k < r.num_points; ++k) {
            EXPECT_NEAR(box_sdf(a.half_extents, r.point[k].pivotA), 0, 1e-4) << "case " << i;
            EXPECT_NEAR(box_sdf(b.half_extents, r.point[k].pivotB), 0, 1e-4) << "case " << i;
        }
        expect_consistent(r, ctx, 1e-4);
        auto s = collide_pair(b, a, swap_context(ctx));
        ASSERT_GE(s.num_points, 1u) << "case " << i;
        EXPECT_NEAR(min_distance(s), min_distance(r), sat_bias(min_distance(r))) << "case " << i;
    }
    EXPECT_GT(apart, 30);
    EXPECT_GT(overlapping, 200);
}

// Box–capsule.

TEST(collide_box_test, capsule_lying_on_box_face) {
    collision_context ctx;
    ctx.posB = {0.2, 0.69, 0.3};
    auto r = collide_pair(box_shape{1, 0.5, 1}, capsule_shape{0.2, 0.5, coordinate_axis::x}, ctx);
    ASSERT_EQ(r.num_points, 2u);
    scalar xs[2];
    for (std::size_t i = 0; i < 2; ++i) {
        auto &p = r.point[i];
        EXPECT_NEAR(p.distance, -0.01, box_tol);
        expect_vec_near(p.normal, -vector3_y, box_tol);
        expect_feature(p.featureA, box_feature::face, 2);
        expect_feature(p.featureB, capsule_feature::side, 0);
        EXPECT_NEAR(p.pivotA.y, 0.5, box_tol);
        EXPECT_NEAR(p.pivotB.y, -0.2, box_tol);
        xs[i] = p.pivotA.x;
    }
    EXPECT_NEAR(std::min(xs[0], xs[1]), -0.3, box_tol);
    EXPECT_NEAR(std::max(xs[0], xs[1]), 0.7, box_tol);
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, capsule_overhanging_is_clipped_to_the_face) {
    collision_context ctx;
    ctx.ornA = quaternion_axis_angle(vector3_x, 0.5);
    ctx.posB = rotate(ctx.ornA, vector3{0, 0.7, 0.4});
    ctx.ornB = ctx.ornA;
    auto r = collide_pair(box_shape{1, 0.5, 1}, capsule_shape{0.2, 2, coordinate_axis::x}, ctx);
    ASSERT_EQ(r.num_points, 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(r.point[i].distance, 0, box_tol);
        EXPECT_NEAR(std::abs(r.point[i].pivotA.x), 1, box_tol);
        expect_vec_near(r.point[i].normal, rotate(ctx.ornA, -vector3_y), box_tol);
    }
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, capsule_standing_on_box_face) {
    collision_context ctx;
    ctx.posB = {0.3, 0.5 + 0.5 + 0.2 - 0.01, 0};
    auto r = collide_pair(box_shape{1, 0.5, 1}, capsule_shape{0.2, 0.5, coordinate_axis::y}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, -0.01, box_tol);
    expect_feature(r.point[0].featureA, box_feature::face, 2);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 1);
    expect_vec_near(r.point[0].pivotB, {0, -0.7, 0}, box_tol);
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, capsule_along_box_edge_gives_two_points) {
    collision_context ctx;
    ctx.threshold = 0.1;
    ctx.posB = {1.1, 0.6, 0.2};
    auto r = collide_pair(box_shape{1, 0.5, 1}, capsule_shape{0.1, 0.5, coordinate_axis::z}, ctx);
    ASSERT_EQ(r.num_points, 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        auto &p = r.point[i];
        EXPECT_NEAR(p.distance, std::sqrt(scalar(0.02)) - scalar(0.1), box_tol);
        expect_vec_near(p.normal, -normalize(vector3{1, 1, 0}), box_tol);
        expect_feature(p.featureA, box_feature::edge, 8);
    }
    EXPECT_NEAR(std::abs(r.point[0].pivotA.z - r.point[1].pivotA.z), 1, box_tol);
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, capsule_end_near_box_vertex) {
    collision_context ctx;
    ctx.threshold = 0.1;
    auto dir = normalize(vector3{1, 1, 1});
    // Capsule along x turned to point along the diagonal, its -x end just off vertex 0.
    ctx.ornB = shortest_arc(vector3_x, dir);
    ctx.posB = vector3{0.5, 0.5, 0.5} + dir * scalar(0.05 + 0.1 + 1);
    auto r = collide_pair(box_shape{0.5, 0.5, 0.5}, capsule_shape{0.1, 1, coordinate_axis::x}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.05, box_tol);
    expect_feature(r.point[0].featureA, box_feature::vertex, 0);
    expect_feature(r.point[0].featureB, capsule_feature::hemisphere, 1);
    expect_vec_near(r.point[0].normal, -dir, box_tol);
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, capsule_through_box_centre) {
    collision_context ctx;
    auto r = collide_pair(box_shape{1, 0.5, 1}, capsule_shape{0.2, 2, coordinate_axis::x}, ctx);
    ASSERT_GE(r.num_points, 1u);
    for (std::size_t i = 0; i < r.num_points; ++i) {
        // Leaving upwards takes 0.5 + 0.2 (the y face, least penetration).
        EXPECT_NEAR(r.point[i].distance, -0.7, box_tol);
        EXPECT_NEAR(std::abs(r.point[i].normal.y), 1, box_tol);
    }
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, capsule_crossing_box_edge_penetrating) {
    // Capsule in the xy plane along (1, -1, 0), its segment cutting the box's +x+y edge: the
    // cross product of that edge with the segment, (1, 1, 0), is the least penetration.
    collision_context ctx;
    ctx.threshold = 0.05;
    ctx.ornB = quaternion_axis_angle(vector3_z, -pi / 4);
    ctx.posB = {0.95, 0.45, 0};
    auto r = collide_pair(box_shape{1, 0.5, 1}, capsule_shape{0.2, 0.5, coordinate_axis::x}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    auto &p = r.point[0];
    EXPECT_NEAR(p.distance, -scalar(0.1) / std::sqrt(scalar(2)) - scalar(0.2), box_tol);
    expect_vec_near(p.normal, -normalize(vector3{1, 1, 0}), box_tol);
    expect_feature(p.featureA, box_feature::edge, 8);
    expect_feature(p.featureB, capsule_feature::side, 0);
    expect_vec_near(p.pivotA, {1, 0.5, 0}, box_tol);
    expect_consistent(r, ctx, box_tol);
}

TEST(collide_box_test, capsule_box_is_the_swap_of_box_capsule) {
    collision_context ctx;
    ctx.posA = {0.2, 0.69, 0.3};
    auto r = collide_pair(capsule_shape{0.2, 0.5, coordinate_axis::x}, box_shape{1, 0.5, 1}, ctx);
    ASSERT_EQ(r.num_points, 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(r.point[i].distance, -0.01, box_tol);
        expect_vec_near(r.point[i].normal, vector3_y, box_tol);
        expect_feature(r.point[i].featureA, capsule_feature::side, 0);
        expect_feature(r.point[i].featureB, box_feature::face, 2);
    }
    expect_consistent(r, ctx, box_tol);
    ctx.posA.y = scalar(0.721);
    EXPECT_EQ(collide_pair(capsule_shape{0.2, 0.5, coordinate_axis::x}, box_shape{1, 0.5, 1}, ctx).num_points,
              0u);
}

TEST(collide_box_test, random_box_capsule_matches_brute_force) {
    rng random(42);
    int apart = 0, overlapping = 0;
    for (int i = 0; i < 1000; ++i) {
        box_shape box{random.vec(0.1, 0.6)};
        capsule_shape capsule{random.uniform(0.05, 0.3), random.uniform(0, 0.7), coordinate_axis(i % 3)};
        collision_context ctx{random.vec(-0.6, 0.6), random.orientation(), random.vec(-0.6, 0.6),
                              random.orientation(), random.uniform(0, 0.2)};
        auto r = collide_pair(box, capsule, ctx);
        vector3 p0, p1;
        capsule_ends(capsule, ctx.posB, ctx.ornB, p0, p1);
        auto l0 = to_object_space(p0, ctx.posA, ctx.ornA), l1 = to_object_space(p1, ctx.posA, ctx.ornA);
        auto segment_sdf = convex_min([&](scalar t) { return box_sdf(box.half_extents, lerp(l0, l1, t)); });

        if (segment_sdf > 0) {
            auto expected = segment_sdf - capsule.radius;
            if (expected > ctx.threshold + 1e-4) {
                EXPECT_EQ(r.num_points, 0u) << "case " << i;
                continue;
            }
            if (expected < ctx.threshold - 1e-4) {
                ASSERT_GE(r.num_points, 1u) << "case " << i;
            }
            if (r.num_points == 0) continue;
            ++apart;
            EXPECT_NEAR(min_distance(r), expected, 1e-4) << "case " << i;
        } else {
            ASSERT_GE(r.num_points, 1u) << "case " << i;
            ++overlapping;
            auto vb = box_vertices(box.half_extents, ctx.posA, ctx.ornA);
            auto dirs = candidate_directions(ctx.ornA, {normalize(p0 - p1)}, random);
            auto max_sep = max_separation(vb, 0, {p0, p1}, capsule.radius, dirs);
            auto d = min_distance(r);
            EXPECT_GE(d, max_sep - sat_bias(d)) << "case " << i;
            EXPECT_LE(d, max_sep + 1e-4) << "case " << i;
        }
        for (std::size_t k = 0; k < r.num_points; ++k) {
            auto w = world_points(r.point[k], ctx);
            EXPECT_NEAR(box_sdf(box.half_extents, r.point[k].pivotA), 0, 1e-4) << "case " << i;
            // Points over a face sit at a radius from the segment along the face normal: on the
            // surface for the segment's ends and for segments parallel to the face, inside the
            // capsule otherwise.
            EXPECT_LE(point_segment_distance(p0, p1, w.b), capsule.radius + 1e-4) << "case " << i;
        }
        expect_consistent(r, ctx, 1e-4);
        auto s = collide_pair(capsule, box, swap_context(ctx));
        ASSERT_EQ(s.num_points, r.num_points) << "case " << i;
        EXPECT_NEAR(min_distance(s), min_distance(r), 1e-4) << "case " << i;
    }
    EXPECT_GT(apart, 100);
    EXPECT_GT(overlapping, 200);
}

// Box feature indexing and tagged clipping (shared with other collide() pairs).

TEST(collide_box_test, box_vertex_and_edge_indices_agree) {
    vector3 he{1, 2, 3};
    for (unsigned v = 0; v < 8; ++v) {
        auto p = detail::box_vertex(he, v);
        EXPECT_EQ(detail::box_vertex_index(p), v);
        EXPECT_EQ(std::abs(p.x), 1);
        EXPECT_EQ(std::abs(p.z), 3);
    }
    for (unsigned e = 0; e < 12; ++e) {
        unsigned v0 = 0, v1 = 0;
        detail::box_edge_vertex_indices(e, v0, v1);
        auto axis = detail::box_edge_axis(e);
        EXPECT_EQ(v0 ^ v1, 1u << axis) << "edge " << e;
        EXPECT_GT(detail::box_vertex(he, v0)[axis], 0) << "edge " << e;
        EXPECT_EQ(detail::box_edge_between(v0, v1), e);
        EXPECT_EQ(detail::box_edge_index(axis, detail::box_vertex(he, v1)), e);
        auto f = detail::box_feature_at(
            he, (detail::box_vertex(he, v0) + detail::box_vertex(he, v1)) * scalar(0.5), 0);
        expect_feature(f, box_feature::edge, e);
    }
    // The documented example: edge 8 runs along z on the +x, +y side; edge 1 along x at -y, +z.
    vector3 a, b;
    detail::box_edge_vertices(he, 8, a, b);
    expect_vec_near(a, {1, 2, 3}, 0);
    expect_vec_near(b, {1, 2, -3}, 0);
    detail::box_edge_vertices(he, 1, a, b);
    expect_vec_near(a, {1, -2, 3}, 0);
}

TEST(collide_box_test, box_faces_are_counter_clockwise_from_outside) {
    vector3 he{1, 2, 3};
    for (unsigned f = 0; f < 6; ++f) {
        vector3 v[4];
        detail::box_face_vertices(he, f, v);
        auto n = detail::box_face_normal(f);
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(dot(v[i], n), he[detail::box_face_axis(f)]) << "face " << f;
            auto turn = dot(cross(v[(i + 1) % 4] - v[i], v[(i + 2) % 4] - v[(i + 1) % 4]), n);
            EXPECT_GT(turn, 0) << "face " << f << " corner " << i;
        }
        EXPECT_EQ(detail::box_support_face(n * scalar(2) + vector3{0.1, 0.1, 0.1} * scalar(0.5)), f);
        expect_feature(std::optional(detail::box_feature_at(
                           he, n * he[detail::box_face_axis(f)] * scalar(0.999), scalar(0.01))),
                       box_feature::face, f);
    }
    // Inside: nearest face.
    expect_feature(std::optional(detail::box_feature_at(he, {0.9, 0, 0}, 0)), box_feature::face, 0);
    expect_feature(std::optional(detail::box_feature_at(he, {-1, -2, -3}, 0)), box_feature::vertex, 7);
}

TEST(collide_box_test, tagged_clipping_reports_incident_features) {
    // Incident square (box face 3 of a 1 x 1 box, i.e. its -y face) placed over a reference face
    // of half extents 0.5 x 0.5 shifted by 0.8 along x: half of it sticks out over +x.
    vector3 ref_he{0.5, 0.5, 0.5};
    detail::clip_vertex polygon[4];
    detail::box_face_polygon({0.5, 0.5, 0.5}, 3, {0.8, 1, 0}, quaternion_identity, polygon);
    for (auto &v : polygon)
        EXPECT_NEAR(v.position.y, 0.5, box_tol);
    detail::clip_vertex out[detail::max_clip_vertices];
    auto face = collision_feature{box_feature::face, 3};
    auto n = detail::clip_polygon_box_face_sides(polygon, 4, ref_he, 2, face, out);
    ASSERT_EQ(n, 4u);
    int vertices = 0, edges = 0;
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_LE(out[i].position.x, 0.5 + box_tol);
        EXPECT_GE(out[i].position.x, 0.3 - box_tol);
        auto kind = std::get<box_feature>(out[i].feature.feature);
        if (kind == box_feature::vertex) {
            ++vertices;
            // Incident vertices kept: those at local x = -0.5 (bit 0 set), y = -0.5 (bit 1 set).
            EXPECT_EQ(out[i].feature.index & 3u, 3u);
        } else {
            ASSERT_EQ(kind, box_feature::edge);
            ++edges;
            // Cut on the incident edges along x (indices 0..3).
            EXPECT_LT(out[i].feature.index, 4u);
            EXPECT_NEAR(out[i].position.x, 0.5, box_tol);
        }
    }
    EXPECT_EQ(vertices, 2);
    EXPECT_EQ(edges, 2);

    // An incident face larger than the reference face: all four corners are cut points inside it.
    detail::box_face_polygon({2, 0.5, 2}, 3, {0, 1, 0}, quaternion_axis_angle(vector3_y, 0.3), polygon);
    n = detail::clip_polygon_box_face_sides(polygon, 4, ref_he, 2, face, out);
    ASSERT_EQ(n, 4u);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(out[i].feature, face);
        EXPECT_NEAR(std::abs(out[i].position.x), 0.5, box_tol);
        EXPECT_NEAR(std::abs(out[i].position.z), 0.5, box_tol);
    }
}
