// Closed-form checks of single bodies: free fall, bounce, sliding, rolling.
#include "behaviour_support.hpp"
#include <edyn/dynamics/integration.hpp>
#include <edyn_scenes/scenes.hpp>
#include <vector>

using namespace edyn;
using edyn::test::world_fixture;

using free_fall = world_fixture;
using contact_motion = world_fixture;

TEST_F(free_fall, follows_half_g_t_squared) {
    auto body = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, 100, 0}));
    run_for(2);
    // Sub-stepped semi-implicit Euler drops g h^2 n (n + 1) / 2 after n sub-steps: within
    // 1/n of the continuous value, 0.2% here.
    auto expected = scalar(100) - scalar(0.5) * scalar(9.8) * 4;
    EXPECT_NEAR(pos(body).y, expected, scalar(0.004) * 19.6) << "expected y " << expected;
    EXPECT_NEAR(vel(body).y, scalar(-9.8) * 2, scalar(1e-3));
    EXPECT_FLOAT_EQ(pos(body).x, 0);
}

TEST_F(free_fall, per_body_gravity_overrides_the_world) {
    auto def = edyn::test::sphere_def(scalar(0.5), {0, 10, 0});
    def.gravity = vector3{0, 0, 0};
    auto floating = make_rigidbody(reg, def);
    set_gravity(reg, {scalar(1), 0, 0});
    auto sideways = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {5, 10, 0}));
    run_for(1);
    EXPECT_EQ(pos(floating), (vector3{0, 10, 0}));
    EXPECT_NEAR(vel(sideways).x, 1, 1e-4);
    EXPECT_NEAR(vel(sideways).y, 0, 1e-6);
}

TEST_F(free_fall, no_body_moves_faster_than_the_speed_limit) {
    set_gravity(reg, vector3_zero);
    // With a limit of 50 m/s, a 1,000 m/s throw and a 100 m/s one both move at 50 m/s, each in
    // its own direction: 50 m in a second.
    auto fast = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, 10, 0}));
    rigidbody_apply_impulse(reg, fast, {600, 800, 0}, vector3_zero);
    set_max_linear_speed(reg, 50);
    EXPECT_EQ(get_max_linear_speed(reg), 50);
    auto slowed = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, -10, 0}));
    reg.replace<linvel>(slowed, vector3{0, 0, 100});
    run_for(1);
    EXPECT_NEAR(vel(fast).x, 30, 1e-3);
    EXPECT_NEAR(vel(fast).y, 40, 1e-3);
    EXPECT_NEAR(pos(fast).y, 10 + 40, 1e-3);
    EXPECT_NEAR(vel(slowed).z, 50, 1e-3);
    EXPECT_NEAR(pos(slowed).z, 50, 1e-3);
    // A body spun at 1,000 rad/s turns at most a quarter turn per sub-step.
    auto &settings = get_settings(reg);
    auto max_turn = max_angular_speed(settings.fixed_dt / scalar(settings.num_substeps));
    reg.replace<angvel>(slowed, vector3{0, 1000, 0});
    run_for(0.1);
    EXPECT_NEAR(reg.get<angvel>(slowed).y, max_turn, max_turn * 1e-5);
    // Back at the default, the same throw keeps 400 m/s.
    set_max_linear_speed(reg, 400);
    rigidbody_apply_impulse(reg, fast, {600, 800, 0}, vector3_zero);
    run_for(1);
    EXPECT_NEAR(length(vel(fast)), 400, 1e-2);
}

namespace {

// A ball of restitution `e` dropped from `height` (its bottom) on the ground, with the
// restitution solver's iterations set to `restitution_iterations`: the peak after its first
// bounce is e^2 height.
void expect_bounce_to_e_squared_h(scalar e, scalar height, unsigned restitution_iterations) {
    registry r;
    attach(r, edyn::test::test_config());
    set_solver_restitution_iterations(r, restitution_iterations);
    scenes::make_ground(r, scalar(0.5), 0);
    auto def = edyn::test::sphere_def(scalar(0.25), {0, height + scalar(0.25), 0});
    def.material->restitution = e;
    auto ball = make_rigidbody(r, def);
    auto peak = edyn::test::rebound_peak(r, ball, scalar(0.25));
    EXPECT_GE(peak, 0) << "the ball did not bounce";
    auto expected = height * e * e;
    EXPECT_NEAR(peak, expected, edyn::test::rebound_tolerance(r, height, expected))
        << "restitution " << e << ", dropped from " << height << " m, " << restitution_iterations
        << " restitution iterations";
    detach(r);
}

} // namespace

// From every height: whether the ball comes within reach of the ground at the start of a step
// or in its middle, and whether the speculative contact braked it short of the surface in the
// step before, it bounces from the speed it fell at (once, from 1 m, it rebounded 2 cm).
TEST_F(contact_motion, bounce_height_ratio_is_restitution_squared) {
    for (scalar e : {scalar(0.5), scalar(0.8)}) {
        for (scalar height :
             {scalar(0.3), scalar(0.4), scalar(0.5), scalar(0.7), scalar(1), scalar(1.3), scalar(2)})
            expect_bounce_to_e_squared_h(e, height, 8);
    }
}

// A box dropped flat, restitution 1 on both sides: its four points pull its turn each way, and
// the bounce leaves it level, going straight up at the speed it landed with; it then keeps its
// height bounce after bounce. (With three passes per manifold, the restitution solver's old
// default, it left spinning at 1 rad/s and drifting at 0.3 m/s, then tumbled, walked 7 m
// sideways and stopped bouncing within 10 s.)
TEST_F(contact_motion, a_box_dropped_flat_bounces_straight_up_and_keeps_its_height) {
    scenes::make_ground(reg, scalar(0.5), 1);
    const scalar half = scalar(0.2), height = 2;
    auto def = edyn::test::box_def({half, half, half}, {0, height + half, 0});
    def.material->restitution = 1;
    def.material->friction = scalar(0.5);
    def.sleeping_disabled = true;
    auto box = make_rigidbody(reg, def);
    scalar approach = 0;
    int bounces = 0;
    scalar last_peak = 0, peak = 0;
    for (int i = 0; i < 60 * 16; ++i) {
        auto before = vel(box).y;
        edyn::test::step(reg);
        peak = std::max(peak, pos(box).y - half);
        if (before < 0 && vel(box).y > 0) {
            if (++bounces == 1) {
                approach = before;
                EXPECT_NEAR(vel(box).y, -approach, scalar(0.02) * -approach);
                EXPECT_LT(length(angular(box)), scalar(0.01)) << "it should leave level";
                EXPECT_LT(std::hypot(vel(box).x, vel(box).z), scalar(0.01)) << "it should go straight up";
            }
            last_peak = peak;
            peak = 0;
        }
    }
    EXPECT_GE(bounces, 10);
    EXPECT_NEAR(last_peak, height, scalar(0.02) * height) << "after " << bounces << " bounces";
    EXPECT_LT(std::hypot(pos(box).x, pos(box).z), scalar(0.05)) << "it should stay where it fell";
}

// With the restitution solver off (0 iterations), restitution still acts as the manual's
// "Restitution" says, in a limited fashion: a point that approaches when the contact meets it
// bounces, all of it in the contact's own normal impulse; one resting (no approach) returns
// nothing, so a ball left on the ground stays there.
TEST_F(contact_motion, without_the_restitution_solver_an_approaching_ball_still_bounces) {
    for (scalar e : {scalar(0.5), scalar(0.8), scalar(1)}) {
        for (scalar height : {scalar(0.4), scalar(1), scalar(2)})
            expect_bounce_to_e_squared_h(e, height, 0);
    }

    // The impulse of a bounce: m v (1 + e), all of it the contact's, none the restitution
    // solver's.
    set_solver_restitution_iterations(reg, 0);
    scenes::make_ground(reg, scalar(0.5), 0);
    auto def = edyn::test::sphere_def(scalar(0.25), {0, scalar(1.25), 0});
    def.material->restitution = scalar(0.8);
    auto ball = make_rigidbody(reg, def);
    scalar impact = 0, largest = 0, from_restitution_solver = 0;
    for (int i = 0; i < 120 && largest == 0; ++i) {
        auto before = vel(ball).y;
        edyn::test::step(reg);
        for (auto [e, manifold] : reg.view<contact_manifold>().each()) {
            for (std::uint32_t k = 0; k < manifold.num_points; ++k) {
                auto &cp = manifold.point[manifold.ids[k]];
                if (cp.normal_impulse > largest) largest = cp.normal_impulse, impact = before;
                from_restitution_solver += cp.normal_restitution_impulse;
            }
        }
    }
    ASSERT_GT(largest, 0) << "no contact impulse";
    // Speed at impact: a step's gravity below the speed the step began with, at most.
    auto expected = -impact * scalar(1.8);
    EXPECT_NEAR(largest, expected, scalar(0.05) * expected);
    EXPECT_EQ(from_restitution_solver, 0);
    EXPECT_GT(vel(ball).y, 0);

    // Resting on the ground, the bouncy ball stays put.
    edyn::test::disable_sleeping(reg);
    run_for(3);
    auto rest = pos(ball).y;
    scalar highest = rest;
    for (int i = 0; i < 120; ++i) {
        edyn::test::step(reg);
        highest = std::max(highest, pos(ball).y);
    }
    EXPECT_NEAR(rest, scalar(0.25), scalar(2e-3));
    EXPECT_LT(highest - rest, scalar(1e-3)) << "the resting ball hopped";
}

// A body that reaches the surface exactly at the end of a step (a gap that is a whole number of
// steps' travel) bounces as any other: the step's contact stops it on the surface with no
// closing speed left, and the bounce is taken from the approach the step saw.
TEST_F(contact_motion, a_body_reaching_the_surface_exactly_at_a_step_boundary_bounces) {
    set_gravity(reg, vector3_zero);
    rigidbody_def floor;
    floor.kind = rigidbody_kind::rb_static;
    floor.shape = box_shape{50, scalar(0.1), 2};
    floor.position = {0, scalar(-0.1), 0};
    make_rigidbody(reg, floor);
    const scalar speed = 3, e = scalar(0.5), radius = scalar(0.2);
    auto travel = speed * get_fixed_dt(reg); // 5 cm a step
    std::vector<std::pair<entity, int>> bodies;
    for (int steps : {2, 4, 6}) {
        for (int shape = 0; shape < 2; ++shape) {
            rigidbody_def def;
            if (shape == 0)
                def.shape = sphere_shape{radius};
            else
                def.shape = box_shape{radius, radius, radius};
            def.position = {scalar(4 * (2 * steps + shape) - 40), radius + travel * scalar(steps), 0};
            def.linvel = {0, -speed, 0};
            def.material->restitution = e;
            bodies.emplace_back(make_rigidbody(reg, def), steps);
        }
    }
    run_for(0.5);
    for (auto [body, steps] : bodies)
        EXPECT_NEAR(vel(body).y, e * speed, scalar(0.01)) << "gap of " << steps << " steps' travel";
}

// The step that brakes a falling ball short of the ground answers its bounce itself: nothing
// of it is left for the next step but the ball's motion. A world rebuilt from the ball's
// position and velocities alone (as a networked client rebuilds the server's) then takes the
// same next step as the world it came from, on every step of the fall, bounce and rise. (When
// the approach was carried to the next step in the contact, the rebuilt ball, which has no
// contact yet, bounced from the braked speed instead.)
TEST_F(contact_motion, a_world_rebuilt_from_the_bodies_motion_bounces_the_same) {
    for (scalar height : {scalar(0.4), scalar(1), scalar(1.3), scalar(2)}) {
        registry original;
        attach(original, edyn::test::test_config());
        scenes::make_ground(original, scalar(0.5), 0);
        auto def = edyn::test::sphere_def(scalar(0.25), {0, height + scalar(0.25), 0});
        def.material->restitution = scalar(0.8);
        auto ball = make_rigidbody(original, def);
        auto bounced = false;
        for (int i = 0; i < 200 && !(bounced && original.get<linvel>(ball).y < 0); ++i) {
            registry rebuilt;
            attach(rebuilt, edyn::test::test_config());
            scenes::make_ground(rebuilt, scalar(0.5), 0);
            auto copy_def = def;
            copy_def.position = original.get<position>(ball);
            copy_def.orientation = original.get<orientation>(ball);
            copy_def.linvel = original.get<linvel>(ball);
            copy_def.angvel = original.get<angvel>(ball);
            auto copy = make_rigidbody(rebuilt, copy_def);
            edyn::test::step(original);
            edyn::test::step(rebuilt);
            bounced |= original.get<linvel>(ball).y > 0;
            ASSERT_NEAR(rebuilt.get<linvel>(copy).y, original.get<linvel>(ball).y, scalar(1e-3))
                << "dropped from " << height << " m, step " << i + 1;
            ASSERT_NEAR(rebuilt.get<position>(copy).y, original.get<position>(ball).y, scalar(1e-5))
                << "dropped from " << height << " m, step " << i + 1;
            detach(rebuilt);
        }
        EXPECT_TRUE(bounced) << "dropped from " << height << " m";
        detach(original);
    }
}

// A bar 2 m long lying 8 cm above the ground, turning at 6 rad/s so that one end comes down
// 10 cm a step: its contact must be found before that end reaches the ground, though the two
// bodies' broadphase margins (3 cm each) lie apart. The bar's box reaches out by how far it turns
// in a step.
TEST_F(contact_motion, a_fast_turning_bar_is_caught_before_its_end_reaches_the_ground) {
    set_gravity(reg, vector3_zero);
    scenes::make_ground(reg, scalar(0.5), 0);
    const vector3 half{1, scalar(0.05), scalar(0.05)};
    auto def = edyn::test::box_def(half, {0, scalar(0.13), 0});
    def.angvel = {0, 0, -6};
    auto bar = make_rigidbody(reg, def);
    auto lowest = scalar(1);
    for (int i = 0; i < 10; ++i) {
        step_simulation(reg);
        wait_for_simulation(reg);
        auto orn = reg.get<orientation>(bar);
        for (int c = 0; c < 8; ++c) {
            vector3 corner{c & 1 ? half.x : -half.x, c & 2 ? half.y : -half.y, c & 4 ? half.z : -half.z};
            lowest = std::min(lowest, (pos(bar) + rotate(orn, corner)).y);
        }
    }
    // Without the contact, the end would be 2 cm into the ground after the first step.
    EXPECT_GT(lowest, scalar(-0.005));
}

TEST_F(contact_motion, sliding_box_stops_after_v_squared_over_2_mu_g) {
    scenes::make_ground(reg, scalar(0.4), 0);
    auto def = edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.5), 0});
    def.material->friction = scalar(0.4);
    def.linvel = {5, 0, 0};
    auto box = make_rigidbody(reg, def);
    run_for(3);
    auto expected = scalar(25) / (2 * scalar(0.4) * scalar(9.8));
    EXPECT_NEAR(pos(box).x, expected, scalar(0.03) * expected) << "expected distance " << expected;
    EXPECT_NEAR(vel(box).x, 0, scalar(1e-3));
    EXPECT_NEAR(pos(box).y, scalar(0.5), scalar(0.01));
}

TEST_F(contact_motion, sphere_rolls_down_incline_at_five_sevenths_g_sin_theta) {
    auto theta = to_radians(20);
    vector3 normal{-std::sin(theta), std::cos(theta), 0};
    rigidbody_def ground;
    ground.kind = rigidbody_kind::rb_static;
    ground.material->friction = 1;
    ground.shape = plane_shape{normal, 0};
    make_rigidbody(reg, ground);

    auto def = edyn::test::sphere_def(scalar(0.5), normal * scalar(0.5));
    def.material->friction = 1;
    auto ball = make_rigidbody(reg, def);
    run_for(2);
    auto expected = scalar(0.5) * (scalar(5) / 7) * scalar(9.8) * std::sin(theta) * 4;
    vector3 down_slope{-std::cos(theta), -std::sin(theta), 0};
    auto travelled = dot(pos(ball) - normal * scalar(0.5), down_slope);
    EXPECT_NEAR(travelled, expected, scalar(0.02) * expected) << "expected distance " << expected;
    // Rolling without slipping: v = w r.
    EXPECT_NEAR(length(vel(ball)), length(angular(ball)) * scalar(0.5), scalar(0.02) * length(vel(ball)));
}

namespace {

// A static plane through the origin tilted `degrees` about z, its surface rising towards -x,
// with friction `mu`; returns its unit normal.
vector3 make_incline(registry &reg, scalar degrees, scalar mu) {
    auto theta = to_radians(degrees);
    vector3 normal{-std::sin(theta), std::cos(theta), 0};
    rigidbody_def ground;
    ground.kind = rigidbody_kind::rb_static;
    ground.material->friction = mu;
    ground.shape = plane_shape{normal, 0};
    make_rigidbody(reg, ground);
    return normal;
}

// A unit box of friction `mu` resting on the incline of normal `normal`, face down, awake.
entity make_box_on_incline(registry &reg, const vector3 &normal, scalar mu) {
    auto def = edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, normal * scalar(0.5));
    def.orientation = quaternion_axis_angle(vector3_z, std::atan2(-normal.x, normal.y));
    def.material->friction = mu;
    def.sleeping_disabled = true;
    return make_rigidbody(reg, def);
}

} // namespace

// Static friction holds a body at rest where it is: a box awake on the ground for 10 s. Without
// the friction anchors (contact_solver_settings::friction_anchor_hertz 0) it crept 1.5 mm, at a
// steady 0.15 mm/s: what the velocity rows leave over each sub-step adds up.
TEST_F(contact_motion, a_box_at_rest_on_the_ground_does_not_creep) {
    scenes::make_ground(reg);
    auto def = edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.5), 0});
    def.sleeping_disabled = true;
    auto box = make_rigidbody(reg, def);
    run_for(1);
    auto settled = pos(box);
    run_for(9);
    auto d = pos(box) - settled;
    EXPECT_LT(std::hypot(d.x, d.z), scalar(1e-4)) << "crept " << std::hypot(d.x, d.z) << " m in 9 s";
}

// Below its friction angle (tan 20 degrees = 0.36 < 0.6) a box stays where it was put on an
// incline; without the anchors it crept 1.5 mm in 10 s, partly up the slope and partly across it.
TEST_F(contact_motion, box_on_an_incline_below_its_friction_angle_stays_put) {
    auto normal = make_incline(reg, 20, scalar(0.6));
    auto box = make_box_on_incline(reg, normal, scalar(0.6));
    auto start = pos(box);
    run_for(10);
    auto d = pos(box) - start;
    auto along = d - normal * dot(d, normal);
    EXPECT_LT(length(along), scalar(2e-4)) << "moved " << length(along) << " m along the incline";
    EXPECT_NEAR(dot(d, normal), 0, scalar(1e-3)) << "sank or rose";
}

// Above it the box slides down at g (sin theta - mu cos theta): the anchors hold only while
// friction does, so a sliding box keeps Coulomb's law.
TEST_F(contact_motion, box_on_an_incline_above_its_friction_angle_slides_at_g_sin_minus_mu_cos) {
    const scalar degrees = 30, mu = scalar(0.2);
    auto normal = make_incline(reg, degrees, mu);
    auto box = make_box_on_incline(reg, normal, mu);
    auto start = pos(box);
    const scalar seconds = 2;
    run_for(seconds);
    auto theta = to_radians(degrees);
    auto a = scalar(9.8) * (std::sin(theta) - mu * std::cos(theta));
    auto expected = a * seconds * seconds / 2;
    vector3 down_slope{-std::cos(theta), -std::sin(theta), 0};
    auto travelled = dot(pos(box) - start, down_slope);
    EXPECT_NEAR(travelled, expected, scalar(0.01) * expected) << "expected distance " << expected;
    EXPECT_NEAR(dot(vel(box), down_slope), a * seconds, scalar(0.01) * a * seconds);
}
