#ifndef EDYN_COLLISION_DETAIL_CYLINDER_GEOM_HPP
#define EDYN_COLLISION_DETAIL_CYLINDER_GEOM_HPP

#include "edyn/collision/collision_result.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/shapes/cylinder_shape.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>

// Exact cylinder geometry for the collide() pairs that involve a cylinder: projections and
// support points, closest points between circles and segments or other circles, and the
// manifold builder that clips a cylinder's supporting feature (cap disc, side line or rim point)
// against the other shape's. Nothing here approximates a cap by a polygon.
namespace edyn::detail {

// A cylinder placed in some frame (world space, or another shape's space).
struct placed_cylinder {
    vector3 center;
    vector3 axis; // Unit; cap 0 lies at center + axis * half_length, cap 1 at the opposite end.
    scalar half_length;
    scalar radius;
};

placed_cylinder place_cylinder(const cylinder_shape &shape, const vector3 &pos,
                               const quaternion &orn) noexcept;

constexpr scalar cylinder_cap_sign(unsigned cap) noexcept { return cap == 0 ? scalar(1) : scalar(-1); }

inline vector3 cylinder_cap_center(const placed_cylinder &cyl, unsigned cap) noexcept {
    return cyl.center + cyl.axis * (cyl.half_length * cylinder_cap_sign(cap));
}

// Half length of the placed cylinder's projection on the unit direction `dir`.
inline scalar cylinder_projection_radius(const placed_cylinder &cyl, const vector3 &dir) noexcept {
    return edyn::cylinder_projection_radius(cyl.axis, cyl.half_length, cyl.radius, dir);
}

// Point of the cylinder farthest along `dir` (any length). On ties, cap 0 and the direction
// plane_space(axis) gives.
vector3 cylinder_support_point(const placed_cylinder &cyl, const vector3 &dir) noexcept;

// Numerics. The circle routines work in double precision internally whatever edyn::scalar is.

// Real roots of c[0] + c[1] x + ... + c[degree] x^degree (degree <= 4) inside [lo, hi], in
// increasing order; a double root shows only where rounding gives it a sign change, so callers
// that need those also test the extrema, which `extrema` receives (roots of the derivative in
// [lo, hi], at most degree - 1) when not null. Returns the number of roots.
std::size_t polynomial_roots(const double *c, int degree, double lo, double hi, double *roots,
                             double *extrema = nullptr, std::size_t *num_extrema = nullptr) noexcept;

// Segment parameters t in [0, 1] of the critical points of the distance between the segment
// [p0, p1] and the circle (center, unit normal, radius), increasing and without repeats: the
// roots of the quartic that the derivative of the squared distance to the circle's nearest point
// gives once its square root is cleared (the same quartic holds for the farthest point), the
// quartic's extrema and two closed-form points standing in for double roots, and both ends.
// The circle's nearest point to the segment point at t is closest_point_circle().
inline constexpr std::size_t max_circle_segment_critical = 12;
std::size_t circle_segment_critical_points(const vector3 &center, const vector3 &normal, scalar radius,
                                           const vector3 &p0, const vector3 &p1,
                                           scalar (&t)[max_circle_segment_critical]) noexcept;

// Local minima of the distance between two circles (a point on each), at most four. Solved
// numerically: the distance from a point of circle A to circle B has a closed form, so its
// derivative along A's angle is sampled at 16 angles and each sign change from - to + is
// bracketed and refined by Newton steps (with the analytic second derivative) kept inside the
// bracket until the angle moves by less than 1e-9 rad, which puts the points far within 1e-6 of
// the minimum relative to the radii. Coaxial circles (every point a minimum) give one pair.
inline constexpr std::size_t max_circle_circle_minima = 4;
std::size_t circle_circle_local_minima(const vector3 &center_a, const vector3 &normal_a, scalar radius_a,
                                       const vector3 &center_b, const vector3 &normal_b, scalar radius_b,
                                       vector3 (&on_a)[max_circle_circle_minima],
                                       vector3 (&on_b)[max_circle_circle_minima]) noexcept;

// Parameter interval [t0, t1] (within [0, 1]) of the segment [p0, p1] inside the sphere of
// `radius` about `center` (for a segment in a disc's plane: the part over the disc). Returns
// false when the segment misses it.
bool clip_segment_sphere(const vector3 &p0, const vector3 &p1, const vector3 &center, scalar radius,
                         scalar &t0, scalar &t1) noexcept;

// Separating-axis bookkeeping. `distance` is the largest separation found so far, `normal` its
// axis oriented from B towards A. A later axis replaces the current one only when it separates
// by more than `bias`: axes are tried faces first, so near ties keep the face axis, and the
// bias (a millionth of the shapes' size) stays far below any distance a test or solver resolves.
//
// Near its maximum the separation changes only to second order with the axis, so the best value
// alone fixes the axis poorly (two rims of a cylinder can give values 1e-7 apart along directions
// 1e-3 apart). Axes taken from a pair of points, one in each shape, are therefore also kept as
// witnesses when the separation along them equals the points' distance (apart) or minus it
// (overlapping): such an axis is exactly the direction between closest (or deepest) points, and
// finish() snaps to the best witness when it ties the best axis within `witness_tolerance`.
//
// Where the shapes touch, a pair of points nearly coincides and the line through them is the
// rounding of their coordinates, not the axis along which they touch: pairs closer than
// `coincident` also test the axis their features give (a side's normal, the line across two
// crossing edges).
struct sat_result {
    vector3 normal{vector3_y};
    scalar distance{-large_scalar};
    scalar bias{0};
    vector3 witness_normal{vector3_y};
    scalar witness_distance{-large_scalar};
    scalar witness_tolerance{0};
    scalar coincident{0};

    // The tolerances for shapes of `size` (the sum of their extents): bias a millionth of it,
    // witness_tolerance 1e-5, coincident 1 %.
    void scale_to(scalar size) noexcept {
        bias = scalar(1e-6) * size;
        witness_tolerance = scalar(1e-5) * size;
        coincident = scalar(0.01) * size;
    }

    // Tests unit axis `n`: `delta` is dot(center A - center B, n), `radius_a`/`radius_b` the
    // shapes' projection half lengths on n.
    void test(const vector3 &n, scalar delta, scalar radius_a, scalar radius_b) noexcept {
        auto sep = std::abs(delta) - radius_a - radius_b;
        if (sep > distance + bias) {
            distance = sep;
            normal = delta < 0 ? -n : n;
        }
    }

    // Tests the unit axis `n` = (pA - pB) / len for points pA in A and pB in B, `len` apart.
    void test_witness(const vector3 &n, scalar len, scalar delta, scalar radius_a, scalar radius_b) noexcept {
        test(n, delta, radius_a, radius_b);
        auto sep_plus = delta - radius_a - radius_b;
        auto sep_minus = -delta - radius_a - radius_b;
        if (std::abs(sep_plus - len) <= witness_tolerance && sep_plus > witness_distance) {
            witness_distance = sep_plus;
            witness_normal = n;
        } else if (std::abs(sep_minus + len) <= witness_tolerance && sep_minus > witness_distance) {
            witness_distance = sep_minus;
            witness_normal = -n;
        }
    }

    // Whether the shapes are apart and a witness pair is known to be closest: its points lie
    // `len` apart and the shapes are separated along their axis by `len` within the witness
    // tolerance, and the shapes' distance lies between those two. Every axis not tested yet
    // separates them by at most that distance, so no later test can do more than tie.
    bool closest_pair_found() const noexcept { return witness_distance > 0; }

    void finish() noexcept {
        if (witness_distance >= distance - witness_tolerance) {
            normal = witness_normal;
            distance = witness_distance;
        }
    }
};

// The feature through which a shape touches the other along a contact normal, in the frame of
// the separating-axis test. build_manifold() clips two of them.
enum class contact_feature_kind : unsigned char {
    point,   // vertices[0]: a box vertex, a capsule end.
    segment, // vertices[0..1]: a box edge, a cylinder's or capsule's side line.
    polygon, // vertices[0..3], counter-clockwise seen from outside; `normal` outward: a box face.
    disc,    // center, normal (outward), radius: a cylinder cap facing the other shape;
             // vertices[0] is its rim point deepest in the feature's direction.
    rim      // A cylinder cap tilted towards the other shape: vertices[0] is its deepest rim
             // point; center, normal, radius describe the cap as for `disc`.
};

struct contact_feature {
    contact_feature_kind kind{contact_feature_kind::point};
    // The shape's exact support point in the feature's direction (on the feature).
    vector3 support{vector3_zero};
    vector3 vertices[4]{};
    vector3 center{vector3_zero};
    vector3 normal{vector3_zero};
    scalar radius{0};
    collision_feature id{};
    bool has_id{false};
};

// Sine of the angle within which a cylinder's cap counts as facing the contact normal (a disc)
// and its side as lying across it (a side line); also used for box faces and edges and capsule
// sides. About 2.9 degrees: a resting shape keeps its multi-point manifold through the small
// tilts a solver leaves, and points that a tilted feature lifts beyond the threshold are
// dropped anyway.
inline constexpr scalar feature_tolerance = scalar(0.05);

// Supporting feature of a cylinder in direction `dir` (unit), i.e. towards the other shape, and
// the feature every point of its manifold reports: a cap facing `dir` is a disc,
// {cylinder_feature::face, cap}; a side across it a segment, {cylinder_feature::side_edge, 0};
// otherwise the tilted cap's rim, {cylinder_feature::cap_edge, cap}. Cap 0 is at +half_length.
contact_feature cylinder_support_feature(const placed_cylinder &cyl, const vector3 &dir) noexcept;

// Supporting feature of a box of `half_extents` centred at the origin with identity orientation
// in direction `dir` (unit): a face, an edge or a vertex (box_features.hpp indices).
contact_feature box_support_feature(const vector3 &half_extents, const vector3 &dir) noexcept;

// Supporting feature of a capsule whose segment runs from p0 (hemisphere 0) to p1 (hemisphere
// 1), in direction `dir` (unit): its side line or the deeper hemisphere's support point.
contact_feature capsule_support_feature(const vector3 &p0, const vector3 &p1, scalar radius,
                                        const vector3 &dir) noexcept;

// Clips feature `a` of shape A against feature `b` of shape B, both in the frame of `ctx` (whose
// transforms map that frame's points to each shape's object space as to_object_space does),
// for the unit `normal` (that frame, from B towards A). Each point is lifted along the normal
// onto both features, so that its pivots differ by exactly its distance along the normal; points
// whose lift misses the other feature (a feature taken within feature_tolerance of the normal
// while the support is in fact one of its vertices) and points beyond ctx.threshold are dropped.
// When no point is left the exact support points make the one point. `to_world` rotates the
// frame's normal to world space.
void build_manifold(const contact_feature &a, const contact_feature &b, const vector3 &normal,
                    const collision_context &ctx, const quaternion &to_world,
                    collision_result &result) noexcept;

} // namespace edyn::detail

#endif // EDYN_COLLISION_DETAIL_CYLINDER_GEOM_HPP
