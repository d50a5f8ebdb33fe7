// The asynchronous mode's lifecycle: changes made while running that must reach the worker
// (checked through the physics they cause there), bodies destroyed under their constraints, and
// step callbacks that throw.
#include "unit/simulation/async_lifecycle_support.hpp"

using namespace edyn;
using namespace edyn::async_lifecycle_support;

TEST_F(async_lifecycle, a_falling_body_made_static_stops_where_the_main_side_shows_it) {
    start();
    auto box = make_box(reg, {0, 20, 0});
    run_frames(30);
    set_paused(reg, true);
    step_simulation(reg);
    rigidbody_set_kind(reg, box, rigidbody_kind::rb_static);
    wait_for_simulation(reg);
    set_paused(reg, false);
    run_frames(60);
    auto y = pos(box).y;
    // 31 steps of fall from 20 m: 18.7 m.
    EXPECT_GT(y, 18) << "the box fell on after it was made static";
    EXPECT_LT(y, 19.5) << "the box did not fall before it was made static";
    auto top = worker_surface_height(reg, 0, 0, 50);
    EXPECT_NEAR(top, y + 0.5, 1e-3) << "the worker's box top vs the main side's box position + 0.5";

    run_frames(60);
    EXPECT_EQ(pos(box).y, y) << "a static body moved on the main side";
    auto top_later = worker_surface_height(reg, 0, 0, 50);
    EXPECT_EQ(top_later, top) << "a static body moved in the worker";

    rigidbody_set_kind(reg, box, rigidbody_kind::rb_dynamic);
    run_frames(240);
    EXPECT_NEAR(pos(box).y, 0.5, 0.02) << "made dynamic again, the box should rest on the ground";
}

// A resting box whose shape is removed falls through the ground; given a shape again and lifted
// it lands on it. A shape removed and given back within one frame, and a box swapped for a
// smaller sphere (which settles lower), show the worker ends up with the last shape set.
TEST_F(async_lifecycle, shapes_removed_restored_and_swapped_while_running_reach_the_worker) {
    start();
    auto removed = make_box(reg, {0, 0.5, 0});
    auto restored = make_box(reg, {3, 0.5, 0});
    auto swapped = make_box(reg, {6, 0.5, 0});
    run_frames(30);
    update_without_waiting(); // changed while the worker runs this step
    rigidbody_set_shape(reg, removed, std::nullopt);
    rigidbody_set_shape(reg, restored, std::nullopt);
    rigidbody_set_shape(reg, restored, box_shape{0.5, 0.5, 0.5});
    rigidbody_set_shape(reg, swapped, sphere_shape{0.25});
    run_frames(60);
    EXPECT_LT(pos(removed).y, -2) << "a body without a shape should fall through the ground (1 s: -4.4 m)";
    EXPECT_NEAR(pos(restored).y, 0.5, 0.02) << "a shape removed and given back in one frame";
    EXPECT_NEAR(pos(swapped).y, 0.25, 0.02) << "a box swapped for a sphere of radius 0.25 rests on it";

    rigidbody_set_shape(reg, removed, box_shape{0.5, 0.5, 0.5});
    reg.replace<position>(removed, position{0, 3, 0});
    reg.replace<linvel>(removed, linvel{vector3_zero});
    run_frames(120);
    EXPECT_NEAR(pos(removed).y, 0.5, 0.02) << "given a shape again and lifted, the box lands on the ground";
}

// A resting box whose centre of mass is moved past the edge of its base tips over in the worker,
// while an untouched one stays upright; the worker shifts its own position with the centre of
// mass, so the body's origin stays put across the next step.
TEST_F(async_lifecycle, a_centre_of_mass_moved_past_the_base_while_running_tips_the_body_over) {
    start();
    auto tipped = make_box(reg, {0, 0.5, 0});
    auto upright = make_box(reg, {5, 0.5, 0});
    // Well before the boxes could fall asleep (time_to_sleep is 30 steps): see the next test.
    run_frames(10);
    update_without_waiting(); // changed while the worker runs this step
    set_center_of_mass(reg, tipped, {0.8, 0, 0});
    EXPECT_NEAR(pos(tipped).x, 0.8, 1e-3) << "the main side's position moves with the centre of mass at once";
    wait_for_simulation(reg);
    set_paused(reg, true);
    step_simulation(reg);
    wait_for_simulation(reg);
    auto origin = get_rigidbody_origin(reg, tipped);
    EXPECT_NEAR(origin.x, 0, 0.01) << "origin after a step in the worker (its position shifted too)";
    EXPECT_NEAR(origin.y, 0.5, 0.01) << "origin after a step in the worker (its position shifted too)";
    set_paused(reg, false);

    run_frames(120);
    EXPECT_LT(up_axis(reg, tipped).y, 0.7)
        << "the box with its centre of mass outside its base stays upright";
    EXPECT_GT(up_axis(reg, upright).y, 0.99) << "the untouched box";
}

// The same change on the last step before the box's island would fall asleep (it has rested for
// time_to_sleep less one step): the change must keep it awake, and the box tip over, rather
// than let it sleep with its centre of mass outside its base. Run step by step so that the
// change lands between steps 29 and 30 every time.
TEST_F(async_lifecycle, a_centre_of_mass_moved_just_before_the_body_would_sleep_still_tips_it_over) {
    start();
    set_paused(reg, true);
    auto tipped = make_box(reg, {0, 0.5, 0});
    auto steps_to_sleep = static_cast<int>(std::lround(get_settings(reg).time_to_sleep / get_fixed_dt(reg)));
    for (int i = 0; i < steps_to_sleep - 1; ++i)
        step_simulation(reg);
    wait_for_simulation(reg);
    ASSERT_FALSE(reg.all_of<sleeping_tag>(tipped)) << "asleep after " << steps_to_sleep - 1 << " steps";
    set_center_of_mass(reg, tipped, {0.8, 0, 0});
    for (int i = 0; i < 120; ++i)
        step_simulation(reg);
    wait_for_simulation(reg);
    EXPECT_LT(up_axis(reg, tipped).y, 0.7) << "the box with its centre of mass outside its base stays upright"
                                           << (reg.all_of<sleeping_tag>(tipped) ? " (asleep)" : "");
}

// Two boxes rest on static platforms; the collision of one pair is excluded while running, and
// that box falls through its platform to the ground while the other stays.
TEST_F(async_lifecycle, a_pair_excluded_while_resting_passes_through) {
    start();
    auto platform = make_box(reg, {0, 2, 0}, {2, 0.25, 2}, rigidbody_kind::rb_static);
    make_box(reg, {10, 2, 0}, {2, 0.25, 2}, rigidbody_kind::rb_static);
    auto excluded = make_box(reg, {0, 2.75, 0});
    auto kept = make_box(reg, {10, 2.75, 0});
    run_frames(30);
    update_without_waiting(); // changed while the worker runs this step
    exclude_collision(reg, platform, excluded);
    run_frames(90);
    EXPECT_NEAR(pos(excluded).y, 0.5, 0.02)
        << "the excluded box should fall through the platform to the ground";
    EXPECT_NEAR(pos(kept).y, 2.75, 0.02) << "the other box stays on its platform";
}

// A material replaced while running (friction to zero) reaches the worker: pushed alike, the
// slick box slides on at its speed while the other stops within a metre or two.
TEST_F(async_lifecycle, a_material_replaced_while_running_changes_the_friction_in_the_worker) {
    start();
    auto slick = make_box(reg, {0, 0.5, 0});
    auto rough = make_box(reg, {0, 0.5, 5});
    run_frames(30);
    update_without_waiting(); // changed while the worker runs this step
    auto m = reg.get<material>(slick);
    m.friction = 0;
    reg.replace<material>(slick, m);
    reg.replace<linvel>(slick, linvel{4, 0, 0});
    reg.replace<linvel>(rough, linvel{4, 0, 0});
    run_frames(90);
    // Without friction: 4 m/s for 1.5 s. With friction 0.5: stops after 1.6 m.
    EXPECT_GT(pos(slick).x, 5.5) << "distance slid without friction";
    EXPECT_NEAR(reg.get<linvel>(slick).x, 4, 0.1) << "speed without friction";
    EXPECT_LT(pos(rough).x, 2.5) << "distance slid with friction";
    EXPECT_NEAR(reg.get<linvel>(rough).x, 0, 0.05) << "speed with friction";
}

// A pendulum (body B hanging from a static anchor S by a point constraint) has other bodies
// joined to it and destroyed: one in the frame that made it (its creation never reached the
// worker), one after a step with it ran, one right after an update (while the worker steps),
// on either side of their constraints. Each time the constraint goes at once on the main side;
// bodies then made on the freed entity indices are not confused with the old ones; the
// pendulum keeps swinging on its one constraint and the worker has exactly the live bodies.
TEST_F(async_lifecycle, destroying_a_body_under_its_constraints_on_either_side_of_a_step) {
    start();
    set_paused(reg, true);
    auto anchor = make_ball(reg, {0, 5, 0}, scalar(0.1), rigidbody_kind::rb_static);
    auto bob = make_ball(reg, {1, 5, 0}, scalar(0.2));
    auto swing = make_constraint<point_constraint>(reg, anchor, bob, [](point_constraint &c) {
        c.pivot[0] = vector3_zero;
        c.pivot[1] = {-1, 0, 0};
    });
    step_simulation(reg);
    wait_for_simulation(reg);

    // 1. Made and destroyed in one frame: the worker gets the body and its end together.
    auto a = make_ball(reg, {2, 5, 0}, scalar(0.2));
    auto a_joint = make_constraint<point_constraint>(reg, a, bob, [](point_constraint &c) {
        c.pivot[0] = {-0.5, 0, 0};
        c.pivot[1] = {0.5, 0, 0};
    });
    auto a_hinge = make_constraint<hinge_constraint>(reg, bob, a);
    reg.destroy(a);
    EXPECT_FALSE(reg.valid(a_joint)) << "a body's constraint (body[0] side) outlived it on the main side";
    EXPECT_FALSE(reg.valid(a_hinge)) << "a body's constraint (body[1] side) outlived it on the main side";
    EXPECT_EQ(constraint_entities_of(reg, bob), std::vector<entity>{swing});
    step_simulation(reg);
    wait_for_simulation(reg);

    // 2. Destroyed after a step with it ran in the worker.
    auto c = make_ball(reg, {2, 5, 0}, scalar(0.2));
    auto c_joint =
        make_constraint<distance_constraint>(reg, bob, c, [](distance_constraint &d) { d.distance = 1; });
    step_simulation(reg);
    wait_for_simulation(reg);
    ASSERT_TRUE(reg.valid(c_joint));
    reg.destroy(c);
    EXPECT_FALSE(reg.valid(c_joint)) << "a body's constraint (body[1] side) outlived it on the main side";
    EXPECT_EQ(constraint_entities_of(reg, bob), std::vector<entity>{swing});
    // Entities made now reuse the freed indices: a free body and a constraint that is not the
    // pendulum's.
    auto reused = make_ball(reg, {10, 5, 0}, scalar(0.2));
    auto other = make_ball(reg, {12, 5, 0}, scalar(0.2));
    auto reused_joint = make_constraint<null_constraint>(reg, reused, other);
    for (int i = 0; i < 3; ++i)
        step_simulation(reg);
    wait_for_simulation(reg);

    // 3. Destroyed right after an update, while the worker may be stepping with it.
    set_paused(reg, false);
    auto d = make_ball(reg, {2, 5, 0}, scalar(0.2));
    auto d_joint = make_constraint<point_constraint>(reg, d, bob, [](point_constraint &con) {
        con.pivot[0] = {-0.5, 0, 0};
        con.pivot[1] = {0.5, 0, 0};
    });
    run_frames(3);
    update_without_waiting();
    reg.destroy(d);
    EXPECT_FALSE(reg.valid(d_joint)) << "a body's constraint (body[0] side) outlived it on the main side";
    EXPECT_EQ(constraint_entities_of(reg, bob), std::vector<entity>{swing});
    run_frames(90);

    EXPECT_TRUE(reg.valid(swing) && reg.valid(reused_joint));
    EXPECT_EQ(reg.view<point_constraint>().size(), 1u) << "point constraints left on the main side";
    EXPECT_EQ(reg.view<distance_constraint>().size(), 0u) << "distance constraints left on the main side";
    EXPECT_EQ(reg.view<hinge_constraint>().size(), 0u) << "hinge constraints left on the main side";
    EXPECT_EQ(reg.view<null_constraint>().size(), 1u) << "null constraints left on the main side";
    EXPECT_NEAR(distance(pos(bob), pos(anchor)), 1, 0.02) << "the pendulum's length after swinging";
    EXPECT_LT(pos(bob).y, 4.9) << "the pendulum should have swung down";
    EXPECT_TRUE(isfinite(pos(bob)) && isfinite(reg.get<orientation>(bob)));
    // The bodies on the reused indices fell freely, far from the pendulum, to the ground.
    EXPECT_NEAR(pos(reused).x, 10, 1e-3) << "a body on a reused index was pulled sideways";
    EXPECT_NEAR(pos(reused).y, 0.2, 0.02) << "a body on a reused index should rest on the ground";
    auto expected = std::vector<entity>{anchor, bob, reused, other};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(worker_bodies(reg, ground), expected) << "the worker's bodies";
}

// The static anchor of a pendulum is destroyed right after an update: the constraint goes with
// it at once on the main side, the bob, freed, falls to the ground, and the worker no longer
// has the anchor.
TEST_F(async_lifecycle, destroying_the_static_anchor_of_a_constraint_frees_the_body) {
    start();
    auto anchor = make_ball(reg, {0, 5, 0}, scalar(0.1), rigidbody_kind::rb_static);
    auto bob = make_ball(reg, {1, 5, 0}, scalar(0.2));
    auto swing = make_constraint<point_constraint>(reg, anchor, bob, [](point_constraint &c) {
        c.pivot[0] = vector3_zero;
        c.pivot[1] = {-1, 0, 0};
    });
    run_frames(10);
    update_without_waiting();
    reg.destroy(anchor);
    EXPECT_FALSE(reg.valid(swing)) << "the constraint outlived its static body on the main side";
    EXPECT_EQ(constraint_entities_of(reg, bob), std::vector<entity>{});
    run_frames(90);
    EXPECT_NEAR(pos(bob).y, 0.2, 0.02) << "freed from its anchor, the bob should fall to the ground";
    EXPECT_EQ(worker_bodies(reg, ground), std::vector<entity>{bob}) << "the worker's bodies";
}

// A pre-step callback throws on its third call: the next wait_for_simulation() rethrows that
// exception on the main thread, once; the worker goes on stepping (the box keeps falling and the
// step count advances) and later waits throw nothing.
TEST_F(async_lifecycle, an_exception_from_a_step_callback_is_rethrown_once_by_the_next_wait) {
    start();
    set_paused(reg, true);
    auto box = make_box(reg, {0, 10, 0});
    callback_calls = 0;
    throw_on_call = 3;
    set_pre_step_callback(reg, &throwing_pre_step);
    for (int i = 0; i < 2; ++i) {
        step_simulation(reg);
        EXPECT_NO_THROW(wait_for_simulation(reg)) << "step " << i;
    }
    EXPECT_EQ(get_step_count(reg), 2u);
    step_simulation(reg);
    std::string what;
    try {
        wait_for_simulation(reg);
    } catch (const std::runtime_error &e) {
        what = e.what();
    }
    EXPECT_EQ(what, "pre-step callback failed on call 3") << "what wait_for_simulation rethrew";

    auto steps = get_step_count(reg);
    auto y = pos(box).y;
    for (int i = 0; i < 5; ++i) {
        step_simulation(reg);
        EXPECT_NO_THROW(wait_for_simulation(reg)) << "the same exception thrown again, step " << i;
    }
    EXPECT_EQ(get_step_count(reg), steps + 5) << "steps after the one that threw";
    EXPECT_LT(pos(box).y, y - 0.01) << "the box stopped falling after the callback threw";
    EXPECT_EQ(callback_calls.load(), 8);
}

// The same through update() alone: the callback throws on its call after nine frames, in a step asked for
// by an update() not waited for; update() calls that follow (asking for no new step) rethrow
// it once the worker's message is back, exactly once, and a second of updates after that
// throws nothing while the box falls on.
TEST_F(async_lifecycle, an_exception_from_a_step_callback_is_rethrown_once_by_a_later_update) {
    start();
    auto box = make_box(reg, {0, 10, 0});
    callback_calls = 0;
    throw_on_call = -1;
    set_pre_step_callback(reg, &throwing_pre_step);
    run_frames(9);
    // The next step's call throws.
    throw_on_call = callback_calls.load() + 1;
    update_without_waiting();
    int thrown = 0, updates = 0;
    std::string what;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (thrown == 0 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ++updates;
        try {
            update(reg, t);
        } catch (const std::runtime_error &e) {
            ++thrown;
            what = e.what();
        }
    }
    EXPECT_EQ(thrown, 1) << "update() did not rethrow the worker's exception within 10 s (" << updates
                         << " updates)";
    EXPECT_EQ(what, "pre-step callback failed on call " + std::to_string(throw_on_call.load()))
        << "what update() rethrew";

    auto steps = get_step_count(reg);
    auto y = pos(box).y;
    int thrown_later = 0;
    for (int i = 0; i < 60; ++i) {
        t += frame;
        try {
            update(reg, t);
            wait_for_simulation(reg);
        } catch (const std::exception &) {
            ++thrown_later;
        }
    }
    EXPECT_EQ(thrown_later, 0) << "exceptions from updates and waits after the one rethrown";
    EXPECT_GE(get_step_count(reg), steps + 59) << "steps in the second after the exception";
    EXPECT_LT(pos(box).y, y - 1) << "the box stopped falling after the callback threw";
    EXPECT_EQ(callback_calls.load(), throw_on_call.load() + int(get_step_count(reg) - steps))
        << "callback calls";
}

// The registry is dropped without detach() while the worker has many steps of a pile of boxes
// to run, operations not yet sent, a query waiting for its reply and (every other round) an
// exception waiting to be rethrown. Destroying it must neither crash nor hang (ASan checks that
// nothing leaks), in 20 rounds.
