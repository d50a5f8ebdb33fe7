#include "collide_test_helpers.hpp"
#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/box_features.hpp"
#include "edyn/collision/detail/cylinder_geom.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/transform.hpp"
#include "unit/shapes/shape_test_util.hpp"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <type_traits>
#include <vector>

// collide() for every pair with a cylinder. Hand-built configurations check points, normals,
// distances and features against exact geometry; random configurations check the distance
// against brute force: sampled surfaces with exact point distances while apart, and a search over
// all directions of the gap between sampled supports (the separating-axis theorem, with no
// candidate axes) in every case.
namespace {

using namespace edyn;
using collide_test::expect_feature;
using collide_test::expect_vec_near;
using collide_test::min_distance;
using edyn::test::random_direction;
using edyn::test::random_orientation;

constexpr coordinate_axis all_axes[] = {coordinate_axis::x, coordinate_axis::y, coordinate_axis::z};
// Geometry of one collide() call is exact to float rounding on shapes of about a metre.
constexpr scalar cylinder_tol = scalar(2e-5);

quaternion axis_to(coordinate_axis axis, const vector3 &dir) {
    return shortest_arc(coordinate_axis_vector(axis), normalize(dir));
}

collision_context make_ctx(const vector3 &pos_a, const quaternion &orn_a, const vector3 &pos_b,
                           const quaternion &orn_b, scalar threshold = scalar(0.02)) {
    return {pos_a, orn_a, pos_b, orn_b, threshold};
}

template<typename A, typename B>
vector3 world_a(const collision_context &ctx, const collision_result::collision_point &p) {
    return to_world_space(p.pivotA, ctx.posA, ctx.ornA);
}

template<typename A, typename B>
vector3 world_b(const collision_context &ctx, const collision_result::collision_point &p) {
    return to_world_space(p.pivotB, ctx.posB, ctx.ornB);
}

// Runs collide(a, b) and collide(b, a), checks what must hold for every result and that the
// two orders agree with A and B exchanged; returns the (a, b) result.
template<typename A, typename B>
collision_result collide_cylinder_checked(const A &a, const B &b, const collision_context &ctx) {
    collision_result r;
    collide(a, b, ctx, r);
    EXPECT_LE(r.num_points, collision_result::max_contacts);
    for (std::size_t i = 0; i < r.num_points; ++i) {
        const auto &p = r.point[i];
        EXPECT_NEAR(length(p.normal), 1, 1e-5);
        EXPECT_LE(p.distance, ctx.threshold + cylinder_tol);
        auto d = world_a<A, B>(ctx, p) - world_b<A, B>(ctx, p);
        EXPECT_NEAR(dot(d, p.normal), p.distance, cylinder_tol) << "point " << i;
        EXPECT_NEAR(length(d - p.normal * p.distance), 0, cylinder_tol)
            << "pivots apart across the normal, point " << i;
    }
    collision_result s;
    collide(b, a, swap_context(ctx), s);
    EXPECT_EQ(s.num_points, r.num_points);
    // Same points with A and B exchanged; a pair of one shape type computes both orders itself,
    // so the order of the points may differ.
    for (std::size_t i = 0; i < r.num_points; ++i) {
        const auto &p = r.point[i];
        std::size_t match = 0;
        auto best = large_scalar;
        for (std::size_t j = 0; j < s.num_points; ++j) {
            auto d = distance(p.pivotA, s.point[j].pivotB) + distance(p.pivotB, s.point[j].pivotA);
            if (d < best) {
                best = d;
                match = j;
            }
        }
        if (s.num_points == 0) break;
        const auto &q = s.point[match];
        EXPECT_NEAR(best, 0, 2 * cylinder_tol) << "point " << i;
        EXPECT_NEAR(distance(p.normal, -q.normal), 0, cylinder_tol);
        EXPECT_NEAR(p.distance, q.distance, cylinder_tol);
        EXPECT_TRUE(p.featureA == q.featureB);
        EXPECT_TRUE(p.featureB == q.featureA);
    }
    return r;
}

template<typename A, typename B>
scalar manifold_area(const collision_result &r, const collision_context &ctx) {
    if (r.num_points < 3) return 0;
    vector3 v[4];
    for (std::size_t i = 0; i < 4; ++i)
        v[i] = world_a<A, B>(ctx, r.point[std::min(i, r.num_points - 1)]);
    return quadrilateral_area(v[0], v[1], v[2], v[3]);
}

// Exact signed distances from a world point to each shape, written independently of the
// implementation.
scalar sd(const cylinder_shape &s, const vector3 &pos, const quaternion &orn, const vector3 &x) {
    auto p = to_object_space(x, pos, orn);
    auto k = coordinate_axis_index(s.axis);
    auto off = p;
    off[k] = 0;
    auto dx = std::abs(p[k]) - s.half_length;
    auto dr = length(off) - s.radius;
    if (dx <= 0 && dr <= 0) return std::max(dx, dr);
    return std::sqrt(square(std::max(dx, scalar(0))) + square(std::max(dr, scalar(0))));
}

scalar sd(const box_shape &s, const vector3 &pos, const quaternion &orn, const vector3 &x) {
    return collide_test::box_sdf(s.half_extents, to_object_space(x, pos, orn));
}

scalar sd(const capsule_shape &s, const vector3 &pos, const quaternion &orn, const vector3 &x) {
    auto p = to_object_space(x, pos, orn);
    auto k = coordinate_axis_index(s.axis);
    auto c = p;
    c[k] -= std::clamp(p[k], -s.half_length, s.half_length);
    return length(c) - s.radius;
}

scalar sd(const sphere_shape &s, const vector3 &pos, const quaternion &, const vector3 &x) {
    return distance(x, pos) - s.radius;
}

// Unit vectors u, v completing the shape axis k (object space).
void other_axes(int k, vector3 &u, vector3 &v) {
    u = coordinate_axis_vector(coordinate_axis((k + 1) % 3));
    v = coordinate_axis_vector(coordinate_axis((k + 2) % 3));
}

int steps(scalar length, scalar spacing) { return std::max(1, int(std::ceil(length / spacing))); }

// Surface samples, each surface point within `spacing` of one.
void ring(const vector3 &center, const vector3 &u, const vector3 &v, scalar radius, scalar spacing,
          std::vector<vector3> &out) {
    auto n = steps(pi2 * radius, spacing);
    for (int j = 0; j < n; ++j) {
        auto a = pi2 * scalar(j) / scalar(n);
        out.push_back(center + (u * std::cos(a) + v * std::sin(a)) * radius);
    }
}

std::vector<vector3> sample_surface(const cylinder_shape &s, scalar spacing) {
    std::vector<vector3> out;
    auto k = coordinate_axis_index(s.axis);
    auto e = coordinate_axis_vector(s.axis);
    vector3 u, v;
    other_axes(k, u, v);
    for (auto sign : {scalar(1), scalar(-1)}) {
        auto nr = steps(s.radius, spacing);
        for (int i = 0; i <= nr; ++i)
            ring(e * (s.half_length * sign), u, v, s.radius * scalar(i) / nr, spacing, out);
    }
    auto nl = steps(2 * s.half_length, spacing);
    for (int i = 0; i <= nl; ++i)
        ring(e * (-s.half_length + 2 * s.half_length * scalar(i) / nl), u, v, s.radius, spacing, out);
    return out;
}

std::vector<vector3> sample_surface(const box_shape &s, scalar spacing) {
    std::vector<vector3> out;
    for (int k = 0; k < 3; ++k) {
        vector3 u, v;
        other_axes(k, u, v);
        auto he = s.half_extents;
        auto nu = steps(2 * he[(k + 1) % 3], spacing), nv = steps(2 * he[(k + 2) % 3], spacing);
        for (auto sign : {scalar(1), scalar(-1)}) {
            for (int i = 0; i <= nu; ++i) {
                for (int j = 0; j <= nv; ++j) {
                    auto p = coordinate_axis_vector(coordinate_axis(k)) * (he[k] * sign) +
                             u * (-he[(k + 1) % 3] + 2 * he[(k + 1) % 3] * scalar(i) / nu) +
                             v * (-he[(k + 2) % 3] + 2 * he[(k + 2) % 3] * scalar(j) / nv);
                    out.push_back(p);
                }
            }
        }
    }
    return out;
}

void sample_hemisphere(const vector3 &center, const vector3 &pole, const vector3 &u, const vector3 &v,
                       scalar radius, scalar spacing, std::vector<vector3> &out) {
    auto nt = steps(half_pi * radius, spacing);
    for (int i = 0; i <= nt; ++i) {
        auto theta = half_pi * scalar(i) / nt;
        ring(center + pole * (radius * std::cos(theta)), u, v, radius * std::sin(theta), spacing, out);
    }
}

std::vector<vector3> sample_surface(const capsule_shape &s, scalar spacing) {
    std::vector<vector3> out;
    auto k = coordinate_axis_index(s.axis);
    auto e = coordinate_axis_vector(s.axis);
    vector3 u, v;
    other_axes(k, u, v);
    sample_hemisphere(e * s.half_length, e, u, v, s.radius, spacing, out);
    sample_hemisphere(-e * s.half_length, -e, u, v, s.radius, spacing, out);
    auto nl = steps(2 * s.half_length, spacing);
    for (int i = 0; i <= nl; ++i)
        ring(e * (-s.half_length + 2 * s.half_length * scalar(i) / nl), u, v, s.radius, spacing, out);
    return out;
}

std::vector<vector3> sample_surface(const sphere_shape &s, scalar spacing) {
    std::vector<vector3> out;
    sample_hemisphere(vector3_zero, vector3_y, vector3_z, vector3_x, s.radius, spacing, out);
    sample_hemisphere(vector3_zero, -vector3_y, vector3_z, vector3_x, s.radius, spacing, out);
    return out;
}

// Smallest distance between two separated shapes: each one's surface samples against the other's
// exact distance, both ways. Exceeds the true distance by at most `spacing`.
template<typename A, typename B>
scalar sampled_distance(const A &a, const B &b, const collision_context &ctx, scalar spacing) {
    auto best = large_scalar;
    for (const auto &p : sample_surface(a, spacing)) {
        best = std::min(best, sd(b, ctx.posB, ctx.ornB, to_world_space(p, ctx.posA, ctx.ornA)));
    }
    for (const auto &p : sample_surface(b, spacing)) {
        best = std::min(best, sd(a, ctx.posA, ctx.ornA, to_world_space(p, ctx.posB, ctx.ornB)));
    }
    return best;
}

// A shape's support function from the points its hull is spanned by (rims sampled densely,
// box corners, capsule and sphere centres grown by the radius).
struct support_set {
    std::vector<vector3> points;
    scalar inflate{0};
    // The shape's axes: the gap's kinks lie along them and their cross products.
    std::vector<vector3> axes{};

    // `coarse`: every 8th point of a densely sampled set, to pick where to search.
    scalar support(const vector3 &n, bool coarse = false) const {
        std::size_t stride = coarse && points.size() > 256 ? 8 : 1;
        auto best = -large_scalar;
        for (std::size_t i = 0; i < points.size(); i += stride)
            best = std::max(best, dot(points[i], n));
        return best + inflate;
    }
};

support_set support_of(const cylinder_shape &s, const vector3 &pos, const quaternion &orn) {
    support_set set;
    auto k = coordinate_axis_index(s.axis);
    auto e = coordinate_axis_vector(s.axis);
    vector3 u, v;
    other_axes(k, u, v);
    std::vector<vector3> local;
    for (auto sign : {scalar(1), scalar(-1)})
        ring(e * (s.half_length * sign), u, v, s.radius, pi2 * s.radius / 512, local);
    for (const auto &p : local)
        set.points.push_back(to_world_space(p, pos, orn));
    set.axes.push_back(rotate(orn, e));
    return set;
}

support_set support_of(const box_shape &s, const vector3 &pos, const quaternion &orn) {
    support_set set;
    for (int i = 0; i < 8; ++i) {
        vector3 c{i & 1 ? scalar(-1) : scalar(1), i & 2 ? scalar(-1) : scalar(1),
                  i & 4 ? scalar(-1) : scalar(1)};
        set.points.push_back(to_world_space(c * s.half_extents, pos, orn));
    }
    set.axes = {rotate(orn, vector3_x), rotate(orn, vector3_y), rotate(orn, vector3_z)};
    return set;
}

support_set support_of(const capsule_shape &s, const vector3 &pos, const quaternion &orn) {
    auto e = coordinate_axis_vector(s.axis, orn);
    return {{pos + e * s.half_length, pos - e * s.half_length}, s.radius, {e}};
}

support_set support_of(const sphere_shape &s, const vector3 &pos, const quaternion &) {
    return {{pos}, s.radius};
}

// Signed distance as the largest gap, over all unit directions n, between A's lowest and B's
// highest point along n, searched from the best few dense directions and from the shapes' axes
// and their cross products.
scalar searched_distance(const support_set &a, const support_set &b) {
    std::vector<vector3> starts;
    for (const auto &x : a.axes) {
        for (const auto &y : b.axes) {
            auto c = cross(x, y);
            if (try_normalize(c)) starts.insert(starts.end(), {c, -c});
        }
    }
    for (const auto *set : {&a, &b}) {
        for (const auto &x : set->axes)
            starts.insert(starts.end(), {x, -x});
    }
    return searched_max_gap(
        [&](const vector3 &n, bool coarse) { return -a.support(-n, coarse) - b.support(n, coarse); }, starts);
}

// The largest gap between the shapes along the normals collide() reported.
scalar largest_gap_along_normals(const support_set &a, const support_set &b, const collision_result &r) {
    auto best = -large_scalar;
    for (std::size_t k = 0; k < r.num_points; ++k) {
        const auto &n = r.point[k].normal;
        best = std::max(best, -a.support(-n) - b.support(n));
    }
    return best;
}

// Half the time a multiple of quarter turns about the axes, a third of those tilted by 1e-3 rad:
// the parallel and face-to-face configurations where degenerate cases live.
quaternion aligned_or_random_orientation(std::mt19937 &rng) {
    std::uniform_int_distribution<int> pick(0, 5);
    auto kind = pick(rng);
    if (kind < 3) return random_orientation(rng);
    auto q = quaternion_identity;
    for (const auto &axis : {vector3_x, vector3_y, vector3_z}) {
        q = quaternion_axis_angle(axis, half_pi * scalar(pick(rng) % 4)) * q;
    }
    if (kind == 5) q = quaternion_axis_angle(normalize(vector3{1, 2, 3}), scalar(1e-3)) * q;
    return q;
}

// Random placements of A around B, from deep overlap to apart: the reported distance must match
// the direction search always, and the sampled surfaces while apart.
// Random configurations per pair, and an offset added to every seed (both changed together to
// run many more configurations while working on these routines).
constexpr int random_configs = 100;
constexpr unsigned random_seed_offset = 0;

template<typename A, typename B, typename MakeA, typename MakeB>
void random_against_brute_force(MakeA &&make_a, MakeB &&make_b, scalar reach, unsigned seed) {
    const int count = random_configs;
    std::mt19937 rng(seed + random_seed_offset);
    std::uniform_real_distribution<scalar> offset(scalar(0.2), scalar(1.15));
    int apart = 0, overlapping = 0;
    for (int i = 0; i < count; ++i) {
        A a = make_a(rng);
        B b = make_b(rng);
        auto orn_a = aligned_or_random_orientation(rng), orn_b = aligned_or_random_orientation(rng);
        auto pos_b = vector3{scalar(0.3), scalar(-0.2), scalar(0.1)};
        auto pos_a = pos_b + random_direction(rng) * (offset(rng) * reach);
        auto ctx = make_ctx(pos_a, orn_a, pos_b, orn_b, scalar(100));
        collision_result r;
        collide(a, b, ctx, r);
        ASSERT_GT(r.num_points, 0u) << "config " << i;
        auto reported = min_distance(r);
        auto searched = searched_distance(support_of(a, pos_a, orn_a), support_of(b, pos_b, orn_b));
        EXPECT_NEAR(reported, searched, 5e-4) << "config " << i << " normal " << r.point[0].normal.x << " "
                                              << r.point[0].normal.y << " " << r.point[0].normal.z;
        for (std::size_t j = 0; j < r.num_points; ++j) {
            const auto &p = r.point[j];
            if (p.distance > reported + scalar(1e-3)) continue;
            // The deepest points lie on both surfaces.
            EXPECT_NEAR(sd(a, pos_a, orn_a, to_world_space(p.pivotA, pos_a, orn_a)), 0, 1e-3)
                << "config " << i;
            EXPECT_NEAR(sd(b, pos_b, orn_b, to_world_space(p.pivotB, pos_b, orn_b)), 0, 1e-3)
                << "config " << i << " point " << j << " of " << r.num_points << " distance " << p.distance;
        }
        if (searched > scalar(0.01)) {
            ++apart;
            constexpr scalar spacing = scalar(0.015);
            auto sampled = sampled_distance(a, b, ctx, spacing);
            EXPECT_LE(reported, sampled + scalar(1e-4)) << "config " << i;
            EXPECT_GE(reported, sampled - spacing - scalar(1e-4)) << "config " << i;
        } else {
            ++overlapping;
        }
    }
    // Both regimes are exercised.
    EXPECT_GT(apart, count / 8);
    EXPECT_GT(overlapping, count / 8);
}

// Pairs that touch (separated by -2 mm to 2 mm) at 20 m from the origin, where float rounding of
// the positions is about 1e-6 m and the line between two nearly coincident points is noise: the
// pair is reported within the threshold and its deepest point within 0.1 mm of the direction
// search. A is moved along the line between the centres until the search says it touches.
template<typename A, typename B, typename MakeA, typename MakeB>
void random_touching_far_from_origin(MakeA &&make_a, MakeB &&make_b, scalar reach, unsigned seed) {
    constexpr int count = 40;
    std::mt19937 rng(seed + random_seed_offset);
    std::uniform_real_distribution<scalar> offset(scalar(0.3), scalar(1)), gap(scalar(-0.002), scalar(0.002));
    const auto pos_b = vector3{scalar(20.3), scalar(1.7), scalar(-15.2)};
    for (int i = 0; i < count; ++i) {
        A a = make_a(rng);
        B b = make_b(rng);
        auto orn_a = aligned_or_random_orientation(rng), orn_b = aligned_or_random_orientation(rng);
        auto dir = random_direction(rng);
        auto target = gap(rng);
        auto separation = [&](scalar t) {
            return searched_distance(support_of(a, pos_b + dir * t, orn_a), support_of(b, pos_b, orn_b));
        };
        auto [t, searched] = secant_to(separation, offset(rng) * reach, target);
        auto pos_a = pos_b + dir * t;
        ASSERT_LT(std::abs(searched), scalar(0.005)) << "config " << i << " did not come to touch";
        auto ctx = make_ctx(pos_a, orn_a, pos_b, orn_b, scalar(0.02));
        collision_result r;
        collide(a, b, ctx, r);
        ASSERT_GT(r.num_points, 0u) << "config " << i << " at " << searched;
        EXPECT_NEAR(min_distance(r), searched, 1e-4) << "config " << i;
    }
}

// Configurations recorded from a 16,384-body pile of boxes, cylinders and capsules where
// collide() once missed a touching contact or reported its deepest point centimetres too
// shallow: every pair within the threshold is reported, with its deepest point within 0.1 mm
// of the direction search. Float literals as recorded, so that the rounding is the pile's.
template<typename B>
struct recorded_pair {
    cylinder_shape a;
    B b;
    collision_context ctx;
};

template<typename B>
void expect_recorded_pairs_exact(const std::vector<recorded_pair<B>> &pairs) {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const auto &[a, b, ctx] = pairs[i];
        collision_result r;
        collide(a, b, ctx, r);
        auto searched =
            searched_distance(support_of(a, ctx.posA, ctx.ornA), support_of(b, ctx.posB, ctx.ornB));
        if (searched < ctx.threshold - scalar(1e-3)) {
            ASSERT_GT(r.num_points, 0u) << "pair " << i << " at " << searched << " within " << ctx.threshold;
        }
        if (r.num_points > 0) {
            EXPECT_NEAR(min_distance(r), searched, 1e-4) << "pair " << i;
        }
    }
}

cylinder_shape random_cylinder(std::mt19937 &rng) {
    std::uniform_real_distribution<scalar> size(scalar(0.15), scalar(0.6));
    std::uniform_int_distribution<int> axis(0, 2);
    return {size(rng), size(rng), coordinate_axis(axis(rng))};
}

box_shape random_box(std::mt19937 &rng) {
    std::uniform_real_distribution<scalar> size(scalar(0.1), scalar(0.6));
    return {{size(rng), size(rng), size(rng)}};
}

// A cylinder touching (-2 mm to 2 mm) B at 20 m from the origin, its axis within 2e-3 rad of
// an axis of B (a cylinder's or capsule's own, a box face's normal): cap against cap, end or
// face, or a rim just tipped onto it. Along directions that close to the axis a cylinder's
// projection once lost half its digits (sqrt(1 - c^2) in float), and the deepest point of
// cylinder pairs came out up to 0.3 mm too deep. A is moved along a line near B's axis until
// the direction search says it touches.
template<typename B, typename MakeB>
void random_nearly_coaxial_touching(MakeB &&make_b, unsigned seed) {
    std::mt19937 rng(seed + random_seed_offset);
    std::uniform_real_distribution<scalar> tilt(0, scalar(2e-3)), lateral(0, scalar(0.8)),
        gap(scalar(-0.002), scalar(0.002));
    std::uniform_int_distribution<int> pick_axis(0, 2);
    const auto pos_b = vector3{scalar(20.3), scalar(1.7), scalar(-15.2)};
    for (int i = 0; i < 60; ++i) {
        B b = make_b(rng);
        auto a = random_cylinder(rng);
        // B's half size along the axis, where the secant starts.
        scalar b_half;
        if constexpr (std::is_same_v<B, cylinder_shape>) {
            a.axis = b.axis;
            b_half = b.half_length;
        } else if constexpr (std::is_same_v<B, capsule_shape>) {
            a.axis = b.axis;
            b_half = b.half_length + b.radius;
        } else {
            a.axis = coordinate_axis(pick_axis(rng));
            b_half = b.half_extents[coordinate_axis_index(a.axis)];
        }
        auto orn_b = random_orientation(rng);
        auto axis_b = coordinate_axis_vector(a.axis, orn_b);
        auto side = normalize(cross(axis_b, random_direction(rng)));
        auto orn_a = quaternion_axis_angle(side, tilt(rng)) * orn_b;
        auto off_axis = normalize(cross(axis_b, random_direction(rng)));
        auto dir = normalize(axis_b + off_axis * lateral(rng));
        auto target = gap(rng);
        auto separation = [&](scalar t) {
            return searched_distance(support_of(a, pos_b + dir * t, orn_a), support_of(b, pos_b, orn_b));
        };
        auto [t, searched] = secant_to(separation, a.half_length + b_half + scalar(0.01), target);
        ASSERT_LT(std::abs(searched), scalar(0.005)) << "config " << i << " did not come to touch";
        auto ctx = make_ctx(pos_b + dir * t, orn_a, pos_b, orn_b, scalar(0.02));
        collision_result r;
        collide(a, b, ctx, r);
        ASSERT_GT(r.num_points, 0u) << "config " << i << " at " << searched;
        // Where the side runs along a box edge the gap is a narrow ridge that the search can
        // miss; any direction's gap is a lower bound of the distance, the reported normals' too.
        searched = std::max(searched, largest_gap_along_normals(support_of(a, ctx.posA, orn_a),
                                                                support_of(b, pos_b, orn_b), r));
        EXPECT_NEAR(min_distance(r), searched, 5e-5) << "config " << i;
    }
}

capsule_shape random_capsule(std::mt19937 &rng) {
    std::uniform_real_distribution<scalar> size(scalar(0.1), scalar(0.5));
    std::uniform_int_distribution<int> axis(0, 2);
    return {size(rng), size(rng), coordinate_axis(axis(rng))};
}

} // namespace

// Cylinder–cylinder.

TEST(CollideCylinderCylinder, StackedCoaxialCapsGiveTheSmallerRim) {
    for (auto axis_a : all_axes) {
        for (auto axis_b : all_axes) {
            cylinder_shape a{scalar(0.5), scalar(0.4), axis_a};
            cylinder_shape b{scalar(0.7), scalar(0.3), axis_b};
            auto gap = scalar(0.01);
            auto ctx = make_ctx({0, 0.7f + gap, 0}, axis_to(axis_a, vector3_y), vector3_zero,
                                axis_to(axis_b, vector3_y));
            auto r = collide_cylinder_checked(a, b, ctx);
            ASSERT_EQ(r.num_points, 4u);
            for (std::size_t i = 0; i < 4; ++i) {
                const auto &p = r.point[i];
                EXPECT_NEAR(p.distance, gap, cylinder_tol);
                expect_vec_near(p.normal, vector3_y, cylinder_tol);
                auto pa = world_a<cylinder_shape, cylinder_shape>(ctx, p);
                EXPECT_NEAR(pa.y, 0.3f + gap, cylinder_tol);
                EXPECT_NEAR(std::hypot(pa.x, pa.z), a.radius, 1e-4);
                expect_feature(p.featureA, cylinder_feature::face, 1);
                expect_feature(p.featureB, cylinder_feature::face, 0);
            }
            // Four rim points a quarter turn apart span 2 r^2.
            EXPECT_NEAR((manifold_area<cylinder_shape, cylinder_shape>(r, ctx)), 2 * a.radius * a.radius,
                        1e-3);
        }
    }
}

TEST(CollideCylinderCylinder, OffsetCapsGiveTheLensCorners) {
    cylinder_shape a{scalar(0.5), scalar(0.4), coordinate_axis::y};
    cylinder_shape b{scalar(0.5), scalar(0.3), coordinate_axis::y};
    auto depth = scalar(0.005);
    auto ctx = make_ctx({0.6f, 0.7f - depth, 0}, quaternion_identity, vector3_zero, quaternion_identity);
    auto r = collide_cylinder_checked(a, b, ctx);
    ASSERT_EQ(r.num_points, 4u);
    // Lens of two unit-diameter discs 0.6 apart: corners (0.3, +-0.4), tips at x 0.1 and 0.5.
    bool corner_pos = false, corner_neg = false, tip_a = false, tip_b = false;
    for (std::size_t i = 0; i < 4; ++i) {
        const auto &p = r.point[i];
        EXPECT_NEAR(p.distance, -depth, cylinder_tol);
        expect_vec_near(p.normal, vector3_y, cylinder_tol);
        auto w = world_a<cylinder_shape, cylinder_shape>(ctx, p);
        EXPECT_LE(std::hypot(w.x - 0.6f, w.z), a.radius + 1e-4);
        EXPECT_LE(std::hypot(w.x, w.z), b.radius + 1e-4);
        corner_pos |= distance(w, vector3{0.3f, w.y, 0.4f}) < 1e-4;
        corner_neg |= distance(w, vector3{0.3f, w.y, -0.4f}) < 1e-4;
        tip_a |= distance(w, vector3{0.1f, w.y, 0}) < 1e-4;
        tip_b |= distance(w, vector3{0.5f, w.y, 0}) < 1e-4;
    }
    EXPECT_TRUE(corner_pos && corner_neg && tip_a && tip_b);
}

TEST(CollideCylinderCylinder, ParallelSidesGiveTheOverlapEnds) {
    for (auto axis_a : all_axes) {
        for (auto axis_b : all_axes) {
            cylinder_shape a{scalar(0.3), scalar(0.6), axis_a};
            cylinder_shape b{scalar(0.4), scalar(0.5), axis_b};
            auto gap = scalar(-0.004);
            auto ctx = make_ctx({0.2f, 0.7f + gap, 0}, axis_to(axis_a, vector3_x), vector3_zero,
                                axis_to(axis_b, -vector3_x));
            auto r = collide_cylinder_checked(a, b, ctx);
            ASSERT_EQ(r.num_points, 2u);
            scalar xs[2];
            for (std::size_t i = 0; i < 2; ++i) {
                const auto &p = r.point[i];
                EXPECT_NEAR(p.distance, gap, cylinder_tol);
                expect_vec_near(p.normal, vector3_y, cylinder_tol);
                expect_feature(p.featureA, cylinder_feature::side_edge, 0);
                expect_feature(p.featureB, cylinder_feature::side_edge, 0);
                auto w = world_a<cylinder_shape, cylinder_shape>(ctx, p);
                EXPECT_NEAR(w.y, 0.4f + gap, cylinder_tol);
                EXPECT_NEAR(w.z, 0, cylinder_tol);
                xs[i] = w.x;
            }
            EXPECT_NEAR(std::min(xs[0], xs[1]), -0.4f, cylinder_tol);
            EXPECT_NEAR(std::max(xs[0], xs[1]), 0.5f, cylinder_tol);
        }
    }
}

TEST(CollideCylinderCylinder, CrossedSidesGiveOnePoint) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.3), scalar(0.6), axis};
        cylinder_shape b{scalar(0.4), scalar(0.5), axis};
        auto gap = scalar(0.012);
        auto ctx = make_ctx({0.05f, 0.7f + gap, -0.1f}, axis_to(axis, vector3_x), vector3_zero,
                            axis_to(axis, vector3_z));
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 1u);
        const auto &p = r.point[0];
        EXPECT_NEAR(p.distance, gap, cylinder_tol);
        expect_vec_near(p.normal, vector3_y, cylinder_tol);
        expect_vec_near(world_b<cylinder_shape, cylinder_shape>(ctx, p), {0, 0.4f, -0.1f}, cylinder_tol);
        expect_feature(p.featureA, cylinder_feature::side_edge, 0);
        expect_feature(p.featureB, cylinder_feature::side_edge, 0);
    }
}

TEST(CollideCylinderCylinder, TiltedRimOnCapGivesTheDeepestRimPoint) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.3), scalar(0.5), axis};
        cylinder_shape b{scalar(1), scalar(0.2), coordinate_axis::y};
        auto tilt = quaternion_axis_angle(vector3_z, to_radians(30));
        auto orn_a = tilt * axis_to(axis, vector3_y);
        auto gap = scalar(0.008);
        auto lowest = a.half_length * std::cos(to_radians(30)) + a.radius * std::sin(to_radians(30));
        auto ctx = make_ctx({0.1f, 0.2f + gap + lowest, 0}, orn_a, vector3_zero, quaternion_identity);
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 1u);
        const auto &p = r.point[0];
        EXPECT_NEAR(p.distance, gap, cylinder_tol);
        expect_vec_near(p.normal, vector3_y, cylinder_tol);
        auto w = world_a<cylinder_shape, cylinder_shape>(ctx, p);
        EXPECT_NEAR(w.y, 0.2f + gap, cylinder_tol);
        auto cap_center = ctx.posA - rotate(tilt, vector3_y) * a.half_length;
        EXPECT_NEAR(distance(w, cap_center), a.radius, 1e-4);
        expect_feature(p.featureA, cylinder_feature::cap_edge, 1);
        expect_feature(p.featureB, cylinder_feature::face, 0);
    }
}

TEST(CollideCylinderCylinder, ThresholdDecides) {
    cylinder_shape a{scalar(0.5), scalar(0.4), coordinate_axis::z};
    cylinder_shape b{scalar(0.5), scalar(0.3), coordinate_axis::x};
    auto orn_a = axis_to(coordinate_axis::z, vector3_y), orn_b = axis_to(coordinate_axis::x, vector3_y);
    EXPECT_EQ(
        collide_cylinder_checked(a, b, make_ctx({0.2f, 0.75f, 0}, orn_a, vector3_zero, orn_b)).num_points,
        0u);
    EXPECT_EQ(
        collide_cylinder_checked(a, b, make_ctx({0.2f, 0.715f, 0}, orn_a, vector3_zero, orn_b)).num_points,
        4u);
    EXPECT_EQ(
        collide_cylinder_checked(a, b, make_ctx({0.2f, 0.75f, 0}, orn_a, vector3_zero, orn_b, scalar(0.06)))
            .num_points,
        4u);
    // Apart side by side, beyond and within the threshold.
    EXPECT_EQ(collide_cylinder_checked(a, b, make_ctx({1.03f, 0, 0}, orn_a, vector3_zero, orn_b)).num_points,
              0u);
    auto r = collide_cylinder_checked(a, b, make_ctx({1.01f, 0, 0}, orn_a, vector3_zero, orn_b));
    ASSERT_GT(r.num_points, 0u);
    EXPECT_NEAR(min_distance(r), 0.01f, cylinder_tol);
}

TEST(CollideCylinderCylinder, DeepPenetrationTakesTheLeastDepth) {
    cylinder_shape a{scalar(0.5), scalar(0.5), coordinate_axis::y};
    cylinder_shape b{scalar(0.5), scalar(0.5), coordinate_axis::y};
    // Coaxial, 0.2 apart: 0.8 deep along the axis, 1.0 across.
    auto r = collide_cylinder_checked(
        a, b, make_ctx({0, 0.2f, 0}, quaternion_identity, vector3_zero, quaternion_identity));
    ASSERT_EQ(r.num_points, 4u);
    EXPECT_NEAR(min_distance(r), -0.8f, cylinder_tol);
    expect_vec_near(r.point[0].normal, vector3_y, cylinder_tol);
    // Side by side 0.3 apart and long: 0.7 deep across.
    cylinder_shape c{scalar(0.5), scalar(2), coordinate_axis::y};
    auto s = collide_cylinder_checked(
        c, c, make_ctx({0.3f, 0.1f, 0}, quaternion_identity, vector3_zero, quaternion_identity));
    ASSERT_GT(s.num_points, 0u);
    EXPECT_NEAR(min_distance(s), -0.7f, cylinder_tol);
    expect_vec_near(s.point[0].normal, vector3_x, cylinder_tol);
}

TEST(CollideCylinderCylinder, RigidMotionOfBothLeavesTheResult) {
    std::mt19937 rng(7);
    cylinder_shape a{scalar(0.3), scalar(0.6), coordinate_axis::z};
    cylinder_shape b{scalar(0.4), scalar(0.5), coordinate_axis::x};
    auto base =
        make_ctx({0.1f, 0.55f, 0.2f}, quaternion_axis_angle(normalize(vector3{1, 2, 3}), 0.7f), vector3_zero,
                 quaternion_axis_angle(normalize(vector3{-1, 0, 2}), 0.3f), scalar(0.5));
    auto reference = collide_cylinder_checked(a, b, base);
    ASSERT_GT(reference.num_points, 0u);
    for (int i = 0; i < 10; ++i) {
        auto q = random_orientation(rng);
        auto t = random_direction(rng) * scalar(5);
        auto ctx = make_ctx(t + rotate(q, base.posA), q * base.ornA, t + rotate(q, base.posB), q * base.ornB,
                            base.threshold);
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, reference.num_points);
        for (std::size_t j = 0; j < r.num_points; ++j) {
            EXPECT_NEAR(r.point[j].distance, reference.point[j].distance, 1e-4);
            expect_vec_near(r.point[j].normal, rotate(q, reference.point[j].normal), 1e-4);
            expect_vec_near(r.point[j].pivotA, reference.point[j].pivotA, 1e-3);
        }
    }
}

// A witness proves its pair closest once the shapes' separation along the pair's own axis equals
// the pair's distance: no axis separates the shapes more, no two points lie closer. The cylinder
// routines stop looking for axes there.
TEST(CylinderSeparatingAxes, AWitnessOfApartShapesIsTheirClosestPair) {
    detail::sat_result sat;
    sat.witness_tolerance = scalar(1e-5);
    EXPECT_FALSE(sat.closest_pair_found());
    // Points 0.1 apart along y, the shapes separated along y by 0.05 only: points elsewhere are
    // closer than these two.
    sat.test_witness(vector3_y, scalar(0.1), scalar(1), scalar(0.5), scalar(0.45));
    EXPECT_FALSE(sat.closest_pair_found());
    EXPECT_NEAR(sat.distance, 0.05f, 1e-6);
    // Separated along y by their whole distance: the closest pair.
    sat.test_witness(vector3_y, scalar(0.1), scalar(1), scalar(0.5), scalar(0.4));
    EXPECT_TRUE(sat.closest_pair_found());
    // Overlapping shapes have no closest pair to prove: the deepest pair is a witness, not a proof.
    detail::sat_result overlap;
    overlap.witness_tolerance = scalar(1e-5);
    overlap.test_witness(vector3_y, scalar(0.02), scalar(-0.88), scalar(0.5), scalar(0.4));
    EXPECT_LT(overlap.witness_distance, 0);
    EXPECT_FALSE(overlap.closest_pair_found());
}

TEST(CollideCylinderCylinder, ApartPairsStopAtTheirClosestPair) {
    // Apart by 1 cm in two of the ways a closest pair is proved: cap over cap (the cap's own
    // witness) and a tilted rim beside the other's side (a rim against the other's axis).
    cylinder_shape a{scalar(0.3), scalar(0.5), coordinate_axis::y};
    auto gap = scalar(0.01);
    // Cap over cap, offset: the gap along y.
    auto r = collide_cylinder_checked(
        a, a, make_ctx({0.2f, 1 + gap, 0}, quaternion_identity, vector3_zero, quaternion_identity));
    ASSERT_EQ(r.num_points, 4u);
    EXPECT_NEAR(min_distance(r), gap, cylinder_tol);
    expect_vec_near(r.point[0].normal, vector3_y, cylinder_tol);
    // A's rim beside B's side: A tilted about z, so that its point of least x is on its upper rim,
    // placed at x = 0.3 + gap beside the middle of B's side.
    auto tilt = quaternion_axis_angle(vector3_z, 0.4f);
    auto rim_low = rotate(tilt, vector3{-0.3f, 0.5f, 0});
    auto s = collide_cylinder_checked(
        a, a, make_ctx(vector3{0.3f + gap, 0, 0} - rim_low, tilt, vector3_zero, quaternion_identity));
    ASSERT_GT(s.num_points, 0u);
    EXPECT_NEAR(min_distance(s), gap, cylinder_tol);
    expect_vec_near(s.point[0].normal, vector3_x, 1e-4);
}

TEST(CollideCylinderCylinder, RandomAgainstBruteForce) {
    random_against_brute_force<cylinder_shape, cylinder_shape>(random_cylinder, random_cylinder, scalar(1.6),
                                                               11);
}

TEST(CollideCylinderCylinder, RandomTouchingFarFromTheOrigin) {
    random_touching_far_from_origin<cylinder_shape, cylinder_shape>(random_cylinder, random_cylinder,
                                                                    scalar(1.6), 13);
}

TEST(CollideCylinderCylinder, RandomNearlyCoaxialTouching) {
    random_nearly_coaxial_touching<cylinder_shape>(random_cylinder, 71);
}

TEST(CollideCylinderCylinder, RecordedPilePairsAreExact) {
    using c = cylinder_shape;
    using a = coordinate_axis;
    expect_recorded_pairs_exact<cylinder_shape>({
        // Deepest point 3.9 cm too shallow: a rim point just outside the other cylinder's outline.
        {c{0x1.daa92ap-3f, 0x1.daa92ap-3f, a::y},
         c{0x1.c08adep-3f, 0x1.c08adep-3f, a::y},
         {{0x1.f42b4ap+2f, 0x1.a62b7ep+0f, -0x1.e91db4p+3f},
          {-0x1.1ec556p-1f, 0x1.f42f16p-3f, -0x1.f3e7e4p-3f, -0x1.818d8p-1f},
          {0x1.eaf6bp+2f, 0x1.c37adp+0f, -0x1.d9336ep+3f},
          {0x1.c837d4p-4f, 0x1.18a9f4p-1f, -0x1.779ccp-1f, 0x1.8b256cp-2f},
          0x1.d5937cp-4f}},
        {c{0x1.913848p-3f, 0x1.913848p-3f, a::y},
         c{0x1.0ef8fap-2f, 0x1.0ef8fap-2f, a::y},
         {{0x1.410ae6p+4f, 0x1.a88c2p-2f, -0x1.8be6cp+1f},
          {-0x1.d9240ep-5f, -0x1.b9ef66p-2f, -0x1.cce5d2p-1f, 0x1.0110bap-7f},
          {0x1.46cc9cp+4f, 0x1.c1ea06p-1f, -0x1.a35dbp+1f},
          {0x1.ebaa8cp-2f, 0x1.dfac6cp-3f, 0x1.77772ap-1f, 0x1.ae9b16p-2f},
          0x1.76ad04p-5f}},
        {c{0x1.18721ap-2f, 0x1.18721ap-2f, a::y},
         c{0x1.327724p-2f, 0x1.327724p-2f, a::y},
         {{0x1.ee5474p+2f, 0x1.2d14fp+1f, -0x1.0a07a4p+0f},
          {-0x1.edb65cp-3f, 0x1.9c2942p-3f, -0x1.0a2f46p-1f, 0x1.96bd98p-1f},
          {0x1.009d36p+3f, 0x1.4c062cp+1f, -0x1.982332p+0f},
          {0x1.a0d4b2p-1f, 0x1.758564p-2f, -0x1.c1195p-2f, 0x1.bcff8ap-4f},
          0x1.96ef68p-6f}},
        {c{0x1.1e3072p-2f, 0x1.1e3072p-2f, a::y},
         c{0x1.0f05c2p-2f, 0x1.0f05c2p-2f, a::y},
         {{-0x1.7b90a4p+0f, 0x1.3f8e6ep+0f, -0x1.f7c0ecp+1f},
          {0x1.2bc05ap-2f, -0x1.c0334cp-1f, 0x1.b4e624p-4f, -0x1.7a7f7cp-2f},
          {-0x1.3aedb6p+0f, 0x1.62105p+0f, -0x1.a94bfp+1f},
          {0x1.4733c6p-1f, -0x1.7619bap-2f, 0x1.006398p-1f, -0x1.d24d74p-2f},
          0x1.3e840cp-3f}},
        // Touching and once missed: the rejected candidate suppressed the support fallbacks.
        {c{0x1.320ef8p-2f, 0x1.320ef8p-2f, a::y},
         c{0x1.0e062p-2f, 0x1.0e062p-2f, a::y},
         {{0x1.90554cp+2f, 0x1.af37ccp-2f, 0x1.212258p+3f},
          {0x1.81cf78p-1f, 0x1.9e9d8p-2f, 0x1.a9662ap-2f, -0x1.3cb682p-2f},
          {0x1.ba1072p+2f, 0x1.1b4eb4p-2f, 0x1.1b44d2p+3f},
          {-0x1.be9348p-3f, -0x1.80beap-4f, -0x1.4e87f6p-1f, -0x1.700b06p-1f},
          0x1.7048b4p-5f}},
        {c{0x1.ae3078p-3f, 0x1.ae3078p-3f, a::y},
         c{0x1.2d8dbp-2f, 0x1.2d8dbp-2f, a::y},
         {{0x1.280d1ep+4f, 0x1.ad7a32p-3f, 0x1.1f5bc6p+4f},
          {0x1.64656cp-2f, 0x1.3b7894p-1f, -0x1.3b31fap-1f, 0x1.631312p-2f},
          {0x1.20827cp+4f, 0x1.5b7caap-2f, 0x1.25ba9ep+4f},
          {0x1.69e6ecp-8f, 0x1.18fc34p-1f, 0x1.8701eep-1f, 0x1.5c1e1ep-2f},
          0x1.f9f098p-5f}},
    });
}

// Cylinder–box.

TEST(CollideCylinderBox, StandingOnAFaceGivesFourRimPoints) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.4), scalar(0.5), axis};
        box_shape b{{1, 0.3f, 1}};
        auto gap = scalar(-0.003);
        auto ctx =
            make_ctx({0.1f, 0.8f + gap, -0.2f}, axis_to(axis, vector3_y), vector3_zero, quaternion_identity);
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            const auto &p = r.point[i];
            EXPECT_NEAR(p.distance, gap, cylinder_tol);
            expect_vec_near(p.normal, vector3_y, cylinder_tol);
            auto w = world_a<cylinder_shape, box_shape>(ctx, p);
            EXPECT_NEAR(std::hypot(w.x - 0.1f, w.z + 0.2f), a.radius, 1e-4);
            EXPECT_NEAR((world_b<cylinder_shape, box_shape>(ctx, p).y), 0.3f, cylinder_tol);
            expect_feature(p.featureA, cylinder_feature::face, 1);
            expect_feature(p.featureB, box_feature::face, 2);
        }
        EXPECT_NEAR((manifold_area<cylinder_shape, box_shape>(r, ctx)), 2 * a.radius * a.radius, 1e-3);
    }
}

TEST(CollideCylinderBox, CapOverACornerClipsTheCircleToTheFace) {
    // Cap centred over the box's corner (1, 1): the overlap is a quarter disc, from the corner
    // to the circle's crossings with the two edges and its extreme points in between.
    cylinder_shape a{scalar(0.4), scalar(0.5), coordinate_axis::y};
    box_shape b{{1, 0.3f, 1}};
    auto gap = scalar(0.01);
    auto ctx = make_ctx({1, 0.8f + gap, 1}, quaternion_identity, vector3_zero, quaternion_identity);
    auto r = collide_cylinder_checked(a, b, ctx);
    ASSERT_GE(r.num_points, 3u);
    bool corner = false, crossing_x = false, crossing_z = false;
    for (std::size_t i = 0; i < r.num_points; ++i) {
        const auto &p = r.point[i];
        EXPECT_NEAR(p.distance, gap, cylinder_tol);
        auto w = world_b<cylinder_shape, box_shape>(ctx, p);
        EXPECT_LE(w.x, 1 + cylinder_tol);
        EXPECT_LE(w.z, 1 + cylinder_tol);
        EXPECT_LE(std::hypot(w.x - 1, w.z - 1), a.radius + 1e-4);
        corner |= distance(w, vector3{1, 0.3f, 1}) < 1e-4;
        crossing_x |= distance(w, vector3{0.6f, 0.3f, 1}) < 1e-4;
        crossing_z |= distance(w, vector3{1, 0.3f, 0.6f}) < 1e-4;
    }
    EXPECT_TRUE(corner && crossing_x && crossing_z);
    // The quarter disc has area pi r^2 / 4; three corners and a rim point span at least the
    // triangle r^2 / 2.
    EXPECT_GE((manifold_area<cylinder_shape, box_shape>(r, ctx)), 0.5f * a.radius * a.radius - 1e-4);
}

TEST(CollideCylinderBox, SmallBoxOnALargeCapGivesTheBoxCorners) {
    for (auto axis : all_axes) {
        box_shape a{{0.2f, 0.1f, 0.15f}};
        cylinder_shape b{scalar(1), scalar(0.3), axis};
        auto gap = scalar(0.005);
        auto spin = quaternion_axis_angle(vector3_y, 0.4f);
        auto ctx = make_ctx({0.3f, 0.4f + gap, 0.1f}, spin, vector3_zero, axis_to(axis, vector3_y));
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            const auto &p = r.point[i];
            EXPECT_NEAR(p.distance, gap, cylinder_tol);
            expect_vec_near(p.normal, vector3_y, cylinder_tol);
            auto local = p.pivotA;
            EXPECT_NEAR(std::abs(local.x), 0.2f, cylinder_tol);
            EXPECT_NEAR(local.y, -0.1f, cylinder_tol);
            EXPECT_NEAR(std::abs(local.z), 0.15f, cylinder_tol);
            expect_feature(p.featureA, box_feature::face, 3);
            expect_feature(p.featureB, cylinder_feature::face, 0);
        }
    }
}

TEST(CollideCylinderBox, LyingOnAFaceGivesTheSideLineClipped) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.3), scalar(0.8), axis};
        box_shape b{{0.5f, 0.2f, 1}};
        auto gap = scalar(0.006);
        // Overhangs the face's +x edge: the side line is clipped at x = 0.5.
        auto ctx =
            make_ctx({0.4f, 0.5f + gap, 0.3f}, axis_to(axis, vector3_x), vector3_zero, quaternion_identity);
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 2u);
        scalar xs[2];
        for (std::size_t i = 0; i < 2; ++i) {
            const auto &p = r.point[i];
            EXPECT_NEAR(p.distance, gap, cylinder_tol);
            expect_vec_near(p.normal, vector3_y, cylinder_tol);
            expect_feature(p.featureA, cylinder_feature::side_edge, 0);
            expect_feature(p.featureB, box_feature::face, 2);
            auto w = world_b<cylinder_shape, box_shape>(ctx, p);
            EXPECT_NEAR(w.z, 0.3f, cylinder_tol);
            xs[i] = w.x;
        }
        EXPECT_NEAR(std::min(xs[0], xs[1]), -0.4f, cylinder_tol);
        EXPECT_NEAR(std::max(xs[0], xs[1]), 0.5f, cylinder_tol);
    }
}

TEST(CollideCylinderBox, TiltedRimOnAFaceGivesOnePoint) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.3), scalar(0.5), axis};
        box_shape b{{1, 0.2f, 1}};
        auto angle = to_radians(40);
        auto tilt = quaternion_axis_angle(vector3_x, angle);
        auto gap = scalar(0.004);
        auto lowest = a.half_length * std::cos(angle) + a.radius * std::sin(angle);
        auto ctx = make_ctx({0, 0.2f + gap + lowest, 0.2f}, tilt * axis_to(axis, vector3_y), vector3_zero,
                            quaternion_identity);
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 1u);
        EXPECT_NEAR(r.point[0].distance, gap, cylinder_tol);
        expect_vec_near(r.point[0].normal, vector3_y, cylinder_tol);
        expect_feature(r.point[0].featureA, cylinder_feature::cap_edge, 1);
        expect_feature(r.point[0].featureB, box_feature::face, 2);
        // Nearly upright, the neighbouring rim points come within the threshold.
        auto small = to_radians(scalar(3.5));
        auto lowest2 = a.half_length * std::cos(small) + a.radius * std::sin(small);
        // Rim points a quarter turn away sit r sin(3.5 deg) = 0.018 higher, the opposite one 0.037.
        auto gap2 = scalar(-0.001);
        auto ctx2 = make_ctx({0, 0.2f + gap2 + lowest2, 0.2f},
                             quaternion_axis_angle(vector3_x, small) * axis_to(axis, vector3_y), vector3_zero,
                             quaternion_identity);
        auto r2 = collide_cylinder_checked(a, b, ctx2);
        ASSERT_EQ(r2.num_points, 3u);
        EXPECT_NEAR(min_distance(r2), gap2, cylinder_tol);
        for (std::size_t i = 0; i < 3; ++i)
            expect_feature(r2.point[i].featureA, cylinder_feature::cap_edge, 1);
    }
}

TEST(CollideCylinderBox, EdgeAcrossTheSideGivesOnePoint) {
    for (auto axis : all_axes) {
        // Box turned 45 degrees about z: its top edge runs along z under a cylinder along x.
        cylinder_shape a{scalar(0.3), scalar(0.8), axis};
        box_shape b{{0.5f, 0.5f, 0.6f}};
        auto gap = scalar(0.01);
        auto top = 0.5f * std::sqrt(2.f);
        auto ctx = make_ctx({0.1f, top + 0.3f + gap, 0.2f}, axis_to(axis, vector3_x), vector3_zero,
                            quaternion_axis_angle(vector3_z, to_radians(45)));
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 1u);
        const auto &p = r.point[0];
        EXPECT_NEAR(p.distance, gap, cylinder_tol);
        expect_vec_near(p.normal, vector3_y, cylinder_tol);
        expect_vec_near(world_b<cylinder_shape, box_shape>(ctx, p), {0, top, 0.2f}, 1e-4);
        expect_feature(p.featureA, cylinder_feature::side_edge, 0);
        ASSERT_TRUE(p.featureB.has_value());
        EXPECT_EQ(int(std::get<box_feature>(p.featureB->feature)), int(box_feature::edge));
    }
}

TEST(CollideCylinderBox, RimAgainstAnEdgeIsExact) {
    // Cylinder upright beside the box, its lower rim reaching past the box's top edge along z:
    // the closest points are the rim's and the edge's, 0.01 apart along the bisector.
    cylinder_shape a{scalar(0.3), scalar(0.5), coordinate_axis::y};
    box_shape b{{0.5f, 0.5f, 0.5f}};
    auto d = scalar(0.01) / std::sqrt(scalar(2));
    auto ctx = make_ctx({0.5f + 0.3f + d, 0.5f + 0.5f + d, 0}, quaternion_identity, vector3_zero,
                        quaternion_identity);
    auto r = collide_cylinder_checked(a, b, ctx);
    ASSERT_EQ(r.num_points, 1u);
    EXPECT_NEAR(r.point[0].distance, 0.01f, cylinder_tol);
    expect_vec_near(r.point[0].normal, normalize(vector3{1, 1, 0}), 1e-4);
    expect_feature(r.point[0].featureA, cylinder_feature::cap_edge, 1);
    // Edge along z (axis 2) on the +x, +y side.
    expect_feature(r.point[0].featureB, box_feature::edge, detail::box_edge_index(2, {1, 1, 0}));
}

TEST(CollideCylinderBox, RandomAgainstBruteForce) {
    random_against_brute_force<cylinder_shape, box_shape>(random_cylinder, random_box, scalar(1.7), 23);
}

TEST(CollideCylinderBox, RandomTouchingFarFromTheOrigin) {
    random_touching_far_from_origin<cylinder_shape, box_shape>(random_cylinder, random_box, scalar(1.7), 29);
}

TEST(CollideCylinderBox, RandomNearlyCoaxialTouching) {
    random_nearly_coaxial_touching<box_shape>(random_box, 73);
}

TEST(CollideCylinderBox, RecordedPilePairsAreExact) {
    using a = coordinate_axis;
    expect_recorded_pairs_exact<box_shape>({
        // Deepest point 1.5 cm too shallow.
        {cylinder_shape{0x1.f6a176p-3f, 0x1.f6a176p-3f, a::y},
         box_shape{{0x1.5280dp-2f, 0x1.0ecd74p-2f, 0x1.96342ep-3f}},
         {{-0x1.5e6568p-2f, 0x1.3e7cfcp-1f, -0x1.12df26p+4f},
          {0x1.5f76dcp-3f, 0x1.558d3ap-3f, 0x1.30d3b2p-1f, 0x1.88b31ep-1f},
          {-0x1.1712cep-2f, 0x1.9c7164p-3f, -0x1.0b34a4p+4f},
          {0x1.a087cp-3f, 0x1.5ca34ep-1f, 0x1.58797cp-1f, -0x1.a53944p-3f},
          0x1.a4a7a8p-4f}},
        // Touching and once missed.
        {cylinder_shape{0x1.f9a50ap-3f, 0x1.f9a50ap-3f, a::y},
         box_shape{{0x1.d784ap-2f, 0x1.7936e6p-2f, 0x1.1ae92ep-2f}},
         {{-0x1.816e86p-2f, 0x1.773d84p+0f, 0x1.7aaf16p+3f},
          {-0x1.ed4274p-1f, 0x1.0b8ff6p-2f, 0x1.d35e76p-5f, 0x1.2cc9f2p-6f},
          {-0x1.6f275ap-3f, 0x1.61f14p-1f, 0x1.815674p+3f},
          {-0x1.579532p-2f, -0x1.8f1f28p-1f, 0x1.7044f6p-2f, -0x1.8d214p-2f},
          0x1.7e535cp-6f}},
        {cylinder_shape{0x1.6f9c0cp-3f, 0x1.6f9c0cp-3f, a::y},
         box_shape{{0x1.20e4f8p-2f, 0x1.ce3b26p-3f, 0x1.5aac5ep-3f}},
         {{-0x1.95af3ep-3f, 0x1.7f3f36p+0f, 0x1.00ef02p-1f},
          {-0x1.1c7fe4p-1f, -0x1.01f05ep-2f, -0x1.8de75ap-1f, -0x1.3c1042p-3f},
          {-0x1.612202p-2f, 0x1.354ee6p+0f, 0x1.df9adp-1f},
          {0x1.ebab94p-3f, 0x1.5876a6p-3f, 0x1.9274c8p-1f, -0x1.16a794p-1f},
          0x1.82995ep-6f}},
    });
}

// Cylinder–capsule.

TEST(CollideCylinderCapsule, LyingOnACapGivesTheSegmentOverTheDisc) {
    for (auto axis_a : all_axes) {
        for (auto axis_b : all_axes) {
            capsule_shape a{scalar(0.1), scalar(0.4), axis_a};
            cylinder_shape b{scalar(0.6), scalar(0.3), axis_b};
            auto gap = scalar(0.004);
            auto ctx = make_ctx({0.5f, 0.4f + gap, 0}, axis_to(axis_a, vector3_x), vector3_zero,
                                axis_to(axis_b, vector3_y));
            auto r = collide_cylinder_checked(a, b, ctx);
            ASSERT_EQ(r.num_points, 2u);
            scalar xs[2];
            for (std::size_t i = 0; i < 2; ++i) {
                const auto &p = r.point[i];
                EXPECT_NEAR(p.distance, gap, cylinder_tol);
                expect_vec_near(p.normal, vector3_y, cylinder_tol);
                expect_feature(p.featureA, capsule_feature::side, 0);
                expect_feature(p.featureB, cylinder_feature::face, 0);
                xs[i] = world_b<capsule_shape, cylinder_shape>(ctx, p).x;
            }
            EXPECT_NEAR(std::min(xs[0], xs[1]), 0.1f, cylinder_tol);
            EXPECT_NEAR(std::max(xs[0], xs[1]), 0.6f, cylinder_tol);
        }
    }
}

TEST(CollideCylinderCapsule, ParallelAndCrossedSides) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.3), scalar(0.6), axis};
        capsule_shape b{scalar(0.1), scalar(0.5), axis};
        auto gap = scalar(-0.002);
        auto ctx =
            make_ctx({0.2f, 0.4f + gap, 0}, axis_to(axis, vector3_x), vector3_zero, axis_to(axis, vector3_x));
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(r.num_points, 2u);
        scalar xs[2];
        for (std::size_t i = 0; i < 2; ++i) {
            EXPECT_NEAR(r.point[i].distance, gap, cylinder_tol);
            expect_vec_near(r.point[i].normal, vector3_y, cylinder_tol);
            expect_feature(r.point[i].featureA, cylinder_feature::side_edge, 0);
            expect_feature(r.point[i].featureB, capsule_feature::side, 0);
            xs[i] = world_a<cylinder_shape, capsule_shape>(ctx, r.point[i]).x;
        }
        EXPECT_NEAR(std::min(xs[0], xs[1]), -0.4f, cylinder_tol);
        EXPECT_NEAR(std::max(xs[0], xs[1]), 0.5f, cylinder_tol);

        auto crossed = make_ctx({0.2f, 0.4f + gap, 0.1f}, axis_to(axis, vector3_x), vector3_zero,
                                axis_to(axis, vector3_z));
        auto s = collide_cylinder_checked(a, b, crossed);
        ASSERT_EQ(s.num_points, 1u);
        EXPECT_NEAR(s.point[0].distance, gap, cylinder_tol);
        expect_vec_near(world_b<cylinder_shape, capsule_shape>(crossed, s.point[0]), {0, 0.1f, 0.1f},
                        cylinder_tol);
    }
}

TEST(CollideCylinderCapsule, HemisphereOnTheCapAndOnTheRim) {
    for (auto axis : all_axes) {
        capsule_shape a{scalar(0.1), scalar(0.3), axis};
        cylinder_shape b{scalar(0.5), scalar(0.3), axis};
        auto up_a = axis_to(axis, vector3_y), up_b = axis_to(axis, vector3_y);
        auto gap = scalar(0.007);
        auto r = collide_cylinder_checked(a, b, make_ctx({0.2f, 0.7f + gap, 0.1f}, up_a, vector3_zero, up_b));
        ASSERT_EQ(r.num_points, 1u);
        EXPECT_NEAR(r.point[0].distance, gap, cylinder_tol);
        expect_vec_near(r.point[0].normal, vector3_y, cylinder_tol);
        expect_feature(r.point[0].featureA, capsule_feature::hemisphere, 1);
        expect_feature(r.point[0].featureB, cylinder_feature::face, 0);

        // The lower end's centre diagonally off the rim at (0.5, 0.3, 0).
        auto ctx = make_ctx({0.6f, 0.4f + 0.3f, 0}, up_a, vector3_zero, up_b, scalar(0.1));
        auto s = collide_cylinder_checked(a, b, ctx);
        ASSERT_EQ(s.num_points, 1u);
        EXPECT_NEAR(s.point[0].distance, 0.1f * std::sqrt(2.f) - 0.1f, cylinder_tol);
        expect_vec_near(s.point[0].normal, normalize(vector3{1, 1, 0}), 1e-4);
        expect_vec_near(world_b<capsule_shape, cylinder_shape>(ctx, s.point[0]), {0.5f, 0.3f, 0}, 1e-4);
        expect_feature(s.point[0].featureA, capsule_feature::hemisphere, 1);
        expect_feature(s.point[0].featureB, cylinder_feature::cap_edge, 0);
    }
}

TEST(CollideCylinderCapsule, RandomAgainstBruteForce) {
    random_against_brute_force<cylinder_shape, capsule_shape>(random_cylinder, random_capsule, scalar(1.6),
                                                              37);
}

TEST(CollideCylinderCapsule, RandomNearlyCoaxialTouching) {
    random_nearly_coaxial_touching<capsule_shape>(random_capsule, 79);
}

TEST(CollideCylinderCapsule, RandomTouchingFarFromTheOrigin) {
    random_touching_far_from_origin<cylinder_shape, capsule_shape>(random_cylinder, random_capsule,
                                                                   scalar(1.6), 43);
}

TEST(CollideCylinderCapsule, RecordedPilePairsAreExact) {
    using a = coordinate_axis;
    // Deepest point 2 cm too shallow: the axis between two nearly coincident points was noise.
    expect_recorded_pairs_exact<capsule_shape>({
        {cylinder_shape{0x1.c66d44p-3f, 0x1.c66d44p-3f, a::y},
         capsule_shape{0x1.8bed2p-3f, 0x1.8bed2p-3f, a::x},
         {{0x1.0ec8d6p+4f, 0x1.c63c5ap-3f, -0x1.8f3d28p+3f},
          {0x1.fd871cp-3f, -0x1.6a0014p-1f, -0x1.52e86ep-1f, 0x1.f121ecp-8f},
          {0x1.08ad22p+4f, 0x1.38c576p-1f, -0x1.84f4cep+3f},
          {-0x1.ed3c5ep-4f, -0x1.f61b1cp-1f, 0x1.38398ap-3f, 0x1.7a1e98p-6f},
          0x1.94bee4p-6f}},
    });
}

// Cylinder–sphere.

TEST(CollideCylinderSphere, CapSideAndRim) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.5), scalar(0.4), axis};
        sphere_shape b{scalar(0.2)};
        auto orn = axis_to(axis, vector3_y);
        // Sphere below cap 1, inside the rim.
        auto r = collide_cylinder_checked(
            a, b, make_ctx(vector3_zero, orn, {0.3f, -0.61f, 0}, quaternion_identity));
        ASSERT_EQ(r.num_points, 1u);
        EXPECT_NEAR(r.point[0].distance, 0.01f, cylinder_tol);
        expect_vec_near(r.point[0].normal, vector3_y, cylinder_tol);
        expect_vec_near(to_world_space(r.point[0].pivotA, vector3_zero, orn), {0.3f, -0.4f, 0}, cylinder_tol);
        expect_feature(r.point[0].featureA, cylinder_feature::face, 1);
        EXPECT_FALSE(r.point[0].featureB.has_value());
        // Beside the side.
        auto s = collide_cylinder_checked(a, b,
                                          make_ctx(vector3_zero, orn, {0, 0.1f, 0.69f}, quaternion_identity));
        ASSERT_EQ(s.num_points, 1u);
        EXPECT_NEAR(s.point[0].distance, -0.01f, cylinder_tol);
        expect_vec_near(s.point[0].normal, -vector3_z, cylinder_tol);
        expect_feature(s.point[0].featureA, cylinder_feature::side_edge, 0);
        // Diagonally off the rim of cap 0.
        auto d = (scalar(0.2) + scalar(0.015)) / std::sqrt(scalar(2));
        auto t = collide_cylinder_checked(
            a, b, make_ctx(vector3_zero, orn, {0.5f + d, 0.4f + d, 0}, quaternion_identity));
        ASSERT_EQ(t.num_points, 1u);
        EXPECT_NEAR(t.point[0].distance, 0.015f, cylinder_tol);
        expect_vec_near(t.point[0].normal, -normalize(vector3{1, 1, 0}), 1e-4);
        expect_feature(t.point[0].featureA, cylinder_feature::cap_edge, 0);
        // Beyond the threshold.
        EXPECT_EQ(
            collide_cylinder_checked(a, b, make_ctx(vector3_zero, orn, {0, 0.1f, 0.73f}, quaternion_identity))
                .num_points,
            0u);
    }
}

TEST(CollideCylinderSphere, CentreInsideLeavesThroughTheNearerBoundary) {
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.5), scalar(0.4), axis};
        sphere_shape b{scalar(0.1)};
        auto orn = axis_to(axis, vector3_y);
        // 0.1 below cap 0, 0.3 inside the side: out through the cap.
        auto r =
            collide_cylinder_checked(a, b, make_ctx(vector3_zero, orn, {0.2f, 0.3f, 0}, quaternion_identity));
        ASSERT_EQ(r.num_points, 1u);
        EXPECT_NEAR(r.point[0].distance, -0.2f, cylinder_tol);
        expect_vec_near(r.point[0].normal, -vector3_y, cylinder_tol);
        expect_feature(r.point[0].featureA, cylinder_feature::face, 0);
        // 0.35 below cap 0, 0.05 inside the side: out through the side.
        auto s = collide_cylinder_checked(
            a, b, make_ctx(vector3_zero, orn, {0, 0.05f, -0.45f}, quaternion_identity));
        ASSERT_EQ(s.num_points, 1u);
        EXPECT_NEAR(s.point[0].distance, -0.15f, cylinder_tol);
        expect_vec_near(s.point[0].normal, vector3_z, cylinder_tol);
        expect_feature(s.point[0].featureA, cylinder_feature::side_edge, 0);
    }
}

TEST(CollideCylinderSphere, RandomAgainstBruteForce) {
    auto make_sphere = [](std::mt19937 &rng) {
        std::uniform_real_distribution<scalar> size(scalar(0.05), scalar(0.5));
        return sphere_shape{size(rng)};
    };
    random_against_brute_force<cylinder_shape, sphere_shape>(random_cylinder, make_sphere, scalar(1.3), 41);
}

// Cylinder–plane.

TEST(CollideCylinderPlane, StandingLyingAndTilted) {
    // A sloped plane through (0, 1, 0); the cylinder is placed in the plane's frame.
    auto n = normalize(vector3{0.3f, 1, -0.2f});
    plane_shape b{n, dot(n, vector3{0, 1, 0})};
    vector3 t0, t1;
    plane_space(n, t0, t1);
    auto base = vector3{0, 1, 0} + t0 * 0.4f;
    for (auto axis : all_axes) {
        cylinder_shape a{scalar(0.3), scalar(0.5), axis};
        auto gap = scalar(-0.005);
        // Standing on cap 1: four rim points, a quarter turn apart.
        auto standing = make_ctx(base + n * (0.5f + gap), axis_to(axis, n), {9, 9, 9},
                                 quaternion_axis_angle(vector3_x, 1));
        auto r = collide_cylinder_checked(a, b, standing);
        ASSERT_EQ(r.num_points, 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            EXPECT_NEAR(r.point[i].distance, gap, cylinder_tol);
            expect_vec_near(r.point[i].normal, n, cylinder_tol);
            expect_feature(r.point[i].featureA, cylinder_feature::face, 1);
            EXPECT_NEAR(dot(n, world_b<cylinder_shape, plane_shape>(standing, r.point[i])) - b.constant, 0,
                        cylinder_tol);
        }
        EXPECT_NEAR((manifold_area<cylinder_shape, plane_shape>(r, standing)), 2 * a.radius * a.radius, 1e-3);
        // Lying along t1: the two ends of the lowest side line.
        auto lying = make_ctx(base + n * (0.3f + gap), axis_to(axis, t1), vector3_zero, quaternion_identity);
        auto s = collide_cylinder_checked(a, b, lying);
        ASSERT_EQ(s.num_points, 2u);
        for (std::size_t i = 0; i < 2; ++i) {
            EXPECT_NEAR(s.point[i].distance, gap, cylinder_tol);
            expect_feature(s.point[i].featureA, cylinder_feature::side_edge, 0);
            EXPECT_NEAR(std::abs(dot(s.point[i].pivotB - base, t1)), 0.5f, cylinder_tol);
        }
        // Tilted by 30 degrees about t0: the deepest rim point only.
        auto angle = to_radians(30);
        auto tilt = quaternion_axis_angle(t0, angle);
        auto lowest = a.half_length * std::cos(angle) + a.radius * std::sin(angle);
        auto tilted =
            make_ctx(base + n * (lowest + gap), tilt * axis_to(axis, n), vector3_zero, quaternion_identity);
        auto t = collide_cylinder_checked(a, b, tilted);
        ASSERT_EQ(t.num_points, 1u);
        EXPECT_NEAR(t.point[0].distance, gap, cylinder_tol);
        expect_feature(t.point[0].featureA, cylinder_feature::cap_edge, 1);
        // Apart beyond the threshold.
        auto apart = make_ctx(base + n * 0.53f, axis_to(axis, n), vector3_zero, quaternion_identity);
        EXPECT_EQ(collide_cylinder_checked(a, b, apart).num_points, 0u);
    }
}

TEST(CollideCylinderPlane, RandomAgainstSampledRims) {
    std::mt19937 rng(53 + random_seed_offset);
    std::uniform_real_distribution<scalar> height(scalar(-0.5), scalar(0.8));
    for (int i = 0; i < 200; ++i) {
        auto a = random_cylinder(rng);
        auto n = random_direction(rng);
        plane_shape b{n, scalar(0.2)};
        auto ctx = make_ctx(n * (b.constant + height(rng)), random_orientation(rng), vector3_zero,
                            quaternion_identity, scalar(100));
        auto r = collide_cylinder_checked(a, b, ctx);
        ASSERT_GT(r.num_points, 0u);
        auto rims = support_of(a, ctx.posA, ctx.ornA);
        auto lowest = -rims.support(-n) - b.constant;
        EXPECT_NEAR(min_distance(r), lowest, 1e-4) << "config " << i;
        for (std::size_t j = 0; j < r.num_points; ++j) {
            EXPECT_NEAR((sd(a, ctx.posA, ctx.ornA, world_a<cylinder_shape, plane_shape>(ctx, r.point[j]))), 0,
                        1e-4);
        }
    }
}
