#ifndef EDYN_MATH_GEOM_HPP
#define EDYN_MATH_GEOM_HPP

#include "edyn/math/vector2.hpp"
#include "edyn/math/vector3.hpp"
#include <cstddef>

// Closest-point and clipping routines shared by every collide() pair. None of them allocates;
// polygon routines write into caller-provided arrays whose required size is stated below.
namespace edyn {

// Segments and lines.

// Closest point to q on the segment [p0, p1]; `t` receives its parameter (0 at p0, 1 at p1). A
// degenerate segment (p0 == p1) gives p0 and t = 0.
vector3 closest_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &q, scalar &t) noexcept;

inline vector3 closest_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &q) noexcept {
    scalar t;
    return closest_point_segment(p0, p1, q, t);
}

inline scalar distance_sqr_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &q) noexcept {
    return distance_sqr(closest_point_segment(p0, p1, q), q);
}

// Closest point to q on the infinite line p + dir * t; `t` receives its parameter.
// Precondition: dir is not the zero vector.
vector3 closest_point_line(const vector3 &p, const vector3 &dir, const vector3 &q, scalar &t) noexcept;

// Result of closest_points_segment_segment. Point i is pointA[i] = a0 + (a1 - a0) * sA[i] on
// segment A paired with pointB[i] = b0 + (b1 - b0) * sB[i] on segment B.
struct segment_closest_points {
    // 1, or 2 when the segments are parallel and their projections overlap: then the two pairs
    // sit at the ends of the overlap, each pointB the closest point of B to its pointA.
    std::size_t num_points{0};
    vector3 pointA[2];
    vector3 pointB[2];
    scalar sA[2];
    scalar sB[2];
    // Smallest squared distance among the pairs.
    scalar distance_sqr{0};
};

// Sine of the angle below which closest_points_segment_segment treats two segments as parallel.
// The distance of the parallel pairs exceeds the true minimum by at most this sine times the
// shorter segment's length.
inline constexpr scalar segment_parallel_tolerance = scalar(1e-3);

// Closest points between the segments [a0, a1] and [b0, b1]. Degenerate segments (points) are
// handled. When they are parallel (see segment_parallel_tolerance) and their projections on
// A's line overlap by more than a rounding error, two pairs are returned (see above).
segment_closest_points
closest_points_segment_segment(const vector3 &a0, const vector3 &a1, const vector3 &b0, const vector3 &b1,
                               scalar parallel_tolerance = segment_parallel_tolerance) noexcept;

// Support point of the segment [p0, p1] in direction `dir` (p0 on ties).
inline vector3 support_point_segment(const vector3 &p0, const vector3 &p1, const vector3 &dir) noexcept {
    return dot(p1 - p0, dir) > 0 ? p1 : p0;
}

// Clips the parametric interval [t0, t1] of the line p + dir * t to the half-space
// dot(normal, x) <= constant. Returns false when nothing is left.
bool clip_line_interval(const vector3 &p, const vector3 &dir, const vector3 &normal, scalar constant,
                        scalar &t0, scalar &t1) noexcept;

// Clips the segment [p0, p1] in place to the half-space dot(normal, x) <= constant. Returns
// false (leaving p0, p1 unspecified) when nothing is left.
bool clip_segment_half_space(vector3 &p0, vector3 &p1, const vector3 &normal, scalar constant) noexcept;

// Planes: the points x with dot(normal, x) == constant; `normal` is unit length.

constexpr scalar distance_point_plane(const vector3 &normal, scalar constant, const vector3 &p) noexcept {
    return dot(normal, p) - constant;
}

constexpr vector3 project_point_plane(const vector3 &normal, scalar constant, const vector3 &p) noexcept {
    return p - normal * distance_point_plane(normal, constant, p);
}

// Boxes: axis aligned, centred at the origin, given by their half extents (a box's object space).

// Closest point of the solid box to p (p itself when inside).
constexpr vector3 closest_point_box(const vector3 &half_extents, const vector3 &p) noexcept {
    return {std::clamp(p.x, -half_extents.x, half_extents.x),
            std::clamp(p.y, -half_extents.y, half_extents.y),
            std::clamp(p.z, -half_extents.z, half_extents.z)};
}

// Whether p lies in the box grown by `tolerance` on every side.
constexpr bool point_in_box(const vector3 &half_extents, const vector3 &p, scalar tolerance = 0) noexcept {
    return p.x <= half_extents.x + tolerance && p.x >= -half_extents.x - tolerance &&
           p.y <= half_extents.y + tolerance && p.y >= -half_extents.y - tolerance &&
           p.z <= half_extents.z + tolerance && p.z >= -half_extents.z - tolerance;
}

// Vertex of the box farthest along `dir` (the positive vertex on ties).
constexpr vector3 support_point_box(const vector3 &half_extents, const vector3 &dir) noexcept {
    return {dir.x < 0 ? -half_extents.x : half_extents.x, dir.y < 0 ? -half_extents.y : half_extents.y,
            dir.z < 0 ? -half_extents.z : half_extents.z};
}

// Half length of the box's projection on `axis` (box space; unit length for a distance).
inline scalar box_projection_radius(const vector3 &half_extents, const vector3 &axis) noexcept {
    return half_extents.x * std::abs(axis.x) + half_extents.y * std::abs(axis.y) +
           half_extents.z * std::abs(axis.z);
}

// Closest point of the box surface to a point inside it: the projection on the nearest face.
// Returns that face's axis (0, 1, 2); `sign` receives +1 or -1 for the face's side and `depth`
// the distance from p to the face (>= 0 inside). Ties go to the lower axis.
int nearest_box_face(const vector3 &half_extents, const vector3 &p, scalar &sign, scalar &depth) noexcept;

// Closest points between the segment [p0, p1] and the solid box. Returns the squared distance
// (0 when the segment touches or crosses the box); `t` receives the parameter of the point on
// the segment, `on_segment` and `on_box` the two points. Exact: the squared distance is a
// convex piecewise quadratic in t whose pieces are minimised in closed form.
scalar closest_points_segment_box(const vector3 &half_extents, const vector3 &p0, const vector3 &p1,
                                  scalar &t, vector3 &on_segment, vector3 &on_box) noexcept;

// Discs and circles (a cylinder's caps and rims).

// Closest point to p on the solid disc of `radius` centred at `center` with unit `normal`.
vector3 closest_point_disc(const vector3 &center, const vector3 &normal, scalar radius,
                           const vector3 &p) noexcept;

// Closest point to p on the circle of `radius` centred at `center` with unit `normal`. When p is
// on the axis (every point is closest) the point along plane_space(normal)'s first vector.
vector3 closest_point_circle(const vector3 &center, const vector3 &normal, scalar radius,
                             const vector3 &p) noexcept;

// Polygons: arrays of at least three vertices in order (clip segments with
// clip_segment_half_space); clipping follows Sutherland–Hodgman, so convex inputs give convex
// outputs. A vertex lying exactly on a clipping line is kept once, never duplicated.

// Keeps the part of the convex polygon `in` (n vertices) with dot(normal, p) <= constant and
// writes it to `out`, which needs room for n + 1 vertices. Returns the number written.
std::size_t clip_polygon_half_plane(const vector2 *in, std::size_t n, const vector2 &normal, scalar constant,
                                    vector2 *out) noexcept;

// 3D counterpart: keeps the part with dot(normal, p) <= constant; `out` needs n + 1 vertices.
std::size_t clip_polygon_half_space(const vector3 *in, std::size_t n, const vector3 &normal, scalar constant,
                                    vector3 *out) noexcept;

// Intersection of the polygon `subject` (n vertices) with the convex polygon `clip` (m
// vertices, counter-clockwise). `out` and `scratch` each need room for n + m vertices. Returns
// the number of vertices written to `out`.
std::size_t clip_polygon_convex(const vector2 *subject, std::size_t n, const vector2 *clip, std::size_t m,
                                vector2 *out, vector2 *scratch) noexcept;

// Whether p lies in the convex counter-clockwise polygon grown by `tolerance`.
bool point_in_convex_polygon(const vector2 *polygon, std::size_t n, const vector2 &p,
                             scalar tolerance = 0) noexcept;

// Signed area of a polygon: positive when counter-clockwise.
scalar polygon_signed_area(const vector2 *polygon, std::size_t n) noexcept;

// Area of the quadrilateral with vertices p0..p3 taken in the order (of the three possible)
// that gives the largest area; for four points in convex position, the area of their hull.
inline scalar quadrilateral_area(const vector3 &p0, const vector3 &p1, const vector3 &p2,
                                 const vector3 &p3) noexcept {
    // Area of a quad is half the cross product of its diagonals.
    auto a0 = length_sqr(cross(p2 - p0, p3 - p1));
    auto a1 = length_sqr(cross(p3 - p0, p1 - p2));
    auto a2 = length_sqr(cross(p1 - p0, p2 - p3));
    return scalar(0.5) * std::sqrt(std::max(a0, std::max(a1, a2)));
}

} // namespace edyn

#endif // EDYN_MATH_GEOM_HPP
