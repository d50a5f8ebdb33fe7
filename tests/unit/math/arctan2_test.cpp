#include "src/math/arctan2.hpp"
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>

using edyn::scalar;
using edyn::detail::arctan2;

namespace {

// The exact angle, computed in double.
double exact(scalar y, scalar x) { return std::atan2(double(y), double(x)); }

constexpr double max_error = 3e-7; // radians

} // namespace

TEST(arctan2, within_3e_7_rad_all_around_the_circle) {
    // Every direction in steps of 1e-4 rad, at lengths from 1e-6 to 1e6: the folding at pi/8,
    // pi/4, pi/2 and pi and the sign of y are all crossed.
    auto worst = 0.0;
    for (auto length : {1e-6, 1e-3, 1.0, 7.5, 1e6}) {
        for (auto a = -3.14159; a < 3.14159; a += 1e-4) {
            auto x = scalar(length * std::cos(a)), y = scalar(length * std::sin(a));
            worst = std::max(worst, std::abs(double(arctan2(y, x)) - exact(y, x)));
        }
    }
    EXPECT_LT(worst, max_error);

    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-2, 2);
    for (int i = 0; i < 100000; ++i) {
        auto x = coordinate(rng), y = coordinate(rng);
        ASSERT_NEAR(double(arctan2(y, x)), exact(y, x), max_error) << "y " << y << ", x " << x;
    }
}

TEST(arctan2, the_axes_and_diagonals_come_out_at_their_angles) {
    const double pi = 3.14159265358979323846;
    EXPECT_EQ(arctan2(0, 1), 0);
    EXPECT_NEAR(arctan2(1, 0), pi / 2, max_error);
    EXPECT_NEAR(arctan2(-1, 0), -pi / 2, max_error);
    EXPECT_NEAR(arctan2(1, 1), pi / 4, max_error);
    EXPECT_NEAR(arctan2(-1, -1), -3 * pi / 4, max_error);
    EXPECT_NEAR(arctan2(0, -1), pi, max_error);
}

TEST(arctan2, zeros_infinities_and_nans_are_std_atan2_s) {
    const auto inf = std::numeric_limits<scalar>::infinity();
    const auto nan = std::numeric_limits<scalar>::quiet_NaN();
    for (auto y : {scalar(0), -scalar(0), scalar(1), -scalar(1), inf, -inf}) {
        for (auto x : {scalar(0), -scalar(0), scalar(1), -scalar(1), inf, -inf}) {
            auto expected = std::atan2(y, x);
            auto got = arctan2(y, x);
            EXPECT_NEAR(got, expected, max_error) << "y " << y << ", x " << x;
            EXPECT_EQ(std::signbit(got), std::signbit(expected)) << "y " << y << ", x " << x;
        }
    }
    EXPECT_TRUE(std::isnan(arctan2(nan, 1)));
    EXPECT_TRUE(std::isnan(arctan2(1, nan)));
}
