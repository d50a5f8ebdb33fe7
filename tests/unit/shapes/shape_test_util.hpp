#ifndef EDYN_TESTS_UNIT_SHAPES_SHAPE_TEST_UTIL_HPP
#define EDYN_TESTS_UNIT_SHAPES_SHAPE_TEST_UTIL_HPP

#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/scalar.hpp"
#include "edyn/shapes/shapes.hpp"
#include <cmath>
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

// Points on the surface of each shape in object space. The extreme points of every shape lie on
// rims, spheres or vertices, which are sampled densely enough for 1e-4 at unit size.

inline std::vector<vector3> fibonacci_sphere(scalar radius, const vector3 &centre, int count) {
    std::vector<vector3> points;
    auto golden = pi * (3 - std::sqrt(scalar(5)));
    for (int i = 0; i < count; ++i) {
        auto y = 1 - 2 * (scalar(i) + scalar(0.5)) / scalar(count);
        auto r = std::sqrt(1 - y * y);
        auto theta = golden * scalar(i);
        points.push_back(centre + vector3{r * std::cos(theta), y, r * std::sin(theta)} * radius);
    }
    return points;
}

inline vector3 axis_point(coordinate_axis axis, scalar along, scalar u, scalar v) {
    auto k = coordinate_axis_index(axis);
    vector3 p;
    p[k] = along;
    p[(k + 1) % 3] = u;
    p[(k + 2) % 3] = v;
    return p;
}

inline std::vector<vector3> surface_samples(const cylinder_shape &c) {
    std::vector<vector3> points;
    constexpr int n = 8192;
    for (int i = 0; i < n; ++i) {
        auto angle = pi2 * scalar(i) / n;
        for (scalar along : {-c.half_length, c.half_length, scalar(0)}) {
            points.push_back(
                axis_point(c.axis, along, c.radius * std::cos(angle), c.radius * std::sin(angle)));
        }
    }
    return points;
}

inline std::vector<vector3> surface_samples(const capsule_shape &c) {
    auto k = coordinate_axis_index(c.axis);
    auto offset = vector3_zero;
    offset[k] = c.half_length;
    auto points = fibonacci_sphere(c.radius, offset, 400000);
    auto lower = fibonacci_sphere(c.radius, -offset, 400000);
    points.insert(points.end(), lower.begin(), lower.end());
    return points;
}

inline std::vector<vector3> surface_samples(const box_shape &b) {
    std::vector<vector3> points;
    for (int i = 0; i < 8; ++i) {
        points.push_back({i & 1 ? -b.half_extents.x : b.half_extents.x,
                          i & 2 ? -b.half_extents.y : b.half_extents.y,
                          i & 4 ? -b.half_extents.z : b.half_extents.z});
    }
    return points;
}

inline std::vector<vector3> surface_samples(const sphere_shape &s) {
    return fibonacci_sphere(s.radius, vector3_zero, 400000);
}

inline std::vector<vector3> surface_samples(const polyhedron_shape &p) { return p.mesh->vertices; }

} // namespace edyn::test

#endif // EDYN_TESTS_UNIT_SHAPES_SHAPE_TEST_UTIL_HPP
