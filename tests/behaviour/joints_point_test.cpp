// Point, distance, soft distance and null constraints against closed-form physics.
#include "joints_support.hpp"

using namespace edyn;
using edyn::test::crossing_timer;
using edyn::test::world_fixture;

using point_joint = world_fixture;
using distance_joint = world_fixture;
using null_joint = world_fixture;

TEST_F(point_joint, pendulum_period_is_two_pi_sqrt_l_over_g) {
    const scalar length = 1, radius = scalar(0.05), g = scalar(9.8);
    const scalar theta0 = to_radians(5);
    auto anchor = edyn::test::make_anchor(reg, {0, 2, 0});
    auto def = edyn::test::sphere_def(radius, {length * std::sin(theta0), 2 - length * std::cos(theta0), 0});
    def.orientation = quaternion_axis_angle(vector3_z, theta0);
    auto bob = make_rigidbody(reg, def);
    make_constraint<point_constraint>(reg, anchor, bob, [&](point_constraint &c) {
        c.pivot[0] = vector3_zero;
        c.pivot[1] = {0, length, 0};
    });

    crossing_timer timer;
    for (int i = 0; i < 60 * 12; ++i) {
        edyn::test::step(reg);
        timer.sample(get_simulation_time(reg), pos(bob).x);
    }
    // A sphere on a massless rod is a physical pendulum: I = m L^2 + 2/5 m r^2 about the pivot.
    // The finite amplitude lengthens the period by theta0^2 / 16.
    auto inertia_ratio = (length * length + scalar(0.4) * radius * radius) / length;
    auto expected = 2 * pi * std::sqrt(inertia_ratio / g) * (1 + theta0 * theta0 / 16);
    auto measured = timer.mean_period();
    ASSERT_GE(timer.times.size(), 5u);
    EXPECT_NEAR(measured, expected, 0.01 * expected)
        << "measured period " << measured << " s, expected " << expected << " s";
    // The bob stays on its circle.
    auto r = distance(pos(bob), vector3{0, 2, 0});
    EXPECT_NEAR(r, length, scalar(0.002)) << "measured radius " << r << ", expected " << length;
}

TEST_F(point_joint, bodies_written_after_make_constraint_are_refused_by_the_step) {
    // A joint's bodies are fixed when it is made: its islands, the bodies' lists of constraints
    // and sleeping follow them. Moving the joint to another body, to null or to a destroyed
    // entity once made let the solver pull the new body while the islands kept the old pair
    // (the old body fell free, the new one was drawn towards the anchor from another island).
    // The step refuses each, naming the entity, until the pair is put back.
    auto anchor = edyn::test::make_anchor(reg, {0, 2, 0});
    auto bob = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.1), {1, 2, 0}));
    auto other = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.1), {4, 2, 0}));
    auto gone = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.1), {8, 2, 0}));
    reg.destroy(gone);
    auto joint = make_constraint<point_constraint>(reg, anchor, bob, [](point_constraint &c) {
        c.pivot[1] = {-1, 0, 0};
    });
    edyn::test::step(reg);
    auto expected = "constraint entity " + std::to_string(to_index(joint));
    for (auto body : {other, entity(null), gone, anchor}) {
        reg.patch<point_constraint>(joint, [&](point_constraint &c) { c.body[1] = body; });
        try {
            edyn::test::step(reg);
            ADD_FAILURE() << "the step accepted body[1] = " << to_integral(body);
        } catch (const std::invalid_argument &error) {
            std::string what = error.what();
            EXPECT_NE(what.find("body[]"), std::string::npos) << what;
            EXPECT_NE(what.find(expected), std::string::npos) << what;
        }
    }
    // Nothing pulled the other ball: it fell as a free body does, straight down.
    EXPECT_NEAR(pos(other).x, 4, scalar(1e-4));
    reg.patch<point_constraint>(joint, [&](point_constraint &c) { c.body[1] = bob; });
    run_for(1);
    EXPECT_NEAR(distance(pos(bob), vector3{0, 2, 0}), 1, scalar(0.002)) << "the bob left its rope";
}

TEST_F(point_joint, pivots_are_relative_to_the_origin_not_the_centre_of_mass) {
    auto anchor = edyn::test::make_anchor(reg, {0, 3, 0});
    auto def = edyn::test::box_def({scalar(0.1), scalar(0.5), scalar(0.1)}, {0, 2, 0});
    def.center_of_mass = vector3{0, scalar(-0.3), 0};
    auto bar = make_rigidbody(reg, def);
    const vector3 pivot{0, scalar(0.5), 0};
    make_constraint<point_constraint>(reg, anchor, bar, [&](point_constraint &c) {
        c.pivot[0] = {0, -scalar(0.5), 0};
        c.pivot[1] = pivot;
    });
    rigidbody_apply_impulse(reg, bar, {2, 0, 1}, vector3_zero);
    run_for(2);
    auto gap = distance(edyn::test::world_pivot(reg, bar, pivot), vector3{0, scalar(2.5), 0});
    EXPECT_LT(gap, scalar(0.005)) << "pivot separation " << gap << " m, expected 0";
}

TEST_F(point_joint, friction_torque_stops_a_spinning_body_at_the_rate_it_sets) {
    set_gravity(reg, vector3_zero);
    auto anchor = edyn::test::make_anchor(reg, {0, 0, 0});
    auto def = edyn::test::sphere_def(scalar(0.5), {0, 0, 0}, 2);
    def.angvel = {0, 4, 0};
    auto ball = make_rigidbody(reg, def);
    const scalar torque = scalar(0.2);
    make_constraint<point_constraint>(reg, anchor, ball,
                                      [&](point_constraint &c) { c.friction_torque = torque; });
    // I = 2/5 m r^2 = 0.2: the spin decelerates at torque / I = 1 rad/s^2.
    run_for(2);
    auto inertia = scalar(0.4) * 2 * scalar(0.25);
    auto expected = 4 - torque / inertia * 2;
    EXPECT_NEAR(angular(ball).y, expected, scalar(0.02))
        << "measured " << angular(ball).y << " rad/s, expected " << expected;
    run_for(3);
    EXPECT_NEAR(angular(ball).y, 0, scalar(1e-3));
}

TEST_F(point_joint, a_joint_made_with_its_bodies_apart_draws_them_together_gently) {
    // Two free boxes 3 m apart, joined at their facing corners by a ball joint, and two more
    // welded (a generic constraint, every degree locked). The soft correction closes the gap
    // at max_correction_speed: before, the projection shut it in one sub-step, throwing the
    // boxes together at 100 m/s and leaving them spinning with hundreds of joules.
    set_gravity(reg, vector3_zero);
    auto box = [&](vector3 at) {
        return make_rigidbody(reg, edyn::test::box_def({scalar(0.3), scalar(0.3), scalar(0.3)}, at, 1));
    };
    auto a = box({0, 2, 0}), b = box({3, 2, 1});
    auto c = box({0, 2, 5}), d = box({3, 2, 6});
    make_constraint<point_constraint>(reg, a, b, [](point_constraint &j) {
        j.pivot[0] = {scalar(0.3), scalar(0.3), 0};
        j.pivot[1] = {scalar(-0.3), scalar(-0.3), 0};
    });
    make_constraint<generic_constraint>(reg, c, d, [](generic_constraint &j) {
        j.pivot[0] = {scalar(0.3), scalar(0.3), 0};
        j.pivot[1] = {scalar(-0.3), scalar(-0.3), 0};
    });
    auto gap = [&](entity x, entity y) {
        return distance(edyn::test::world_pivot(reg, x, {scalar(0.3), scalar(0.3), 0}),
                        edyn::test::world_pivot(reg, y, {scalar(-0.3), scalar(-0.3), 0}));
    };
    auto max_correction = get_settings(reg).joint.max_correction_speed;
    scalar fastest = 0;
    for (int i = 0; i < 60 * 3; ++i) {
        edyn::test::step(reg);
        for (auto e : {a, b, c, d})
            fastest = std::max(fastest, length(vel(e)));
    }
    EXPECT_LT(gap(a, b), scalar(0.001));
    EXPECT_LT(gap(c, d), scalar(0.001));
    // Each of a pair moves at about half the closing speed; what they spin is little.
    EXPECT_LT(fastest, max_correction) << "a box moved at " << fastest << " m/s";
    // Momentum is kept: each pair's centre stays where it was.
    EXPECT_LT(distance((pos(a) + pos(b)) / 2, vector3{scalar(1.5), 2, scalar(0.5)}), scalar(0.01));
    EXPECT_LT(distance((pos(c) + pos(d)) / 2, vector3{scalar(1.5), 2, scalar(5.5)}), scalar(0.01));
}

TEST_F(distance_joint, chain_of_twenty_keeps_every_length_within_half_a_percent) {
    // A straight chain released 30 degrees from the vertical, swinging for 5 s.
    const int links = 20;
    const scalar spacing = scalar(0.5), angle = to_radians(30);
    auto anchor = edyn::test::make_anchor(reg, {0, 20, 0});
    std::vector<entity> bodies{anchor};
    for (int i = 1; i <= links; ++i) {
        auto along = spacing * scalar(i);
        bodies.push_back(make_rigidbody(
            reg,
            edyn::test::sphere_def(scalar(0.1), {along * std::sin(angle), 20 - along * std::cos(angle), 0})));
        make_constraint<distance_constraint>(reg, bodies[i - 1], bodies[i],
                                             [&](distance_constraint &c) { c.distance = spacing; });
    }
    scalar worst = 0, lowest_x = 0;
    for (int step = 0; step < 60 * 5; ++step) {
        edyn::test::step(reg);
        for (int i = 1; i <= links; ++i) {
            auto error = std::abs(distance(pos(bodies[i - 1]), pos(bodies[i])) - spacing) / spacing;
            worst = std::max(worst, error);
        }
        lowest_x = std::min(lowest_x, pos(bodies.back()).x);
    }
    EXPECT_LT(worst, scalar(0.005)) << "worst relative length error " << worst << ", expected below 0.005";
    // It swung through the vertical to the other side.
    EXPECT_LT(lowest_x, scalar(-1));
}

namespace {

// A 2 kg ball on a soft distance constraint from a fixed anchor, pulled 10 cm past its rest
// length and let go along the spring, with no gravity. It does not sleep: what is measured is
// the spring, until the end.
struct spring_world : world_fixture {
    static constexpr scalar k = 200, m = 2, rest = 1, x0 = scalar(0.1);
    entity body{null};

    void make_spring(scalar damping) {
        set_gravity(reg, vector3_zero);
        auto anchor = edyn::test::make_anchor(reg, {0, 0, 0});
        auto def = edyn::test::sphere_def(scalar(0.1), {rest + x0, 0, 0}, m);
        def.sleeping_disabled = true;
        body = make_rigidbody(reg, def);
        make_constraint<soft_distance_constraint>(reg, anchor, body, [&](soft_distance_constraint &c) {
            c.distance = rest;
            c.stiffness = k;
            c.damping = damping;
        });
    }

    // The oscillator m x'' + c x' + k x = 0 has the roots s = -g +- i wd (g = c / 2m,
    // wd = sqrt(k / m - g^2)), and z = x' - conj(s) x turns with z' = s z: |z| / wd is its
    // amplitude, whatever the phase, and decays as exp(-g t) (it is hypot(x, x' / w) undamped).
    // Integrated in sub-steps of h as the solver does, implicit in the spring (v' = (v - h k/m x)
    // / D, x' = x + h v' with D = 1 + h c / m + h^2 k / m), the same z is multiplied by
    // (1 - conj(s) h) / D, of modulus D^(-1/2), each sub-step: exp(-g h) to first order, and the
    // rest, about (h w)^2 / 2, the integration's own damping.
    scalar amplitude(scalar damping) const {
        auto g = damping / (2 * m), wd = std::sqrt(k / m - g * g);
        auto x = pos(body).x - rest, v = vel(body).x;
        return std::hypot(v + g * x, wd * x) / wd;
    }
    scalar expected_amplitude(scalar damping, int steps) const {
        auto g = damping / (2 * m), wd = std::sqrt(k / m - g * g);
        auto h = double(get_fixed_dt(reg)) / get_solver_substeps(reg);
        auto D = 1 + h * double(damping / m) + h * h * double(k / m);
        auto n = double(steps) * get_solver_substeps(reg);
        return scalar(double(std::hypot(g * x0, wd * x0) / wd) * std::pow(D, -n / 2));
    }
};

// What separates the measured amplitude from the closed form is float rounding alone: the
// ball's position near 1 m is resolved to 6e-8 m, and the sub-steps' rounding errors add up to
// 4e-7 m over 5 s (measured against the exact discrete solution), 1e-5 of the amplitude. A
// thousandth of the amplitude leaves room for that and is far below the integration's own
// damping (13% a second at the default sub-steps), which an error in the spring's integration
// would change.
constexpr scalar amplitude_tolerance = scalar(1e-3);

using soft_distance_spring = spring_world;

} // namespace

TEST_F(soft_distance_spring, oscillates_at_sqrt_k_over_m) {
    make_spring(0);
    crossing_timer timer;
    const int steps = 60 * 5;
    for (int i = 0; i < steps; ++i) {
        edyn::test::step(reg);
        timer.sample(get_simulation_time(reg), vel(body).x);
    }
    auto expected = 2 * pi / std::sqrt(k / m);
    auto measured = timer.mean_period();
    ASSERT_GE(timer.times.size(), 3u);
    EXPECT_NEAR(measured, expected, 0.03 * expected)
        << "measured period " << measured << " s, expected " << expected << " s";
    // Undamped, the amplitude stays 10 cm but for the integration's damping.
    auto amplitude = this->amplitude(0), expected_amplitude = this->expected_amplitude(0, steps);
    EXPECT_NEAR(amplitude, expected_amplitude, amplitude_tolerance * expected_amplitude)
        << "measured amplitude " << amplitude << " m, expected " << expected_amplitude << " m (undamped "
        << x0 << " m)";
}

TEST_F(soft_distance_spring, damping_decays_the_amplitude_exponentially) {
    const scalar c = 8;
    make_spring(c);
    const int steps = 60;
    run_for(1);
    auto amplitude = this->amplitude(c), expected = expected_amplitude(c, steps);
    EXPECT_NEAR(amplitude, expected, amplitude_tolerance * expected)
        << "measured amplitude " << amplitude << " m, expected " << expected
        << " m (exp(-c t / 2m) alone: " << x0 * std::exp(-c / (2 * m)) << " m)";
}

TEST_F(null_joint, keeps_two_distant_bodies_in_one_island) {
    // Islands live where the step runs: the worker's registry in the asynchronous mode.
    auto island = [&](entity e) { return reg.get<island_resident>(e).island_entity; };
    auto a = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, 5, 0}));
    auto b = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {50, 5, 0}));
    if (edyn::test::simulates_here(reg)) {
        EXPECT_NE(island(a), island(b));
    }
    auto edge = make_constraint<null_constraint>(reg, a, b);
    if (edyn::test::simulates_here(reg)) {
        EXPECT_EQ(island(a), island(b));
        EXPECT_EQ(island(edge), island(a));
    }
    run_for(1);
    // They fall freely: no force between them.
    EXPECT_NEAR(pos(b).x, 50, scalar(1e-5));
    if (edyn::test::simulates_here(reg)) {
        EXPECT_EQ(island(a), island(b));
    }
    // Destroying a body destroys its constraints.
    reg.destroy(b);
    EXPECT_FALSE(reg.valid(edge));
}

TEST_F(null_joint, connects_an_external_entity_to_a_body_island) {
    auto body = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {0, 5, 0}));
    auto external = reg.create();
    tag_external_entity(reg, external);
    auto edge = make_constraint<null_constraint>(reg, body, external);
    if (edyn::test::simulates_here(reg)) {
        EXPECT_EQ(reg.get<island_resident>(edge).island_entity, reg.get<island_resident>(body).island_entity);
    }
    reg.destroy(external);
    EXPECT_FALSE(reg.valid(edge));
    run_for(scalar(0.1));
}

TEST_F(point_joint, a_light_link_between_heavy_bodies_holds_when_they_hit_the_ground) {
    // Heavy, light, heavy in a row joined end to end, like a torso, a neck and a head, falling
    // 4 m and landing on one end: the light link is pulled from both sides at once.
    rigidbody_def ground;
    ground.kind = rigidbody_kind::rb_static;
    ground.shape = plane_shape{vector3_y, 0};
    make_rigidbody(reg, ground);
    const scalar half = scalar(0.15);
    const scalar masses[3]{16, scalar(1.6), 5};
    const auto tilt = quaternion_axis_angle(vector3_z, to_radians(60));
    entity bodies[3];
    for (int i = 0; i < 3; ++i) {
        auto def = edyn::test::box_def(
            {half, scalar(0.08), scalar(0.08)},
            vector3{0, 4, 0} + rotate(tilt, vector3{2 * half * scalar(i - 1), 0, 0}), masses[i]);
        def.orientation = tilt;
        bodies[i] = make_rigidbody(reg, def);
    }
    std::vector<entity> joints;
    for (int i = 0; i < 2; ++i) {
        joints.push_back(
            make_constraint<point_constraint>(reg, bodies[i], bodies[i + 1], [&](point_constraint &c) {
                c.pivot[0] = {half, 0, 0};
                c.pivot[1] = {-half, 0, 0};
            }));
        exclude_collision(reg, bodies[i], bodies[i + 1]);
    }
    scalar worst = 0;
    for (int step = 0; step < 90; ++step) {
        edyn::test::step(reg);
        for (auto e : joints) {
            auto &c = reg.get<point_constraint>(e);
            worst = std::max(worst, distance(edyn::test::world_pivot(reg, c.body[0], c.pivot[0]),
                                             edyn::test::world_pivot(reg, c.body[1], c.pivot[1])));
        }
    }
    EXPECT_LT(pos(bodies[0]).y, 1) << "did not land";
    EXPECT_LT(worst, scalar(0.005)) << "largest pivot separation " << worst << " m";
}
