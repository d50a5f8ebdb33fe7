#ifndef EDYN_TESTS_UNIT_COLLISION_COLLIDE_TEST_HELPERS_HPP
#define EDYN_TESTS_UNIT_COLLISION_COLLIDE_TEST_HELPERS_HPP

// Shared by the sphere/box/capsule/plane collide() tests: independent geometry (written here
// from the definitions, not through edyn's geom routines) and checks every reported point must
// pass whatever the pair.

#include "edyn/collision/collide.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/transform.hpp"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

namespace collide_test {

using namespace edyn;

inline vector3 vec(double x, double y, double z) { return {scalar(x), scalar(y), scalar(z)}; }

inline std::string str(const vector3 &v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

inline void expect_vec_near(const vector3 &actual, const vector3 &expected, scalar tol) {
    EXPECT_NEAR(actual.x, expected.x, tol) << "x of " << str(actual) << " vs " << str(expected);
    EXPECT_NEAR(actual.y, expected.y, tol) << "y of " << str(actual) << " vs " << str(expected);
    EXPECT_NEAR(actual.z, expected.z, tol) << "z of " << str(actual) << " vs " << str(expected);
}

// collide(a, b) in the given placement, as it is.
inline collision_result collide_pair(const auto &a, const auto &b, const collision_context &ctx) {
    collision_result r;
    collide(a, b, ctx, r);
    return r;
}

template<typename Kind>
void expect_feature(const std::optional<collision_feature> &f, Kind kind, std::uint32_t index) {
    ASSERT_TRUE(f.has_value()) << "feature missing";
    ASSERT_TRUE(std::holds_alternative<Kind>(f->feature)) << "feature of another shape";
    EXPECT_EQ(int(std::get<Kind>(f->feature)), int(kind));
    EXPECT_EQ(f->index, index);
}

inline scalar min_distance(const collision_result &r) {
    auto d = large_scalar;
    for (std::size_t i = 0; i < r.num_points; ++i)
        d = std::min(d, r.point[i].distance);
    return d;
}

inline std::size_t deepest_index(const collision_result &r) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < r.num_points; ++i) {
        if (r.point[i].distance < r.point[k].distance) k = i;
    }
    return k;
}

// World-space pivots (every shape's pivot is in its body's object space, a plane's too).
struct world_pair {
    vector3 a, b;
};

inline world_pair world_points(const collision_result::collision_point &p, const collision_context &ctx) {
    return {to_world_space(p.pivotA, ctx.posA, ctx.ornA), to_world_space(p.pivotB, ctx.posB, ctx.ornB)};
}

// Checks every point: unit normal, distance within the threshold, and the two world points
// apart by exactly `distance` along the normal.
inline void expect_consistent(const collision_result &r, const collision_context &ctx, scalar tol) {
    ASSERT_LE(r.num_points, collision_result::max_contacts);
    for (std::size_t i = 0; i < r.num_points; ++i) {
        auto &p = r.point[i];
        EXPECT_NEAR(length(p.normal), 1, 1e-4) << "point " << i;
        EXPECT_LE(p.distance, ctx.threshold + tol) << "point " << i;
        auto w = world_points(p, ctx);
        expect_vec_near(w.a - w.b, p.normal * p.distance, tol);
    }
}

// Deterministic random numbers.
struct rng {
    std::mt19937 engine;
    explicit rng(unsigned seed)
        : engine(seed) {}
    scalar uniform(scalar lo, scalar hi) { return std::uniform_real_distribution<scalar>(lo, hi)(engine); }
    vector3 vec(scalar lo, scalar hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    vector3 unit() {
        for (;;) {
            auto v = vec(-1, 1);
            auto l = length(v);
            if (l > scalar(0.1) && l <= 1) return v / l;
        }
    }
    quaternion orientation() {
        auto q = quaternion{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        return length(q) > scalar(0.1) ? normalize(q) : quaternion_identity;
    }
};

// Signed distance from p to a box centred at the origin (the usual closed form).
inline scalar box_sdf(const vector3 &he, const vector3 &p) {
    auto q = abs(p) - he;
    auto outside = length(max(q, vector3_zero));
    return outside + std::min(max_component(q), scalar(0));
}

// Distance from p to the segment [a, b], by projection written out here.
inline scalar point_segment_distance(const vector3 &a, const vector3 &b, const vector3 &p) {
    auto ab = b - a;
    auto denom = dot(ab, ab);
    auto t = denom > 0 ? std::clamp(dot(p - a, ab) / denom, scalar(0), scalar(1)) : scalar(0);
    return length(a + ab * t - p);
}

// Minimum of a convex function on [0, 1] by ternary search (independent of edyn's closed forms).
template<typename F>
scalar convex_min(F &&f) {
    double lo = 0, hi = 1;
    for (int i = 0; i < 100; ++i) {
        auto m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (f(scalar(m1)) < f(scalar(m2)))
            hi = m2;
        else
            lo = m1;
    }
    return std::min({f(scalar(lo)), f(scalar(0)), f(scalar(1))});
}

inline void capsule_ends(const capsule_shape &c, const vector3 &pos, const quaternion &orn, vector3 &p0,
                         vector3 &p1) {
    vector3 axis = vector3_zero;
    axis[int(c.axis)] = c.half_length;
    p0 = to_world_space(axis, pos, orn);
    p1 = to_world_space(-axis, pos, orn);
}

// World vertices of a box.
inline std::vector<vector3> box_vertices(const vector3 &he, const vector3 &pos, const quaternion &orn) {
    std::vector<vector3> v;
    for (int i = 0; i < 8; ++i) {
        v.push_back(
            to_world_space({i & 1 ? -he.x : he.x, i & 2 ? -he.y : he.y, i & 4 ? -he.z : he.z}, pos, orn));
    }
    return v;
}

// World edges of a box as pairs of vertices.
inline std::vector<std::pair<vector3, vector3>> box_edges(const vector3 &he, const vector3 &pos,
                                                          const quaternion &orn) {
    auto v = box_vertices(he, pos, orn);
    std::vector<std::pair<vector3, vector3>> e;
    for (int i = 0; i < 8; ++i) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(i & bit)) e.emplace_back(v[i], v[i | bit]);
        }
    }
    return e;
}

// Projection interval of a set of points on a direction, widened by `radius`.
struct interval {
    scalar lo{large_scalar}, hi{-large_scalar};
};

inline interval project(const std::vector<vector3> &points, const vector3 &n, scalar radius = 0) {
    interval r;
    for (auto &p : points) {
        r.lo = std::min(r.lo, dot(p, n) - radius);
        r.hi = std::max(r.hi, dot(p, n) + radius);
    }
    return r;
}

// Separation of A from B along n (positive when apart): the gap between their projections with
// A on the positive side.
inline scalar separation_along(const interval &a, const interval &b) { return a.lo - b.hi; }

// Largest separation over `directions` and their opposites: for overlapping convex shapes, minus
// the penetration depth when the directions contain the optimal one.
inline scalar max_separation(const std::vector<vector3> &a_points, scalar a_radius,
                             const std::vector<vector3> &b_points, scalar b_radius,
                             const std::vector<vector3> &directions) {
    auto best = -large_scalar;
    for (auto n : directions) {
        for (auto s : {scalar(1), scalar(-1)}) {
            auto ia = project(a_points, n * s, a_radius);
            auto ib = project(b_points, n * s, b_radius);
            best = std::max(best, separation_along(ia, ib));
        }
    }
    return best;
}

// Face normals of a box and their cross products with the given directions, plus random ones.
inline std::vector<vector3> candidate_directions(const quaternion &orn_a, const std::vector<vector3> &others,
                                                 rng &random, int num_random = 200) {
    std::vector<vector3> dirs;
    vector3 axes[3] = {rotate(orn_a, vector3_x), rotate(orn_a, vector3_y), rotate(orn_a, vector3_z)};
    for (auto &a : axes) {
        dirs.push_back(a);
        for (auto &o : others) {
            auto c = cross(a, o);
            if (length(c) > scalar(1e-3)) dirs.push_back(normalize(c));
        }
    }
    for (auto &o : others)
        dirs.push_back(o);
    for (int i = 0; i < num_random; ++i)
        dirs.push_back(random.unit());
    return dirs;
}

// Expected bound on how much deeper than the minimum a separating-axis pair may report (the
// face-axis bias documented in collision/detail/collide_common.hpp).
inline scalar sat_bias(scalar depth) { return scalar(1e-3) + scalar(0.02) * std::abs(depth) + scalar(2e-4); }

// The largest value of `gap(n, coarse)` over unit directions n: dense directions (scored with
// `coarse` set, which may be cheaper and rougher), then a compass search from the best
// `num_best` of them and from `starts`, its stencil turned at random each round so that it also
// climbs along the ridges where the supporting points switch.
template<typename Gap>
scalar searched_max_gap(Gap &&gap, std::vector<vector3> starts, int num_best = 8) {
    constexpr int num_dirs = 2000;
    std::vector<std::pair<scalar, vector3>> coarse;
    for (int i = 0; i < num_dirs; ++i) {
        auto y = 1 - 2 * (scalar(i) + scalar(0.5)) / num_dirs;
        auto rho = std::sqrt(std::max(scalar(0), 1 - y * y));
        auto phi = scalar(i) * scalar(2.399963229728653);
        vector3 n{rho * std::cos(phi), y, rho * std::sin(phi)};
        coarse.emplace_back(gap(n, true), n);
    }
    std::sort(coarse.begin(), coarse.end(), [](const auto &x, const auto &y) { return x.first > y.first; });
    for (int i = 0; i < num_best; ++i)
        starts.insert(starts.begin() + i, coarse[i].second);
    std::mt19937 rng(3);
    std::uniform_real_distribution<scalar> phase(0, pi2);
    auto best = -large_scalar;
    for (auto n : starts) {
        auto value = gap(n, false);
        for (scalar step = scalar(0.08); step > scalar(1e-6);) {
            vector3 t0, t1;
            plane_space(n, t0, t1);
            auto offset = phase(rng);
            auto moved = false;
            for (int j = 0; j < 12; ++j) {
                auto angle = offset + pi2 * scalar(j) / 12;
                auto m = normalize(n + (t0 * std::cos(angle) + t1 * std::sin(angle)) * step);
                auto g = gap(m, false);
                if (g > value) {
                    value = g;
                    n = m;
                    moved = true;
                }
            }
            if (!moved) step *= scalar(0.5);
        }
        best = std::max(best, value);
    }
    return best;
}

// Where `separation(t)`, which grows with t at a slope of at most 1, comes to `target`: secant
// steps from t0 to within 0.1 mm. Returns t and the separation there.
struct secant_result {
    scalar t, separation;
};

template<typename Separation>
secant_result secant_to(Separation &&separation, scalar t0, scalar target) {
    auto f0 = separation(t0) - target;
    auto t1 = t0 - f0, f1 = separation(t1) - target;
    for (int k = 0; k < 3 && std::abs(f1) > scalar(1e-4) && f1 != f0; ++k) {
        auto t2 = t1 - f1 * (t1 - t0) / (f1 - f0);
        t0 = t1;
        f0 = f1;
        t1 = t2;
        f1 = separation(t1) - target;
    }
    return {t1, f1 + target};
}

} // namespace collide_test

#endif // EDYN_TESTS_UNIT_COLLISION_COLLIDE_TEST_HELPERS_HPP
