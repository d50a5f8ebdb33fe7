#include "edyn/collision/manifold_update.hpp"
#include "edyn/math/transform.hpp"
#include <algorithm>
#include <gtest/gtest.h>
#include <set>

namespace {

using edyn::collision_feature;
using edyn::collision_result;
using edyn::contact_manifold;
using edyn::manifold_transforms;
using edyn::scalar;
using edyn::vector3;

constexpr scalar contact_manifold_tol = scalar(1e-5);

// Body B at the origin, body A one metre above; contact normals point up (from B to A).
struct manifold_fixture : ::testing::Test {
    manifold_transforms tf{{0, 1, 0}, edyn::quaternion_identity, {0, 0, 0}, edyn::quaternion_identity};
    contact_manifold manifold;

    // A point whose pivot on B is `on_b` (world) and whose pivot on A lies `distance` above it.
    collision_result::collision_point make_point(vector3 on_b, scalar distance) const {
        collision_result::collision_point p{};
        p.normal = edyn::vector3_y;
        p.distance = distance;
        p.pivotB = edyn::to_object_space(on_b, tf.posB, tf.ornB);
        p.pivotA = edyn::to_object_space(on_b + edyn::vector3_y * distance, tf.posA, tf.ornA);
        return p;
    }

    static collision_result make_result(std::initializer_list<collision_result::collision_point> points) {
        collision_result result;
        for (auto &p : points)
            result.point[result.num_points++] = p;
        return result;
    }

    // Live points' pivots on B, in world space, rounded to millimetres for set comparison.
    std::set<std::array<long, 3>> live_positions() const {
        std::set<std::array<long, 3>> out;
        manifold.each_point([&](const edyn::contact_point &cp) {
            auto p = edyn::to_world_space(cp.pivotB, tf.posB, tf.ornB);
            out.insert({std::lround(p.x * 1000), std::lround(p.y * 1000), std::lround(p.z * 1000)});
        });
        return out;
    }

    // Checks that `ids` is a permutation of the slots.
    void expect_ids_permutation() const {
        auto ids = manifold.ids;
        std::sort(ids.begin(), ids.end());
        for (std::size_t i = 0; i < ids.size(); ++i)
            EXPECT_EQ(ids[i], i);
    }
};

TEST_F(manifold_fixture, new_points_fill_slots_and_start_contact) {
    auto result = make_result({make_point({0, 0, 0}, -0.01f), make_point({0.5f, 0, 0}, 0)});
    auto changes = edyn::update_contact_manifold(manifold, tf, result);

    ASSERT_EQ(manifold.num_points, 2u);
    EXPECT_EQ(changes.num_created, 2u);
    EXPECT_EQ(changes.num_destroyed, 0u);
    EXPECT_TRUE(changes.contact_started());
    EXPECT_FALSE(changes.contact_ended());
    EXPECT_EQ(changes.num_points_before, 0u);
    EXPECT_EQ(changes.num_points_after, 2u);
    std::set<int> created{changes.created[0], changes.created[1]};
    std::set<int> live{manifold.ids[0], manifold.ids[1]};
    EXPECT_EQ(created, live);

    auto &cp = manifold.point[manifold.ids[0]];
    EXPECT_NEAR(cp.distance, -0.01, contact_manifold_tol);
    EXPECT_NEAR(cp.pivotA.y, -1.01, contact_manifold_tol);
    EXPECT_EQ(cp.lifetime, 0u);
    EXPECT_EQ(cp.normal_impulse, 0);
    expect_ids_permutation();
}

TEST_F(manifold_fixture, matched_point_keeps_slot_impulses_and_ages) {
    auto first = make_result({make_point({0, 0, 0}, -0.01f), make_point({1, 0, 0}, -0.01f)});
    edyn::update_contact_manifold(manifold, tf, first);
    ASSERT_EQ(manifold.num_points, 2u);

    auto slot0 = manifold.ids[0];
    auto slot1 = manifold.ids[1];
    manifold.point[slot0].normal_impulse = 3;
    manifold.point[slot0].friction_impulse = {0.5f, -0.25f};
    manifold.point[slot1].normal_impulse = 7;

    // Same contact a little deeper and shifted by 1 cm on B (within the caching radius).
    auto second = make_result({make_point({1.01f, 0, 0}, -0.02f), make_point({0.01f, 0, 0}, -0.02f)});
    auto changes = edyn::update_contact_manifold(manifold, tf, second);

    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(changes.num_destroyed, 0u);
    EXPECT_FALSE(changes.contact_started());
    ASSERT_EQ(manifold.num_points, 2u);
    EXPECT_EQ(manifold.ids[0], slot0);
    EXPECT_EQ(manifold.ids[1], slot1);

    auto &p0 = manifold.point[slot0];
    auto &p1 = manifold.point[slot1];
    EXPECT_EQ(p0.normal_impulse, 3);
    EXPECT_EQ(p0.friction_impulse[0], 0.5f);
    EXPECT_EQ(p0.friction_impulse[1], -0.25f);
    EXPECT_EQ(p1.normal_impulse, 7);
    EXPECT_EQ(p0.lifetime, 1u);
    EXPECT_NEAR(p0.pivotB.x, 0.01, contact_manifold_tol);
    EXPECT_NEAR(p1.pivotB.x, 1.01, contact_manifold_tol);
    EXPECT_NEAR(p0.distance, -0.02, contact_manifold_tol);
}

TEST_F(manifold_fixture, equal_features_match_beyond_caching_radius) {
    auto with_features = [](collision_result::collision_point p, std::uint32_t a, std::uint32_t b) {
        p.featureA = collision_feature{edyn::box_feature::vertex, a};
        p.featureB = collision_feature{edyn::box_feature::face, b};
        return p;
    };
    auto first = make_result({with_features(make_point({0, 0, 0}, 0), 3, 2)});
    edyn::update_contact_manifold(manifold, tf, first);
    auto slot = manifold.ids[0];
    manifold.point[slot].normal_impulse = 5;

    // Same features, 5 cm away on both bodies: the point continues even though it lies past the
    // caching radius.
    auto changes = edyn::update_contact_manifold(
        manifold, tf, make_result({with_features(make_point({0.05f, 0, 0}, 0), 3, 2)}));
    EXPECT_EQ(changes.num_created, 0u);
    ASSERT_EQ(manifold.num_points, 1u);
    EXPECT_EQ(manifold.point[slot].normal_impulse, 5);
    EXPECT_NEAR(manifold.point[slot].pivotA.x, 0.05, contact_manifold_tol);

    // Other features at the very same place: clipping relabelled the point, which continues
    // with its impulse (warm starting depends on it).
    changes = edyn::update_contact_manifold(manifold, tf,
                                            make_result({with_features(make_point({0.05f, 0, 0}, 0), 4, 2)}));
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(changes.num_destroyed, 0u);
    ASSERT_EQ(manifold.num_points, 1u);
    EXPECT_EQ(manifold.point[slot].normal_impulse, 5);
    EXPECT_EQ(std::get<edyn::box_feature>(manifold.point[slot].featureA->feature), edyn::box_feature::vertex);
    EXPECT_EQ(manifold.point[slot].featureA->index, 4u);

    // Features on one side only cannot be compared with features on both: proximity decides.
    auto half = make_point({0.06f, 0, 0}, 0);
    half.featureA = collision_feature{edyn::box_feature::vertex, 9};
    changes = edyn::update_contact_manifold(manifold, tf, make_result({half}));
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(manifold.num_points, 1u);
}

TEST_F(manifold_fixture, proximity_match_needs_caching_radius) {
    edyn::update_contact_manifold(manifold, tf, make_result({make_point({0, 0, 0}, 0)}));
    auto slot = manifold.ids[0];
    manifold.point[slot].normal_impulse = 2;

    // 3 cm away on both bodies: within contact_caching_threshold (4 cm), same point.
    auto changes = edyn::update_contact_manifold(manifold, tf, make_result({make_point({0.03f, 0, 0}, 0)}));
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(manifold.point[slot].normal_impulse, 2);

    // 6 cm away on both bodies: a new point; the old one, still touching, stays.
    changes = edyn::update_contact_manifold(manifold, tf, make_result({make_point({0.09f, 0, 0}, 0)}));
    EXPECT_EQ(changes.num_created, 1u);
    EXPECT_EQ(manifold.num_points, 2u);
    auto other = changes.created[0];

    // Rolling: the pivot on A moved 5 cm over A's surface, the one on B only 1 cm. Near on one
    // body is enough.
    auto rolled = make_point({0.04f, 0, 0}, 0);
    rolled.pivotA = manifold.point[slot].pivotA + vector3{0, 0, scalar(0.05)};
    changes = edyn::update_contact_manifold(manifold, tf, make_result({rolled}));
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(manifold.point[slot].normal_impulse, 2);
    EXPECT_NEAR(manifold.point[slot].pivotA.z, 0.05, contact_manifold_tol);
    EXPECT_NEAR(manifold.point[other].pivotB.x, 0.09, contact_manifold_tol);
}

TEST_F(manifold_fixture, a_one_point_pair_continues_its_point_wherever_the_result_lies) {
    constexpr auto one_point = true;
    edyn::update_contact_manifold(manifold, tf, make_result({make_point({0, 0, 0}, 0)}), false, one_point);
    auto slot = manifold.ids[0];
    manifold.point[slot].normal_impulse = 2;

    // 9 cm away on both bodies, beyond contact_caching_threshold: still the pair's one point,
    // with its impulses.
    auto changes = edyn::update_contact_manifold(manifold, tf, make_result({make_point({0.09f, 0, 0}, 0)}),
                                                 false, one_point);
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(changes.num_destroyed, 0u);
    ASSERT_EQ(manifold.num_points, 1u);
    EXPECT_EQ(manifold.ids[0], slot);
    EXPECT_EQ(manifold.point[slot].normal_impulse, 2);
    EXPECT_NEAR(manifold.point[slot].pivotB.x, 0.09, contact_manifold_tol);

    // No point in the result: the pair does not touch within the threshold, though the live
    // point's pivots are still close.
    changes = edyn::update_contact_manifold(manifold, tf, make_result({}), false, one_point);
    EXPECT_EQ(changes.num_destroyed, 1u);
    EXPECT_EQ(manifold.num_points, 0u);

    // Without the flag, the same two results leave two points (see the test above).
    edyn::update_contact_manifold(manifold, tf, make_result({make_point({0, 0, 0}, 0)}));
    edyn::update_contact_manifold(manifold, tf, make_result({make_point({0.09f, 0, 0}, 0)}));
    EXPECT_EQ(manifold.num_points, 2u);
    expect_ids_permutation();
}

TEST_F(manifold_fixture, fifth_point_replaces_to_maximise_area) {
    // Unit square of existing points: A(0,0) B(1,0) C(1,1) D(0,1) in the x-z plane.
    auto square = make_result({make_point({0, 0, 0}, 0), make_point({1, 0, 0}, 0), make_point({1, 0, 1}, 0),
                               make_point({0, 0, 1}, 0)});
    edyn::update_contact_manifold(manifold, tf, square);
    ASSERT_EQ(manifold.num_points, 4u);
    auto slot_b = manifold.ids[1];
    for (std::uint32_t i = 0; i < 4; ++i)
        manifold.point[manifold.ids[i]].normal_impulse = scalar(i + 1);

    // A deeper point at (2, 0.2): kept. Dropping B leaves the quadrilateral A N C D of area 1.4,
    // more than dropping C (1.1), A (1.0) or D (1.0).
    auto changes =
        edyn::update_contact_manifold(manifold, tf, make_result({make_point({2, 0, 0.2f}, -0.01f)}));
    ASSERT_EQ(changes.num_destroyed, 1u);
    ASSERT_EQ(changes.num_created, 1u);
    EXPECT_EQ(changes.destroyed[0], slot_b);
    // The freed slot is reused.
    EXPECT_EQ(changes.created[0], slot_b);
    EXPECT_EQ(manifold.num_points, 4u);
    std::set<std::array<long, 3>> expected{{0, 0, 0}, {2000, 0, 200}, {1000, 0, 1000}, {0, 0, 1000}};
    EXPECT_EQ(live_positions(), expected);
    EXPECT_EQ(manifold.point[slot_b].normal_impulse, 0);
    EXPECT_EQ(manifold.point[slot_b].lifetime, 0u);
    // The others kept their impulses.
    scalar total = 0;
    manifold.each_point([&](const edyn::contact_point &cp) { total += cp.normal_impulse; });
    EXPECT_EQ(total, 1 + 3 + 4);
    expect_ids_permutation();
}

TEST_F(manifold_fixture, fifth_point_that_shrinks_area_is_dropped) {
    auto square = make_result({make_point({0, 0, 0}, 0), make_point({1, 0, 0}, 0), make_point({1, 0, 1}, 0),
                               make_point({0, 0, 1}, -0.01f)});
    edyn::update_contact_manifold(manifold, tf, square);
    auto before = live_positions();

    // In the middle and not the deepest: any set with it spans half the square.
    auto changes = edyn::update_contact_manifold(manifold, tf, make_result({make_point({0.5f, 0, 0.5f}, 0)}));
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(changes.num_destroyed, 0u);
    EXPECT_EQ(live_positions(), before);
}

TEST_F(manifold_fixture, deepest_point_is_always_kept) {
    auto square = make_result({make_point({0, 0, 0}, -0.01f), make_point({1, 0, 0}, -0.01f),
                               make_point({1, 0, 1}, -0.01f), make_point({0, 0, 1}, -0.01f)});
    edyn::update_contact_manifold(manifold, tf, square);

    auto changes =
        edyn::update_contact_manifold(manifold, tf, make_result({make_point({0.5f, 0, 0.5f}, -0.05f)}));
    EXPECT_EQ(changes.num_created, 1u);
    EXPECT_EQ(changes.num_destroyed, 1u);
    EXPECT_EQ(manifold.num_points, 4u);
    EXPECT_TRUE(live_positions().count({500, 0, 500}));
    scalar deepest = 1;
    manifold.each_point([&](const edyn::contact_point &cp) { deepest = std::min(deepest, cp.distance); });
    EXPECT_NEAR(deepest, -0.05, contact_manifold_tol);
}

TEST_F(manifold_fixture, two_new_points_into_three_replace_together) {
    auto three =
        make_result({make_point({0, 0, 0}, 0), make_point({1, 0, 0}, 0), make_point({0.5f, 0, 0.1f}, 0)});
    edyn::update_contact_manifold(manifold, tf, three);
    ASSERT_EQ(manifold.num_points, 3u);

    // Two new far corners: the thin middle point is the one to go, both new ones come in.
    auto changes = edyn::update_contact_manifold(
        manifold, tf, make_result({make_point({1, 0, 1}, -0.001f), make_point({0, 0, 1}, 0)}));
    EXPECT_EQ(changes.num_destroyed, 1u);
    EXPECT_EQ(changes.num_created, 2u);
    std::set<std::array<long, 3>> expected{{0, 0, 0}, {1000, 0, 0}, {1000, 0, 1000}, {0, 0, 1000}};
    EXPECT_EQ(live_positions(), expected);
    expect_ids_permutation();
}

TEST_F(manifold_fixture, separation_removes_points_and_ends_contact) {
    edyn::update_contact_manifold(manifold, tf,
                                  make_result({make_point({0, 0, 0}, 0), make_point({1, 0, 0}, 0)}));
    ASSERT_EQ(manifold.num_points, 2u);

    // A rises by 1 cm: both points at +1 cm, below the 2 cm threshold, kept.
    tf.posA.y += 0.01f;
    auto changes = edyn::refresh_contact_manifold(manifold, tf);
    EXPECT_EQ(changes.num_destroyed, 0u);
    EXPECT_NEAR(manifold.point[manifold.ids[0]].distance, 0.01, contact_manifold_tol);
    EXPECT_NEAR(manifold.point[manifold.ids[1]].distance, 0.01, contact_manifold_tol);

    // A tilts about z around the first point: the second rises by sin(0.03) ~ 3 cm, past the
    // threshold, while the first stays.
    auto first_slot = manifold.ids[0];
    auto q = edyn::quaternion_axis_angle(edyn::vector3_z, scalar(0.03));
    auto pivot_world = vector3{0, scalar(0.01), 0};
    tf.posA = pivot_world + edyn::rotate(q, vector3{0, scalar(1.01), 0} - pivot_world);
    tf.ornA = q;
    changes = edyn::update_contact_manifold(manifold, tf, collision_result{});
    EXPECT_EQ(changes.num_destroyed, 1u);
    ASSERT_EQ(manifold.num_points, 1u);
    EXPECT_EQ(manifold.ids[0], first_slot);
    EXPECT_NEAR(manifold.point[first_slot].distance, 0.01, 1e-4);
    EXPECT_FALSE(changes.contact_ended());

    tf.posA.y += 0.05f;
    changes = edyn::refresh_contact_manifold(manifold, tf);
    EXPECT_EQ(changes.num_destroyed, 1u);
    EXPECT_EQ(changes.destroyed[0], first_slot);
    EXPECT_EQ(manifold.num_points, 0u);
    EXPECT_TRUE(changes.contact_ended());
    expect_ids_permutation();
}

TEST_F(manifold_fixture, tangential_drift_removes_points) {
    edyn::update_contact_manifold(manifold, tf, make_result({make_point({0, 0, 0}, -0.005f)}));
    tf.posA.x += 0.015f; // below contact_drift_threshold (2 cm)
    EXPECT_EQ(edyn::refresh_contact_manifold(manifold, tf).num_destroyed, 0u);
    EXPECT_NEAR(manifold.point[manifold.ids[0]].distance, -0.005, contact_manifold_tol);
    tf.posA.x += 0.01f; // 2.5 cm in total
    auto changes = edyn::refresh_contact_manifold(manifold, tf);
    EXPECT_EQ(changes.num_destroyed, 1u);
    EXPECT_EQ(manifold.num_points, 0u);
}

TEST_F(manifold_fixture, removal_keeps_other_slots) {
    auto three = make_result({make_point({0, 0, 0}, 0), make_point({1, 0, 0}, 0), make_point({2, 0, 0}, 0)});
    edyn::update_contact_manifold(manifold, tf, three);
    auto slots = manifold.ids;
    manifold.point[slots[2]].normal_impulse = 9;

    // The middle point separates (its pivot on B drops 5 cm, as if B's surface fell away).
    manifold.point[slots[1]].pivotB.y = -0.05f;
    auto changes = edyn::refresh_contact_manifold(manifold, tf);
    ASSERT_EQ(changes.num_destroyed, 1u);
    EXPECT_EQ(changes.destroyed[0], slots[1]);
    ASSERT_EQ(manifold.num_points, 2u);
    // The last id took the removed one's place; the points did not move.
    EXPECT_EQ(manifold.ids[0], slots[0]);
    EXPECT_EQ(manifold.ids[1], slots[2]);
    EXPECT_EQ(manifold.point[slots[2]].normal_impulse, 9);
    EXPECT_NEAR(manifold.point[slots[2]].pivotB.x, 2, contact_manifold_tol);
    expect_ids_permutation();
}

TEST_F(manifold_fixture, far_result_points_are_ignored_or_end_their_point) {
    auto changes = edyn::update_contact_manifold(manifold, tf, make_result({make_point({0, 0, 0}, 0.05f)}));
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_EQ(manifold.num_points, 0u);

    edyn::update_contact_manifold(manifold, tf, make_result({make_point({0, 0, 0}, 0)}));
    ASSERT_EQ(manifold.num_points, 1u);
    // The collision routine now finds the same point 3 cm apart.
    auto far = make_point({0, 0, 0}, 0.03f);
    far.pivotA = manifold.point[manifold.ids[0]].pivotA;
    changes = edyn::update_contact_manifold(manifold, tf, make_result({far}));
    EXPECT_EQ(changes.num_destroyed, 1u);
    EXPECT_EQ(changes.num_created, 0u);
    EXPECT_TRUE(changes.contact_ended());
}

TEST_F(manifold_fixture, rotated_bodies_use_object_space_pivots) {
    tf.ornA = edyn::quaternion_axis_angle(edyn::vector3_y, edyn::half_pi);
    tf.ornB = edyn::quaternion_axis_angle(edyn::vector3_x, scalar(0.3));
    tf.posB = {3, -2, 1};
    // Normal fixed in world space; pivots expressed through the rotations by make_point.
    edyn::update_contact_manifold(manifold, tf, make_result({make_point({3.2f, -2, 1}, -0.004f)}));
    ASSERT_EQ(manifold.num_points, 1u);
    auto changes = edyn::refresh_contact_manifold(manifold, tf);
    EXPECT_EQ(changes.num_destroyed, 0u);
    EXPECT_NEAR(manifold.point[manifold.ids[0]].distance, -0.004, contact_manifold_tol);
    EXPECT_EQ(manifold.point[manifold.ids[0]].lifetime, 1u);
}

TEST_F(manifold_fixture, clear_destroys_all) {
    edyn::update_contact_manifold(manifold, tf,
                                  make_result({make_point({0, 0, 0}, 0), make_point({1, 0, 0}, 0)}));
    auto changes = edyn::clear_contact_manifold(manifold);
    EXPECT_EQ(changes.num_destroyed, 2u);
    EXPECT_EQ(manifold.num_points, 0u);
    EXPECT_TRUE(changes.contact_ended());
    expect_ids_permutation();
}

} // namespace

// Contact reuse: points are refreshed instead of recomputed only while nothing that could
// change them has changed since collide() last ran.
TEST_F(manifold_fixture, contacts_are_reused_only_after_a_collide_with_the_same_shapes) {
    EXPECT_FALSE(edyn::can_reuse_contacts(manifold, tf, 0, {0, 0})) << "collide() never ran for this pair";
    edyn::remember_collide(manifold, tf, {3, 1});
    EXPECT_TRUE(edyn::can_reuse_contacts(manifold, tf, 0, {3, 1}));
    EXPECT_FALSE(edyn::can_reuse_contacts(manifold, tf, 0, {4, 1})) << "body A's shape changed since";
    EXPECT_FALSE(edyn::can_reuse_contacts(manifold, tf, 0, {3, 2})) << "body B's shape changed since";
}

TEST_F(manifold_fixture, contacts_are_not_reused_after_moving_past_the_thresholds) {
    edyn::remember_collide(manifold, tf, {0, 0});
    auto near = tf;
    near.posA.x += edyn::contact_reuse_max_distance / 2;
    near.ornB = edyn::quaternion_axis_angle(edyn::vector3_z, edyn::contact_reuse_max_angle / 2);
    EXPECT_TRUE(edyn::can_reuse_contacts(manifold, near, 0, {0, 0}));

    auto moved = tf;
    moved.posB.y -= edyn::contact_reuse_max_distance * 2;
    EXPECT_FALSE(edyn::can_reuse_contacts(manifold, moved, 0, {0, 0}));

    auto turned = tf;
    turned.ornA = edyn::quaternion_axis_angle(edyn::vector3_x, edyn::contact_reuse_max_angle * 2);
    EXPECT_FALSE(edyn::can_reuse_contacts(manifold, turned, 0, {0, 0}));

    EXPECT_FALSE(edyn::can_reuse_contacts(manifold, tf, edyn::contact_reuse_max_distance * 2, {0, 0}))
        << "the bodies are about to close in faster than reuse allows";
}

TEST_F(manifold_fixture, updates_leave_the_pivots_in_world_space) {
    auto result = make_result({make_point({0.25f, 0, 0}, -0.01f)});
    edyn::update_contact_manifold(manifold, tf, result);
    ASSERT_EQ(manifold.num_points, 1u);
    auto &cp = manifold.point[manifold.ids[0]];
    EXPECT_NEAR(edyn::distance(cp.positionB, {0.25f, 0, 0}), 0, contact_manifold_tol);
    EXPECT_NEAR(edyn::distance(cp.positionA, {0.25f, -0.01f, 0}), 0, contact_manifold_tol);

    tf.posA.y -= scalar(0.005);
    edyn::refresh_contact_manifold(manifold, tf);
    EXPECT_NEAR(edyn::distance(cp.positionA, {0.25f, -0.015f, 0}), 0, contact_manifold_tol);
    EXPECT_NEAR(cp.distance, scalar(-0.015), contact_manifold_tol);
}

// A held point (old enough for static friction to hold it) found again by collide() keeps how
// far its surfaces slid since they stuck while it touches one body at the same material point;
// a young one, one that slid farther than contact_anchor_max_slip, or one touching both bodies
// elsewhere now starts again where it touches.
TEST_F(manifold_fixture, a_held_point_found_again_keeps_its_surfaces_slip) {
    auto slip_after = [&](std::uint32_t lifetime, scalar slide, scalar roll) {
        manifold = {};
        tf.posA = {0, 1, 0};
        edyn::update_contact_manifold(manifold, tf, make_result({make_point({0, 0, 0}, scalar(-0.005))}));
        manifold.point[manifold.ids[0]].lifetime = lifetime;
        // A slides by `slide` along x; the new result's pivot on A lies `roll` from the old one.
        tf.posA.x += slide;
        auto again = make_point({slide + roll, 0, 0}, scalar(-0.005));
        edyn::update_contact_manifold(manifold, tf, make_result({again}));
        EXPECT_EQ(manifold.num_points, 1u);
        auto &cp = manifold.point[manifold.ids[0]];
        EXPECT_EQ(cp.positionA, edyn::to_world_space(cp.pivotA, tf.posA, tf.ornA));
        EXPECT_EQ(cp.positionB, edyn::to_world_space(cp.pivotB, tf.posB, tf.ornB));
        EXPECT_NEAR(cp.distance, -0.005, contact_manifold_tol);
        return cp.positionA - cp.positionB;
    };
    const auto held = edyn::contact_anchor_min_lifetime;
    auto kept = slip_after(held, scalar(0.003), 0);
    EXPECT_NEAR(kept.x, 0.003, contact_manifold_tol);
    EXPECT_NEAR(kept.y, -0.005, contact_manifold_tol);
    EXPECT_NEAR(slip_after(held - 2, scalar(0.003), 0).x, 0, contact_manifold_tol) << "young";
    EXPECT_NEAR(slip_after(held, edyn::contact_anchor_max_slip * 2, 0).x, 0, contact_manifold_tol) << "slid";
    EXPECT_NEAR(slip_after(held, scalar(0.003), scalar(0.01)).x, 0, contact_manifold_tol) << "rolled";
}
