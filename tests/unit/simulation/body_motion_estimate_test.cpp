#include <cmath>
#include <edyn/edyn.hpp>
#include <edyn/simulation/body_motion_estimate.hpp>
#include <gtest/gtest.h>
#include <limits>

// What the step tells the broadphase of a body's coming motion.

namespace edyn {
namespace {

rigidbody_def box_body(rigidbody_kind kind, const vector3 &v, const vector3 &w) {
    rigidbody_def def;
    def.kind = kind;
    def.shape = box_shape{{scalar(0.5), scalar(0.25), scalar(0.25)}};
    def.position = {1, 2, 3};
    if (kind != rigidbody_kind::rb_static) {
        def.linvel = v;
        def.angvel = w;
    }
    return def;
}

TEST(body_motion_estimate, a_dynamic_body_moves_by_its_velocity_and_turns_out_by_its_spin) {
    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    settings s;
    s.fixed_dt = scalar(1) / 50;
    auto e = make_rigidbody(reg, box_body(rigidbody_kind::rb_dynamic, {3, -4, 0}, {0, 0, 2}));
    auto &aabb = reg.get<AABB>(e);
    proxy_motion_estimate estimate;
    ASSERT_TRUE(estimate_body_motion(s, reg, e, aabb, estimate));
    EXPECT_NEAR(estimate.displacement.x, scalar(0.06), 1e-6);
    EXPECT_NEAR(estimate.displacement.y, scalar(-0.08), 1e-6);
    EXPECT_EQ(estimate.displacement.z, 0);
    // The box's AABB is itself, centred on its centre of mass, and its bounding sphere's radius
    // its half diagonal (0.61 m): a turn of 0.04 rad moves no point farther than 0.04 x 0.61 m.
    auto half_diagonal = std::sqrt(scalar(0.25) + scalar(0.0625) * 2);
    EXPECT_NEAR(estimate.reach, scalar(0.04) * half_diagonal, 1e-6);

    // Spinning six radians a step, the box still stays in that sphere: its nearest sides, 0.25 m
    // from the centre, move out by no more than the rest of the radius.
    reg.replace<angvel>(e, vector3{0, 300, 0});
    ASSERT_TRUE(estimate_body_motion(s, reg, e, aabb, estimate));
    EXPECT_NEAR(estimate.reach, half_diagonal - scalar(0.25), 1e-6);

    // A spinning sphere's AABB stays where it is.
    auto def = rigidbody_def{};
    def.shape = sphere_shape{scalar(0.3)};
    def.angvel = {5, 7, 1};
    auto ball = make_rigidbody(reg, def);
    ASSERT_TRUE(estimate_body_motion(s, reg, ball, reg.get<AABB>(ball), estimate));
    EXPECT_NEAR(estimate.reach, 0, 1e-6);

    // Through the bound estimator, as the step uses it.
    const body_motion_estimate source(s, reg);
    auto estimator = source.estimator();
    proxy_motion_estimate again;
    ASSERT_TRUE(estimator(reg, e, aabb, again));
    EXPECT_NEAR(again.reach, half_diagonal - scalar(0.25), 1e-6);
    detach(reg);
}

TEST(body_motion_estimate, kinematic_static_and_broken_bodies_are_left_to_the_broadphase) {
    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    settings s;
    proxy_motion_estimate estimate;
    for (auto kind : {rigidbody_kind::rb_kinematic, rigidbody_kind::rb_static}) {
        auto e = make_rigidbody(reg, box_body(kind, {1, 0, 0}, {0, 1, 0}));
        EXPECT_FALSE(estimate_body_motion(s, reg, e, reg.get<AABB>(e), estimate));
    }
    auto e = make_rigidbody(reg, box_body(rigidbody_kind::rb_dynamic, {1, 0, 0}, {0, 1, 0}));
    reg.replace<linvel>(e, vector3{std::numeric_limits<scalar>::quiet_NaN(), 0, 0});
    EXPECT_FALSE(estimate_body_motion(s, reg, e, reg.get<AABB>(e), estimate));
    reg.replace<linvel>(e, vector3_zero);
    reg.replace<angvel>(e, vector3{std::numeric_limits<scalar>::infinity(), 0, 0});
    EXPECT_FALSE(estimate_body_motion(s, reg, e, reg.get<AABB>(e), estimate));
    detach(reg);
}

} // namespace
} // namespace edyn
