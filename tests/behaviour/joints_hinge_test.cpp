// Hinge constraint: axis, limits, restitution, springs, friction and damping in closed form.
#include "joints_support.hpp"

using namespace edyn;
using edyn::test::crossing_timer;
using edyn::test::world_fixture;

namespace {

struct hinge_world : world_fixture {
    entity anchor{null};
    entity body{null};
    entity joint{null};

    // A body hinged about world z at the origin. The body's origin is at `position`; its pivot
    // is the origin of the world.
    template<typename Setup>
    void make_hinged(const rigidbody_def &def, Setup setup) {
        anchor = edyn::test::make_anchor(reg, vector3_zero);
        body = make_rigidbody(reg, def);
        joint = make_constraint<hinge_constraint>(reg, anchor, body, [&](hinge_constraint &h) {
            h.pivot[0] = vector3_zero;
            h.pivot[1] = -def.position;
            h.set_axes(vector3_z, vector3_z);
            setup(h);
        });
    }

    scalar angle() const { return reg.get<hinge_constraint>(joint).angle; }
};

// A 1 m bar of 1 kg along +x from the hinge: I about the hinge = m (l^2 + t^2) / 12 + m (l/2)^2.
rigidbody_def bar_def() {
    return edyn::test::box_def({scalar(0.5), scalar(0.05), scalar(0.05)}, {scalar(0.5), 0, 0});
}
const scalar bar_inertia = (scalar(1) + scalar(0.01)) / 12 + scalar(0.25);

} // namespace

using hinge_joint = hinge_world;

TEST_F(hinge_joint, door_swings_only_about_its_axis) {
    // A door 1 m wide and 2 m tall hinged along world y at x = 0, under gravity.
    anchor = edyn::test::make_anchor(reg, {0, 1, 0});
    auto door =
        make_rigidbody(reg, edyn::test::box_def({scalar(0.5), 1, scalar(0.02)}, {scalar(0.5), 1, 0}, 20));
    make_constraint<hinge_constraint>(reg, anchor, door, [](hinge_constraint &h) {
        h.pivot[0] = vector3_zero;
        h.pivot[1] = {-scalar(0.5), 0, 0};
        h.set_axes(vector3_y, vector3_y);
    });
    rigidbody_apply_impulse(reg, door, {0, 0, 10}, {scalar(0.5), 0, 0});
    scalar worst_tilt = 0, worst_drift = 0;
    for (int i = 0; i < 120; ++i) {
        edyn::test::step(reg);
        auto w = angular(door);
        worst_tilt = std::max(worst_tilt, std::sqrt(w.x * w.x + w.z * w.z));
        // The door's centre stays on a horizontal circle of radius 0.5 around the hinge line.
        auto p = pos(door);
        worst_drift = std::max(worst_drift, std::abs(p.y - 1) + std::abs(std::hypot(p.x, p.z) - scalar(0.5)));
    }
    EXPECT_GT(std::abs(angular(door).y), scalar(0.5)) << "the door should be swinging";
    EXPECT_LT(worst_tilt, scalar(0.01)) << "angular velocity off the axis " << worst_tilt << " rad/s";
    EXPECT_LT(worst_drift, scalar(0.005)) << "centre left its circle by " << worst_drift << " m";
}

TEST_F(hinge_joint, limit_holds_a_bar_under_gravity) {
    make_hinged(bar_def(), [](hinge_constraint &h) {
        h.angle_min = -scalar(0.5);
        h.angle_max = scalar(0.5);
    });
    run_for(3);
    EXPECT_NEAR(angle(), -0.5, 0.01) << "measured angle " << angle() << ", expected -0.5";
    EXPECT_NEAR(angular(body).z, 0, 0.01);
}

TEST_F(hinge_joint, limit_bounces_with_limit_restitution) {
    set_gravity(reg, vector3_zero);
    auto def = bar_def();
    make_hinged(def, [](hinge_constraint &h) {
        h.angle_min = -scalar(0.5);
        h.limit_restitution = scalar(0.5);
    });
    // Spin the bar at -2 rad/s about the hinge (its centre moves at -1 m/s along y).
    reg.replace<angvel>(body, vector3{0, 0, -2});
    reg.replace<linvel>(body, vector3{0, -1, 0});
    run_for(0.5);
    auto expected = scalar(0.5) * 2;
    EXPECT_NEAR(angular(body).z, expected, scalar(0.05) * expected)
        << "measured " << angular(body).z << " rad/s after the bounce, expected " << expected;
    EXPECT_GT(angle(), -scalar(0.5));
}

TEST_F(hinge_joint, limit_without_restitution_stops_the_bar_dead) {
    // The same swing into the lower limit with the default limit_restitution of 0. The limit's
    // torque turns the bar about its centre, which the pivot turns back about the hinge: the
    // rebound this left (0.35 rad/s out of 2, from the limit's position correction) is gone,
    // but for what an approach slower than the joints' restitution threshold may leave.
    set_gravity(reg, vector3_zero);
    make_hinged(bar_def(), [](hinge_constraint &h) { h.angle_min = -scalar(0.5); });
    reg.replace<angvel>(body, vector3{0, 0, -2});
    reg.replace<linvel>(body, vector3{0, -1, 0});
    scalar fastest_rebound = 0;
    for (int i = 0; i < 60; ++i) {
        edyn::test::step(reg);
        fastest_rebound = std::max(fastest_rebound, angular(body).z);
    }
    auto threshold = get_settings(reg).joint.restitution_threshold;
    EXPECT_LT(fastest_rebound, threshold / 4) << "the bar left the limit at " << fastest_rebound << " rad/s";
    EXPECT_NEAR(angle(), -0.5, 0.01) << "the bar rests at " << angle() << " rad, the limit is at -0.5";
}

TEST_F(hinge_joint, stiffness_oscillates_about_rest_angle_at_sqrt_k_over_i) {
    set_gravity(reg, vector3_zero);
    const scalar k = 30;
    make_hinged(bar_def(), [&](hinge_constraint &h) {
        h.rest_angle = scalar(0.3);
        h.stiffness = k;
    });
    crossing_timer timer;
    for (int i = 0; i < 60 * 4; ++i) {
        edyn::test::step(reg);
        timer.sample(get_simulation_time(reg), angular(body).z);
    }
    auto expected = 2 * pi * std::sqrt(bar_inertia / k);
    auto measured = timer.mean_period();
    ASSERT_GE(timer.times.size(), 3u);
    EXPECT_NEAR(measured, expected, 0.03 * expected)
        << "measured period " << measured << " s, expected " << expected;
}

TEST_F(hinge_joint, stiffness_with_damping_returns_to_rest_angle) {
    set_gravity(reg, vector3_zero);
    const scalar k = 30;
    make_hinged(bar_def(), [&](hinge_constraint &h) {
        h.rest_angle = scalar(0.3);
        h.stiffness = k;
        h.damping = 2 * std::sqrt(k * bar_inertia); // critical
    });
    run_for(4);
    EXPECT_NEAR(angle(), 0.3, 0.005) << "measured angle " << angle() << ", expected the rest angle 0.3";
    EXPECT_NEAR(angular(body).z, 0, 0.01);
}

TEST_F(hinge_joint, friction_torque_decelerates_at_torque_over_inertia) {
    set_gravity(reg, vector3_zero);
    // A 2 kg ball of radius 0.5 hinged through its centre: I = 0.2.
    auto def = edyn::test::sphere_def(scalar(0.5), vector3_zero, 2);
    def.angvel = {0, 0, 5};
    make_hinged(def, [](hinge_constraint &h) { h.friction_torque = scalar(0.4); });
    run_for(1);
    auto expected = 5 - scalar(0.4) / scalar(0.2) * 1;
    EXPECT_NEAR(angular(body).z, expected, 0.02)
        << "measured " << angular(body).z << " rad/s, expected " << expected;
    run_for(2);
    EXPECT_NEAR(angular(body).z, 0, 1e-3);
}

TEST_F(hinge_joint, damping_decays_the_speed_exponentially) {
    set_gravity(reg, vector3_zero);
    auto def = edyn::test::sphere_def(scalar(0.5), vector3_zero, 2);
    def.angvel = {0, 0, 5};
    const scalar c = scalar(0.1);
    make_hinged(def, [&](hinge_constraint &h) { h.damping = c; });
    run_for(2);
    auto expected = 5 * std::exp(-c / scalar(0.2) * 2);
    EXPECT_NEAR(angular(body).z, expected, 0.02 * expected)
        << "measured " << angular(body).z << " rad/s, expected " << expected;
}

TEST_F(hinge_joint, angle_is_tracked_past_half_a_turn) {
    set_gravity(reg, vector3_zero);
    auto def = edyn::test::sphere_def(scalar(0.5), vector3_zero, 2);
    def.angvel = {0, 0, 2};
    make_hinged(def, [](hinge_constraint &h) { h.angle_max = 4; });
    run_for(3);
    EXPECT_NEAR(angle(), 4, 0.02) << "measured angle " << angle() << ", expected the limit 4 rad";
}

TEST(hinge_validation, rejects_inverted_limits_and_skewed_frames) {
    registry reg;
    attach(reg, edyn::test::test_config());
    auto a = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), vector3_zero));
    auto b = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {2, 0, 0}));
    auto alive = reg.alive();
    try {
        make_constraint<hinge_constraint>(reg, a, b, [](hinge_constraint &h) {
            h.angle_min = 1;
            h.angle_max = scalar(0.5);
        });
        ADD_FAILURE() << "expected std::invalid_argument";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("make_constraint<hinge_constraint>: angle_min"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(make_constraint<hinge_constraint>(reg, a, b,
                                                   [](hinge_constraint &h) {
                                                       h.frame[0] =
                                                           matrix3x3_columns(vector3_x, vector3_x, vector3_z);
                                                   }),
                 std::invalid_argument);
    EXPECT_THROW(make_constraint<hinge_constraint>(reg, a, b, [](hinge_constraint &h) { h.stiffness = -1; }),
                 std::invalid_argument);
    // The manual's rule: angle_min smaller than angle_max, so equal limits are refused too.
    EXPECT_THROW(make_constraint<hinge_constraint>(
                     reg, a, b, [](hinge_constraint &h) { h.angle_min = h.angle_max = 0.3f; }),
                 std::invalid_argument);
    EXPECT_EQ(reg.alive(), alive);
    detach(reg);
}

TEST_F(hinge_joint, values_written_after_make_constraint_are_checked_by_the_step) {
    // A restitution of 5 would make every limit hit five times faster: the step refuses it,
    // naming the field and the entity, and keeps refusing until it is put right.
    make_hinged(bar_def(), [](hinge_constraint &h) {
        h.angle_min = -scalar(0.5);
        h.angle_max = scalar(0.5);
    });
    edyn::test::step(reg);
    reg.patch<hinge_constraint>(joint, [](hinge_constraint &h) { h.limit_restitution = 5; });
    auto expected = "constraint entity " + std::to_string(to_index(joint));
    for (int attempt = 0; attempt < 2; ++attempt) {
        try {
            edyn::test::step(reg);
            ADD_FAILURE() << "a limit restitution of 5 was accepted";
        } catch (const std::invalid_argument &error) {
            std::string what = error.what();
            EXPECT_NE(what.find("limit_restitution"), std::string::npos) << what;
            EXPECT_NE(what.find(expected), std::string::npos) << what;
        }
    }
    reg.patch<hinge_constraint>(joint, [](hinge_constraint &h) { h.limit_restitution = scalar(0.5); });
    EXPECT_NO_THROW(edyn::test::step(reg));
    // An empty range written later is refused too.
    reg.patch<hinge_constraint>(joint, [](hinge_constraint &h) { h.angle_min = 1; });
    EXPECT_THROW(edyn::test::step(reg), std::invalid_argument);
}
