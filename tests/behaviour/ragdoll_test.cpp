// Rag dolls: joints that hold and limits that stay when they fall and pile up, and piles that
// come to rest, at the default 60 Hz.
#include "joints_support.hpp"
#include <edyn_scenes/pivot_separation.hpp>
#include <edyn_scenes/scenes.hpp>

using namespace edyn;
using edyn::test::world_fixture;
using edyn::test::world_pivot;

namespace {

// How far the cone's point is beyond its elliptical wall, in radians (negative inside).
scalar cone_excess(const registry &reg, const cone_constraint &c) {
    auto frame = to_matrix3x3(reg.get<orientation>(c.body[0])) * c.frame;
    auto r = world_pivot(reg, c.body[1], c.pivot[1]) - world_pivot(reg, c.body[0], c.pivot[0]);
    auto x = dot(r, frame.column(0)), y = dot(r, frame.column(1)), z = dot(r, frame.column(2));
    auto rho = std::hypot(y, z);
    if (rho < scalar(1e-9)) return -c.span_angle[0];
    auto t0 = std::tan(c.span_angle[0]), t1 = std::tan(c.span_angle[1]);
    auto wall = std::atan(t0 * t1 / std::hypot(t1 * y / rho, t0 * z / rho));
    return std::atan2(rho, x) - wall;
}

// How far any angular limit is exceeded, in radians: hinge angles, CV twists, cones.
struct limit_report {
    scalar hinge{-1}, twist{-1}, cone{-1};
    scalar knee_min{0}; // most negative knee angle (bent backwards)
};

void measure_limits(const registry &reg, const ragdoll_entities &e, limit_report &report) {
    reg.view<hinge_constraint>().each([&](const hinge_constraint &c) {
        report.hinge = std::max({report.hinge, c.angle_min - c.angle, c.angle - c.angle_max});
    });
    reg.view<cvjoint_constraint>().each([&](const cvjoint_constraint &c) {
        report.twist = std::max({report.twist, c.twist_min - c.twist_angle, c.twist_angle - c.twist_max});
    });
    reg.view<cone_constraint>().each(
        [&](const cone_constraint &c) { report.cone = std::max(report.cone, cone_excess(reg, c)); });
    for (auto knee : {e.knee_hinge_left, e.knee_hinge_right})
        report.knee_min = std::min(report.knee_min, reg.get<hinge_constraint>(knee).angle);
}

bool all_finite(const registry &reg) {
    bool ok = true;
    reg.view<rigidbody_tag>().each([&](entity e) {
        ok = ok && isfinite(vector3(reg.get<position>(e))) && isfinite(reg.get<orientation>(e)) &&
             isfinite(vector3(reg.get<linvel>(e))) && isfinite(vector3(reg.get<angvel>(e)));
    });
    return ok;
}

std::size_t awake_bodies(const registry &reg) {
    std::size_t awake = 0;
    reg.view<rigidbody_tag, dynamic_tag>().each([&](entity e) { awake += !reg.all_of<sleeping_tag>(e); });
    return awake;
}

using ragdolls = world_fixture;

} // namespace

TEST_F(ragdolls, pile_of_ten_settles_with_joints_together_and_falls_asleep) {
    scenes::make_ground(reg);
    // Three layers; the top one falls about 5 m onto the others.
    auto pile = scenes::make_ragdoll_pile(reg, 10);
    ASSERT_EQ(pile.size(), 10u);
    const double time_limit = 10;
    auto dt = double(get_fixed_dt(reg));
    scalar worst = 0;
    double worst_at = 0, asleep_at = -1;
    for (int i = 0; i < int(time_limit / dt) && asleep_at < 0; ++i) {
        edyn::test::step(reg);
        auto t = (i + 1) * dt;
        ASSERT_TRUE(all_finite(reg)) << "a body is not finite at t = " << t << " s";
        if (auto separation = scenes::max_pivot_separation(reg); separation > worst) {
            worst = separation;
            worst_at = t;
        }
        if (awake_bodies(reg) == 0) asleep_at = t;
    }
    EXPECT_LT(worst, scalar(0.01)) << "largest joint separation " << worst << " m at t = " << worst_at
                                   << " s";
    EXPECT_GT(asleep_at, 0) << awake_bodies(reg) << " bodies still awake after " << time_limit << " s";
    // The pile lies on the ground, nothing sank through it or flew off.
    for (auto &ragdoll : pile) {
        for (auto body : ragdoll.bodies()) {
            EXPECT_GT(pos(body).y, -scalar(0.02)) << "a part sank to y = " << pos(body).y;
            EXPECT_LT(pos(body).y, scalar(2.5)) << "a part rests at y = " << pos(body).y;
        }
    }
}

TEST_F(ragdolls, falling_from_standing_keeps_every_joint_within_its_limits) {
    scenes::make_ground(reg);
    // Standing on the ground, leaning back a little: it falls on its back, and its weight bends
    // the knees backwards (without their limit they fold by 150 degrees the wrong way).
    ragdoll_simple_def def;
    def.position = {0, scalar(0.01), 0};
    def.orientation = quaternion_axis_angle(vector3_x, to_radians(-5));
    auto e = make_ragdoll(reg, def);
    limit_report falling, resting;
    scalar separation = 0;
    for (int i = 0; i < 60 * 4; ++i) {
        edyn::test::step(reg);
        ASSERT_TRUE(all_finite(reg)) << "a body is not finite after step " << i + 1;
        measure_limits(reg, e, i < 60 * 3 ? falling : resting);
        separation = std::max(separation, scenes::max_pivot_separation(reg));
    }
    EXPECT_LT(pos(e.head).y, scalar(0.4)) << "did not fall: head at y = " << pos(e.head).y;
    EXPECT_LT(separation, scalar(0.01)) << "largest joint separation " << separation << " m";
    // Limits are soft: hit by the falling body they give a little, and most where a light part
    // stops a heavy one (the neck and head hitting the ground stop the torso).
    EXPECT_GT(falling.knee_min, to_radians(-5 - 4))
        << "a knee bent backwards by " << to_degrees(-falling.knee_min) << " deg; limit 5";
    EXPECT_LT(falling.hinge, to_radians(8))
        << "a hinge passed its limit by " << to_degrees(falling.hinge) << " deg";
    EXPECT_LT(falling.twist, to_radians(8))
        << "a twist passed its limit by " << to_degrees(falling.twist) << " deg";
    // The worst is the head's cone (25 by 20 degrees), left by 26.2 degrees 0.93 s in, as the
    // head lands at 5.6 m/s and the body drives the neck on: far more than the other limits
    // give, and the figure to bring down. (21.3 degrees before the cone's correction was held
    // to max_correction_speed, which keeps a point found far outside from being flung back.)
    // The allowance is that figure plus 2 degrees, its spread under rounding-sized changes to
    // the fall (0.2 degrees for a 0.01 degree change of the lean, 2 degrees for 0.05), so that
    // any growth shows.
    const scalar cone_overshoot_measured = to_radians(scalar(26.2)), cone_overshoot_margin = to_radians(2);
    EXPECT_LT(falling.cone, cone_overshoot_measured + cone_overshoot_margin)
        << "a cone was left by " << to_degrees(falling.cone) << " deg; measured 26.2 deg when this was set";
    // Lying still, the limits hold it.
    for (auto [name, excess] : {std::pair{"hinge", resting.hinge}, std::pair{"twist", resting.twist},
                                std::pair{"cone", resting.cone}}) {
        EXPECT_LT(excess, to_radians(4))
            << "at rest a " << name << " is " << to_degrees(excess) << " deg past its limit";
    }
}
