#ifndef EDYN_TESTS_UNIT_SHAPES_SHAPE_TEST_UTIL_HPP
#define EDYN_TESTS_UNIT_SHAPES_SHAPE_TEST_UTIL_HPP

#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/quaternion.hpp"
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

// Helpers shared by the shape and shape raycast tests.
namespace edyn::test {

inline std::string str(const vector3 &v) {
    std::ostringstream os;
    os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return os.str();
}

inline void expect_vector_near(const vector3 &actual, const vector3 &expected, scalar tolerance,
                               const std::string &what = {}) {
    EXPECT_NEAR(actual.x, expected.x, tolerance)
        << what << " actual " << str(actual) << " expected " << str(expected);
    EXPECT_NEAR(actual.y, expected.y, tolerance)
        << what << " actual " << str(actual) << " expected " << str(expected);
    EXPECT_NEAR(actual.z, expected.z, tolerance)
        << what << " actual " << str(actual) << " expected " << str(expected);
}

inline void expect_matrix_near(const matrix3x3 &actual, const matrix3x3 &expected, scalar tolerance) {
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(actual[i][j], expected[i][j], tolerance) << "element (" << i << ", " << j << ")";
        }
    }
}

// Expects `fn` to throw std::invalid_argument whose message contains every one of `parts`.
inline void expect_invalid_argument(const std::function<void()> &fn, const std::vector<std::string> &parts) {
    try {
        fn();
        ADD_FAILURE() << "expected std::invalid_argument mentioning '" << (parts.empty() ? "" : parts[0])
                      << "', nothing was thrown";
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        for (const auto &part : parts) {
            EXPECT_NE(what.find(part), std::string::npos)
                << "message '" << what << "' lacks '" << part << "'";
        }
    }
}

inline quaternion random_orientation(std::mt19937 &rng) {
    std::normal_distribution<scalar> n(0, 1);
    quaternion q{n(rng), n(rng), n(rng), n(rng)};
    return normalize(q);
}

// A unit vector, uniform over the sphere.
inline vector3 random_direction(std::mt19937 &rng) {
    std::normal_distribution<scalar> n(0, 1);
    vector3 v{n(rng), n(rng), n(rng)};
    return normalize(v);
}

inline vector3 random_vector(std::mt19937 &rng, scalar lo, scalar hi) {
    std::uniform_real_distribution<scalar> u(lo, hi);
    return {u(rng), u(rng), u(rng)};
}

// Cube of half size h centred at `centre`: vertex i has coordinates
// (i in {1,2,5,6} ? + : -) x, (i in {2,3,6,7} ? + : -) y, (i >= 4 ? + : -) z.
inline std::vector<vector3> cube_vertices(scalar h = 1, const vector3 &centre = vector3_zero) {
    return {centre + vector3{-h, -h, -h}, centre + vector3{h, -h, -h}, centre + vector3{h, h, -h},
            centre + vector3{-h, h, -h},  centre + vector3{-h, -h, h}, centre + vector3{h, -h, h},
            centre + vector3{h, h, h},    centre + vector3{-h, h, h}};
}

// Faces of cube_vertices(), counter-clockwise seen from outside: -z, +z, -y, +y, -x, +x.
inline std::vector<std::vector<std::uint32_t>> cube_faces() {
    return {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
}

} // namespace edyn::test

#endif // EDYN_TESTS_UNIT_SHAPES_SHAPE_TEST_UTIL_HPP
