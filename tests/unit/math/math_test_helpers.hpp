#ifndef EDYN_TESTS_UNIT_MATH_MATH_TEST_HELPERS_HPP
#define EDYN_TESTS_UNIT_MATH_MATH_TEST_HELPERS_HPP

// Shared by the math tests: a tolerance and element-wise comparisons that print the vector.

#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/vector2.hpp"
#include "edyn/math/vector3.hpp"
#include <gtest/gtest.h>

namespace math_test {

using namespace edyn;

constexpr scalar tol = scalar(1e-5);

inline void expect_near(const vector3 &a, const vector3 &b, scalar t = tol) {
    EXPECT_NEAR(a.x, b.x, t) << "x of (" << a.x << ", " << a.y << ", " << a.z << ")";
    EXPECT_NEAR(a.y, b.y, t) << "y of (" << a.x << ", " << a.y << ", " << a.z << ")";
    EXPECT_NEAR(a.z, b.z, t) << "z of (" << a.x << ", " << a.y << ", " << a.z << ")";
}

inline void expect_near(const vector2 &a, const vector2 &b, scalar t = tol) {
    EXPECT_NEAR(a.x, b.x, t) << "x of (" << a.x << ", " << a.y << ")";
    EXPECT_NEAR(a.y, b.y, t) << "y of (" << a.x << ", " << a.y << ")";
}

inline void expect_near(const matrix3x3 &a, const matrix3x3 &b, scalar t = tol) {
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        expect_near(a[i], b[i], t);
    }
}

} // namespace math_test

#endif // EDYN_TESTS_UNIT_MATH_MATH_TEST_HELPERS_HPP
