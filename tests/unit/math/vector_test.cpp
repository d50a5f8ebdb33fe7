#include "edyn/math/math.hpp"
#include "edyn/math/vector2.hpp"
#include "edyn/math/vector3.hpp"
#include "math_test_helpers.hpp"
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <utility>

using namespace edyn;
using namespace math_test;

TEST(vector3_test, constants) {
    EXPECT_EQ(vector3_zero, (vector3{0, 0, 0}));
    EXPECT_EQ(vector3_x, (vector3{1, 0, 0}));
    EXPECT_EQ(vector3_y, (vector3{0, 1, 0}));
    EXPECT_EQ(vector3_z, (vector3{0, 0, 1}));
    EXPECT_EQ(vector3_one, (vector3{1, 1, 1}));
}

TEST(vector3_test, arithmetic) {
    vector3 a{1, 2, 3}, b{4, -5, 6};
    EXPECT_EQ(a + b, (vector3{5, -3, 9}));
    EXPECT_EQ(a - b, (vector3{-3, 7, -3}));
    EXPECT_EQ(-a, (vector3{-1, -2, -3}));
    EXPECT_EQ(a * 2, (vector3{2, 4, 6}));
    EXPECT_EQ(2 * a, (vector3{2, 4, 6}));
    EXPECT_EQ(a * b, (vector3{4, -10, 18}));
    EXPECT_EQ(b / 2, (vector3{2, -2.5, 3}));
    EXPECT_EQ(b / a, (vector3{4, -2.5, 2}));
    auto c = a;
    c += b;
    c -= a;
    EXPECT_EQ(c, b);
    c *= 2;
    EXPECT_EQ(c, (vector3{8, -10, 12}));
    c /= 4;
    EXPECT_EQ(c, (vector3{2, -2.5, 3}));
    c = a;
    c *= b;
    EXPECT_EQ(c, a * b);
    EXPECT_EQ(a[0], 1);
    EXPECT_EQ(a[1], 2);
    EXPECT_EQ(a[2], 3);
    a[1] = 7;
    EXPECT_EQ(a.y, 7);
}

TEST(vector3_test, dot_and_cross) {
    vector3 a{1, 2, 3}, b{4, -5, 6};
    EXPECT_FLOAT_EQ(dot(a, b), 4 - 10 + 18);
    EXPECT_EQ(cross(vector3_x, vector3_y), vector3_z);
    EXPECT_EQ(cross(vector3_y, vector3_z), vector3_x);
    EXPECT_EQ(cross(vector3_z, vector3_x), vector3_y);
    auto c = cross(a, b);
    EXPECT_NEAR(dot(c, a), 0, tol);
    EXPECT_NEAR(dot(c, b), 0, tol);
    expect_near(cross(a, b), -cross(b, a));
    // |a x b|^2 = |a|^2 |b|^2 - (a.b)^2 (Lagrange's identity).
    EXPECT_NEAR(length_sqr(c), length_sqr(a) * length_sqr(b) - dot(a, b) * dot(a, b), 1e-3);
}

TEST(vector3_test, length_and_normalize) {
    vector3 v{3, 4, 12};
    EXPECT_FLOAT_EQ(length_sqr(v), 169);
    EXPECT_FLOAT_EQ(length(v), 13);
    EXPECT_FLOAT_EQ(distance(v, vector3_zero), 13);
    EXPECT_FLOAT_EQ(distance_sqr(v, vector3{3, 4, 0}), 144);
    auto n = normalize(v);
    EXPECT_NEAR(length(n), 1, tol);
    expect_near(n, v / 13);

    auto w = v;
    EXPECT_TRUE(try_normalize(w));
    expect_near(w, n);
    auto z = vector3_zero;
    EXPECT_FALSE(try_normalize(z));
    EXPECT_EQ(z, vector3_zero);
}

TEST(vector3_test, try_normalize_across_stays_orthogonal_when_nearly_along_the_normal) {
    auto n = normalize(vector3{scalar(0.3), 1, scalar(-0.2)});
    auto t = normalize(cross(n, vector3{1, scalar(0.1), scalar(0.7)}));
    // The orthogonal part from a thousandth to all of v: what is left along n after normalising
    // stays at rounding size however short that part was (one projection leaves up to ~1e-3).
    for (auto part : {scalar(1), scalar(1e-1), scalar(1e-2), scalar(1e-3)}) {
        auto v = n * 10 + t * (10 * part);
        ASSERT_TRUE(try_normalize_across(v, n)) << part;
        EXPECT_NEAR(length(v), 1, tol) << part;
        EXPECT_NEAR(dot(v, n), 0, 1e-6) << part;
        // The direction itself is only as good as v's rounding over the orthogonal part.
        EXPECT_NEAR(dot(v, t), 1, 1e-3) << part;
    }
    auto along = n * 5;
    EXPECT_FALSE(try_normalize_across(along, n));
    // An axis rotated by a quaternion rounded off unit length is a little long: what a vector
    // along it leaves across it is then along it too, and gives no direction.
    auto long_n = n * scalar(1 + 1e-6);
    auto unit = n;
    EXPECT_FALSE(try_normalize_across(unit, long_n));
    auto zero = vector3_zero;
    EXPECT_FALSE(try_normalize_across(zero, n));
}

TEST(vector3_test, min_max_abs) {
    vector3 a{1, -2, 3}, b{-4, 5, 0};
    EXPECT_EQ(min(a, b), (vector3{-4, -2, 0}));
    EXPECT_EQ(max(a, b), (vector3{1, 5, 3}));
    EXPECT_EQ(abs(a), (vector3{1, 2, 3}));
    EXPECT_EQ(max_component(a), 3);
    EXPECT_EQ(min_component(a), -2);
    EXPECT_EQ(max_index(a), 2);
    EXPECT_EQ(min_index(a), 1);
    EXPECT_EQ(max_index(vector3{2, 2, 1}), 0);
}

TEST(vector3_test, isfinite_detects_nan_and_inf) {
    EXPECT_TRUE(isfinite(vector3{1, 2, 3}));
    EXPECT_FALSE(isfinite(vector3{std::numeric_limits<scalar>::quiet_NaN(), 0, 0}));
    EXPECT_FALSE(isfinite(vector3{0, std::numeric_limits<scalar>::infinity(), 0}));
}

TEST(vector3_test, project_plane_removes_normal_component) {
    auto p = project_plane(vector3{1, 2, 3}, vector3_y);
    EXPECT_EQ(p, (vector3{1, 0, 3}));
}

TEST(vector3_test, plane_space_builds_right_handed_orthonormal_basis) {
    const vector3 normals[] = {vector3_x,
                               vector3_y,
                               vector3_z,
                               -vector3_z,
                               -vector3_x,
                               normalize(vector3{1, 1, 1}),
                               normalize(vector3{0.1, -0.3, 0.95}),
                               normalize(vector3{-0.7, 0.7, 0.1}),
                               normalize(vector3{0, 0.7071, 0.7072})};
    for (auto n : normals) {
        vector3 t0, t1;
        plane_space(n, t0, t1);
        EXPECT_NEAR(length(t0), 1, tol);
        EXPECT_NEAR(length(t1), 1, tol);
        EXPECT_NEAR(dot(t0, n), 0, tol);
        EXPECT_NEAR(dot(t1, n), 0, tol);
        EXPECT_NEAR(dot(t0, t1), 0, tol);
        expect_near(cross(t0, t1), n);
    }
}

TEST(vector2_test, operations) {
    vector2 a{3, 4}, b{-1, 2};
    EXPECT_FLOAT_EQ(length(a), 5);
    EXPECT_FLOAT_EQ(length_sqr(a), 25);
    EXPECT_EQ(a + b, (vector2{2, 6}));
    EXPECT_EQ(a - b, (vector2{4, 2}));
    EXPECT_EQ(-b, (vector2{1, -2}));
    EXPECT_EQ(a * 2, (vector2{6, 8}));
    EXPECT_EQ(2 * a, (vector2{6, 8}));
    EXPECT_EQ(a / 2, (vector2{1.5, 2}));
    EXPECT_FLOAT_EQ(dot(a, b), 5);
    EXPECT_FLOAT_EQ(perp_product(vector2_x, vector2_y), 1);
    EXPECT_EQ(orthogonal(vector2_x), vector2_y);
    EXPECT_NEAR(length(normalize(a)), 1, tol);
    EXPECT_FLOAT_EQ(distance(a, vector2_zero), 5);
    EXPECT_FLOAT_EQ(distance_sqr(a, vector2_zero), 25);
    auto c = a;
    c += b;
    c -= b;
    c *= 2;
    EXPECT_EQ(c, (vector2{6, 8}));
    EXPECT_EQ(a[0], 3);
    EXPECT_EQ(a[1], 4);
}

TEST(math_test, angle_conversions) {
    EXPECT_NEAR(to_radians(180), pi, tol);
    EXPECT_NEAR(to_radians(90), half_pi, tol);
    EXPECT_NEAR(to_degrees(pi), 180, 1e-4);
    EXPECT_NEAR(to_degrees(to_radians(37)), 37, 1e-4);
    // 1 Nm per degree is 57.2958 Nm per radian.
    EXPECT_NEAR(to_Nm_per_radian(1), 57.29578, 1e-3);
}

TEST(math_test, lerp_scalars_and_vectors) {
    EXPECT_FLOAT_EQ(lerp(scalar(2), scalar(4), scalar(0.25)), 2.5);
    auto v = lerp(vector3{0, 0, 0}, vector3{2, 4, -8}, scalar(0.5));
    expect_near(v, vector3{1, 2, -4});
    EXPECT_EQ(lerp(vector3_x, vector3_y, 0), vector3_x);
    EXPECT_EQ(lerp(vector3_x, vector3_y, 1), vector3_y);
}

TEST(math_test, normalize_angle_wraps_into_half_open_range) {
    EXPECT_NEAR(normalize_angle(3 * pi), -pi, tol);
    EXPECT_NEAR(normalize_angle(-half_pi), -half_pi, tol);
    EXPECT_NEAR(normalize_angle(pi2 + 0.5), 0.5, 1e-4);
    EXPECT_NEAR(normalize_angle(-pi2 - 0.5), -0.5, 1e-4);
}

TEST(vector2_test, index_outside_0_and_1_is_refused_in_debug_builds) {
    vector2 v{3, 4};
    EXPECT_EQ(v[0], 3);
    EXPECT_EQ(v[1], 4);
#if defined(EDYN_ASSERTIONS) && EDYN_ASSERTIONS
    EXPECT_DEATH((void)v[2], "i >= 0 && i < 2");
    EXPECT_DEATH((void)std::as_const(v)[-1], "i >= 0 && i < 2");
#else
    GTEST_SKIP() << "EDYN_ASSERT is compiled out in this build";
#endif
}
