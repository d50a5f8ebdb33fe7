// The stacking bar: pyramids, towers, a brick wall and spheres in a box stand still for 10 s
// with sleeping off, so that the solver holds them up. Where it does not yet, the test says
// so and bounds what it measured, so that a worse solver shows.
#include "behaviour_support.hpp"
#include <edyn_scenes/scenes.hpp>
#include <vector>

using namespace edyn;

namespace {

struct stacking : edyn::test::world_fixture {
    // The largest distances any of `bodies` moved from where it started, across and along
    // gravity, over `seconds` with sleeping off; fails at once on a body that is not finite.
    struct drift {
        scalar horizontal{0}, vertical{0};
    };
    drift run_awake(const std::vector<entity> &bodies, double seconds) {
        edyn::test::disable_sleeping(reg);
        std::vector<vector3> start;
        for (auto e : bodies)
            start.push_back(pos(e));
        drift worst;
        auto steps = int(std::lround(seconds / double(get_fixed_dt(reg))));
        for (int i = 0; i < steps; ++i) {
            edyn::test::step(reg);
            for (std::size_t k = 0; k < bodies.size(); ++k) {
                auto d = pos(bodies[k]) - start[k];
                EXPECT_TRUE(isfinite(d)) << "body " << k << " is not finite after step " << i + 1;
                if (!isfinite(d)) return worst;
                worst.horizontal = std::max(worst.horizontal, std::hypot(d.x, d.z));
                worst.vertical = std::max(worst.vertical, std::abs(d.y));
            }
        }
        return worst;
    }
};

// What a stack standing still may move: 1 cm, the bar the 30-box tower is held to asleep and
// the pyramid's target.
constexpr scalar standing_still = scalar(0.01);

} // namespace

// Once asleep a stack stands whatever the solver does: this checks that the pyramid settles
// quickly enough to fall asleep before it has moved, not that the solver holds it up.
TEST_F(stacking, pyramid_of_210_boxes_falls_asleep_before_it_moves) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_pyramid(reg, 20);
    ASSERT_EQ(boxes.size(), 210u);
    auto top = boxes.back();
    auto start = pos(top);
    run_for(10);
    for (auto e : boxes) {
        ASSERT_TRUE(isfinite(pos(e)));
        ASSERT_TRUE(reg.all_of<sleeping_tag>(e)) << "a box is still awake after 10 s";
    }
    auto moved = length(pos(top) - start);
    EXPECT_LT(moved, scalar(0.01)) << "top box moved " << moved << " m";
}

// The solver's own stability: the benchmark's pyramid, awake for all of the 10 s.
TEST_F(stacking, pyramid_of_210_boxes_with_sleeping_off_stands_for_ten_seconds) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_pyramid(reg, 20);
    edyn::test::disable_sleeping(reg);
    auto top = boxes.back();
    auto start = pos(top);
    run_for(10);
    for (auto e : boxes) {
        ASSERT_TRUE(isfinite(pos(e)));
        ASSERT_FALSE(reg.all_of<sleeping_tag>(e));
    }
    // Below 1 cm (Jolt's pyramid drifts 2.7 cm, Bullet's 25 cm). Measured: 4.5 mm, nearly all of
    // it the springs' compression under the rows above; 1.6 mm sideways at most for any box.
    // Without static friction's anchors (contact_solver_settings::friction_anchor_hertz) the
    // top box crept out of the pyramid's plane at about 1 cm/s after the first 2 s, 6.6 cm in all.
    auto moved = length(pos(top) - start);
    EXPECT_LT(moved, standing_still) << "top box moved " << moved << " m";
}

// Asleep, like the first pyramid above; the tower awake is measured further down.
TEST_F(stacking, tower_of_30_boxes_falls_asleep_standing) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_tower(reg, 30);
    auto start = pos(boxes.back());
    run_for(10);
    // Standing: every box still rests on the one below it, and the top has neither fallen nor
    // sunk by more than the contacts' compression under the tower's weight.
    for (std::size_t i = 1; i < boxes.size(); ++i) {
        auto below = pos(boxes[i - 1]), above = pos(boxes[i]);
        auto offset = length(vector3{above.x - below.x, 0, above.z - below.z});
        EXPECT_LT(offset, scalar(0.01)) << "box " << i << " is off the one below by " << offset << " m";
        EXPECT_NEAR(above.y - below.y, 1, scalar(0.01)) << "box " << i;
    }
    auto top = pos(boxes.back());
    EXPECT_NEAR(top.y, start.y, scalar(0.05)) << "top box sank " << start.y - top.y << " m";
    auto sideways = length(vector3{top.x - start.x, 0, top.z - start.z});
    EXPECT_LT(sideways, scalar(0.01)) << "top box crept sideways by " << sideways << " m";
    // Still, so it sleeps.
    EXPECT_TRUE(reg.all_of<sleeping_tag>(boxes.back()));
}

// A pyramid four times the size: the top settles by the springs' compression and does not creep.
// Awake: with sleeping on it falls asleep at 7 s, and would stand from then on whatever the
// solver did. Measured awake at 10 s: no box more than 6.7 mm sideways (1.3 cm before static
// friction's anchors), and the top 1.8 cm down.
TEST_F(stacking, pyramid_of_820_boxes_with_sleeping_off_does_not_creep) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_pyramid(reg, 40);
    edyn::test::disable_sleeping(reg);
    auto top = boxes.back();
    auto start = pos(top);
    run_for(10);
    auto now = pos(top);
    auto sideways = length(vector3{now.x - start.x, 0, now.z - start.z});
    EXPECT_LT(sideways, standing_still) << "top box crept sideways by " << sideways << " m";
    EXPECT_NEAR(now.y, start.y, scalar(0.03)) << "top box sank " << start.y - now.y << " m";
}

// The tower the contact damping was tuned on, awake: it does not stand yet. Its top leans
// away, 6.7 cm at 10 s when this bound was set (21.6 cm, and ever faster, before static
// friction's anchors). The target is the 1 cm the sleeping tower is held to; until the solver
// meets it, the bound is the measured lean and a fifth, so that a worse solver shows.
TEST_F(stacking, tower_of_30_boxes_with_sleeping_off_leans_no_further_than_when_measured) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_tower(reg, 30);
    auto worst = run_awake(boxes, 10);
    const scalar measured_when_set = scalar(0.067), bound = measured_when_set * scalar(1.2);
    EXPECT_LT(worst.horizontal, bound) << "a box moved sideways by " << worst.horizontal << " m, bound "
                                       << bound << " m (target " << standing_still << " m)";
}

// The same tower with twice the sub-steps, as the guide's pitfalls (01-the-step.md) advise for
// tall stacks kept awake: it leans less. Measured when this bound was set: 1.9 cm at 10 s with
// 12 sub-steps against 6.7 cm with the default 6; the bound is that and a fifth, and the lean
// must stay under half the default's, run again here.
// In double precision the tower leans 4.1 cm with 12 sub-steps against 5.5 cm with 6. The
// difference is not the solver: integrate() leaves an orientation alone when a sub-step turns it
// by less than epsilon (16 machine epsilons: 1.9e-6 rad in float), so in float a sub-step drops
// angular velocities under 1.4e-3 rad/s (12 sub-steps) or 6.9e-4 rad/s (6), and with them much
// of the tower's slow tilt; double integrates them. (The double build with float's threshold
// leans 2.0 and 6.8 cm.) Both results are deterministic: a 1e-5 m or 1e-5 rad nudge to the
// tower leaves them unchanged to 0.1 mm.
TEST_F(stacking, tower_of_30_boxes_with_sleeping_off_leans_less_with_more_substeps) {
    scenes::make_ground(reg);
    auto by_default = run_awake(scenes::make_tower(reg, 30), 10);
    // The same world again, in a fresh registry, with 12 sub-steps.
    detach(reg);
    reg = registry{};
    attach(reg, edyn::test::test_config());
    set_solver_substeps(reg, 12);
    scenes::make_ground(reg);
    auto stiffer = run_awake(scenes::make_tower(reg, 30), 10);
#ifdef EDYN_DOUBLE_PRECISION
    const scalar measured_when_set = scalar(0.0414), share_of_default = scalar(0.8);
#else
    const scalar measured_when_set = scalar(0.019), share_of_default = scalar(0.5);
#endif
    const scalar bound = measured_when_set * scalar(1.2);
    EXPECT_LT(stiffer.horizontal, bound)
        << "a box moved sideways by " << stiffer.horizontal << " m, bound " << bound << " m";
    EXPECT_LT(stiffer.horizontal, by_default.horizontal * share_of_default)
        << "12 sub-steps: " << stiffer.horizontal << " m, 6: " << by_default.horizontal << " m";
}

// 15 boxes of different sizes and masses, heavy ones on light ones (up to 8 times their mass).
TEST_F(stacking, tower_of_15_mixed_boxes_with_sleeping_off_stands_for_ten_seconds) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_mixed_tower(reg, 15);
    auto worst = run_awake(boxes, 10);
    // The soft contacts give under the load, 15 of them in series, the lowest under 59 kg: as
    // they take it in the first tenth of a second the top box dips by up to 3.2 cm, then
    // rests 1.8 cm low (measured) and holds that height. Sideways no box moves more than 1.3 mm
    // (measured; 1.6 cm and growing before static friction's anchors).
    const scalar sink_measured = scalar(0.032);
    EXPECT_LT(worst.vertical, sink_measured * scalar(1.2))
        << "a box moved up or down by " << worst.vertical << " m, measured " << sink_measured
        << " m when set";
    EXPECT_LT(worst.horizontal, standing_still) << "a box crept sideways by " << worst.horizontal << " m";
    // Nothing fell off: each box still rests on the one below, well inside its top face.
    for (std::size_t i = 1; i < boxes.size(); ++i) {
        auto below = pos(boxes[i - 1]), above = pos(boxes[i]);
        auto offset = std::hypot(above.x - below.x, above.z - below.z);
        EXPECT_LT(offset, standing_still) << "box " << i << " is off the one below by " << offset << " m";
        EXPECT_GT(above.y, below.y) << "box " << i;
    }
}

// A 1 m box of 300 kg on one of 1 kg, sleeping off: the solver passes, which carry the ground's
// support up from below, hold a mass ratio of 300: as the soft contacts take the load the heavy
// box dips by up to 3.2 cm, then rests 1.8 cm low, the light box 0.9 cm into the ground and the
// heavy one as far again into it (measured). At 1,000 the heavy box sinks through the light one
// and both end on the ground: the mass-ratio limit the step guide states.
TEST_F(stacking, a_box_three_hundred_times_heavier_stands_on_a_light_one_for_ten_seconds) {
    scenes::make_ground(reg);
    auto light = make_rigidbody(
        reg, edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.5), 0}));
    auto heavy = make_rigidbody(
        reg, edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(1.5), 0}, scalar(300)));
    auto worst = run_awake({light, heavy}, 10);
    const scalar sink_measured = scalar(0.032);
    EXPECT_LT(worst.vertical, sink_measured * scalar(1.2))
        << "a box moved up or down by " << worst.vertical << " m, measured " << sink_measured
        << " m when set";
    EXPECT_LT(worst.horizontal, standing_still) << "a box crept sideways by " << worst.horizontal << " m";
    EXPECT_NEAR(pos(heavy).y, scalar(1.5) - scalar(0.018), scalar(0.005)) << "where the heavy box rests";
}

// 10 rows of 8 bricks, every other row shifted by half a brick: each brick rests on two.
TEST_F(stacking, brick_wall_in_running_bond_with_sleeping_off_stands_for_ten_seconds) {
    scenes::make_ground(reg);
    const vector3 brick{scalar(0.25), scalar(0.125), scalar(0.125)};
    auto bricks = scenes::make_brick_wall(reg, 10, 8, brick);
    ASSERT_EQ(bricks.size(), 5u * 8 + 5u * 9);
    auto worst = run_awake(bricks, 10);
    // Measured: 5 mm sideways (a half brick at an end of the top row, across the wall) and
    // 2.6 mm down.
    EXPECT_LT(worst.horizontal, standing_still) << "a brick moved sideways by " << worst.horizontal << " m";
    EXPECT_LT(worst.vertical, standing_still) << "a brick moved up or down by " << worst.vertical << " m";
}

// 4 layers of spheres stacked as fruit is (4 by 4, 3 by 3, 4 by 4, 3 by 3) in an open box.
TEST_F(stacking, spheres_stacked_in_a_box_with_sleeping_off_stand_for_ten_seconds) {
    auto scene = scenes::make_spheres_in_box(reg, 4, 4, scalar(0.25));
    ASSERT_EQ(scene.spheres.size(), 50u);
    auto worst = run_awake(scene.spheres, 10);
    // Measured: 4 mm each way, as the layers settle into each other in the first second.
    EXPECT_LT(worst.horizontal, standing_still) << "a sphere moved sideways by " << worst.horizontal << " m";
    EXPECT_LT(worst.vertical, standing_still) << "a sphere moved up or down by " << worst.vertical << " m";
    // None left the box: every centre is inside its walls, above its floor and below the top
    // of the stack.
    auto limit = scene.inner_half_width - scalar(0.25);
    for (auto e : scene.spheres) {
        auto p = pos(e);
        EXPECT_LE(std::max(std::abs(p.x), std::abs(p.z)), limit + standing_still)
            << "a sphere is at (" << p.x << ", " << p.y << ", " << p.z << ")";
        EXPECT_GT(p.y, scalar(0.25) - standing_still) << "a sphere sank to y = " << p.y;
    }
}

// Everything inelastic (restitution 0, the default): a ball dropped from 1 m onto a 1 kg box
// resting on the ground lands on it, and neither rises. The relax passes take back, from the
// ground up, what the biased pass gave to push overlap out; the ball's contact, taken back from
// both bodies, handed the box the ball's push the other way after the ground's contact was
// done with it, and both rose together: the box by 57 mm under a 5 kg ball and by 177 mm under
// a 20 kg one, the ball leaving at 1.1 and 1.9 m/s (measured). The relax passes now hold the
// box still while the ball parts from it (contact_hold_parting_speed): the box does not rise,
// and the ball leaves the box at 0.03 and 0.05 m/s at most as it settles.
TEST_F(stacking, a_heavy_ball_landing_on_a_box_on_the_ground_does_not_lift_it) {
    for (auto mass : {scalar(5), scalar(20)}) {
        registry world;
        attach(world, edyn::test::test_config());
        scenes::make_ground(world);
        auto box = make_rigidbody(
            world, edyn::test::box_def({scalar(0.25), scalar(0.25), scalar(0.25)}, {0, scalar(0.25), 0}));
        for (int i = 0; i < 60; ++i)
            edyn::test::step(world);
        auto box_rest = world.get<position>(box).y;
        auto ball = make_rigidbody(world, edyn::test::sphere_def(scalar(0.1), {0, scalar(1.6), 0}, mass));
        scalar box_top = box_rest, ball_up = 0;
        auto landed = false;
        for (int i = 0; i < 120; ++i) {
            edyn::test::step(world);
            auto y = world.get<position>(ball).y;
            ASSERT_TRUE(std::isfinite(y));
            landed = landed || y < scalar(0.61);
            if (landed) ball_up = std::max(ball_up, world.get<linvel>(ball).y);
            box_top = std::max(box_top, world.get<position>(box).y);
        }
        EXPECT_TRUE(landed) << mass << " kg";
        EXPECT_LT(box_top - box_rest, scalar(0.001))
            << "the box rose by " << box_top - box_rest << " m under a " << mass << " kg ball";
        EXPECT_LT(ball_up, scalar(0.1)) << "the " << mass << " kg ball left the box at " << ball_up << " m/s";
        EXPECT_NEAR(world.get<position>(ball).y, scalar(0.6), scalar(0.005))
            << "the " << mass << " kg ball rests on the box";
        detach(world);
    }
}

// A 5 kg box dropped from 1 m onto a tower of five 1 kg boxes of 0.5 m: the tower's boxes rose
// by up to 151 mm, its top one, and the dropped box by 159 mm (measured); now the tower's do not
// rise and the dropped box, as it settles into the soft contact, by 3 mm.
TEST_F(stacking, a_heavy_box_landing_on_a_tower_does_not_lift_it) {
    scenes::make_ground(reg);
    auto tower = scenes::make_tower(reg, 5, scalar(0.25));
    run_for(1);
    std::vector<scalar> rest;
    for (auto e : tower)
        rest.push_back(pos(e).y);
    auto top = rest.back() + scalar(0.25);
    auto dropped = make_rigidbody(reg, edyn::test::box_def({scalar(0.25), scalar(0.25), scalar(0.25)},
                                                           {0, top + scalar(1.25), 0}, scalar(5)));
    std::vector<scalar> highest(rest);
    scalar dropped_top = -large_scalar;
    auto landed = false;
    for (int i = 0; i < 120; ++i) {
        edyn::test::step(reg);
        for (std::size_t k = 0; k < tower.size(); ++k)
            highest[k] = std::max(highest[k], pos(tower[k]).y);
        auto y = pos(dropped).y;
        ASSERT_TRUE(std::isfinite(y));
        landed = landed || y < top + scalar(0.26);
        if (landed) dropped_top = std::max(dropped_top, y);
    }
    ASSERT_TRUE(landed);
    for (std::size_t k = 0; k < tower.size(); ++k)
        EXPECT_LT(highest[k] - rest[k], scalar(0.001))
            << "box " << k << " rose by " << highest[k] - rest[k] << " m";
    auto dropped_rest = pos(dropped).y;
    EXPECT_LT(dropped_top - dropped_rest, scalar(0.01))
        << "the dropped box rose by " << dropped_top - dropped_rest << " m after it landed";
    EXPECT_NEAR(dropped_rest, top + scalar(0.25), scalar(0.01)) << "the dropped box rests on the tower";
}

// The price of holding the lower body still: momentum. In zero gravity a ball lands at 4 m/s
// on the end of a 4 m, 4 kg plank lying on a static cylinder (a seesaw), 1.5 m from it:
// angular momentum about the pivot, m v d = (I + m d^2) w, gives the plank's turn after the
// landing. The relax passes hold the plank still while the ball parts from it, so the plank
// keeps pushes the ball gives back: 3.2 % too fast under a 1 kg ball, 7.4 % under a 5 kg one
// (measured; 0.5 % and 2.8 % without the hold).
TEST_F(stacking, a_ball_landing_on_a_seesaw_turns_it_as_angular_momentum_says_within_the_holds_price) {
    for (auto mass : {scalar(1), scalar(5)}) {
        registry world;
        attach(world, edyn::test::test_config());
        set_gravity(world, vector3_zero);
        auto pivot = rigidbody_def();
        pivot.kind = rigidbody_kind::rb_static;
        pivot.shape = cylinder_shape{scalar(0.05), 1, coordinate_axis::z};
        make_rigidbody(world, pivot);
        auto plank = make_rigidbody(
            world, edyn::test::box_def({2, scalar(0.05), scalar(0.5)}, {0, scalar(0.1), 0}, 4));
        for (int i = 0; i < 10; ++i)
            edyn::test::step(world);
        const scalar d = scalar(1.5), v = 4;
        auto def = edyn::test::sphere_def(scalar(0.1), {d, scalar(0.45), 0}, mass);
        def.linvel = {0, -v, 0};
        make_rigidbody(world, def);
        for (int i = 0; i < 8; ++i)
            edyn::test::step(world);
        // The plank's moment of inertia about the line it turns on, 5 cm below its centre.
        auto inertia = scalar(4) * (16 + scalar(0.01)) / 12 + scalar(4) * scalar(0.05) * scalar(0.05);
        auto expected = mass * v * d / (inertia + mass * d * d);
        auto turn = -world.get<angvel>(plank).z;
        EXPECT_NEAR(turn, expected, expected * scalar(0.08)) << mass << " kg ball";
        EXPECT_GT(turn, expected * scalar(0.99)) << mass << " kg ball: the hold only adds to the turn";
        detach(world);
    }
}
