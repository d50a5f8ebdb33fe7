// Cone constraint: a swing limit that holds under hard pushes, elliptical spans, restitution.
#include "joints_support.hpp"

using namespace edyn;
using edyn::test::world_fixture;

namespace {

const vector3 apex{0, 2, 0};
const scalar rod_half_length = scalar(0.5);

// A 1 m rod hanging from a ball joint at `apex`, its lower end held inside a cone opening
// downwards by span0 towards +x and span1 towards +z.
struct cone_world : world_fixture {
    entity anchor{null};
    entity rod{null};

    void make_rod(scalar span0, scalar span1) {
        anchor = edyn::test::make_anchor(reg, apex);
        rod = make_rigidbody(reg, edyn::test::box_def({scalar(0.05), rod_half_length, scalar(0.05)},
                                                      apex - vector3{0, rod_half_length, 0}));
        make_constraint<point_constraint>(reg, anchor, rod, [](point_constraint &c) {
            c.pivot[0] = vector3_zero;
            c.pivot[1] = {0, rod_half_length, 0};
        });
        make_constraint<cone_constraint>(reg, anchor, rod, [&](cone_constraint &c) {
            c.pivot[0] = vector3_zero;
            c.pivot[1] = {0, -rod_half_length, 0};
            c.frame = matrix3x3_columns(-vector3_y, vector3_x, vector3_z);
            c.span_angle[0] = span0;
            c.span_angle[1] = span1;
        });
    }

    // The lower end relative to the apex: tilt from the vertical, and how far beyond the wall
    // of the elliptical cone it is (radians, positive outside), from the ellipse in closed form.
    struct swing {
        scalar tilt, excess;
    };
    swing measure(scalar span0, scalar span1) const {
        auto r = edyn::test::world_pivot(reg, rod, {0, -rod_half_length, 0}) - apex;
        auto down = -r.y, rho = std::hypot(r.x, r.z);
        auto tilt = std::atan2(rho, down);
        if (rho < scalar(1e-9)) return {tilt, -span0};
        // Polar radius of the ellipse of semi-axes tan(span0), tan(span1) at the point's heading.
        auto t0 = std::tan(span0), t1 = std::tan(span1);
        auto c = r.x / rho, s = r.z / rho;
        auto wall = std::atan(t0 * t1 / std::hypot(t1 * c, t0 * s));
        return {tilt, tilt - wall};
    }
};

using cone_joint = cone_world;

} // namespace

TEST_F(cone_joint, pendulum_pushed_hard_stays_inside_a_thirty_degree_cone) {
    const auto span = to_radians(30);
    make_rod(span, span);
    // 4 N s at the lower end: enough to swing the 1 kg rod past the horizontal unconstrained.
    rigidbody_apply_impulse(reg, rod, {4, 0, scalar(1.5)}, {0, -rod_half_length, 0});
    scalar worst = -1, largest_tilt = 0;
    for (int i = 0; i < 60 * 3; ++i) {
        edyn::test::step(reg);
        auto m = measure(span, span);
        worst = std::max(worst, m.excess);
        largest_tilt = std::max(largest_tilt, m.tilt);
    }
    EXPECT_GT(largest_tilt, span - to_radians(1)) << "the push should reach the wall";
    EXPECT_LT(worst, to_radians(1)) << "largest tilt " << to_degrees(largest_tilt) << " deg, cone "
                                    << to_degrees(span) << " deg; worst excess " << to_degrees(worst)
                                    << " deg";
    auto top = edyn::test::world_pivot(reg, rod, {0, rod_half_length, 0});
    EXPECT_LT(distance(top, apex), scalar(0.005));
}

// A rod started 80 degrees from the axis of a 20-degree cone, as a limb left outside its limit
// or a cone narrowed at run time, is drawn back no faster than a joint's pivots are drawn
// together (constraint_solver_settings::max_correction_speed, 3 m/s at its end), not flung back;
// and a ball behind the apex of a cone of its own is not flung at all.
TEST_F(cone_joint, a_rod_far_outside_the_cone_is_drawn_back_at_the_correction_speed) {
    const auto span = to_radians(20);
    anchor = edyn::test::make_anchor(reg, apex);
    auto tilt = quaternion_axis_angle(vector3_z, to_radians(80));
    auto def = edyn::test::box_def({scalar(0.05), rod_half_length, scalar(0.05)},
                                   apex + rotate(tilt, vector3{0, -rod_half_length, 0}));
    def.orientation = tilt;
    rod = make_rigidbody(reg, def);
    make_constraint<point_constraint>(reg, anchor, rod, [](point_constraint &c) {
        c.pivot[1] = {0, rod_half_length, 0};
    });
    make_constraint<cone_constraint>(reg, anchor, rod, [&](cone_constraint &c) {
        c.pivot[1] = {0, -rod_half_length, 0};
        c.frame = matrix3x3_columns(-vector3_y, vector3_x, vector3_z);
        c.span_angle[0] = c.span_angle[1] = span;
    });
    auto ball_def = edyn::test::sphere_def(scalar(0.1), {-1, 0, 5});
    ball_def.gravity = vector3_zero;
    ball_def.linvel = {0, 1, 0};
    auto ball_anchor = edyn::test::make_anchor(reg, {0, 0, 5});
    auto ball = make_rigidbody(reg, ball_def);
    make_constraint<cone_constraint>(reg, ball_anchor, ball);
    scalar fastest_swing = 0, fastest_ball = 0;
    auto steps = int(std::lround(2 / get_fixed_dt(reg)));
    for (int i = 0; i < steps; ++i) {
        edyn::test::step(reg);
        fastest_swing = std::max(fastest_swing, length(angular(rod)));
        fastest_ball = std::max(fastest_ball, length(vel(ball)));
    }
    // The rod's end, 1 m out, at 3 m/s, with what the relax pass leaves of the push.
    EXPECT_LT(fastest_swing, 5) << "the cone flung the rod back at " << fastest_swing << " rad/s";
    EXPECT_LT(measure(span, span).excess, scalar(0.01)) << "tilt " << measure(span, span).tilt;
    EXPECT_LT(fastest_ball, 10) << "the cone flung the ball at " << fastest_ball << " m/s";
    EXPECT_TRUE(isfinite(pos(ball)));
}

TEST_F(cone_joint, elliptical_cone_respects_each_span) {
    const auto span0 = to_radians(20), span1 = to_radians(45);
    // Pushed along each span's direction, the rod stops at that span; pushed between them, at
    // the ellipse.
    const vector3 pushes[3]{{5, 0, 0}, {0, 0, 5}, {4, 0, 4}};
    const scalar expected[3]{span0, span1, -1};
    for (int k = 0; k < 3; ++k) {
        registry r;
        std::swap(reg, r);
        attach(reg, edyn::test::test_config());
        make_rod(span0, span1);
        rigidbody_apply_impulse(reg, rod, pushes[k], {0, -rod_half_length, 0});
        scalar worst = -1, largest_tilt = 0;
        for (int i = 0; i < 60 * 2; ++i) {
            edyn::test::step(reg);
            auto m = measure(span0, span1);
            worst = std::max(worst, m.excess);
            largest_tilt = std::max(largest_tilt, m.tilt);
        }
        EXPECT_LT(worst, to_radians(1)) << "push " << k << ": worst excess " << to_degrees(worst) << " deg";
        if (expected[k] > 0) {
            EXPECT_NEAR(largest_tilt, expected[k], to_radians(1))
                << "push " << k << ": largest tilt " << to_degrees(largest_tilt) << " deg, expected "
                << to_degrees(expected[k]);
        }
        detach(reg);
        std::swap(reg, r);
    }
}

TEST_F(cone_joint, wall_reflects_the_normal_velocity_with_restitution) {
    set_gravity(reg, vector3_zero);
    const auto span = to_radians(30);
    const scalar e = scalar(0.5);
    anchor = edyn::test::make_anchor(reg, vector3_zero);
    // A ball 1 m along the cone's axis (+x) moving sideways at 1 m/s: it meets the wall at
    // 30 degrees, where the inward normal is (sin 30, -cos 30, 0).
    auto def = edyn::test::sphere_def(scalar(0.1), {1, 0, 0});
    def.linvel = {0, 1, 0};
    auto ball = make_rigidbody(reg, def);
    make_constraint<cone_constraint>(reg, anchor, ball, [&](cone_constraint &c) {
        c.span_angle[0] = c.span_angle[1] = span;
        c.restitution = e;
    });
    run_for(1);
    const vector3 n{std::sin(span), -std::cos(span), 0};
    const vector3 v0{0, 1, 0};
    auto expected = v0 - n * ((1 + e) * dot(v0, n));
    auto v = vel(ball);
    EXPECT_LT(distance(v, expected), scalar(0.03))
        << "measured (" << v.x << ", " << v.y << ", " << v.z << "), expected (" << expected.x << ", "
        << expected.y << ", " << expected.z << ")";
}

TEST_F(cone_joint, a_rod_held_at_the_apex_rebounds_with_the_restitution_times_its_swing) {
    // The rod hangs from the apex by a point or CV joint, given either way round, and swings
    // about it at w0 (no gravity) into a 30 degree cone. The wall stops its lower end, and the
    // joint holds the upper one, so the rod turns back about the apex: at -e w0, its upper end
    // still at the apex. (Bounced by the wall's row alone, the joint took the apex's share of the
    // push back: -1.01 rad/s for e = 1, -0.26 for e = 0.5, 0 for e = 0.1.)
    const auto span = to_radians(30);
    const scalar w0 = 2;
    enum class apex_joint { point, point_reversed, cvjoint };
    for (auto joint : {apex_joint::point, apex_joint::point_reversed, apex_joint::cvjoint}) {
        for (scalar e : {scalar(0.1), scalar(0.5), scalar(1)}) {
            registry r;
            std::swap(reg, r);
            attach(reg, edyn::test::test_config());
            set_gravity(reg, vector3_zero);
            anchor = edyn::test::make_anchor(reg, apex);
            auto def = edyn::test::box_def({scalar(0.05), rod_half_length, scalar(0.05)},
                                           apex - vector3{0, rod_half_length, 0});
            def.angvel = {0, 0, w0};
            def.linvel = {w0 * rod_half_length, 0, 0};
            rod = make_rigidbody(reg, def);
            const vector3 top{0, rod_half_length, 0};
            if (joint == apex_joint::point) {
                make_constraint<point_constraint>(reg, anchor, rod,
                                                  [&](point_constraint &c) { c.pivot[1] = top; });
            } else if (joint == apex_joint::point_reversed) {
                make_constraint<point_constraint>(reg, rod, anchor,
                                                  [&](point_constraint &c) { c.pivot[0] = top; });
            } else {
                make_constraint<cvjoint_constraint>(reg, anchor, rod, [&](cvjoint_constraint &c) {
                    c.pivot[1] = top;
                    c.frame[0] = c.frame[1] = matrix3x3_columns(-vector3_y, vector3_x, vector3_z);
                });
            }
            make_constraint<cone_constraint>(reg, anchor, rod, [&](cone_constraint &c) {
                c.pivot[1] = {0, -rod_half_length, 0};
                c.frame = matrix3x3_columns(-vector3_y, vector3_x, vector3_z);
                c.span_angle[0] = c.span_angle[1] = span;
                c.restitution = e;
            });
            // The wall is reached after span / w0 = 0.26 s; the rod is back at the vertical
            // 0.26 / e s later.
            run_for(span / w0 + scalar(0.1));
            auto w = angular(rod);
            EXPECT_NEAR(w.z, -e * w0, scalar(0.01) * w0)
                << "joint " << int(joint) << ", e = " << e << ": rebound (" << w.x << ", " << w.y << ", "
                << w.z << ") rad/s";
            EXPECT_LT(std::hypot(w.x, w.y), scalar(1e-3)) << "joint " << int(joint) << ", e = " << e;
            EXPECT_LT(distance(edyn::test::world_pivot(reg, rod, top), apex), scalar(0.002))
                << "joint " << int(joint) << ", e = " << e;
            detach(reg);
            std::swap(reg, r);
        }
    }
}

TEST_F(cone_joint, bump_stop_slows_the_swing_before_the_wall) {
    set_gravity(reg, vector3_zero);
    const auto span = to_radians(30), bump_stop = to_radians(10);
    const scalar k = 50, w0 = scalar(0.3);
    anchor = edyn::test::make_anchor(reg, vector3_zero);
    auto def = edyn::test::sphere_def(scalar(0.1), {1, 0, 0});
    def.linvel = {0, w0, 0};
    auto ball = make_rigidbody(reg, def);
    make_constraint<cone_constraint>(reg, anchor, ball, [&](cone_constraint &c) {
        c.span_angle[0] = c.span_angle[1] = span;
        c.bump_stop_angle = bump_stop;
        c.bump_stop_stiffness = k;
    });
    // Held 1 m from the apex through its centre, the 1 kg ball swings about the apex with
    // I = m L^2 = 1 and does not turn; free, it would also move away from the apex and the
    // spring would act on a growing lever.
    make_constraint<distance_constraint>(reg, anchor, ball, [](distance_constraint &c) { c.distance = 1; });
    scalar largest = 0;
    for (int i = 0; i < 60 * 3; ++i) {
        edyn::test::step(reg);
        largest = std::max(largest, std::atan2(std::abs(pos(ball).y), pos(ball).x));
    }
    // It enters the spring's 10 degrees at w0 and turns back a quarter period of w = sqrt(k / I)
    // later: 0.5 I w0^2 = 0.5 k a^2 gives a = w0 / w (2.43 degrees, the wall is 10 degrees
    // away). The spring is integrated implicitly in sub-steps of h, each of which keeps
    // (1 + (h w)^2)^(-1/2) of the amplitude, over the quarter period's pi / (2 w h) sub-steps:
    // 1.5% of a at the default sub-steps.
    const scalar w = std::sqrt(k / 1), h = get_fixed_dt(reg) / scalar(get_solver_substeps(reg));
    const auto quarter_substeps = pi / (2 * w * h);
    const auto a = w0 / w * std::pow(1 + (h * w) * (h * w), -quarter_substeps / 2);
    const auto expected = span - bump_stop + a;
    // The swing is sampled once a step, so its peak may be missed by up to 0.5 a w^2 (dt / 2)^2,
    // 0.2% of a; half a percent of a bounds that and is a third of the integration's damping.
    EXPECT_NEAR(largest, expected, scalar(0.005) * a)
        << "largest swing " << to_degrees(largest) << " deg, expected " << to_degrees(expected)
        << " deg (without the integration's damping " << to_degrees(span - bump_stop + w0 / w) << " deg)";
    EXPECT_LT(vel(ball).y, 0) << "it should be moving back";
}

TEST(cone_validation, rejects_spans_outside_zero_to_a_right_angle) {
    registry reg;
    attach(reg, edyn::test::test_config());
    auto a = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), vector3_zero));
    auto b = make_rigidbody(reg, edyn::test::sphere_def(scalar(0.5), {2, 0, 0}));
    auto alive = reg.alive();
    try {
        make_constraint<cone_constraint>(reg, a, b, [](cone_constraint &c) { c.span_angle[1] = 2; });
        ADD_FAILURE() << "expected std::invalid_argument";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("make_constraint<cone_constraint>: span_angle[1]"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(make_constraint<cone_constraint>(reg, a, b, [](cone_constraint &c) { c.span_angle[0] = 0; }),
                 std::invalid_argument);
    EXPECT_THROW(make_constraint<cone_constraint>(reg, a, b, [](cone_constraint &c) { c.restitution = 2; }),
                 std::invalid_argument);
    EXPECT_THROW(make_constraint<cone_constraint>(reg, a, b,
                                                  [](cone_constraint &c) {
                                                      c.frame =
                                                          matrix3x3_columns(vector3_x, vector3_x, vector3_z);
                                                  }),
                 std::invalid_argument);
    EXPECT_EQ(reg.alive(), alive);
    detach(reg);
}
