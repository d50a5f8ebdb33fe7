// Gravity constraint: a circular orbit with the period Kepler's third law gives.
#include "joints_support.hpp"

using namespace edyn;
using edyn::test::crossing_timer;
using edyn::test::world_fixture;

using gravity_joint = world_fixture;

TEST_F(gravity_joint, circular_orbit_has_keplers_period) {
    set_gravity(reg, vector3_zero);
    const scalar big_mass = scalar(1e12), small_mass = 1, radius = 10;
    auto mu = gravitational_constant * (big_mass + small_mass);
    auto speed = std::sqrt(mu / radius);
    auto big_def = edyn::test::sphere_def(1, vector3_zero, big_mass);
    // Momentum zero, so that the centre of mass stays put.
    big_def.linvel = {0, -speed * small_mass / (big_mass + small_mass), 0};
    auto planet = make_rigidbody(reg, big_def);
    auto moon_def = edyn::test::sphere_def(scalar(0.1), {radius, 0, 0}, small_mass);
    moon_def.linvel = {0, speed * big_mass / (big_mass + small_mass), 0};
    auto moon = make_rigidbody(reg, moon_def);
    make_constraint<gravity_constraint>(reg, planet, moon);

    crossing_timer timer;
    scalar min_r = radius, max_r = radius;
    auto expected = 2 * pi * std::sqrt(radius * radius * radius / mu);
    auto steps = int(2.2 * double(expected) * 60);
    for (int i = 0; i < steps; ++i) {
        edyn::test::step(reg);
        auto rel = pos(moon) - pos(planet);
        timer.sample(get_simulation_time(reg), rel.y);
        min_r = std::min(min_r, length(rel));
        max_r = std::max(max_r, length(rel));
    }
    ASSERT_GE(timer.times.size(), 2u);
    auto measured = timer.mean_period();
    EXPECT_NEAR(measured, expected, 0.02 * expected)
        << "measured period " << measured << " s, expected " << expected << " s";
    // Circular: the distance stays within 2% of the radius.
    EXPECT_NEAR(min_r, radius, scalar(0.02) * radius) << "closest " << min_r;
    EXPECT_NEAR(max_r, radius, scalar(0.02) * radius) << "farthest " << max_r;
}

// make_constraint refuses a static or kinematic body; one made so later stops attracting
// (its mass is then large_scalar) and attracts again, with its mass, once dynamic again.
TEST_F(gravity_joint, a_body_made_static_or_kinematic_later_stops_attracting) {
    set_gravity(reg, vector3_zero);
    const scalar big_mass = scalar(1e12);
    for (auto kind : {rigidbody_kind::rb_static, rigidbody_kind::rb_kinematic}) {
        auto planet = make_rigidbody(reg, edyn::test::sphere_def(1, vector3_zero, big_mass));
        // Drifting slowly while the planet does not pull, it would fall asleep.
        auto moon_def = edyn::test::sphere_def(scalar(0.1), {10, 0, 0}, 1);
        moon_def.sleeping_disabled = true;
        auto moon = make_rigidbody(reg, moon_def);
        make_constraint<gravity_constraint>(reg, planet, moon);
        edyn::test::step(reg);
        rigidbody_set_kind(reg, planet, kind);
        for (int i = 0; i < 60; ++i)
            edyn::test::step(reg);
        // One step of attraction at 10 m: a = G M / r^2 = 0.667 m/s^2 for 1/60 s.
        auto one_step = gravitational_constant * big_mass / 100 / 60;
        EXPECT_NEAR(vel(moon).x, -one_step, scalar(1e-3))
            << "the moon was pulled while the planet was not dynamic";
        EXPECT_NEAR(pos(moon).x, 10, scalar(0.02));
        rigidbody_set_kind(reg, planet, rigidbody_kind::rb_dynamic);
        for (int i = 0; i < 60; ++i)
            edyn::test::step(reg);
        EXPECT_LT(vel(moon).x, -one_step * 30) << "the attraction did not return";
        EXPECT_TRUE(std::isfinite(pos(moon).x));
        reg.destroy(planet);
        reg.destroy(moon);
    }
}
