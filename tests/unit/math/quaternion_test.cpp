#include "edyn/math/math.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/transform.hpp"
#include "math_test_helpers.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace edyn;
using namespace math_test;

namespace {

// q and -q are the same rotation.
void expect_same_rotation(const quaternion &a, const quaternion &b, scalar t = tol) {
    EXPECT_NEAR(std::abs(dot(a, b)), 1, t)
        << "(" << a.x << ", " << a.y << ", " << a.z << ", " << a.w << ") vs (" << b.x << ", " << b.y << ", "
        << b.z << ", " << b.w << ")";
}
} // namespace

TEST(quaternion_test, layout_is_x_y_z_w) {
    quaternion q{1, 2, 3, 4};
    EXPECT_EQ(q[0], 1);
    EXPECT_EQ(q[1], 2);
    EXPECT_EQ(q[2], 3);
    EXPECT_EQ(q[3], 4);
    EXPECT_EQ(quaternion_identity, (quaternion{0, 0, 0, 1}));
    static_assert(offsetof(quaternion, w) == 3 * sizeof(scalar));
}

TEST(quaternion_test, axis_angle_rotates_vectors) {
    auto q = quaternion_axis_angle(vector3_y, to_radians(90));
    expect_near(rotate(q, vector3_x), -vector3_z);
    expect_near(rotate(q, vector3_z), vector3_x);
    expect_near(rotate(q, vector3_y), vector3_y);
    EXPECT_NEAR(length(q), 1, tol);
    EXPECT_NEAR(quaternion_angle(q), half_pi, 1e-4);
    expect_near(quaternion_axis(q), vector3_y);
    expect_near(quaternion_axis(quaternion_identity), vector3_x);
}

TEST(quaternion_test, rotate_preserves_length_and_matches_product_form) {
    auto q = normalize(quaternion{0.3, -0.5, 0.2, 0.8});
    vector3 v{1.5, -2, 0.7};
    auto r = rotate(q, v);
    EXPECT_NEAR(length(r), length(v), 1e-4);
    // q v q* with v as a pure quaternion.
    auto p = q * quaternion{v.x, v.y, v.z, 0} * conjugate(q);
    expect_near(r, vector3{p.x, p.y, p.z}, 1e-4);
}

TEST(quaternion_test, multiply_composes_right_to_left) {
    auto a = quaternion_axis_angle(vector3_z, to_radians(90));
    auto b = quaternion_axis_angle(vector3_x, to_radians(90));
    vector3 v{0, 1, 0};
    expect_near(rotate(a * b, v), rotate(a, rotate(b, v)));
    auto c = a;
    c *= b;
    expect_same_rotation(c, a * b);
    expect_same_rotation(a * quaternion_identity, a);
}

TEST(quaternion_test, conjugate_and_inverse) {
    auto q = normalize(quaternion{1, 2, 3, 4});
    EXPECT_EQ(conjugate(q), (quaternion{-q.x, -q.y, -q.z, q.w}));
    expect_same_rotation(q * conjugate(q), quaternion_identity);
    quaternion s{0, 0, 0, 2};
    auto inv = inverse(s);
    EXPECT_NEAR(inv.w, 0.5, tol);
    vector3 v{1, 2, 3};
    expect_near(rotate(conjugate(q), rotate(q, v)), v, 1e-4);
}

TEST(quaternion_test, normalize_and_is_unit) {
    quaternion q{1, 2, 3, 4};
    EXPECT_FALSE(is_unit(q));
    auto n = normalize(q);
    EXPECT_NEAR(length(n), 1, tol);
    EXPECT_NEAR(length_sqr(n), 1, tol);
    EXPECT_TRUE(is_unit(n));
    EXPECT_FALSE(isfinite(quaternion{0, std::nanf(""), 0, 1}));
    EXPECT_TRUE(isfinite(n));
}

TEST(quaternion_test, slerp_interpolates_along_the_arc) {
    auto q0 = quaternion_identity;
    auto q1 = quaternion_axis_angle(vector3_z, to_radians(90));
    expect_same_rotation(slerp(q0, q1, 0), q0);
    expect_same_rotation(slerp(q0, q1, 1), q1);
    auto half = slerp(q0, q1, 0.5);
    expect_same_rotation(half, quaternion_axis_angle(vector3_z, to_radians(45)));
    EXPECT_NEAR(length(half), 1, tol);
    // Takes the shorter arc when q1 is given with the opposite sign.
    expect_same_rotation(slerp(q0, -q1, 0.5), quaternion_axis_angle(vector3_z, to_radians(45)));
    // Nearly equal inputs do not divide by zero.
    auto near = slerp(q0, quaternion_axis_angle(vector3_z, 1e-7), 0.5);
    EXPECT_TRUE(isfinite(near));
}

TEST(quaternion_test, integrate_rotates_by_angular_velocity_times_dt) {
    // 1 rad/s about y for 60 steps of 1/60 s is one radian.
    auto q = quaternion_identity;
    vector3 w{0, 1, 0};
    for (int i = 0; i < 60; ++i) {
        q = integrate(q, w, scalar(1) / 60);
    }
    expect_same_rotation(q, quaternion_axis_angle(vector3_y, 1), 1e-5);
    EXPECT_NEAR(length(q), 1, tol);
    // Zero angular velocity leaves the orientation alone.
    EXPECT_EQ(integrate(q, vector3_zero, 1), q);
    // angular_velocity inverts integrate.
    auto q0 = normalize(quaternion{0.1, 0.2, 0.3, 0.9});
    vector3 w1{0.4, -1.2, 2};
    auto q1 = integrate(q0, w1, scalar(0.1));
    expect_near(angular_velocity(q0, q1, scalar(0.1)), w1, 1e-3);
}

TEST(quaternion_test, shortest_arc_maps_a_onto_b) {
    auto a = normalize(vector3{1, 2, 3});
    auto b = normalize(vector3{-2, 0.5, 1});
    expect_near(rotate(shortest_arc(a, b), a), b, 1e-4);
    // Opposite vectors still give a valid half turn.
    auto q = shortest_arc(vector3_x, -vector3_x);
    EXPECT_NEAR(length(q), 1, tol);
    expect_near(rotate(q, vector3_x), -vector3_x, 1e-4);
}

TEST(transform_test, world_and_object_space_are_inverse) {
    vector3 pos{1, 2, 3};
    auto orn = quaternion_axis_angle(vector3_z, to_radians(90));
    auto world = to_world_space(vector3_x, pos, orn);
    expect_near(world, vector3{1, 3, 3});
    expect_near(to_object_space(world, pos, orn), vector3_x);
}
