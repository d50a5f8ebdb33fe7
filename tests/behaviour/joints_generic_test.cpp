// Generic constraint: weld, slider, limits and springs per degree of freedom, in closed form.
#include "joints_support.hpp"

using namespace edyn;
using edyn::test::crossing_timer;
using edyn::test::world_fixture;

using generic_joint = world_fixture;

namespace {

// Every degree of freedom locked but those listed, which are free.
void free_only(generic_constraint &c, std::initializer_list<int> linear, std::initializer_list<int> angular) {
    for (auto i : linear)
        c.linear[i].mode = dof_mode::free;
    for (auto i : angular)
        c.angular[i].mode = dof_mode::free;
}

} // namespace

TEST_F(generic_joint, all_locked_welds_a_body_to_the_ground_under_gravity) {
    auto anchor = edyn::test::make_anchor(reg, {0, 2, 0});
    // A 1 kg box held 1 m out to the side: gravity pulls with a 9.8 Nm moment at the weld.
    auto box = make_rigidbody(reg, edyn::test::box_def({scalar(0.2), scalar(0.1), scalar(0.1)}, {1, 2, 0}));
    make_constraint<generic_constraint>(reg, anchor, box, [](generic_constraint &c) {
        c.pivot[1] = {-1, 0, 0};
    });
    scalar worst_offset = 0, worst_angle = 0;
    for (int i = 0; i < 60 * 3; ++i) {
        edyn::test::step(reg);
        worst_offset = std::max(worst_offset, distance(pos(box), vector3{1, 2, 0}));
        worst_angle = std::max(worst_angle, quaternion_angle(reg.get<orientation>(box)));
    }
    EXPECT_LT(worst_offset, scalar(0.01)) << "box moved up to " << worst_offset << " m from its place";
    EXPECT_LT(worst_angle, scalar(0.01)) << "box turned up to " << worst_angle << " rad";
}

TEST_F(generic_joint, all_locked_keeps_two_falling_bodies_together) {
    auto a = make_rigidbody(reg, edyn::test::box_def({scalar(0.5), scalar(0.1), scalar(0.1)}, {0, 5, 0}, 2));
    auto b = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.2), {scalar(0.8), 5, 0}));
    rigidbody_apply_impulse(reg, b, {0, 0, 2}, vector3_zero);
    make_constraint<generic_constraint>(reg, a, b, [](generic_constraint &c) {
        c.pivot[0] = {scalar(0.5), 0, 0};
        c.pivot[1] = {-scalar(0.3), 0, 0};
    });
    scalar worst = 0;
    for (int i = 0; i < 60; ++i) {
        edyn::test::step(reg);
        auto pa = edyn::test::world_pivot(reg, a, {scalar(0.5), 0, 0});
        auto pb = edyn::test::world_pivot(reg, b, {-scalar(0.3), 0, 0});
        worst = std::max(worst, distance(pa, pb));
    }
    EXPECT_LT(worst, scalar(0.01)) << "pivots came apart by " << worst << " m";
    // Welded, the pair spins as one: equal angular velocities.
    EXPECT_LT(distance(angular(a), angular(b)), scalar(0.02));
}

TEST_F(generic_joint, one_free_linear_axis_is_a_slider) {
    // A frictionless slide at 45 degrees: the body accelerates along it at g sin 45 and moves
    // nowhere else.
    const scalar g = scalar(9.8), angle = to_radians(45);
    const vector3 axis{std::cos(angle), -std::sin(angle), 0};
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto body = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.2), vector3_zero));
    make_constraint<generic_constraint>(reg, anchor, body, [&](generic_constraint &c) {
        c.frame[0] = to_matrix3x3(quaternion_axis_angle(vector3_z, -angle));
        c.frame[1] = c.frame[0];
        free_only(c, {0}, {});
    });
    scalar worst = 0;
    for (int i = 0; i < 60; ++i) {
        edyn::test::step(reg);
        auto p = pos(body);
        worst = std::max(worst, length(p - axis * dot(p, axis)));
    }
    auto travelled = dot(pos(body), axis);
    auto expected = g * std::sin(angle) / 2;
    EXPECT_NEAR(travelled, expected, 0.01 * expected)
        << "travelled " << travelled << " m, expected " << expected;
    EXPECT_LT(worst, scalar(0.001)) << "left the axis by " << worst << " m";
    EXPECT_LT(length(angular(body)), scalar(1e-3));
}

TEST_F(generic_joint, limited_linear_axis_holds_at_its_limit) {
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto body = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.2), vector3_zero));
    make_constraint<generic_constraint>(reg, anchor, body, [](generic_constraint &c) {
        c.linear[1].mode = dof_mode::limited;
        c.linear[1].min = -scalar(0.5);
        c.linear[1].max = scalar(0.5);
    });
    run_for(2);
    EXPECT_NEAR(pos(body).y, -0.5, 0.01) << "rests at y = " << pos(body).y << ", limit -0.5";
    EXPECT_NEAR(pos(body).x, 0, 0.001);
    EXPECT_NEAR(vel(body).y, 0, 0.01);
}

TEST_F(generic_joint, a_bar_swung_into_an_angular_limit_stops_dead) {
    // A 1 m bar held at one end, free to turn about z within [-0.5, 0.5] rad, swung at 2 rad/s.
    // The limit's torque turns the bar about its centre, which the locked pivot turns back about
    // the end: the rebound this left (0.35 rad/s, from the limit's position correction) is gone,
    // but for what an approach slower than the joints' restitution threshold may leave.
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = edyn::test::box_def({scalar(0.5), scalar(0.05), scalar(0.05)}, {scalar(0.5), 0, 0});
    def.angvel = {0, 0, 2};
    def.linvel = {0, 1, 0};
    auto bar = make_rigidbody(reg, def);
    make_constraint<generic_constraint>(reg, anchor, bar, [](generic_constraint &c) {
        c.pivot[1] = {-scalar(0.5), 0, 0};
        c.angular[2].mode = dof_mode::limited;
        c.angular[2].min = -scalar(0.5);
        c.angular[2].max = scalar(0.5);
    });
    scalar fastest_rebound = 0;
    for (int i = 0; i < 60; ++i) {
        edyn::test::step(reg);
        fastest_rebound = std::max(fastest_rebound, -angular(bar).z);
    }
    auto threshold = get_settings(reg).joint.restitution_threshold;
    EXPECT_LT(fastest_rebound, threshold / 4) << "the bar left the limit at " << fastest_rebound << " rad/s";
    auto tip = pos(bar) + rotate(reg.get<orientation>(bar), vector3{scalar(0.5), 0, 0});
    auto angle = std::atan2(tip.y, tip.x);
    EXPECT_NEAR(angle, 0.5, 0.01) << "the bar rests at " << angle << " rad, the limit is at 0.5";
}

TEST_F(generic_joint, linear_spring_oscillates_at_sqrt_k_over_m) {
    set_gravity(reg, vector3_zero);
    const scalar k = 200, m = 2;
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto body = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.1), {scalar(0.1), 0, 0}, m));
    make_constraint<generic_constraint>(reg, anchor, body, [&](generic_constraint &c) {
        free_only(c, {0}, {});
        c.linear[0].stiffness = k;
    });
    crossing_timer timer;
    for (int i = 0; i < 60 * 5; ++i) {
        edyn::test::step(reg);
        timer.sample(get_simulation_time(reg), vel(body).x);
    }
    auto expected = 2 * pi * std::sqrt(m / k);
    auto measured = timer.mean_period();
    ASSERT_GE(timer.times.size(), 3u);
    EXPECT_NEAR(measured, expected, 0.03 * expected)
        << "measured period " << measured << " s, expected " << expected;
}

TEST_F(generic_joint, angular_spring_oscillates_at_sqrt_k_over_i) {
    set_gravity(reg, vector3_zero);
    // A 2 kg ball of radius 0.5 held at its centre: I = 0.2.
    const scalar k = 5, inertia = scalar(0.2);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = edyn::test::sphere_def(scalar(0.5), vector3_zero, 2);
    def.angvel = {0, 0, 1};
    auto body = make_rigidbody(reg, def);
    make_constraint<generic_constraint>(reg, anchor, body, [&](generic_constraint &c) {
        free_only(c, {}, {2});
        c.angular[2].stiffness = k;
    });
    crossing_timer timer;
    for (int i = 0; i < 60 * 5; ++i) {
        edyn::test::step(reg);
        timer.sample(get_simulation_time(reg), angular(body).z);
    }
    auto expected = 2 * pi * std::sqrt(inertia / k);
    auto measured = timer.mean_period();
    ASSERT_GE(timer.times.size(), 3u);
    EXPECT_NEAR(measured, expected, 0.03 * expected)
        << "measured period " << measured << " s, expected " << expected;
    EXPECT_LT(std::hypot(angular(body).x, angular(body).y), scalar(1e-3));
}

TEST_F(generic_joint, linear_friction_decelerates_at_force_over_mass) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = edyn::test::sphere_def(scalar(0.1), vector3_zero, 2);
    def.linvel = {3, 0, 0};
    auto body = make_rigidbody(reg, def);
    make_constraint<generic_constraint>(reg, anchor, body, [](generic_constraint &c) {
        free_only(c, {0}, {});
        c.linear[0].friction = 2;
    });
    run_for(1);
    EXPECT_NEAR(vel(body).x, 2, 0.02) << "measured " << vel(body).x << " m/s, expected 3 - 2 / 2 * 1";
}

TEST(generic_validation, rejects_inverted_limits_and_negative_springs) {
    registry reg;
    attach(reg, edyn::test::test_config());
    auto a = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), vector3_zero));
    auto b = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {2, 0, 0}));
    auto alive = reg.alive();
    try {
        make_constraint<generic_constraint>(reg, a, b, [](generic_constraint &c) {
            c.angular[1].mode = dof_mode::limited;
            c.angular[1].min = 1;
            c.angular[1].max = 0;
        });
        ADD_FAILURE() << "expected std::invalid_argument";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("make_constraint<generic_constraint>: angular[1].min"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(make_constraint<generic_constraint>(
                     reg, a, b, [](generic_constraint &c) { c.linear[2].stiffness = -1; }),
                 std::invalid_argument);
    EXPECT_EQ(reg.alive(), alive);
    detach(reg);
}
