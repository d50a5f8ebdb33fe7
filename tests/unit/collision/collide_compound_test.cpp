#include "collide_test_helpers.hpp"
#include <initializer_list>
#include <set>
#include <type_traits>
#include <utility>

// collide() for every pair with a compound. Hand-built scenes check depths, normals, child
// indices (collision_feature::part) and pivots against exact geometry; random scenes check the
// compound against running every child (or pair of children) on its own, which the compound
// must match in its deepest point and in which children it reports.

using namespace edyn;
using namespace collide_test;

namespace {

// Shapes of about a metre at positions up to a few metres: float rounding stays below this.
constexpr scalar compound_tol = scalar(1e-4);
constexpr scalar compound_depth = scalar(0.01);

struct child_def {
    compound_child_shape_t shape;
    vector3 pos{vector3_zero};
    quaternion orn{quaternion_identity};
};

compound_shape make_compound(std::initializer_list<child_def> defs) {
    compound_shape c;
    for (const auto &d : defs)
        c.add_shape(d.shape, d.pos, d.orn);
    c.finish();
    return c;
}

// Two bars meeting at a right angle, both bottoms at y = -0.25 and tops at y = 0.25: child 0
// spans x [-1, 1], z [-0.25, 0.25]; child 1 spans x [1, 1.5], z [-0.25, 1.75].
compound_shape l_shape() {
    return make_compound({{box_shape{{1, 0.25, 0.25}}}, {box_shape{{0.25, 0.25, 1}}, {1.25, 0, 0.75}}});
}

// Frustum of a square pyramid: base of half side `base` at y = -h, top of half side `top` at y = h.
polyhedron_shape frustum(scalar base, scalar top, scalar h) {
    return polyhedron_shape(std::vector<vector3>{{base, -h, base},
                                                 {-base, -h, base},
                                                 {-base, -h, -base},
                                                 {base, -h, -base},
                                                 {top, h, top},
                                                 {-top, h, top},
                                                 {-top, h, -top},
                                                 {top, h, -top}});
}

// Runs both argument orders, checks the world-space geometry of every point and that the two
// orders report the same points with A and B exchanged; returns the (a, b) result. Two compounds
// visit their children in a different order in each argument order, so when more than four
// points are found the kept four may differ: there, only the deepest point must agree, within the
// separating-axis bias (each child pair runs in the opposite argument order in the two calls).
template<typename A, typename B>
collision_result collide_compound_checked(const A &a, const B &b, const collision_context &ctx) {
    collision_result r, s;
    collide(a, b, ctx, r);
    collide(b, a, swap_context(ctx), s);
    expect_consistent(r, ctx, compound_tol);
    expect_consistent(s, swap_context(ctx), compound_tol);
    if constexpr (std::is_same_v<A, compound_shape> && std::is_same_v<B, compound_shape>) {
        EXPECT_EQ(r.num_points > 0, s.num_points > 0);
        if (r.num_points > 0 && s.num_points > 0) {
            EXPECT_NEAR(min_distance(r), min_distance(s), sat_bias(min_distance(r)));
        }
        return r;
    }
    EXPECT_EQ(r.num_points, s.num_points);
    for (std::size_t i = 0; i < r.num_points; ++i) {
        const auto &p = r.point[i];
        bool found = false;
        for (std::size_t j = 0; j < s.num_points && !found; ++j) {
            const auto &q = s.point[j];
            if (distance(q.pivotB, p.pivotA) > compound_tol || distance(q.pivotA, p.pivotB) > compound_tol)
                continue;
            found = true;
            expect_vec_near(q.normal, -p.normal, compound_tol);
            EXPECT_NEAR(q.distance, p.distance, compound_tol);
            EXPECT_EQ(q.featureA, p.featureB);
            EXPECT_EQ(q.featureB, p.featureA);
        }
        EXPECT_TRUE(found) << "point " << i << " at " << str(p.pivotA) << " missing from the (b, a) result";
    }
    return r;
}

int part_of(const std::optional<collision_feature> &f) {
    EXPECT_TRUE(f.has_value()) << "a compound's point must carry a feature";
    return f ? f->part : -2;
}

// Signed distance of a point (compound object space) to the surface of a box child.
scalar box_child_sdf(const compound_shape &c, int part, const vector3 &p) {
    const auto &child = c.children.at(std::size_t(part));
    auto local = to_object_space(p, child.position, child.orientation);
    return box_sdf(std::get<box_shape>(child.shape).half_extents, local);
}

// Position and orientation of a scene after moving all of it rigidly by (pos, orn).
collision_context moved(const collision_context &ctx, const vector3 &pos, const quaternion &orn) {
    return {to_world_space(ctx.posA, pos, orn), orn * ctx.ornA, to_world_space(ctx.posB, pos, orn),
            orn * ctx.ornB, ctx.threshold};
}

void expect_same_point(const collision_result::collision_point &actual,
                       const collision_result::collision_point &expected) {
    expect_vec_near(actual.pivotA, expected.pivotA, 0);
    expect_vec_near(actual.pivotB, expected.pivotB, 0);
    expect_vec_near(actual.normal, expected.normal, 0);
    EXPECT_EQ(actual.distance, expected.distance);
    auto child = expected.featureA.value_or(collision_feature{});
    child.part = 0;
    EXPECT_EQ(actual.featureA, child);
    EXPECT_EQ(actual.featureB, expected.featureB);
}

// A compound of one box at its origin must reproduce the box's own result bit for bit, apart
// from `part`. In the (b, a) order the compound runs the (a, b) routine and swaps, so it matches
// the box's (a, b) result swapped exactly, and the box's own (b, a) result up to the
// separating-axis bias (those routines prefer A's faces). Counts the cases with points.
template<typename B>
void expect_single_box_matches(const B &b, unsigned seed, int &touching) {
    auto box = box_shape{{0.4, 0.3, 0.5}};
    auto compound = make_compound({{box}});
    rng random(seed);
    touching = 0;
    for (int i = 0; i < 60; ++i) {
        SCOPED_TRACE(testing::Message() << "case " << i);
        auto dir = random.unit();
        collision_context ctx{
            random.vec(-2, 2), random.orientation(), {}, random.orientation(), scalar(0.02)};
        ctx.posB = ctx.posA + dir * random.uniform(0.3, 1.4);
        collision_result expected, actual;
        collide(box, b, ctx, expected);
        collide(compound, b, ctx, actual);
        ASSERT_EQ(actual.num_points, expected.num_points);
        for (std::size_t k = 0; k < actual.num_points; ++k)
            expect_same_point(actual.point[k], expected.point[k]);

        collision_result box_ba, actual_ba;
        collide(b, box, swap_context(ctx), box_ba);
        collide(b, compound, swap_context(ctx), actual_ba);
        actual_ba.swap();
        ASSERT_EQ(actual_ba.num_points, expected.num_points) << "(b, a)";
        for (std::size_t k = 0; k < actual_ba.num_points; ++k) {
            expect_same_point(actual_ba.point[k], expected.point[k]);
        }
        EXPECT_EQ(box_ba.num_points > 0, actual_ba.num_points > 0) << "(b, a)";
        if (box_ba.num_points > 0 && actual_ba.num_points > 0) {
            EXPECT_NEAR(min_distance(actual_ba), min_distance(box_ba), sat_bias(min_distance(box_ba)));
        }
        touching += actual.num_points > 0;
    }
}

} // namespace

TEST(collide_compound_test, single_box_compound_gives_the_box_result) {
    int touching[6];
    expect_single_box_matches(sphere_shape{0.5}, 1, touching[0]);
    expect_single_box_matches(box_shape{{0.5, 0.2, 0.4}}, 2, touching[1]);
    expect_single_box_matches(capsule_shape{0.3, 0.4, coordinate_axis::z}, 3, touching[2]);
    expect_single_box_matches(cylinder_shape{0.4, 0.3, coordinate_axis::x}, 4, touching[3]);
    expect_single_box_matches(frustum(0.5, 0.3, 0.4), 5, touching[4]);
    expect_single_box_matches(plane_shape{normalize(vector3{0.2, 1, 0.1}), scalar(-0.3)}, 6, touching[5]);
    for (int i = 0; i < 6; ++i)
        EXPECT_GT(touching[i], 10) << "shape " << i;
}

TEST(collide_compound_test, offset_rotated_child_matches_box_at_composed_transform) {
    auto box = box_shape{{0.4, 0.3, 0.5}};
    auto child_pos = vector3{0.7, -0.2, 0.3};
    auto child_orn = quaternion_axis_angle(normalize(vector3{1, 2, -1}), scalar(0.8));
    auto compound = make_compound({{box, child_pos, child_orn}});
    auto other = box_shape{{0.3, 0.3, 0.6}};
    rng random(7);
    int touching = 0;
    for (int i = 0; i < 100; ++i) {
        collision_context ctx{
            random.vec(-2, 2), random.orientation(), {}, random.orientation(), scalar(0.02)};
        auto box_ctx = ctx;
        box_ctx.posA = to_world_space(child_pos, ctx.posA, ctx.ornA);
        box_ctx.ornA = ctx.ornA * child_orn;
        ctx.posB = box_ctx.posA + random.unit() * random.uniform(0.3, 1.3);
        box_ctx.posB = ctx.posB;
        collision_result expected;
        collide(box, other, box_ctx, expected);
        auto r = collide_compound_checked(compound, other, ctx);
        ASSERT_EQ(r.num_points, expected.num_points) << "case " << i;
        for (std::size_t k = 0; k < r.num_points; ++k) {
            expect_vec_near(to_object_space(r.point[k].pivotA, child_pos, child_orn),
                            expected.point[k].pivotA, compound_tol);
            expect_vec_near(r.point[k].pivotB, expected.point[k].pivotB, compound_tol);
            expect_vec_near(r.point[k].normal, expected.point[k].normal, compound_tol);
            EXPECT_NEAR(r.point[k].distance, expected.point[k].distance, compound_tol);
            EXPECT_EQ(part_of(r.point[k].featureA), 0);
        }
        touching += r.num_points > 0;
    }
    EXPECT_GT(touching, 20);
}

// The L lying flat, turned about the vertical, sinks `compound_depth` into the ground: every point lies on
// the bottom face of the child it names, and both children hold points.
template<typename Ground>
void expect_l_shape_resting(const Ground &ground, const vector3 &ground_pos) {
    auto l = l_shape();
    for (auto yaw : {scalar(0), scalar(0.7), scalar(2.0), scalar(-2.9)}) {
        collision_context ctx{{0.3, scalar(0.25) - compound_depth, -0.2},
                              quaternion_axis_angle(vector3_y, yaw),
                              ground_pos,
                              quaternion_identity,
                              scalar(0.02)};
        auto r = collide_compound_checked(l, ground, ctx);
        ASSERT_GT(r.num_points, 0u) << "yaw " << yaw;
        std::set<int> parts;
        for (std::size_t i = 0; i < r.num_points; ++i) {
            const auto &p = r.point[i];
            auto part = part_of(p.featureA);
            ASSERT_TRUE(part == 0 || part == 1) << "part " << part;
            parts.insert(part);
            EXPECT_NEAR(p.distance, -compound_depth, compound_tol) << "yaw " << yaw;
            expect_vec_near(p.normal, vector3_y, compound_tol);
            EXPECT_NEAR(p.pivotA.y, -0.25, compound_tol);
            EXPECT_NEAR(box_child_sdf(l, part, p.pivotA), 0, compound_tol)
                << "pivot " << str(p.pivotA) << " part " << part;
        }
        EXPECT_EQ(parts.size(), 2u) << "yaw " << yaw;
    }
}

TEST(collide_compound_test, l_shape_on_plane_touches_under_both_children) {
    expect_l_shape_resting(plane_shape{vector3_y, 0}, vector3_zero);
}

TEST(collide_compound_test, l_shape_on_box_touches_under_both_children) {
    expect_l_shape_resting(box_shape{{4, 0.5, 4}}, vector3{0.25, -0.5, 0.75});
}

// `shape` (lowest point `bottom` below its origin) above the top of the L's child 1, at `gap`
// (negative: overlapping), the scene moved rigidly by a few transforms.
template<typename B>
void expect_on_child_1(const B &shape, scalar bottom, scalar gap, unsigned seed) {
    auto l = l_shape();
    rng random(seed);
    for (int i = 0; i < 4; ++i) {
        collision_context local{vector3_zero,
                                quaternion_identity,
                                {1.25, scalar(0.25) + bottom + gap, 1.0},
                                quaternion_identity,
                                scalar(0.02)};
        auto ctx = i == 0 ? local : moved(local, random.vec(-3, 3), random.orientation());
        auto r = collide_compound_checked(l, shape, ctx);
        if (gap > ctx.threshold) {
            EXPECT_EQ(r.num_points, 0u) << "gap " << gap;
            continue;
        }
        ASSERT_GT(r.num_points, 0u) << "gap " << gap;
        EXPECT_NEAR(min_distance(r), gap, compound_tol);
        for (std::size_t k = 0; k < r.num_points; ++k) {
            const auto &p = r.point[k];
            EXPECT_EQ(part_of(p.featureA), 1);
            expect_vec_near(p.normal, rotate(ctx.ornA, -vector3_y), compound_tol);
            EXPECT_NEAR(box_child_sdf(l, 1, p.pivotA), 0, compound_tol) << "pivot " << str(p.pivotA);
        }
    }
}

template<typename B>
void expect_resting_and_separated(const B &shape, scalar bottom, unsigned seed) {
    expect_on_child_1(shape, bottom, -compound_depth, seed);
    expect_on_child_1(shape, bottom, scalar(0.01), seed);
    expect_on_child_1(shape, bottom, scalar(0.03), seed);
}

TEST(collide_compound_test, sphere_resting_and_separated) {
    expect_resting_and_separated(sphere_shape{0.2}, scalar(0.2), 10);
}

TEST(collide_compound_test, capsule_resting_and_separated) {
    expect_resting_and_separated(capsule_shape{0.1, 0.15, coordinate_axis::x}, scalar(0.1), 11);
}

TEST(collide_compound_test, cylinder_resting_and_separated) {
    expect_resting_and_separated(cylinder_shape{0.2, 0.1, coordinate_axis::y}, scalar(0.1), 12);
}

TEST(collide_compound_test, box_resting_and_separated) {
    expect_resting_and_separated(box_shape{{0.2, 0.1, 0.2}}, scalar(0.1), 13);
}

TEST(collide_compound_test, polyhedron_resting_and_separated) {
    expect_resting_and_separated(frustum(0.2, 0.1, 0.1), scalar(0.1), 14);
}

// Two feet (A) standing on two blocks (B): each foot touches one block only, and the points
// name both children. B turned half a turn swaps which block is under which foot.
TEST(collide_compound_test, compound_on_compound_pairs_children) {
    auto feet =
        make_compound({{box_shape{{0.2, 0.2, 0.2}}, {-1, 0, 0}}, {box_shape{{0.2, 0.2, 0.2}}, {1, 0, 0}}});
    auto blocks =
        make_compound({{box_shape{{0.5, 0.5, 0.5}}, {-1, 0, 0}}, {box_shape{{0.5, 0.5, 0.5}}, {1, 0, 0}}});
    rng random(20);
    for (auto half_turn : {false, true}) {
        for (int i = 0; i < 3; ++i) {
            collision_context local{{0, scalar(0.7) - compound_depth, 0.1},
                                    quaternion_identity,
                                    vector3_zero,
                                    half_turn ? quaternion_axis_angle(vector3_y, pi) : quaternion_identity,
                                    scalar(0.02)};
            auto ctx = i == 0 ? local : moved(local, random.vec(-3, 3), random.orientation());
            auto r = collide_compound_checked(feet, blocks, ctx);
            ASSERT_GT(r.num_points, 0u);
            std::set<std::pair<int, int>> pairs;
            for (std::size_t k = 0; k < r.num_points; ++k) {
                const auto &p = r.point[k];
                auto pa = part_of(p.featureA), pb = part_of(p.featureB);
                pairs.insert({pa, pb});
                EXPECT_NEAR(p.distance, -compound_depth, compound_tol);
                expect_vec_near(p.normal, rotate(ctx.ornB, vector3_y), compound_tol);
                EXPECT_NEAR(box_child_sdf(feet, pa, p.pivotA), 0, compound_tol);
                EXPECT_NEAR(box_child_sdf(blocks, pb, p.pivotB), 0, compound_tol);
            }
            auto expected = half_turn ? std::set<std::pair<int, int>>{{0, 1}, {1, 0}}
                                      : std::set<std::pair<int, int>>{{0, 0}, {1, 1}};
            EXPECT_EQ(pairs, expected);
        }
    }
    auto ctx = collision_context{{0, scalar(0.7) + scalar(0.03), 0},
                                 quaternion_identity,
                                 vector3_zero,
                                 quaternion_identity,
                                 scalar(0.02)};
    EXPECT_EQ(collide_compound_checked(feet, blocks, ctx).num_points, 0u);
}

// 4 x 4 blocks (more than max_children_without_tree, so queries go through the tree) and a small
// box standing on one of them: only that block reports points.
TEST(collide_compound_test, tree_compound_reports_only_the_touched_child) {
    compound_shape grid;
    for (int ix = 0; ix < 4; ++ix) {
        for (int iz = 0; iz < 4; ++iz) {
            grid.add_shape(box_shape{{0.25, 0.25, 0.25}},
                           {scalar(ix) - scalar(1.5), 0, scalar(iz) - scalar(1.5)});
        }
    }
    grid.finish();
    ASSERT_FALSE(grid.tree.empty());
    auto small = box_shape{{0.1, 0.1, 0.1}};
    rng random(30);
    for (int k = 0; k < 16; ++k) {
        auto top =
            grid.children[std::size_t(k)].position + vector3{0.05, scalar(0.35) - compound_depth, -0.05};
        collision_context local{vector3_zero, quaternion_identity, top, quaternion_identity, scalar(0.02)};
        auto ctx = moved(local, random.vec(-3, 3), random.orientation());
        auto r = collide_compound_checked(grid, small, ctx);
        ASSERT_GT(r.num_points, 0u) << "child " << k;
        EXPECT_NEAR(min_distance(r), -compound_depth, compound_tol) << "child " << k;
        for (std::size_t i = 0; i < r.num_points; ++i) {
            EXPECT_EQ(part_of(r.point[i].featureA), k);
            EXPECT_NEAR(box_child_sdf(grid, k, r.point[i].pivotA), 0, compound_tol);
        }
    }
}

TEST(collide_compound_test, features_without_child_feature_still_name_the_child) {
    // Sphere-plane reports no feature on the sphere: the compound reports monostate with the part.
    auto c = make_compound({{box_shape{{0.5, 0.5, 0.5}}, {0, 3, 0}}, {sphere_shape{0.5}, {2, 0, 0}}});
    collision_context ctx{{0, scalar(0.5) - compound_depth, 0},
                          quaternion_identity,
                          vector3_zero,
                          quaternion_identity,
                          scalar(0.02)};
    auto r = collide_compound_checked(c, plane_shape{vector3_y, 0}, ctx);
    ASSERT_EQ(r.num_points, 1u);
    ASSERT_TRUE(r.point[0].featureA.has_value());
    EXPECT_TRUE(std::holds_alternative<std::monostate>(r.point[0].featureA->feature));
    EXPECT_EQ(r.point[0].featureA->part, 1);
    EXPECT_NEAR(r.point[0].distance, -compound_depth, compound_tol);
    expect_vec_near(r.point[0].pivotA, {2, -0.5, 0}, compound_tol);
}

namespace {

compound_child_shape_t random_child(rng &random) {
    switch (random.engine() % 5) {
    case 0:
        return box_shape{random.vec(0.1, 0.5)};
    case 1:
        return sphere_shape{random.uniform(0.1, 0.5)};
    case 2:
        return capsule_shape{random.uniform(0.1, 0.3), random.uniform(0.1, 0.4), coordinate_axis::y};
    case 3:
        return cylinder_shape{random.uniform(0.1, 0.4), random.uniform(0.1, 0.4), coordinate_axis::z};
    default:
        return frustum(random.uniform(0.2, 0.4), random.uniform(0.05, 0.2), random.uniform(0.1, 0.3));
    }
}

compound_shape random_compound(rng &random, int num_children) {
    compound_shape c;
    for (int i = 0; i < num_children; ++i)
        c.add_shape(random_child(random), random.vec(-1, 1), random.orientation());
    c.finish();
    return c;
}

struct child_points {
    bool any{false};
    scalar min_distance{large_scalar};
    std::set<std::pair<int, int>> parts;
};

// Every child on its own against `b` (the compound's result must agree on the deepest point and
// on which children report anything).
template<typename B>
child_points brute_force(const compound_shape &a, const B &b, const collision_context &ctx) {
    child_points out;
    for (std::size_t i = 0; i < a.children.size(); ++i) {
        const auto &child = a.children[i];
        collision_context child_ctx{to_world_space(child.position, ctx.posA, ctx.ornA),
                                    ctx.ornA * child.orientation, ctx.posB, ctx.ornB, ctx.threshold};
        collision_result r;
        if constexpr (std::is_same_v<B, compound_shape>) {
            // As the compound pair runs it: B's child as A against this child (then swapped).
            for (std::size_t j = 0; j < b.children.size(); ++j) {
                const auto &other = b.children[j];
                collision_context pair_ctx{to_world_space(other.position, ctx.posB, ctx.ornB),
                                           ctx.ornB * other.orientation, child_ctx.posA, child_ctx.ornA,
                                           ctx.threshold};
                r.num_points = 0;
                std::visit([&](const auto &sb, const auto &sa) { collide(sb, sa, pair_ctx, r); }, other.shape,
                           child.shape);
                if (r.num_points == 0) continue;
                out.any = true;
                out.min_distance = std::min(out.min_distance, min_distance(r));
                out.parts.insert({int(i), int(j)});
            }
        } else {
            std::visit([&](const auto &sa) { collide(sa, b, child_ctx, r); }, child.shape);
            if (r.num_points == 0) continue;
            out.any = true;
            out.min_distance = std::min(out.min_distance, min_distance(r));
            out.parts.insert({int(i), -1});
        }
    }
    return out;
}

template<typename B>
int expect_matches_brute_force(const compound_shape &a, const B &b, const collision_context &ctx, int i) {
    auto r = collide_compound_checked(a, b, ctx);
    auto expected = brute_force(a, b, ctx);
    EXPECT_EQ(r.num_points > 0, expected.any) << "case " << i;
    if (r.num_points == 0 || !expected.any) return 0;
    EXPECT_NEAR(min_distance(r), expected.min_distance, compound_tol) << "case " << i;
    for (std::size_t k = 0; k < r.num_points; ++k) {
        auto pa = part_of(r.point[k].featureA);
        auto pb = std::is_same_v<B, compound_shape> ? part_of(r.point[k].featureB) : -1;
        EXPECT_TRUE(expected.parts.count({pa, pb}))
            << "case " << i << ": children " << pa << ", " << pb << " report nothing on their own";
    }
    return 1;
}

template<typename B>
void random_scenes(const B &b, unsigned seed, int num_children) {
    rng random(seed);
    int touching = 0;
    for (int i = 0; i < 60; ++i) {
        auto a = random_compound(random, num_children);
        collision_context ctx{
            random.vec(-2, 2), random.orientation(), {}, random.orientation(), scalar(0.05)};
        ctx.posB = ctx.posA + random.vec(-1.2, 1.2);
        touching += expect_matches_brute_force(a, b, ctx, i);
    }
    EXPECT_GT(touching, 10);
}

} // namespace

TEST(collide_compound_test, random_compounds_match_their_children) {
    for (int n : {3, 12}) {
        random_scenes(box_shape{{0.4, 0.2, 0.6}}, 40 + n, n);
        random_scenes(sphere_shape{0.5}, 41 + n, n);
        random_scenes(capsule_shape{0.2, 0.5, coordinate_axis::x}, 42 + n, n);
        random_scenes(cylinder_shape{0.3, 0.4, coordinate_axis::y}, 43 + n, n);
        random_scenes(frustum(0.4, 0.2, 0.3), 44 + n, n);
        random_scenes(plane_shape{normalize(vector3{0.3, 1, -0.2}), scalar(0.5)}, 45 + n, n);
    }
}

TEST(collide_compound_test, random_compound_pairs_match_their_child_pairs) {
    rng random(50);
    int touching = 0;
    for (int i = 0; i < 60; ++i) {
        auto n = i % 2 == 0 ? 3 : 12;
        auto a = random_compound(random, n);
        auto b = random_compound(random, 15 - n);
        collision_context ctx{
            random.vec(-2, 2), random.orientation(), {}, random.orientation(), scalar(0.05)};
        ctx.posB = ctx.posA + random.vec(-2, 2);
        touching += expect_matches_brute_force(a, b, ctx, i);
    }
    EXPECT_GT(touching, 15);
}
