#include "behaviour/behaviour_support.hpp"
#include <algorithm>
#include <initializer_list>

namespace edyn::test {
namespace {

struct sleeping : world_fixture {
    entity ground;
    void SetUp() override {
        world_fixture::SetUp();
        rigidbody_def def;
        def.kind = rigidbody_kind::rb_static;
        def.shape = plane_shape{vector3_y, 0};
        ground = make_rigidbody(reg, def);
    }
    bool asleep(entity e) const { return reg.all_of<sleeping_tag>(e); }

    // The graph invariant islands rest on: every manifold in contact with a dynamic body is an
    // edge of that body's island.
    void expect_contacts_are_island_edges() const {
        if (!simulates_here(reg)) return;
        for (auto e : reg.view<contact_manifold>()) {
            auto &m = reg.get<contact_manifold>(e);
            if (m.num_points == 0) continue;
            for (auto body : m.body) {
                if (!reg.all_of<dynamic_tag>(body)) continue;
                auto *edge = reg.try_get<island_resident>(e);
                ASSERT_NE(edge, nullptr) << "manifold " << to_integral(e) << " in contact is in no island";
                EXPECT_EQ(edge->island_entity, reg.get<island_resident>(body).island_entity);
            }
        }
    }
};

TEST_F(sleeping, a_resting_box_falls_asleep_with_its_island) {
    auto box = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 0.5, 0}));
    auto time_to_sleep = double(get_settings(reg).time_to_sleep);
    // Awake while its timer runs.
    run_for(time_to_sleep * 0.5);
    EXPECT_FALSE(asleep(box));
    run_for(1.0);
    ASSERT_TRUE(asleep(box)) << "not asleep after " << time_to_sleep * 0.5 + 1 << " s";
    if (simulates_here(reg)) {
        EXPECT_TRUE(asleep(reg.get<island_resident>(box).island_entity));
    }
    EXPECT_EQ(vel(box), vector3_zero);
    EXPECT_EQ(angular(box), vector3_zero);
    // A sleeping body does not move, however many steps run.
    auto before = pos(box);
    run_for(2.0);
    EXPECT_EQ(pos(box), before);
}

TEST_F(sleeping, a_falling_body_stays_awake_and_sleeping_disabled_never_sleeps) {
    auto faller = make_rigidbody(reg, sphere_def(0.5, {10, 100, 0}));
    auto def = box_def({0.5, 0.5, 0.5}, {0, 0.5, 0});
    def.sleeping_disabled = true;
    auto insomniac = make_rigidbody(reg, def);
    run_for(3.0);
    EXPECT_FALSE(asleep(faller));
    EXPECT_FALSE(asleep(insomniac));
}

TEST_F(sleeping, a_body_dropped_on_a_sleeping_stack_wakes_it) {
    auto bottom = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 0.5, 0}));
    auto top = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 1.5, 0}));
    run_for(3.0);
    ASSERT_TRUE(asleep(bottom));
    ASSERT_TRUE(asleep(top));

    // A box, not a ball: a ball with no rolling friction would roll on for ever.
    auto dropped = make_rigidbody(reg, box_def({0.3, 0.3, 0.3}, {0.2, 4, 0.1}, 5));
    bool woke = false;
    for (int i = 0; i < 120 && !woke; ++i) {
        edyn::test::step(reg);
        woke = !asleep(bottom) && !asleep(top);
    }
    EXPECT_TRUE(woke);
    // One island now: the new contact joined it to the stack.
    if (simulates_here(reg)) {
        EXPECT_EQ(reg.get<island_resident>(dropped).island_entity,
                  reg.get<island_resident>(bottom).island_entity);
    }
    // And it all settles and sleeps again.
    run_for(5.0);
    EXPECT_TRUE(asleep(bottom));
    EXPECT_TRUE(asleep(dropped));
    expect_contacts_are_island_edges();
}

TEST_F(sleeping, changes_through_the_registry_or_edyns_functions_wake_a_body) {
    auto box = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 0.5, 0}));
    run_for(2.0);
    ASSERT_TRUE(asleep(box));

    reg.patch<linvel>(box, [](linvel &v) { v = vector3{0, 5, 0}; });
    EXPECT_FALSE(asleep(box));
    edyn::test::step(reg);
    EXPECT_GT(pos(box).y, 0.55) << "the patched velocity took effect";
    run_for(4.0);
    ASSERT_TRUE(asleep(box));

    reg.replace<position>(box, vector3{3, 2, 0});
    EXPECT_FALSE(asleep(box));
    run_for(4.0);
    ASSERT_TRUE(asleep(box));
    EXPECT_NEAR(pos(box).x, 3, 0.01);
    EXPECT_NEAR(pos(box).y, 0.5, 0.02);

    rigidbody_apply_impulse(reg, box, {0, 0, 4}, vector3_zero);
    EXPECT_FALSE(asleep(box));
    edyn::test::step(reg);
    EXPECT_GT(vel(box).z, 1);
    run_for(4.0);
    ASSERT_TRUE(asleep(box));

    set_gravity(reg, {0, 9.8, 0});
    EXPECT_FALSE(asleep(box));
    run_for(0.5);
    EXPECT_GT(pos(box).y, 1) << "the box falls up under the new gravity";
}

// Components a program emplaces or removes (not only replaces) wake the body: its own gravity,
// and sleeping_disabled_tag, which a sleeping body cannot keep.
TEST_F(sleeping, emplacing_or_removing_a_body_s_gravity_or_sleeping_disabled_wakes_it) {
    auto box = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 0.5, 0}));
    run_for(2.0);
    ASSERT_TRUE(asleep(box));

    reg.emplace<gravity>(box, vector3{0, 9.8, 0});
    EXPECT_FALSE(asleep(box));
    run_for(0.5);
    EXPECT_GT(pos(box).y, 1) << "the box's own upward gravity did not lift it";

    // Back under the world's gravity: it falls to the ground and sleeps there.
    reg.remove<gravity>(box);
    run_for(4.0);
    EXPECT_NEAR(pos(box).y, 0.5, 0.02);
    ASSERT_TRUE(asleep(box));
    // Removed while it sleeps, with the world's gravity now pointing up: it wakes and rises.
    reg.emplace<gravity>(box, vector3{0, -9.8, 0});
    set_gravity(reg, {0, 9.8, 0});
    run_for(4.0);
    ASSERT_TRUE(asleep(box)) << "its own gravity holds it on the ground";
    reg.remove<gravity>(box);
    EXPECT_FALSE(asleep(box));
    run_for(0.5);
    EXPECT_GT(pos(box).y, 1) << "the box did not follow the world's gravity once its own went";
    set_gravity(reg, {0, -9.8, 0});
    run_for(4.0);
    ASSERT_TRUE(asleep(box));

    reg.emplace<sleeping_disabled_tag>(box);
    EXPECT_FALSE(asleep(box));
    run_for(3.0);
    EXPECT_FALSE(asleep(box));
    reg.remove<sleeping_disabled_tag>(box);
    run_for(3.0);
    EXPECT_TRUE(asleep(box));
}

// set_gravity wakes resting bodies at every call, whatever the value; they then sleep again,
// in every mode (the main registry's tags follow the worker's in the asynchronous one).
TEST_F(sleeping, bodies_woken_by_set_gravity_fall_asleep_again_even_when_it_did_not_change) {
    auto box = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 0.5, 0}));
    auto g = get_gravity(reg);
    for (int round = 0; round < 2; ++round) {
        run_for(3.0);
        ASSERT_TRUE(asleep(box)) << "round " << round;
        if (round == 0) {
            set_gravity(reg, g);
        } else {
            // Changed and set back before a step: woken all the same.
            set_gravity(reg, g * 2);
            set_gravity(reg, g);
        }
        EXPECT_FALSE(asleep(box)) << "round " << round;
        run_for(0.1);
        EXPECT_FALSE(asleep(box)) << "round " << round;
        run_for(3.0);
        EXPECT_TRUE(asleep(box)) << "round " << round << ": the box does not sleep again";
    }
}

TEST_F(sleeping, separate_islands_sleep_independently) {
    auto resting = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 0.5, 0}));
    // A dropped rolling away on the ground, far off: never slow enough to sleep.
    auto def = sphere_def(0.5, {50, 0.5, 0});
    def.linvel = {3, 0, 0};
    auto roller = make_rigidbody(reg, def);
    run_for(2.0);
    EXPECT_TRUE(asleep(resting));
    EXPECT_FALSE(asleep(roller));
    if (simulates_here(reg)) {
        EXPECT_NE(reg.get<island_resident>(resting).island_entity,
                  reg.get<island_resident>(roller).island_entity);
    }
}

// Two boxes rest side by side, touching, in one island. Pulling one away must not keep the
// other awake: the island splits before it sleeps.
TEST_F(sleeping, an_island_that_comes_apart_splits_and_sleeps_in_parts) {
    auto left = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {-0.5, 0.5, 0}));
    auto right = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0.5, 0.5, 0}));
    run_for(0.2);
    if (simulates_here(reg)) {
        ASSERT_EQ(reg.get<island_resident>(left).island_entity,
                  reg.get<island_resident>(right).island_entity);
    }
    // Push the right box away; friction stops it a few metres off.
    reg.patch<linvel>(right, [](linvel &v) { v = vector3{6, 0, 0}; });
    run_for(6.0);
    EXPECT_GT(pos(right).x, 2) << "the right box went away";
    EXPECT_TRUE(asleep(left));
    EXPECT_TRUE(asleep(right));
    if (simulates_here(reg)) {
        EXPECT_NE(reg.get<island_resident>(left).island_entity,
                  reg.get<island_resident>(right).island_entity);
    }
    // Each box keeps its contact with the ground as an edge of its own island.
    expect_contacts_are_island_edges();
}

// A ball rests against a box, in one island, then rolls away for good: with nothing to slow
// its rolling it never gets slow enough to sleep. The box must still fall asleep: the island
// splits once the box wants to sleep, not only once every body of the island does.
TEST_F(sleeping, a_body_that_never_stops_does_not_keep_the_island_it_left_awake) {
    auto box = make_rigidbody(reg, box_def({0.5, 0.5, 0.5}, {0, 0.5, 0}));
    auto ball = make_rigidbody(reg, sphere_def(0.5, {1, 0.5, 0}));
    run_for(0.2);
    if (simulates_here(reg)) {
        ASSERT_EQ(reg.get<island_resident>(box).island_entity, reg.get<island_resident>(ball).island_entity);
    }
    // Rolling without slipping along +x: v = w x r with r = (0, -0.5, 0).
    reg.patch<linvel>(ball, [](linvel &v) { v = vector3{3, 0, 0}; });
    reg.patch<angvel>(ball, [](angvel &w) { w = vector3{0, 0, -6}; });
    // The box's timer needs time_to_sleep (0.5 s) once the ball has left it.
    run_for(2.0);
    EXPECT_GT(pos(ball).x, 5) << "the ball rolled away";
    EXPECT_GT(length(vel(ball)), get_settings(reg).sleep_linear_velocity) << "the ball still rolls";
    EXPECT_FALSE(asleep(ball));
    EXPECT_TRUE(asleep(box)) << "the ball that left keeps the box awake";
    if (simulates_here(reg)) {
        EXPECT_NE(reg.get<island_resident>(box).island_entity, reg.get<island_resident>(ball).island_entity);
    }
    expect_contacts_are_island_edges();
}

// A kinematic body is in no island: nothing but its motion tells the bodies resting on it that
// they must move. A box asleep on a platform that starts to slide wakes, is dragged up to the
// platform's speed by friction, and rides it. It slips v^2 / (2 mu g) behind on the way.
TEST_F(sleeping, a_box_asleep_on_a_kinematic_platform_rides_it_once_it_moves) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_kinematic;
    def.shape = box_shape{2, scalar(0.25), 2};
    def.position = {0, 1, 0};
    def.material->friction = scalar(0.5);
    auto platform = make_rigidbody(reg, def);
    auto box_on_top = box_def({0.25, 0.25, 0.25}, {0, 1.5, 0});
    box_on_top.material->friction = scalar(0.5);
    auto box = make_rigidbody(reg, box_on_top);
    run_for(2.0);
    ASSERT_TRUE(asleep(box));

    scalar speed = 1;
    reg.patch<linvel>(platform, [&](linvel &v) { v = vector3{speed, 0, 0}; });
    run_for(1.5);
    EXPECT_FALSE(asleep(box)) << "the box sleeps on a moving platform";
    EXPECT_NEAR(vel(box).x, speed, scalar(0.01)) << "the box does not ride the platform";
    EXPECT_NEAR(pos(box).y, 1.5, scalar(0.01));
    // mu = 0.5 for both bodies, mixed to sqrt(0.5 * 0.5).
    auto slip = speed * speed / (2 * scalar(0.5) * length(get_gravity(reg)));
    EXPECT_NEAR(pos(platform).x - pos(box).x, slip, scalar(0.015));
}

// A game sets a kinematic body's velocity every frame, zero while it waits. A box resting on the
// ground inside the bounding box of a plank turned 45 degrees, but 2.5 m from the plank itself,
// must still fall asleep: only what a kinematic body touches follows its velocity.
TEST_F(sleeping, a_box_near_a_kinematic_body_whose_velocity_is_set_every_step_falls_asleep) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_kinematic;
    def.shape = box_shape{3, scalar(0.1), scalar(0.1)};
    def.orientation = quaternion_axis_angle(vector3_y, pi / 4);
    def.position = {0, scalar(0.3), 0};
    auto plank = make_rigidbody(reg, def);
    auto box = make_rigidbody(reg, box_def({0.25, 0.25, 0.25}, {scalar(1.8), scalar(0.25), scalar(1.8)}));
    ASSERT_TRUE(intersect(reg.get<AABB>(plank), reg.get<AABB>(box)))
        << "the box is not where the test needs it";
    // Asleep within a second, it must stay asleep: the patch in each step must not wake it.
    int awake_steps = 0;
    for (int i = 0; i < 120; ++i) {
        reg.patch<linvel>(plank, [](linvel &v) { v = vector3_zero; });
        edyn::test::step(reg);
        if (i >= 60 && !asleep(box)) ++awake_steps;
    }
    EXPECT_EQ(awake_steps, 0) << "of the last 60 steps, the box was awake in " << awake_steps;
}

// A platform rising slower than the sleep speed must not let what rests on it fall asleep: the
// box would stay where it slept while the platform moved through it.
TEST_F(sleeping, a_box_on_a_slowly_rising_kinematic_platform_stays_awake_and_rises) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_kinematic;
    def.shape = box_shape{2, scalar(0.25), 2};
    def.position = {0, 1, 0};
    auto platform = make_rigidbody(reg, def);
    auto box = make_rigidbody(reg, box_def({0.25, 0.25, 0.25}, {0, 1.5, 0}));
    run_for(2.0);
    ASSERT_TRUE(asleep(box));

    auto rate = get_settings(reg).sleep_linear_velocity / 2;
    reg.patch<linvel>(platform, [&](linvel &v) { v = vector3{0, rate, 0}; });
    run_for(3.0);
    EXPECT_NEAR(pos(platform).y, 1 + 3 * rate, scalar(1e-3));
    EXPECT_FALSE(asleep(box)) << "the box sleeps on a moving platform";
    EXPECT_NEAR(pos(box).y - pos(platform).y, 0.5, scalar(0.01)) << "the box did not rise with the platform";
    EXPECT_NEAR(vel(box).y, rate, scalar(0.005));
}

// A static or kinematic body is in no island either: when one that sleeping bodies rest on is
// destroyed, or stops being a rigid body, they lose their support and must fall.
TEST_F(sleeping, boxes_asleep_on_a_static_table_fall_when_it_is_destroyed_or_cleared) {
    auto make_table = [&](scalar x) {
        rigidbody_def def;
        def.kind = rigidbody_kind::rb_static;
        def.shape = box_shape{1, scalar(0.25), 1};
        def.position = {x, 1, 0};
        return make_rigidbody(reg, def);
    };
    auto destroyed = make_table(-3);
    auto cleared = make_table(3);
    auto left = make_rigidbody(reg, box_def({0.25, 0.25, 0.25}, {-3, 1.5, 0}));
    auto right = make_rigidbody(reg, box_def({0.25, 0.25, 0.25}, {3, 1.5, 0}));
    run_for(2.0);
    ASSERT_TRUE(asleep(left));
    ASSERT_TRUE(asleep(right));

    reg.destroy(destroyed);
    clear_rigidbody(reg, cleared);
    // A fall of 1.25 m takes 0.5 s; the boxes then rest on the ground.
    run_for(1.5);
    EXPECT_NEAR(pos(left).y, 0.25, scalar(0.01)) << "the box stays where the destroyed table was";
    EXPECT_NEAR(pos(right).y, 0.25, scalar(0.01)) << "the box stays where the cleared table was";
}

// A body hanging at rest from an anchor on a 2 m rope (a distance constraint), away from
// everything else.
struct hanging {
    entity anchor, rope, bob;
};

hanging hang(registry &reg, rigidbody_kind kind, bool shaped, scalar z) {
    rigidbody_def def;
    def.kind = kind;
    if (shaped) def.shape = box_shape{scalar(0.1), scalar(0.1), scalar(0.1)};
    def.position = {0, 10, z};
    auto anchor = make_rigidbody(reg, def);
    auto bob = make_rigidbody(reg, sphere_def(scalar(0.2), {0, 8, z}));
    auto rope = make_constraint<distance_constraint>(reg, anchor, bob, [](distance_constraint &c) {
        c.pivot[0] = c.pivot[1] = vector3_zero;
        c.distance = 2;
    });
    return {anchor, rope, bob};
}

// Steps 3 s, long enough for bobs hanging at rest to fall asleep: whether all of them did.
bool bobs_fall_asleep(sleeping &test, std::initializer_list<hanging> bobs) {
    test.run_for(3.0);
    return std::all_of(bobs.begin(), bobs.end(), [&](const hanging &h) { return test.asleep(h.bob); });
}

// An anchor is static or kinematic, in no island: a bob asleep under it must still wake and
// follow it when it moves, at its velocity or placed by the program.
TEST_F(sleeping, bobs_asleep_on_ropes_follow_anchors_that_move) {
    auto shaped = hang(reg, rigidbody_kind::rb_kinematic, true, -10);
    auto amorphous = hang(reg, rigidbody_kind::rb_kinematic, false, 0);
    auto placed = hang(reg, rigidbody_kind::rb_static, true, 10);
    ASSERT_TRUE(bobs_fall_asleep(*this, {shaped, amorphous, placed}));

    scalar v = 1;
    for (auto *h : {&shaped, &amorphous})
        reg.patch<linvel>(h->anchor, [&](linvel &vel) { vel = vector3{v, 0, 0}; });
    reg.patch<position>(placed.anchor, [](position &p) { p.x += 1; });
    scalar t = scalar(0.5);
    run_for(t);
    for (auto *h : {&shaped, &amorphous, &placed}) {
        EXPECT_FALSE(asleep(h->bob));
        EXPECT_NEAR(distance(pos(h->bob), pos(h->anchor)), 2, scalar(0.01)) << "the rope stretched";
    }
    // Seen from an anchor that starts moving at v, the bob swings from the bottom at -v: for
    // small angles x = v t - (v / w) sin(w t), with w = sqrt(g / L).
    auto w = std::sqrt(length(get_gravity(reg)) / 2);
    for (auto *h : {&shaped, &amorphous})
        EXPECT_NEAR(pos(h->bob).x, v * t - v / w * std::sin(w * t), scalar(0.01))
            << "the bob did not follow its anchor";
    // Moved 1 m aside, the anchor lets the bob swing from 30 degrees: it is well on its way.
    EXPECT_GT(pos(placed.bob).x, scalar(0.3)) << "the bob did not follow its anchor";
}

// A bob asleep on a rope falls freely once the rope is cut, or its anchor destroyed or cleared.
TEST_F(sleeping, a_bob_asleep_on_a_rope_falls_when_the_rope_or_its_anchor_goes) {
    auto cut = hang(reg, rigidbody_kind::rb_static, true, -10);
    auto destroyed = hang(reg, rigidbody_kind::rb_static, true, 0);
    auto cleared = hang(reg, rigidbody_kind::rb_kinematic, true, 10);
    ASSERT_TRUE(bobs_fall_asleep(*this, {cut, destroyed, cleared}));

    reg.destroy(cut.rope);
    reg.destroy(destroyed.anchor);
    clear_rigidbody(reg, cleared.anchor);
    run_for(1.0);
    for (auto *h : {&cut, &destroyed, &cleared})
        EXPECT_NEAR(pos(h->bob).y, 8 - fall(reg, 1), scalar(0.01)) << "the bob still hangs";
}

// Destroying a sleeping body destroys its joints, which wake the island it is still listed in
// while the registry takes its components away one by one.
TEST_F(sleeping, destroying_a_sleeping_body_with_joints_wakes_what_they_held) {
    auto hung = hang(reg, rigidbody_kind::rb_static, true, 0);
    auto left = make_rigidbody(reg, box_def({0.25, 0.25, 0.25}, {-5, 0.25, 0}));
    auto right = make_rigidbody(reg, box_def({0.25, 0.25, 0.25}, {-4.4, 0.25, 0}));
    make_constraint<point_constraint>(reg, left, right, [](point_constraint &c) {
        c.pivot[0] = {scalar(0.3), 0, 0};
        c.pivot[1] = {scalar(-0.3), 0, 0};
    });
    ASSERT_TRUE(bobs_fall_asleep(*this, {hung}));
    ASSERT_TRUE(asleep(left) && asleep(right));

    reg.destroy(hung.bob);
    reg.destroy(right);
    run_for(0.5);
    EXPECT_TRUE(reg.valid(hung.anchor));
    EXPECT_FALSE(reg.valid(hung.rope));
    EXPECT_EQ(reg.view<point_constraint>().size(), 0u);
    EXPECT_NEAR(pos(left).y, 0.25, scalar(0.01)) << "the box left alone moved";
    // The box it held is free: a push moves it.
    reg.patch<linvel>(left, [](linvel &v) { v = vector3{1, 0, 0}; });
    run_for(0.1);
    EXPECT_GT(pos(left).x, scalar(-5) + scalar(0.02)) << "the box stays where it was held";
}

// A bob asleep on its rope rises with it when the program shortens the rope.
TEST_F(sleeping, a_bob_asleep_on_a_rope_rises_when_the_rope_is_shortened) {
    auto rope = hang(reg, rigidbody_kind::rb_static, true, 0);
    run_for(3.0);
    ASSERT_TRUE(asleep(rope.bob));
    reg.patch<distance_constraint>(rope.rope, [](distance_constraint &c) { c.distance = 1; });
    run_for(1.0);
    EXPECT_NEAR(pos(rope.bob).y, 9, scalar(0.01)) << "the bob stays where the longer rope held it";
}

// A static ramp tilted 0.35 rad about z and a box resting on it, both of friction 0.8 (enough to
// hold it), each with the given material id.
struct ramp_with_box {
    static constexpr scalar angle = scalar(0.35);
    entity ramp, box;

    ramp_with_box(registry &reg, const vector3 &position, material_id_type ramp_id = invalid_material_id,
                  material_id_type box_id = invalid_material_id) {
        auto tilt = quaternion_axis_angle(vector3_z, angle);
        rigidbody_def def;
        def.kind = rigidbody_kind::rb_static;
        def.shape = box_shape{3, scalar(0.25), 3};
        def.orientation = tilt;
        def.position = position;
        def.material->friction = scalar(0.8);
        def.material->id = ramp_id;
        ramp = make_rigidbody(reg, def);
        auto on_top = box_def({0.25, 0.25, 0.25}, position + rotate(tilt, vector3{0, 0.5, 0}));
        on_top.orientation = tilt;
        on_top.material->friction = scalar(0.8);
        on_top.material->id = box_id;
        box = make_rigidbody(reg, on_top);
    }

    // How far a box sliding freely down the ramp from rest goes in t seconds: g sin(angle) t^2 / 2.
    static scalar free_slide(const registry &reg, scalar t) {
        return length(get_gravity(reg)) * std::sin(angle) * t * t / 2;
    }
};

// Boxes asleep on static bodies respond when the program changes those bodies: one on a ramp
// slides once the ramp loses its friction, at g sin(angle); one on a table falls once the table
// is made too narrow to hold it.
TEST_F(sleeping, boxes_asleep_on_static_bodies_respond_when_their_material_or_shape_changes) {
    ramp_with_box slope(reg, {0, 3, -5});
    auto on_ramp = slope.box;

    rigidbody_def table_def;
    table_def.kind = rigidbody_kind::rb_static;
    table_def.shape = box_shape{1, scalar(0.25), 1};
    table_def.position = {0, 1, 5};
    auto table = make_rigidbody(reg, table_def);
    // Its centre 0.6 m from the table's, over the table until the table is 0.6 m wide.
    auto on_table = make_rigidbody(reg, box_def({0.25, 0.25, 0.25}, {scalar(0.6), 1.5, 5}));
    run_for(3.0);
    ASSERT_TRUE(asleep(on_ramp));
    ASSERT_TRUE(asleep(on_table));
    auto start = pos(on_ramp);

    reg.patch<material>(slope.ramp, [](material &m) { m.friction = 0; });
    reg.patch<box_shape>(table, [](box_shape &b) { b.half_extents.x = scalar(0.3); });
    scalar t = 1;
    run_for(t);
    EXPECT_NEAR(length(pos(on_ramp) - start), ramp_with_box::free_slide(reg, t), scalar(0.02))
        << "the box stays on the ramp without friction";
    EXPECT_NEAR(pos(on_table).y, 0.25, scalar(0.01)) << "the box stays over the narrowed table";
}

// A pair of material ids given a frictionless mixing at run time: a box asleep on a ramp, each
// with one of the ids, slides at g sin(angle).
TEST_F(sleeping, a_box_asleep_on_a_ramp_slides_once_their_materials_mix_without_friction) {
    ramp_with_box slope(reg, {0, 3, 0}, 1, 2);
    run_for(3.0);
    ASSERT_TRUE(asleep(slope.box));
    auto start = pos(slope.box);

    material_base ice;
    ice.friction = 0;
    insert_material_mixing(reg, 2, 1, ice);
    scalar t = 1;
    run_for(t);
    EXPECT_NEAR(length(pos(slope.box) - start), ramp_with_box::free_slide(reg, t), scalar(0.02))
        << "the box stays on the ramp";
}

} // namespace
} // namespace edyn::test
