#include "edyn/math/math.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "math_test_helpers.hpp"
#include <gtest/gtest.h>

using namespace edyn;
using namespace math_test;

namespace {

const matrix3x3 m = matrix3x3_rows({2, -1, 0}, {1, 3, 4}, {0.5, 0, 1});
} // namespace

TEST(matrix3x3_test, rows_columns_and_identity) {
    EXPECT_EQ(m[1], (vector3{1, 3, 4}));
    EXPECT_EQ(m.column(0), (vector3{2, 1, 0.5}));
    auto c = matrix3x3_columns({1, 2, 3}, {4, 5, 6}, {7, 8, 9});
    EXPECT_EQ(c.column(1), (vector3{4, 5, 6}));
    EXPECT_EQ(c[0], (vector3{1, 4, 7}));
    EXPECT_EQ((matrix3x3_identity * vector3{1, 2, 3}), (vector3{1, 2, 3}));
    EXPECT_EQ(get_diagonal(m), (vector3{2, 3, 1}));
}

TEST(matrix3x3_test, multiply_and_transpose) {
    vector3 v{1, -2, 0.5};
    expect_near(m * v, vector3{4, -3, 1});
    expect_near(v * m, transpose(m) * v);
    expect_near(m * matrix3x3_identity, m);
    auto mm = m * m;
    expect_near(mm * v, m * (m * v), 1e-4);
    expect_near(transpose(transpose(m)), m);
    EXPECT_EQ(transpose(m)[0], m.column(0));
    expect_near((m + m) - m, m);
    expect_near(m * 2, 2 * m);
    auto a = m;
    a += m;
    expect_near(a, m * 2);
    a = m;
    a *= matrix3x3_identity;
    expect_near(a, m);
}

TEST(matrix3x3_test, inverse_and_determinant) {
    EXPECT_NEAR(determinant(m), 2 * 3 + 1 * (1 - 2) + 0, tol);
    expect_near(inverse(m) * m, matrix3x3_identity, 1e-5);
    expect_near(m * inverse(m), matrix3x3_identity, 1e-5);
    auto d = diagonal_matrix({2, 4, 8});
    expect_near(inverse(d), diagonal_matrix({0.5, 0.25, 0.125}));
}

// An asteroid's inertia (1e19 kg m^2 and more) and a sand grain's (1e-13): their determinants
// overflow a float or fall below its smallest normal value, yet the inverses are ordinary floats.
TEST(matrix3x3_test, inverse_of_very_large_and_very_small_matrices) {
    auto r = to_matrix3x3(normalize(quaternion{scalar(0.3), scalar(-0.2), scalar(0.1), 1}));
    for (scalar size : {scalar(1e13), scalar(1e20), scalar(1e30), scalar(1e-13), scalar(1e-20)}) {
        auto m = r * diagonal_matrix(vector3{1, 2, 3} * size) * transpose(r);
        auto inv = inverse(m);
        // inv * m is the identity, and inv scales as 1 / size.
        expect_near(inv * m, matrix3x3_identity, 1e-5);
        expect_near(inv * size, r * diagonal_matrix({1, scalar(0.5), scalar(1) / 3}) * transpose(r), 1e-5);
    }
}

TEST(matrix3x3_test, skew_matrix_is_cross_product) {
    vector3 a{1, 2, 3}, b{-4, 0.5, 2};
    expect_near(skew_matrix(a) * b, cross(a, b));
    expect_near(transpose(skew_matrix(a)), skew_matrix(-a));
}

TEST(matrix3x3_test, quaternion_to_matrix_and_back) {
    auto q = normalize(quaternion{0.2, -0.4, 0.1, 0.85});
    auto r = to_matrix3x3(q);
    vector3 v{0.3, 1.7, -2.2};
    expect_near(r * v, rotate(q, v), 1e-5);
    expect_near(r * transpose(r), matrix3x3_identity, 1e-5);
    EXPECT_NEAR(determinant(r), 1, 1e-5);
    // Every branch of the conversion: small and large rotations about each axis.
    for (auto axis : {vector3_x, vector3_y, vector3_z, normalize(vector3{1, 1, 1})}) {
        for (auto angle : {scalar(0.1), scalar(2), scalar(3.1)}) {
            auto qa = quaternion_axis_angle(axis, angle);
            auto back = to_quaternion(to_matrix3x3(qa));
            EXPECT_NEAR(std::abs(dot(back, qa)), 1, 1e-5) << "angle " << angle;
        }
    }
    EXPECT_EQ(to_matrix3x3(quaternion_identity), matrix3x3_identity);
}

TEST(matrix3x3_test, rotate_diagonal_transforms_a_tensor) {
    // A tensor diag(1, 2, 3) rotated 90 degrees about z swaps its x and y moments.
    auto r = to_matrix3x3(quaternion_axis_angle(vector3_z, half_pi));
    auto t = rotate_diagonal(r, {1, 2, 3});
    expect_near(get_diagonal(t), vector3{2, 1, 3}, 1e-5);
}
