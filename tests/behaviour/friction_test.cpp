// Closed-form checks of rolling and spinning friction and of material mixing overrides.
//
// The contact solver limits the rolling and spinning resistance of a contact to a torque of
// coefficient x normal force (the coefficient is a torque per unit weight, in metres; see the
// manual's "Friction"). For a sphere of mass m, radius r and I = 2/5 m r^2 on flat ground:
//  - rolling without slipping under a resisting torque c m g decelerates at
//    a = c m g / (r m (1 + I / (m r^2))) = c g / (1.4 r);
//  - spinning about the normal under a torque s m g decelerates at alpha = s m g / I, and stops
//    after t = w0 I / (s m g).
#include "behaviour_support.hpp"
#include <cmath>
#include <edyn_scenes/scenes.hpp>
#include <vector>

using namespace edyn;
using edyn::test::world_fixture;

namespace {

struct friction : world_fixture {
    // A sphere touching the ground at the origin, rolling along +x at speed v without slipping.
    entity make_rolling_sphere(scalar radius, scalar v, scalar roll_friction) {
        auto def = edyn::test::sphere_def(radius, {0, radius, 0});
        def.material->friction = 1;
        def.material->roll_friction = roll_friction;
        def.linvel = {v, 0, 0};
        def.angvel = {0, 0, -v / radius};
        def.sleeping_disabled = true;
        return make_rigidbody(reg, def);
    }

    entity make_spinning_sphere(scalar radius, scalar w, scalar spin_friction) {
        auto def = edyn::test::sphere_def(radius, {0, radius, 0});
        def.material->friction = 1;
        def.material->spin_friction = spin_friction;
        def.angvel = {0, w, 0};
        def.sleeping_disabled = true;
        return make_rigidbody(reg, def);
    }
};

} // namespace

TEST_F(friction, rolling_friction_decelerates_a_rolling_sphere_at_c_g_over_1_4_r) {
    // The ground's coefficient is 0: the default mixing takes the larger one, the sphere's.
    scenes::make_ground(reg, 1, 0);
    const scalar r = scalar(0.5), v0 = 5, c = scalar(0.05);
    auto ball = make_rolling_sphere(r, v0, c);
    // Let the contact settle for a step before measuring.
    edyn::test::step(reg);
    auto v_start = vel(ball).x;
    auto seconds = scalar(2);
    run_for(seconds);
    auto v_end = vel(ball).x;

    auto expected = c * test::earth_g / (scalar(1.4) * r);
    auto measured = (v_start - v_end) / seconds;
    EXPECT_NEAR(measured, expected, scalar(0.03) * expected)
        << "deceleration measured " << measured << " m/s^2, expected " << expected;
    // Still rolling without slipping.
    EXPECT_NEAR(-angular(ball).z * r, v_end, scalar(0.01) * v_end)
        << "w r " << -angular(ball).z * r << " vs v " << v_end;
    EXPECT_NEAR(pos(ball).y, r, scalar(0.01));
}

// Coulomb friction does not depend on the direction of sliding: the friction impulse is limited
// as a vector, not along each of the solver's two tangents apart (which would let a slide at
// 45 degrees to them take sqrt(2) times the force, stop in 1/sqrt(2) of the distance and bend
// its path towards a tangent).
TEST_F(friction, rolling_friction_decelerates_a_sphere_the_same_in_every_direction) {
    scenes::make_ground(reg, 1, 0);
    const scalar r = scalar(0.5), v0 = 5, c = scalar(0.05);
    const scalar degrees[] = {0, 30, 45, 60, 135};
    std::vector<entity> balls;
    for (std::size_t i = 0; i < std::size(degrees); ++i) {
        auto angle = to_radians(degrees[i]);
        auto dir = vector3{std::cos(angle), 0, std::sin(angle)};
        auto def = edyn::test::sphere_def(r, {scalar(20 * i), r, 0});
        def.material->friction = 1;
        def.material->roll_friction = c;
        def.linvel = dir * v0;
        // Rolling without slipping: w = n x v / r, with n the ground's normal.
        def.angvel = cross(vector3_y, dir) * (v0 / r);
        def.sleeping_disabled = true;
        balls.push_back(make_rigidbody(reg, def));
    }
    edyn::test::step(reg);
    std::vector<scalar> start;
    for (auto ball : balls)
        start.push_back(length(vel(ball)));
    const scalar seconds = 2;
    run_for(seconds);
    auto expected = c * test::earth_g / (scalar(1.4) * r);
    for (std::size_t i = 0; i < balls.size(); ++i) {
        auto measured = (start[i] - length(vel(balls[i]))) / seconds;
        EXPECT_NEAR(measured, expected, scalar(0.03) * expected)
            << "at " << degrees[i] << " degrees: deceleration " << measured << " m/s^2, expected "
            << expected;
    }
}

TEST_F(friction, sliding_friction_stops_a_box_after_v_squared_over_2_mu_g_in_every_direction) {
    const scalar mu = scalar(0.4), v0 = 5;
    scenes::make_ground(reg, mu, 0);
    const scalar degrees[] = {0, 30, 45, 60, 135};
    std::vector<entity> boxes;
    std::vector<vector3> dirs;
    for (std::size_t i = 0; i < std::size(degrees); ++i) {
        auto angle = to_radians(degrees[i]);
        dirs.push_back({std::cos(angle), 0, std::sin(angle)});
        auto def =
            edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {scalar(20 * i), scalar(0.5), 0});
        // Turned to face its way, so that every box slides on the same edges.
        def.orientation = quaternion_axis_angle(vector3_y, -angle);
        def.material->friction = mu;
        def.linvel = dirs.back() * v0;
        boxes.push_back(make_rigidbody(reg, def));
    }
    run_for(3);
    // Both materials 0.4: the default mixing gives 0.4.
    auto expected = v0 * v0 / (2 * mu * test::earth_g);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        auto moved = pos(boxes[i]) - vector3{scalar(20 * i), scalar(0.5), 0};
        auto along = dot(moved, dirs[i]);
        EXPECT_NEAR(along, expected, scalar(0.03) * expected)
            << "at " << degrees[i] << " degrees: slid " << along << " m, expected " << expected;
        EXPECT_NEAR(length(moved - dirs[i] * along), 0, scalar(0.01))
            << "at " << degrees[i] << " degrees: strayed from its line";
        EXPECT_NEAR(length(vel(boxes[i])), 0, scalar(1e-3));
    }
}

TEST_F(friction, rolling_friction_stops_a_slow_sphere_and_keeps_it_stopped) {
    scenes::make_ground(reg, 1, 0);
    const scalar r = scalar(0.5), v0 = 1, c = scalar(0.05);
    auto ball = make_rolling_sphere(r, v0, c);
    auto a = c * test::earth_g / (scalar(1.4) * r);
    auto stop_time = v0 / a;
    auto stop_distance = v0 * v0 / (2 * a);
    run_for(stop_time + 1);
    EXPECT_NEAR(vel(ball).x, 0, scalar(1e-3)) << "still moving after " << stop_time + 1 << " s";
    EXPECT_NEAR(pos(ball).x, stop_distance, scalar(0.03) * stop_distance)
        << "stopped after " << pos(ball).x << " m, expected " << stop_distance;
}

TEST_F(friction, without_rolling_friction_a_rolling_sphere_keeps_its_speed) {
    scenes::make_ground(reg, 1, 0);
    const scalar r = scalar(0.5), v0 = 5;
    auto ball = make_rolling_sphere(r, v0, 0);
    run_for(2);
    EXPECT_NEAR(vel(ball).x, v0, scalar(0.01) * v0)
        << "speed " << vel(ball).x << " after 2 s, expected " << v0;
    EXPECT_NEAR(pos(ball).x, 2 * v0, scalar(0.01) * 2 * v0);
}

TEST_F(friction, a_ball_and_a_wheel_rolling_at_fifty_metres_a_second_ride_at_their_radius) {
    // At 50 m/s a wheel of radius 0.5 turns 1.7 rad in a step. Its contact stays at the foot of
    // its centre; the material point that touched rises by most of the radius within the step,
    // and a contact that followed that point saw a gap opening and let gravity pull the wheel
    // 2 to 3 cm into the ground, bobbing at up to 0.8 m/s.
    scenes::make_ground(reg, 1, 0);
    const scalar r = scalar(0.5), v0 = 50;
    auto ball = make_rolling_sphere(r, v0, 0);
    rigidbody_def def;
    def.shape = cylinder_shape{r, scalar(0.2), coordinate_axis::z};
    def.position = {0, r, 5};
    def.material->friction = 1;
    def.linvel = {v0, 0, 0};
    def.angvel = {0, 0, -v0 / r};
    def.sleeping_disabled = true;
    auto wheel = make_rigidbody(reg, def);
    scalar lowest[2]{r, r}, fastest_vertical[2]{0, 0};
    for (int i = 0; i < 60; ++i) {
        edyn::test::step(reg);
        for (int k = 0; k < 2; ++k) {
            auto body = k == 0 ? ball : wheel;
            lowest[k] = std::min(lowest[k], pos(body).y);
            fastest_vertical[k] = std::max(fastest_vertical[k], std::abs(vel(body).y));
        }
    }
    const char *names[2]{"ball", "wheel"};
    for (int k = 0; k < 2; ++k) {
        auto body = k == 0 ? ball : wheel;
        EXPECT_GT(lowest[k], r - scalar(0.002))
            << "the " << names[k] << "'s centre came down to " << lowest[k];
        EXPECT_LT(fastest_vertical[k], scalar(0.05))
            << "the " << names[k] << " bobbed at " << fastest_vertical[k];
        EXPECT_NEAR(vel(body).x, v0, scalar(0.005) * v0) << "the " << names[k] << " rolls at " << vel(body).x;
    }
}

TEST_F(friction, a_sphere_that_lands_rolling_bounces_on_rolling_at_its_speed) {
    // Its bottom meets the ground without sliding, so the ground pushes it straight up through
    // its centre: only the vertical velocity changes, bounce after bounce. At 3 m/s the ball turns
    // its bottom 5 cm away in a step, farther than points are matched by their pivots; a point
    // kept from the step before the landing would push it off its centre and turn spin into speed.
    scenes::make_ground(reg, 1, scalar(0.8));
    const scalar r = scalar(0.5), v0 = 3;
    auto def = edyn::test::sphere_def(r, {0, 2, 0});
    def.material->friction = 1;
    def.material->restitution = scalar(0.8);
    def.linvel = {v0, -5, 0};
    def.angvel = {0, 0, -v0 / r};
    def.sleeping_disabled = true;
    auto ball = make_rigidbody(reg, def);

    scalar worst_speed = 0, worst_spin = 0;
    std::uint32_t most_points = 0;
    auto bounces = 0;
    auto was_falling = true;
    for (auto step = 0; step < 120; ++step) {
        edyn::test::step(reg);
        worst_speed = std::max(worst_speed, std::abs(vel(ball).x - v0));
        worst_spin = std::max(worst_spin, std::abs(angular(ball).z + v0 / r));
        for (auto [e, manifold] : reg.view<contact_manifold>().each())
            most_points = std::max(most_points, manifold.num_points);
        auto falling = vel(ball).y < 0;
        bounces += was_falling && !falling;
        was_falling = falling;
    }
    ASSERT_GE(bounces, 2);
    EXPECT_LT(worst_speed, scalar(0.01) * v0) << "horizontal speed off by " << worst_speed << " m/s";
    EXPECT_LT(worst_spin, scalar(0.01) * v0 / r) << "spin off by " << worst_spin << " rad/s";
    EXPECT_EQ(most_points, 1u) << "a sphere on a plane touches it at one point";
}

TEST_F(friction, rolling_friction_slows_a_cylinder_rolling_about_its_axis_at_c_g_over_1_5_r) {
    // I = 1/2 m r^2 about the axis: a = c m g / (r m (1 + 1/2)).
    scenes::make_ground(reg, 1, 0);
    const scalar r = scalar(0.5), v0 = 5, c = scalar(0.05);
    rigidbody_def def;
    def.shape = cylinder_shape{r, scalar(0.5), coordinate_axis::z};
    def.position = {0, r, 0};
    def.material->friction = 1;
    def.material->roll_friction = c;
    def.linvel = {v0, 0, 0};
    def.angvel = {0, 0, -v0 / r};
    def.sleeping_disabled = true;
    auto wheel = make_rigidbody(reg, def);
    edyn::test::step(reg);
    auto v_start = vel(wheel).x;
    auto seconds = scalar(2);
    run_for(seconds);
    auto expected = c * test::earth_g / (scalar(1.5) * r);
    auto measured = (v_start - vel(wheel).x) / seconds;
    EXPECT_NEAR(measured, expected, scalar(0.03) * expected)
        << "deceleration measured " << measured << " m/s^2, expected " << expected;
    // The line contact's points may push it sideways a little: under 0.5% of the distance
    // rolled (about 9 m).
    EXPECT_NEAR(pos(wheel).z, 0, scalar(0.005) * pos(wheel).x)
        << "the wheel drifted " << pos(wheel).z << " m along its axis over " << pos(wheel).x << " m";
}

TEST_F(friction, spinning_friction_stops_a_spinning_sphere_after_w0_i_over_s_m_g) {
    scenes::make_ground(reg, 1, 0);
    const scalar r = scalar(0.5), m = 1, w0 = 10, s = scalar(0.05);
    auto ball = make_spinning_sphere(r, w0, s);
    auto I = scalar(0.4) * m * r * r;
    auto alpha = s * m * test::earth_g / I;
    auto stop_time = w0 * I / (s * m * test::earth_g);

    edyn::test::step(reg);
    auto w_start = angular(ball).y;
    run_for(1);
    auto measured = w_start - angular(ball).y;
    EXPECT_NEAR(measured, alpha, scalar(0.03) * alpha)
        << "angular deceleration measured " << measured << " rad/s^2, expected " << alpha;

    // Find when it stops.
    auto t = get_fixed_dt(reg) * 61;
    while (angular(ball).y > scalar(1e-3) && t < 2 * stop_time) {
        edyn::test::step(reg);
        t += get_fixed_dt(reg);
    }
    EXPECT_NEAR(t, stop_time, scalar(0.03) * stop_time)
        << "stopped after " << t << " s, expected " << stop_time;
    run_for(1);
    EXPECT_NEAR(angular(ball).y, 0, scalar(1e-3)) << "spins again";
    // Spinning about the normal does not move the ball.
    EXPECT_NEAR(pos(ball).x, 0, scalar(1e-3));
    EXPECT_NEAR(pos(ball).z, 0, scalar(1e-3));
}

TEST_F(friction, without_spinning_friction_a_spinning_sphere_keeps_spinning) {
    scenes::make_ground(reg, 1, 0);
    const scalar w0 = 10;
    auto ball = make_spinning_sphere(scalar(0.5), w0, 0);
    run_for(2);
    EXPECT_NEAR(angular(ball).y, w0, scalar(0.01) * w0) << "spin " << angular(ball).y << " after 2 s";
}

// Material mixing: a pair entry replaces the default mixing for bodies with those ids.
using material_mixing_override = world_fixture;

namespace {

constexpr material_id_type ground_id = 1;
constexpr material_id_type box_id = 2;

entity make_ground_with_id(registry &reg, scalar friction, scalar restitution) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.material->friction = friction;
    def.material->restitution = restitution;
    def.material->id = ground_id;
    def.shape = plane_shape{vector3_y, 0};
    return make_rigidbody(reg, def);
}

entity make_sliding_box(registry &reg, scalar v, scalar friction) {
    auto def = edyn::test::box_def({scalar(0.5), scalar(0.5), scalar(0.5)}, {0, scalar(0.5), 0});
    def.material->friction = friction;
    def.material->id = box_id;
    def.linvel = {v, 0, 0};
    return make_rigidbody(reg, def);
}

} // namespace

TEST_F(material_mixing_override, default_mixing_stops_a_sliding_box_after_v_squared_over_2_mu_g) {
    make_ground_with_id(reg, scalar(0.4), 0);
    auto box = make_sliding_box(reg, 5, scalar(0.4));
    run_for(3);
    // Default mixing: sqrt(0.4 * 0.4) = 0.4.
    auto expected = scalar(25) / (2 * scalar(0.4) * test::earth_g);
    EXPECT_NEAR(pos(box).x, expected, scalar(0.03) * expected)
        << "slid " << pos(box).x << " m, expected " << expected;
    EXPECT_NEAR(vel(box).x, 0, scalar(1e-3));
}

TEST_F(material_mixing_override, zero_friction_pair_lets_the_box_slide_without_slowing) {
    material_base ice;
    ice.friction = 0;
    insert_material_mixing(reg, ground_id, box_id, ice);
    make_ground_with_id(reg, scalar(0.4), 0);
    auto box = make_sliding_box(reg, 5, scalar(0.4));
    run_for(3);
    EXPECT_NEAR(vel(box).x, 5, scalar(1e-3)) << "speed " << vel(box).x << " after 3 s, expected 5";
    EXPECT_NEAR(pos(box).x, 15, scalar(0.01) * 15);
}

TEST_F(material_mixing_override, pair_friction_overrides_in_either_id_order) {
    material_base rough;
    rough.friction = scalar(0.8);
    // Inserted as (box, ground): the contact is (ground, box) or (box, ground), both must match.
    insert_material_mixing(reg, box_id, ground_id, rough);
    make_ground_with_id(reg, scalar(0.1), 0);
    auto box = make_sliding_box(reg, 5, scalar(0.1));
    run_for(3);
    auto expected = scalar(25) / (2 * scalar(0.8) * test::earth_g);
    EXPECT_NEAR(pos(box).x, expected, scalar(0.03) * expected)
        << "slid " << pos(box).x << " m, expected " << expected << " (mixed default would give "
        << scalar(25) / (2 * scalar(0.1) * test::earth_g) << ")";
}

TEST_F(material_mixing_override, pair_restitution_overrides_the_bounce) {
    // Both materials have restitution 0; the pair says 0.8, so the ball bounces to 0.64 h.
    material_base bouncy;
    bouncy.restitution = scalar(0.8);
    const material_id_type ball_id = 3;
    insert_material_mixing(reg, ground_id, ball_id, bouncy);
    make_ground_with_id(reg, scalar(0.5), 0);
    auto def = edyn::test::sphere_def(scalar(0.25), {0, scalar(2.25), 0});
    def.material->id = ball_id;
    auto ball = make_rigidbody(reg, def);

    auto peak = edyn::test::rebound_peak(reg, ball, scalar(0.25));
    ASSERT_GE(peak, 0) << "the ball did not bounce";
    auto expected = 2 * scalar(0.64);
    EXPECT_NEAR(peak, expected, edyn::test::rebound_tolerance(reg, 2, expected))
        << "peak " << peak << " m, expected " << expected;
}

// A sphere set sliding at v0 without turning rolls at 5/7 v0 once friction has stopped the slip,
// whatever its mass: a trillion-kilogram sphere and a 1.5 km rock of 4.2e13 kg as well. Their
// inertias (4e13 and 3.8e19 kg m^2) have determinants past the largest float; inverted as they
// are, the first had no rotation at all (it stopped dead) and the second had NaN in its state
// after the first step.
TEST_F(friction, a_sliding_sphere_rolls_at_five_sevenths_of_its_speed_at_any_mass) {
    scenes::make_ground(reg, 1, 0);
    const scalar v0 = 1;
    struct sphere {
        scalar mass, radius;
    };
    const sphere spheres[]{{1, scalar(0.5)}, {scalar(1e12), 10}, {scalar(4.24e13), 1500}};
    std::vector<entity> bodies;
    for (int k = 0; k < 3; ++k) {
        auto def = edyn::test::sphere_def(spheres[k].radius, {scalar(4000 * k), spheres[k].radius, 0},
                                          spheres[k].mass);
        def.material->friction = 1;
        def.linvel = {v0, 0, 0};
        def.sleeping_disabled = true;
        bodies.push_back(make_rigidbody(reg, def));
    }
    run_for(1);
    for (int k = 0; k < 3; ++k) {
        auto e = bodies[k];
        auto r = spheres[k].radius;
        EXPECT_NEAR(vel(e).x, v0 * 5 / 7, scalar(0.005) * v0) << "mass " << spheres[k].mass;
        EXPECT_NEAR(-angular(e).z * r, vel(e).x, scalar(0.005) * v0) << "mass " << spheres[k].mass;
        EXPECT_NEAR(pos(e).y, r, scalar(0.01)) << "mass " << spheres[k].mass;
    }
}

// A kinematic platform turning at w about the vertical carries a box at radius r for as long as
// friction can give it the centripetal force: w^2 r <= mu g. Held, the box keeps its radius and
// its place on the platform; beyond that it slides outward.
TEST_F(friction, a_box_on_a_turning_platform_keeps_its_radius_while_friction_holds_it) {
    const scalar w = scalar(1.5);
    rigidbody_def platform_def;
    platform_def.kind = rigidbody_kind::rb_kinematic;
    platform_def.shape = cylinder_shape{3, scalar(0.1), coordinate_axis::y};
    platform_def.material->friction = 1;
    platform_def.angvel = {0, w, 0};
    auto platform = make_rigidbody(reg, platform_def);

    // Held: w^2 r up to 5.6 m/s^2 against mu g = 9.8. Beyond: w^2 r = 5.6 against mu g = 2.0.
    const scalar radii[]{scalar(0.5), scalar(1.5), scalar(2.5)};
    std::vector<entity> held;
    for (int k = 0; k < 3; ++k) {
        auto angle = scalar(2.1) * scalar(k);
        auto def = edyn::test::box_def(vector3{scalar(0.1), scalar(0.1), scalar(0.1)},
                                       {radii[k] * std::cos(angle), scalar(0.2), radii[k] * std::sin(angle)});
        def.material->friction = 1;
        def.linvel = cross(vector3{0, w, 0}, def.position);
        def.angvel = {0, w, 0};
        def.sleeping_disabled = true;
        held.push_back(make_rigidbody(reg, def));
    }
    auto def = edyn::test::box_def(vector3{scalar(0.1), scalar(0.1), scalar(0.1)}, {0, scalar(0.2), 2.5});
    def.material->friction = scalar(0.04); // Mixed with the platform's 1: sqrt(0.04) = 0.2.
    def.linvel = cross(vector3{0, w, 0}, def.position);
    def.angvel = {0, w, 0};
    def.sleeping_disabled = true;
    auto slipping = make_rigidbody(reg, def);

    // Where each box sits on the platform, in the platform's frame.
    auto on_platform = [&](entity e) {
        return rotate(conjugate(reg.get<orientation>(platform)), pos(e) - pos(platform));
    };
    std::vector<vector3> start;
    for (auto e : held)
        start.push_back(on_platform(e));
    run_for(20);
    for (int k = 0; k < 3; ++k) {
        auto p = pos(held[k]);
        auto radius = std::sqrt(p.x * p.x + p.z * p.z);
        EXPECT_NEAR(radius, radii[k], scalar(0.01)) << "box at " << radii[k] << " m";
        EXPECT_LT(length(on_platform(held[k]) - start[k]), scalar(0.02)) << "box at " << radii[k] << " m";
        EXPECT_NEAR(p.y, scalar(0.2), scalar(0.01)) << "box at " << radii[k] << " m";
    }
    auto p = pos(slipping);
    EXPECT_GT(std::sqrt(p.x * p.x + p.z * p.z), 3) << "the box friction cannot hold stayed on the platform";
}

// Static friction carries a box on the bed of a kinematic truck that accelerates at a < mu g: the
// box must not creep backwards on the bed, however far the truck goes.
TEST_F(friction, a_box_on_an_accelerating_truck_stays_where_it_was_put) {
    rigidbody_def truck_def;
    truck_def.kind = rigidbody_kind::rb_kinematic;
    truck_def.shape = box_shape{20, scalar(0.1), 2};
    truck_def.material->friction = 1;
    auto truck = make_rigidbody(reg, truck_def);
    auto def = edyn::test::box_def(vector3{scalar(0.3), scalar(0.3), scalar(0.3)}, {0, scalar(0.4), 0});
    def.material->friction = 1;
    def.sleeping_disabled = true;
    auto box = make_rigidbody(reg, def);
    run_for(1);
    auto on_bed = pos(box).x - pos(truck).x;
    // 4 m/s^2 for 5 s, against mu g = 9.8.
    const scalar acceleration = 4;
    auto dt = get_fixed_dt(reg);
    for (int i = 1; i <= 300; ++i) {
        reg.replace<linvel>(truck, vector3{acceleration * dt * scalar(i), 0, 0});
        edyn::test::step(reg);
    }
    EXPECT_NEAR(vel(truck).x, 20, scalar(1e-3));
    EXPECT_NEAR(pos(box).x - pos(truck).x, on_bed, scalar(0.002)) << "the box crept on the bed";
    EXPECT_NEAR(vel(box).x, 20, scalar(0.1));
}

// A ball rolling without slipping with a spin about the vertical (side spin) rolls on in a
// straight line: on flat ground the spin about the normal moves nothing sideways.
TEST_F(friction, a_ball_rolling_with_side_spin_rolls_straight) {
    scenes::make_ground(reg, 1, 0);
    const scalar radius = scalar(0.5), speed = 2, spin = 10;
    auto ball = make_rolling_sphere(radius, speed, 0);
    reg.patch<angvel>(ball, [&](angvel &w) { w.y = spin; });
    run_for(2);
    EXPECT_NEAR(pos(ball).z, 0, scalar(0.01)) << "the ball drifted sideways";
    EXPECT_NEAR(pos(ball).x, 2 * speed, scalar(0.02));
    EXPECT_NEAR(vel(ball).x, speed, scalar(0.01));
    EXPECT_NEAR(angular(ball).y, spin, scalar(0.01));
}
