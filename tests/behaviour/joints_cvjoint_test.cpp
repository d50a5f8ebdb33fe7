// CV joint: rotation transmitted at constant velocity through a bend, twist limits, springs
// and friction about the twist, free bending unless bend friction slows it.
#include "joints_support.hpp"

using namespace edyn;
using edyn::test::crossing_timer;
using edyn::test::world_fixture;

using cvjoint = world_fixture;

namespace {

// A ball of 2 kg and radius 0.5 whose centre is the joint's pivot: I = 2/5 m r^2 = 0.2 about
// any axis, with no lever arm, so twist and bend are pure rotations.
const scalar ball_inertia = scalar(0.2);

rigidbody_def ball_def(const vector3 &position) { return edyn::test::sphere_def(scalar(0.5), position, 2); }

} // namespace

TEST_F(cvjoint, transmits_rotation_at_constant_velocity_through_a_thirty_degree_bend) {
    set_gravity(reg, vector3_zero);
    const scalar omega = 2;
    const auto bend = to_radians(30);
    const vector3 out_axis{std::cos(bend), std::sin(bend), 0};
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    // Input shaft along x ending at the origin, output shaft along out_axis starting there; each
    // turns in its own bearing (a hinge to the ground). The output is a flat bar, so that its
    // inertia differs across its axis, as a driven part's would.
    // The shafts overlap at the joint, so they have no material and do not collide.
    auto in_def = edyn::test::box_def({scalar(0.5), scalar(0.05), scalar(0.05)}, {-scalar(0.5), 0, 0}, 5);
    in_def.material.reset();
    in_def.angvel = vector3_x * omega;
    auto input = make_rigidbody(reg, in_def);
    auto out_def = edyn::test::box_def({scalar(0.5), scalar(0.2), scalar(0.02)}, out_axis * scalar(0.5), 1);
    out_def.orientation = quaternion_axis_angle(vector3_z, bend);
    out_def.material.reset();
    out_def.angvel = out_axis * omega;
    auto output = make_rigidbody(reg, out_def);
    make_constraint<hinge_constraint>(reg, anchor, input, [](hinge_constraint &h) {
        h.pivot[1] = {scalar(0.5), 0, 0};
        h.set_axes(vector3_x, vector3_x);
    });
    make_constraint<hinge_constraint>(reg, anchor, output, [&](hinge_constraint &h) {
        h.pivot[1] = {-scalar(0.5), 0, 0};
        h.set_axes(out_axis, vector3_x);
    });
    auto joint = make_constraint<cvjoint_constraint>(reg, input, output, [](cvjoint_constraint &c) {
        c.pivot[0] = {scalar(0.5), 0, 0};
        c.pivot[1] = {-scalar(0.5), 0, 0};
    });

    // One full revolution, both shafts started at omega and the input driven at omega every step.
    const int steps = int(std::ceil(2 * pi / omega * 60));
    scalar worst = 0, worst_twist = 0;
    for (int i = 0; i < steps; ++i) {
        reg.replace<angvel>(input, vector3_x * omega);
        step_simulation(reg);
        auto rate = dot(angular(output), out_axis);
        worst = std::max(worst, std::abs(rate - omega) / omega);
        worst_twist = std::max(worst_twist, std::abs(reg.get<cvjoint_constraint>(joint).twist_angle));
    }
    EXPECT_LT(worst, scalar(0.02)) << "output rate deviated from the input's " << omega << " rad/s by up to "
                                   << worst * 100 << "%";
    EXPECT_LT(worst_twist, scalar(0.01)) << "largest twist " << worst_twist << " rad";
    // The output turned with the input: both frames' second columns are the same angle round.
    auto input_angle = std::atan2(rotate(reg.get<orientation>(input), vector3_y).z,
                                  rotate(reg.get<orientation>(input), vector3_y).y);
    auto out_y = rotate(reg.get<orientation>(output), vector3_y);
    auto out_rest = rotate(quaternion_axis_angle(vector3_z, bend), vector3_y);
    auto output_angle = std::atan2(dot(cross(out_rest, out_y), out_axis), dot(out_rest, out_y));
    EXPECT_NEAR(normalize_angle(output_angle - input_angle), 0, 0.01)
        << "input turned to " << input_angle << " rad, output to " << output_angle << " rad";
}

TEST_F(cvjoint, twist_limits_hold) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = ball_def(vector3_zero);
    def.angvel = {3, 0, 0};
    auto ball = make_rigidbody(reg, def);
    auto joint = make_constraint<cvjoint_constraint>(reg, anchor, ball, [](cvjoint_constraint &c) {
        c.twist_min = -scalar(0.5);
        c.twist_max = scalar(0.5);
    });
    scalar largest = 0;
    for (int i = 0; i < 60 * 2; ++i) {
        step_simulation(reg);
        largest = std::max(largest, reg.get<cvjoint_constraint>(joint).twist_angle);
    }
    EXPECT_LT(largest, scalar(0.5) + scalar(0.01)) << "largest twist " << largest << " rad, limit 0.5";
    EXPECT_NEAR(reg.get<cvjoint_constraint>(joint).twist_angle, 0.5, 0.01);
    EXPECT_NEAR(angular(ball).x, 0, 0.01);
}

TEST_F(cvjoint, bending_is_free_with_the_twist_locked) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = ball_def(vector3_zero);
    def.angvel = {0, 0, scalar(0.5)};
    auto ball = make_rigidbody(reg, def);
    auto joint = make_constraint<cvjoint_constraint>(reg, anchor, ball);
    run_for(2);
    // Bending about z at 0.5 rad/s for 2 s turns the ball's axis 1 rad round, untouched.
    auto axis = rotate(reg.get<orientation>(ball), vector3_x);
    auto bent = std::atan2(axis.y, axis.x);
    EXPECT_NEAR(bent, 1, 0.005) << "bend angle " << bent << " rad, expected 1";
    EXPECT_NEAR(angular(ball).z, 0.5, 1e-4);
    EXPECT_NEAR(reg.get<cvjoint_constraint>(joint).twist_angle, 0, 1e-3);
}

TEST_F(cvjoint, twist_stiffness_oscillates_at_sqrt_k_over_i) {
    set_gravity(reg, vector3_zero);
    const scalar k = 5;
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto ball = make_rigidbody(reg, ball_def(vector3_zero));
    make_constraint<cvjoint_constraint>(reg, anchor, ball, [&](cvjoint_constraint &c) {
        c.twist_min = -std::numeric_limits<scalar>::infinity();
        c.twist_max = std::numeric_limits<scalar>::infinity();
        c.twist_rest_angle = scalar(0.3);
        c.twist_stiffness = k;
    });
    crossing_timer timer;
    for (int i = 0; i < 60 * 5; ++i) {
        step_simulation(reg);
        timer.sample(get_simulation_time(reg), angular(ball).x);
    }
    auto expected = 2 * pi * std::sqrt(ball_inertia / k);
    auto measured = timer.mean_period();
    ASSERT_GE(timer.times.size(), 3u);
    EXPECT_NEAR(measured, expected, 0.03 * expected)
        << "measured period " << measured << " s, expected " << expected;
}

TEST_F(cvjoint, twist_friction_decelerates_at_torque_over_inertia) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = ball_def(vector3_zero);
    def.angvel = {4, 0, 0};
    auto ball = make_rigidbody(reg, def);
    const scalar torque = scalar(0.2);
    make_constraint<cvjoint_constraint>(reg, anchor, ball, [&](cvjoint_constraint &c) {
        c.twist_min = -std::numeric_limits<scalar>::infinity();
        c.twist_max = std::numeric_limits<scalar>::infinity();
        c.twist_friction_torque = torque;
    });
    run_for(2);
    auto expected = 4 - torque / ball_inertia * 2;
    EXPECT_NEAR(angular(ball).x, expected, 0.02)
        << "measured " << angular(ball).x << " rad/s, expected " << expected;
}

TEST_F(cvjoint, bend_friction_decelerates_at_torque_over_inertia_and_leaves_the_twist_alone) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    const scalar torque = scalar(0.2);
    auto make_ball = [&](const vector3 &position, const vector3 &angvel) {
        auto def = ball_def(position);
        def.angvel = angvel;
        auto ball = make_rigidbody(reg, def);
        make_constraint<cvjoint_constraint>(reg, anchor, ball, [&](cvjoint_constraint &c) {
            c.pivot[0] = position;
            c.twist_min = -std::numeric_limits<scalar>::infinity();
            c.twist_max = std::numeric_limits<scalar>::infinity();
            c.bend_friction_torque = torque;
        });
        return ball;
    };
    // One ball bends about y (across the joint's x axis), the other twists about x.
    auto bending = make_ball(vector3_zero, {0, 1, 0});
    auto twisting = make_ball({3, 0, 0}, {2, 0, 0});
    run_for(0.5);
    auto expected = 1 - torque / ball_inertia * scalar(0.5);
    EXPECT_NEAR(angular(bending).y, expected, 0.02)
        << "bend rate " << angular(bending).y << " rad/s, expected " << expected;
    EXPECT_NEAR(angular(twisting).x, 2, 1e-3) << "twist rate " << angular(twisting).x << " rad/s, expected 2";
    // Friction stops the bend and does not reverse it.
    run_for(1);
    EXPECT_LT(length(angular(bending)), scalar(1e-3)) << "still bending at " << length(angular(bending));
}

TEST_F(cvjoint, twist_limit_bounces_with_restitution) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = ball_def(vector3_zero);
    def.angvel = {-2, 0, 0};
    auto ball = make_rigidbody(reg, def);
    make_constraint<cvjoint_constraint>(reg, anchor, ball, [](cvjoint_constraint &c) {
        c.twist_min = -scalar(0.5);
        c.twist_max = scalar(0.5);
        c.twist_restitution = scalar(0.5);
    });
    run_for(scalar(0.5));
    EXPECT_NEAR(angular(ball).x, 1, 0.05)
        << "measured " << angular(ball).x << " rad/s after the bounce, expected 1";
}

TEST(cvjoint_validation, rejects_inverted_twist_limits_and_negative_stiffness) {
    registry reg;
    attach(reg);
    auto a = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), vector3_zero));
    auto b = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {2, 0, 0}));
    auto alive = reg.alive();
    try {
        make_constraint<cvjoint_constraint>(reg, a, b, [](cvjoint_constraint &c) {
            c.twist_min = 1;
            c.twist_max = 0;
        });
        ADD_FAILURE() << "expected std::invalid_argument";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("make_constraint<cvjoint_constraint>: twist_min"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(
        make_constraint<cvjoint_constraint>(reg, a, b, [](cvjoint_constraint &c) { c.twist_stiffness = -1; }),
        std::invalid_argument);
    EXPECT_EQ(reg.alive(), alive);
    detach(reg);
}
