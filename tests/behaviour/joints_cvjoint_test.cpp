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

namespace {

// Two shafts meeting at the origin through a CV joint bent by 30 degrees: the input along x
// ending there, the output along out_axis starting there, each turning in its own bearing (a
// hinge to the ground). The output is a flat bar, so that its inertia differs across its
// axis, as a driven part's would. The shafts overlap at the joint, so they have no material
// and do not collide.
struct shafts_world : world_fixture {
    const scalar bend = to_radians(30);
    const vector3 out_axis{std::cos(bend), std::sin(bend), 0};
    // Box inertias about the shafts' long axes, m (b^2 + c^2) / 3 from the half extents below.
    const scalar input_inertia = scalar(5) * (scalar(0.05 * 0.05) + scalar(0.05 * 0.05)) / 3;
    const scalar output_inertia = scalar(1) * (scalar(0.2 * 0.2) + scalar(0.02 * 0.02)) / 3;
    entity input{null}, output{null}, joint{null};

    void make_shafts(scalar input_rate) {
        set_gravity(reg, vector3_zero);
        auto anchor = edyn::test::make_anchor(reg, vector3_zero);
        auto in_def = edyn::test::box_def({scalar(0.5), scalar(0.05), scalar(0.05)}, {-scalar(0.5), 0, 0}, 5);
        in_def.material.reset();
        in_def.angvel = vector3_x * input_rate;
        input = make_rigidbody(reg, in_def);
        auto out_def =
            edyn::test::box_def({scalar(0.5), scalar(0.2), scalar(0.02)}, out_axis * scalar(0.5), 1);
        out_def.orientation = quaternion_axis_angle(vector3_z, bend);
        out_def.material.reset();
        output = make_rigidbody(reg, out_def);
        make_constraint<hinge_constraint>(reg, anchor, input, [](hinge_constraint &h) {
            h.pivot[1] = {scalar(0.5), 0, 0};
            h.set_axes(vector3_x, vector3_x);
        });
        make_constraint<hinge_constraint>(reg, anchor, output, [&](hinge_constraint &h) {
            h.pivot[1] = {-scalar(0.5), 0, 0};
            h.set_axes(out_axis, vector3_x);
        });
        joint = make_constraint<cvjoint_constraint>(reg, input, output, [](cvjoint_constraint &c) {
            c.pivot[0] = {scalar(0.5), 0, 0};
            c.pivot[1] = {-scalar(0.5), 0, 0};
        });
    }

    scalar input_rate() const { return dot(angular(input), vector3_x); }
    scalar output_rate() const { return dot(angular(output), out_axis); }
};

} // namespace

// Why the momentum checks below are exact: the bearings' pivots lie on the shafts' axes and
// their angular rows act across them, so the only torque along a shaft is the CV joint's.
// A CV joint turns both shafts at the same rate, so by the balance of power it carries the
// same torque along both axes: what one shaft's axial angular momentum loses, the other's
// gains, to float rounding.
using cvjoint_shafts = shafts_world;

TEST_F(cvjoint_shafts, a_driven_shaft_brings_a_resting_one_up_to_its_speed_through_a_thirty_degree_bend) {
    const scalar omega = 2;
    make_shafts(omega);
    // The input is driven: its rate is set back to omega before every step. Within a step the
    // joint shares the two shafts' momentum, so both leave it at the rate that conserves
    // I_in w_in + I_out w_out; the output's shortfall from omega shrinks by
    // r = I_out / (I_in + I_out) each step: w_out(n) = omega (1 - r^n).
    const scalar r = output_inertia / (input_inertia + output_inertia);
    // Spin-up, then one full revolution at speed.
    const int spin_up = 30, revolution = int(std::ceil(2 * pi / omega * 60));
    // Float rounding in a momentum balance summed over a few hundred steps.
    const scalar momentum_tolerance = scalar(1e-4) * output_inertia * omega;
    // The joint is soft: in the first step, when it must turn the output from rest, the shafts
    // slip by 3e-4 rad and the output runs 1.6e-4 of omega off the rigid figure; 0.1% of omega
    // bounds that with margin and still tells a joint that lags by a step (r^n - r^(n+1), 24%
    // of omega after the first step) from one that does not.
    const scalar spin_up_tolerance = scalar(1e-3) * omega;
    // At speed nothing loads the joint: a Cardan joint's output would swing by 15% of omega
    // at this bend twice a revolution; a CV joint's is off by float rounding only (1e-6 rad/s
    // measured), and slips no more than that over a step.
    const scalar rate_tolerance = scalar(1e-4) * omega, twist_tolerance = scalar(1e-4);
    double taken = 0; // angular momentum the drive had to put back into the input
    scalar worst_spin_up = 0, worst_momentum = 0, worst_rate = 0, worst_twist = 0;
    for (int i = 0; i < spin_up + revolution; ++i) {
        reg.replace<angvel>(input, vector3_x * omega);
        edyn::test::step(reg);
        taken += double(input_inertia * (omega - input_rate()));
        auto gained = output_inertia * output_rate();
        worst_momentum = std::max(worst_momentum, std::abs(scalar(taken) - gained));
        if (i < spin_up) {
            auto expected = omega * (1 - std::pow(r, scalar(i + 1)));
            worst_spin_up = std::max(worst_spin_up, std::abs(output_rate() - expected));
        } else {
            worst_rate = std::max(worst_rate, std::abs(output_rate() - omega));
            worst_twist = std::max(worst_twist, std::abs(reg.get<cvjoint_constraint>(joint).twist_angle));
        }
    }
    EXPECT_LT(worst_momentum, momentum_tolerance)
        << "the output's angular momentum differed from what the input lost by up to " << worst_momentum
        << " N m s (output at speed: " << output_inertia * omega << ")";
    EXPECT_LT(worst_spin_up, spin_up_tolerance)
        << "during spin-up the output's rate was off omega (1 - r^n) by up to " << worst_spin_up << " rad/s";
    EXPECT_LT(worst_rate, rate_tolerance) << "at speed the output's rate was off the input's " << omega
                                          << " rad/s by up to " << worst_rate << " rad/s";
    EXPECT_LT(worst_twist, twist_tolerance) << "largest twist at speed " << worst_twist << " rad";
    // The output turned with the input: both frames' second columns are the same angle round.
    auto input_angle = std::atan2(rotate(reg.get<orientation>(input), vector3_y).z,
                                  rotate(reg.get<orientation>(input), vector3_y).y);
    auto out_y = rotate(reg.get<orientation>(output), vector3_y);
    auto out_rest = rotate(quaternion_axis_angle(vector3_z, bend), vector3_y);
    auto output_angle = std::atan2(dot(cross(out_rest, out_y), out_axis), dot(out_rest, out_y));
    EXPECT_NEAR(normalize_angle(output_angle - input_angle), 0, twist_tolerance)
        << "input turned to " << input_angle << " rad, output to " << output_angle << " rad";
}

TEST_F(cvjoint_shafts, a_free_spinning_shaft_shares_its_momentum_with_a_resting_one) {
    const scalar omega = 2;
    make_shafts(omega);
    // Nothing drives the input: the joint couples the shafts like a clutch, and both end at
    // the rate that keeps I_in w_in + I_out w_out = I_in omega. A joint that carried no torque
    // would leave them at omega and 0.
    const scalar expected = input_inertia * omega / (input_inertia + output_inertia);
    run_for(1);
    EXPECT_NEAR(input_rate(), expected, scalar(1e-3) * omega)
        << "input at " << input_rate() << " rad/s, expected " << expected;
    EXPECT_NEAR(output_rate(), expected, scalar(1e-3) * omega)
        << "output at " << output_rate() << " rad/s, expected " << expected;
    auto momentum = input_inertia * input_rate() + output_inertia * output_rate();
    EXPECT_NEAR(momentum, input_inertia * omega, scalar(1e-4) * input_inertia * omega)
        << "axial angular momentum " << momentum << " N m s, started with " << input_inertia * omega;
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
        edyn::test::step(reg);
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
        edyn::test::step(reg);
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

// Bent by exactly half a turn (its axes opposite) the joint's twist axis vanishes; bend friction
// still slows a bend across body A's axis, and nothing becomes NaN.
TEST_F(cvjoint, bend_friction_holds_a_joint_bent_by_half_a_turn) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    const scalar torque = scalar(0.2);
    auto def = ball_def(vector3_zero);
    def.angvel = {0, 1, 0};
    auto ball = make_rigidbody(reg, def);
    make_constraint<cvjoint_constraint>(reg, anchor, ball, [&](cvjoint_constraint &c) {
        c.set_axes({-1, 0, 0}, {1, 0, 0});
        c.twist_min = -std::numeric_limits<scalar>::infinity();
        c.twist_max = std::numeric_limits<scalar>::infinity();
        c.bend_friction_torque = torque;
    });
    run_for(0.5);
    auto expected = 1 - torque / ball_inertia * scalar(0.5);
    EXPECT_NEAR(angular(ball).y, expected, 0.02)
        << "bend rate " << angular(ball).y << " rad/s, expected " << expected;
    EXPECT_TRUE(isfinite(pos(ball)) && isfinite(vel(ball)) && isfinite(angular(ball)));
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
    attach(reg, edyn::test::test_config());
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
